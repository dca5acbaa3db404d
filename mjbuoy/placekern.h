// placekern: the vertex stage's placement in lanes (seavec.h PlaceIn),
// included by seavec_avx2.cc and seavec_avx512.cc after seavec_kern.h
// (Lanes). Body-frame vertices in, positions relative to the COM (3 each,
// as cpu.cc stores them) and the label search's points and guesses out;
// cpu.cc's placeVertices is the scalar path. Everything here is static.
#ifndef MJBUOY_PLACEKERN_H_
#define MJBUOY_PLACEKERN_H_

#include "seavec.h"

namespace mjb {
namespace {

// component j of the W vectors of N doubles each stored one after another
// from p (N = 2 or 3): two two-source shuffles (the lanes' elements N l + j
// lie in the N loads of W)
template <int W, int N>
static inline typename Lanes<W>::V unzip(const double* p, int j) {
  typedef typename Lanes<W>::V V;
  typedef typename Lanes<W>::I I;
  const V a = Lanes<W>::ld(p), b = Lanes<W>::ld(p + W);
  const V c = N == 3 ? Lanes<W>::ld(p + 2 * W) : a;
  I m1, m2;
  for (int l = 0; l < W; l++) {
    const int e = N * l + j;
    m1[l] = e < 2 * W ? e : 0;
    m2[l] = e < 2 * W ? l : W + e - 2 * W;
  }
  return __builtin_shuffle(__builtin_shuffle(a, b, m1), c, m2);
}

// the W pairs of floats from p split into their first and second members,
// as doubles
template <int W>
struct FLanes {
  typedef float F __attribute__((vector_size(4 * 2 * W)));  // 2 W floats
  typedef int J __attribute__((vector_size(4 * 2 * W)));    // their shuffle
  typedef float H __attribute__((vector_size(4 * W)));      // half of them
};
template <int W>
static inline void unzipPairs(const float* p, typename Lanes<W>::V* a, typename Lanes<W>::V* b) {
  typedef typename FLanes<W>::F F;
  typedef typename FLanes<W>::J J;
  typedef typename FLanes<W>::H H;
  F f;
  __builtin_memcpy(&f, p, sizeof f);
  J m;
  for (int l = 0; l < W; l++) m[l] = 2 * l, m[W + l] = 2 * l + 1;
  const F s = __builtin_shuffle(f, m);
  H h[2];
  __builtin_memcpy(h, &s, sizeof s);
  *a = __builtin_convertvector(h[0], typename Lanes<W>::V);
  *b = __builtin_convertvector(h[1], typename Lanes<W>::V);
}

// the W 3-vectors (x[l], y[l], z[l]) stored one after another from p
template <int W>
static inline void zip3(double* p, typename Lanes<W>::V x, typename Lanes<W>::V y,
                        typename Lanes<W>::V z) {
  typedef typename Lanes<W>::I I;
  for (int q = 0; q < 3; q++) {
    I m1, m2;
    for (int l = 0; l < W; l++) {
      const int e = q * W + l, v = e / 3, c = e % 3;
      m1[l] = c == 0 ? v : c == 1 ? W + v : 0;
      m2[l] = c == 2 ? W + v : l;
    }
    Lanes<W>::st(p + q * W, __builtin_shuffle(__builtin_shuffle(x, y, m1), z, m2));
  }
}

// vertices [q, q + W) of in (cpu.cc placeVertices)
template <int W>
static inline void placeChunk(const PlaceIn& in, int q) {
  typedef typename Lanes<W>::V V;
  const double* p = in.p + 3 * q;
  const V px = unzip<W, 3>(p, 0), py = unzip<W, 3>(p, 1), pz = unzip<W, 3>(p, 2);
  V r[3];
  for (int j = 0; j < 3; j++) {
    r[j] = in.R[3 * j] * px + in.R[3 * j + 1] * py + in.R[3 * j + 2] * pz + in.t[j];
  }
  zip3<W>(in.rel + 3 * q, r[0], r[1], r[2]);
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

// the whole chunks of W vertices; returns how many vertices were placed
// (cpu.cc's scalar loop does the rest)
template <int W>
static int placeLanes(const PlaceIn& in) {
  int q = 0;
  for (; q + W <= in.m; q += W) placeChunk<W>(in, q);
  return q;
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_PLACEKERN_H_
