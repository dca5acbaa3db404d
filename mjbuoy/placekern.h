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

// component j of the W vectors of n doubles each stored one after another
// from p (n = 2 or 3): two two-source shuffles (the lanes' elements n l + j
// lie in the n loads of W)
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
    const double* o = in.o[s] + 2 * q;
    g[0] += in.L[s] * unzip<W, 2>(o, 0);
    g[1] += in.L[s] * unzip<W, 2>(o, 1);
  }
  Lanes<W>::st(in.A0 + q, X + g[0]);
  Lanes<W>::st(in.A1 + q, Y + g[1]);
}

template <int W>
static void placeLanes(const PlaceIn& in) {
  int q = 0;
  for (; q + W <= in.m; q += W) placeChunk<W>(in, q);
  for (; q < in.m; q++) {
    const double* p = in.p + 3 * q;
    double* r = in.rel + 3 * q;
    for (int j = 0; j < 3; j++) {
      r[j] = in.R[3 * j] * p[0] + in.R[3 * j + 1] * p[1] + in.R[3 * j + 2] * p[2] + in.t[j];
    }
    in.X[q] = r[0] + in.com[0];
    in.Y[q] = r[1] + in.com[1];
    double g[2] = {0, 0};
    for (int s = 0; s < 3; s++) {
      if (in.L[s] == 0) continue;
      g[0] += in.L[s] * in.o[s][2 * q];
      g[1] += in.L[s] * in.o[s][2 * q + 1];
    }
    in.A0[q] = in.X[q] + g[0];
    in.A1[q] = in.Y[q] + g[1];
  }
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_PLACEKERN_H_
