// placekern: the vertex stage's passes around the label search in lanes
// (seavec.h PlaceIn, HeightIn, PackIn, WetIn), included by seavec_avx2.cc
// and seavec_avx512.cc after seavec_kern.h (Lanes). Placement: body-frame
// vertices in, positions relative to the COM (3 each, as cpuvert.cc stores
// them) and the label search's points and guesses out; then heights,
// e^L and the records. cpuvert.cc's loops are the scalar path. Everything
// here is static.
#ifndef MJBUOY_PLACEKERN_H_
#define MJBUOY_PLACEKERN_H_

#include "sea/seavec.h"
#include "util/expkern.h"
#include "util/zipkern.h"

namespace mjb {
namespace {

// the W pairs of floats from p split into their first and second members,
// as doubles
template <int W>
struct FLanes {
  typedef float F __attribute__((vector_size(4 * 2 * W)));  // 2 W floats
  typedef float H __attribute__((vector_size(4 * W)));      // half of them
};
template <int W>
static inline void unzipPairs(const float* p, typename Lanes<W>::V* a, typename Lanes<W>::V* b) {
  typedef typename FLanes<W>::F F;
  typedef typename FLanes<W>::H H;
  F f;
  __builtin_memcpy(&f, p, sizeof f);
  f = splitPairs<F, W>(f, std::make_integer_sequence<int, 2 * W>());
  H h[2];
  __builtin_memcpy(h, &f, sizeof f);
  *a = __builtin_convertvector(h[0], typename Lanes<W>::V);
  *b = __builtin_convertvector(h[1], typename Lanes<W>::V);
}

// vertices [q, q + W) of in (cpuvert.cc placeVertices)
template <int W>
static inline void placeChunk(const PlaceIn& in, int q) {
  typedef typename Lanes<W>::V V;
  const double* p = in.p + 3 * q;
  V pb[3];
  unzip3<V, W>(p, pb);
  const V px = pb[0], py = pb[1], pz = pb[2];
  V r[3];
  for (int j = 0; j < 3; j++) {
    r[j] = in.R[3 * j] * px + in.R[3 * j + 1] * py + in.R[3 * j + 2] * pz + in.t[j];
  }
  zip3<V, W>(in.rel + 3 * q, r[0], r[1], r[2]);
  const V X = r[0] + in.com[0], Y = r[1] + in.com[1];
  Lanes<W>::st(in.X + q, X);
  Lanes<W>::st(in.Y + q, Y);
  V g[2] = {V{}, V{}};
  for (int s = 0; s < 3; s++) {
    if (in.L[s] == 0) continue;  // (a cold or short history: fewer loads)
    V ox, oy;
    unzipPairs<W>(in.o[s] + 2 * q, &ox, &oy);
    g[0] += in.L[s] * ox;
    g[1] += in.L[s] * oy;
  }
  Lanes<W>::st(in.A0 + q, X + g[0]);
  Lanes<W>::st(in.A1 + q, Y + g[1]);
}

// the W pairs (a[l], b[l]) stored one after another from p as floats
template <int W>
static inline void zipPairs(float* p, typename Lanes<W>::V a, typename Lanes<W>::V b) {
  typedef typename FLanes<W>::F F;
  typedef typename FLanes<W>::H H;
  const H h[2] = {__builtin_convertvector(a, H), __builtin_convertvector(b, H)};
  F f;
  __builtin_memcpy(&f, h, sizeof f);
  f = mergePairs<F, W>(f, std::make_integer_sequence<int, 2 * W>());
  __builtin_memcpy(p, &f, sizeof f);
}

// vertices [q, q + W) of in (cpuvert.cc vertexOut)
template <int W>
static inline void heightChunk(const HeightIn& in, int q) {
  typedef typename Lanes<W>::V V;
  typedef typename Lanes<W>::I I;
  const V a0 = Lanes<W>::ld(in.A0 + q), a1 = Lanes<W>::ld(in.A1 + q);
  zip2<V, W>(in.lab + 2 * q, a0, a1);
  if (in.first) {
    // (a label not finite, which the height reports, guesses nothing)
    const V o0 = a0 - Lanes<W>::ld(in.X + q), o1 = a1 - Lanes<W>::ld(in.Y + q);
    const I ok = ((o0 - o0) == 0) & ((o1 - o1) == 0);
    zipPairs<W>(in.offNew + 2 * q, ok ? o0 : V{}, ok ? o1 : V{});
  }
  const V rz = unzip<V, W, 3, 2>(in.rel + 3 * q);
  Lanes<W>::st(in.h + q, rz + in.zc - Lanes<W>::ld(in.Z + q));
}

template <int W>
static int heightLanes(const HeightIn& in) {
  int q = 0;
  for (; q + W <= in.m; q += W) heightChunk<W>(in, q);
  return q;
}

// vertices [q, q + W) of in: their records (cpuvert.cc packVertices)
template <int W>
static inline void packChunk(const PackIn& in, int q) {
  typedef typename Lanes<W>::V V;
  V f[kRec];
  unzip3<V, W>(in.rel + 3 * q, f);
  f[3] = Lanes<W>::ld(in.h + q);
  f[4] = Lanes<W>::ld(in.zs + q);
  f[5] = Lanes<W>::ld(in.A0 + q);
  f[6] = Lanes<W>::ld(in.A1 + q);
  f[7] = V{};
  storeRecords<V, W>(in.rec + kRec * q, f);
}

template <int W>
static int packLanes(const PackIn& in) {
  int q = 0;
  for (; q + W <= in.m; q += W) packChunk<W>(in, q);
  return q;
}

// the whole chunks of W vertices; returns how many vertices were placed
// (cpuvert.cc's scalar loop does the rest)
template <int W>
static int placeLanes(const PlaceIn& in) {
  int q = 0;
  for (; q + W <= in.m; q += W) placeChunk<W>(in, q);
  return q;
}

// sea.cc's stretch in lanes, the same operations: glibc's fmin(x, y) is x
// where x <= y (so fmin(-0, 0) is -0) or y is NaN, else y (y where x is
// NaN); fmax the same with >=
template <class V>
static inline V stretchLanes(double depth, V z, V eta) {
  const V t = z - eta;
  if (!(depth > 0)) return t <= 0 ? t : V{};
  const V s = t * depth / (depth + eta);
  const V lo = s >= -depth ? s : V{} - depth;
  const V r = lo <= 0 ? lo : V{};
  return depth + eta > 0 ? r : V{} - depth;
}

// vertices [q, q + W) of in (cpuvert.cc wetVertices and vertexWaves, for
// every vertex: no branch on wet or dry)
template <int W, class M>
static inline void wetChunk(const WetIn& in, int q) {
  typedef typename Lanes<W>::V V;
  V rz;
  for (int l = 0; l < W; l++) rz[l] = in.rel[3 * (q + l) + 2];
  const V zs = stretchLanes<V>(in.depth, rz + in.zc - in.level, Lanes<W>::ld(in.Z + q) - in.level);
  Lanes<W>::st(in.ZS + q, zs);
  for (int f = 0; f < (in.finite ? 2 : 1); f++) {
    for (int j = 0; j < in.n; j++) {
      const V x = f == 0 ? in.k[j] * zs : -in.k[j] * (zs + 2 * in.depth);
      const V a = in.fast ? expFast<V, typename Lanes<W>::I>(x) : M::exp(x);
      const int i = in.perm ? in.perm[j] : j;
      for (int l = 0; l < W; l++) {
        const double* sc = in.SC + 2 * in.nw * (q + l);
        double* er = in.E + in.stride * in.nw * (q + l) + 2 * f * in.nw;
        er[j] = a[l] * sc[2 * i + 1];
        er[in.nw + j] = a[l] * sc[2 * i];
      }
    }
  }
}

template <int W, class M>
static int wetLanes(const WetIn& in) {
  int q = 0;
  for (; q + W <= in.m; q += W) wetChunk<W, M>(in, q);
  return q;
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_PLACEKERN_H_
