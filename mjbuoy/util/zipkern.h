// zipkern: W lanes from and to arrays of small vectors stored one after
// another (3 doubles a vertex or triangle, 2 a label), by two-source
// shuffles instead of a load or store per lane (vector extensions; V of W
// doubles). __builtin_shufflevector with constant lane indices from index
// packs, which GCC (12 on) and clang both take. Included by the lane
// kernels (placekern.h, trivec_kern.h); everything here is static.
#ifndef MJBUOY_ZIPKERN_H_
#define MJBUOY_ZIPKERN_H_

#include <utility>

namespace mjb {
namespace {

template <class V, class T>
static inline V zload(const T* p) {
  V v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}

// lane l of component J of W vectors of N doubles: element N l + J of the
// loads a|b (first shuffle; 0 past them), then lane l kept or the element
// taken from the third load c (second shuffle)
template <int W, int N, int J>
struct UnzipIdx {
  static constexpr int e(int l) { return N * l + J; }
  static constexpr int first(int l) { return e(l) < 2 * W ? e(l) : 0; }
  static constexpr int second(int l) { return e(l) < 2 * W ? l : W + e(l) - 2 * W; }
};
template <class V, int W, int N, int J, int... L>
static inline V unzipSeq(V a, V b, V c, std::integer_sequence<int, L...>) {
  const V t = __builtin_shufflevector(a, b, UnzipIdx<W, N, J>::first(L)...);
  return __builtin_shufflevector(t, c, UnzipIdx<W, N, J>::second(L)...);
}

// component J of the W vectors of N elements each (N = 2 or 3) stored one
// after another from p (doubles, or floats with V of W floats)
template <class V, int W, int N, int J, class T>
static inline V unzip(const T* p) {
  const V a = zload<V>(p), b = zload<V>(p + W);
  const V c = N == 3 ? zload<V>(p + 2 * W) : a;
  return unzipSeq<V, W, N, J>(a, b, c, std::make_integer_sequence<int, W>());
}

// all three components of W 3-vectors stored one after another from p
template <class V, int W, class T>
static inline void unzip3(const T* p, V o[3]) {
  o[0] = unzip<V, W, 3, 0>(p);
  o[1] = unzip<V, W, 3, 1>(p);
  o[2] = unzip<V, W, 3, 2>(p);
}

// block Q (W doubles) of W 3-vectors (x, y, z) stored one after another:
// element Q W + l is component c of vector v, from x|y, then z
template <int W, int Q>
struct Zip3Idx {
  static constexpr int v(int l) { return (Q * W + l) / 3; }
  static constexpr int c(int l) { return (Q * W + l) % 3; }
  static constexpr int first(int l) { return c(l) == 0 ? v(l) : c(l) == 1 ? W + v(l) : 0; }
  static constexpr int second(int l) { return c(l) == 2 ? W + v(l) : l; }
};
template <class V, int W, int Q, int... L>
static inline V zip3Block(V x, V y, V z, std::integer_sequence<int, L...>) {
  const V t = __builtin_shufflevector(x, y, Zip3Idx<W, Q>::first(L)...);
  return __builtin_shufflevector(t, z, Zip3Idx<W, Q>::second(L)...);
}

// the W 3-vectors (x[l], y[l], z[l]) stored one after another from p
template <class V, int W, class T>
static inline void zip3(T* p, V x, V y, V z) {
  const auto s = std::make_integer_sequence<int, W>();
  const V o[3] = {zip3Block<V, W, 0>(x, y, z, s), zip3Block<V, W, 1>(x, y, z, s),
                  zip3Block<V, W, 2>(x, y, z, s)};
  __builtin_memcpy(p, o, sizeof o);
}

// block Q of W pairs (x, y) stored one after another: element Q W + l
template <int W, int Q>
struct Zip2Idx {
  static constexpr int e(int l) { return Q * W + l; }
  static constexpr int at(int l) { return e(l) % 2 == 0 ? e(l) / 2 : W + e(l) / 2; }
};
template <class V, int W, int Q, int... L>
static inline V zip2Block(V x, V y, std::integer_sequence<int, L...>) {
  return __builtin_shufflevector(x, y, Zip2Idx<W, Q>::at(L)...);
}

// the W pairs (x[l], y[l]) stored one after another from p
template <class V, int W>
static inline void zip2(double* p, V x, V y) {
  const auto s = std::make_integer_sequence<int, W>();
  const V o[2] = {zip2Block<V, W, 0>(x, y, s), zip2Block<V, W, 1>(x, y, s)};
  __builtin_memcpy(p, o, sizeof o);
}

// 2 W lanes: the first members of W pairs, then the second members
// (split), and back (merge)
template <int W>
struct PairIdx {
  static constexpr int split(int l) { return l < W ? 2 * l : 2 * (l - W) + 1; }
  static constexpr int merge(int l) { return l % 2 == 0 ? l / 2 : W + l / 2; }
};
template <class F, int W, int... L>
static inline F splitPairs(F f, std::integer_sequence<int, L...>) {
  return __builtin_shufflevector(f, f, PairIdx<W>::split(L)...);
}
template <class F, int W, int... L>
static inline F mergePairs(F f, std::integer_sequence<int, L...>) {
  return __builtin_shufflevector(f, f, PairIdx<W>::merge(L)...);
}

// one butterfly stage of a W x W transpose (W vectors of W doubles, the
// rows): rows i and i + B (i / B even) exchange blocks of B lanes, so
// after the stages B = 1, 2, .. W / 2 row i holds column i
template <int W, int B>
struct TransIdx {
  static constexpr int lo(int l) { return (l / B) % 2 == 0 ? l : W + l - B; }
  static constexpr int hi(int l) { return (l / B) % 2 == 0 ? l + B : W + l; }
};
template <class V, int W, int B, int... L>
static inline void transStage(V r[W], std::integer_sequence<int, L...>) {
  for (int i = 0; i < W; i++) {
    if ((i / B) % 2) continue;
    const V a = r[i], b = r[i + B];
    r[i] = __builtin_shufflevector(a, b, TransIdx<W, B>::lo(L)...);
    r[i + B] = __builtin_shufflevector(a, b, TransIdx<W, B>::hi(L)...);
  }
}

// r[i][l] becomes r[l][i] (W = 4 or 8)
template <class V, int W>
static inline void transpose(V r[W]) {
  const auto s = std::make_integer_sequence<int, W>();
  transStage<V, W, 1>(r, s);
  transStage<V, W, 2>(r, s);
  if (W == 8) transStage<V, W, W == 8 ? 4 : 2>(r, s);
}

// a vertex record (kRec doubles: position relative to the COM, height
// above the surface, stretched height, label, one unused), written by the
// vertex stage (placekern.h packLanes) and read by the triangle kernels
// (trivec_kern.h), a load and a transpose per corner instead of a lane
// insert per value
enum { kRec = 8 };

// the records of W vertices g[l] (rec: kRec doubles each) as kRec vectors
// of W lanes: out[f][l] = rec[kRec g[l] + f]
template <class V, int W>
static inline void loadRecords(const double* rec, const int* g, V out[kRec]) {
  for (int h = 0; h < kRec / W; h++) {
    V r[W];
    for (int l = 0; l < W; l++) r[l] = zload<V>(rec + kRec * g[l] + W * h);
    transpose<V, W>(r);
    for (int i = 0; i < W; i++) out[W * h + i] = r[i];
  }
}

// the inverse: W consecutive records from rec, field f from in[f]
template <class V, int W>
static inline void storeRecords(double* rec, const V in[kRec]) {
  for (int h = 0; h < kRec / W; h++) {
    V r[W];
    for (int i = 0; i < W; i++) r[i] = in[W * h + i];
    transpose<V, W>(r);
    for (int l = 0; l < W; l++) __builtin_memcpy(rec + kRec * l + W * h, &r[l], sizeof(V));
  }
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_ZIPKERN_H_
