// waveint_kern: the series of waveint.h for W components at once (GCC
// vector extensions), included by one file per instruction set. Everything
// here is static: no inline function compiled for AVX can be shared with
// the scalar path. Includes nothing but waveker.h.
#ifndef MJBUOY_WAVEINT_KERN_H_
#define MJBUOY_WAVEINT_KERN_H_

#include "sea/serieskern.h"
#include "sea/waveker.h"

namespace mjb {
namespace {

template <int W>
struct Vec {
  typedef double T __attribute__((vector_size(8 * W)));
  static T ld(const double* p) {
    T v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
  }
  // lanes in order (no stack array: an over-aligned one breaks under
  // AddressSanitizer's fake stack)
  // (through a template: GCC checks v[i] of the dependent vector type only
  // when instantiated)
  template <class U>
  static double lanes(U v) {
    double s = 0;
    for (int i = 0; i < W; i++) s += v[i];
    return s;
  }
  static double sum(T v) { return lanes(v); }
};

// W = 1: GCC makes T a plain double
template <>
struct Vec<1> {
  typedef double T;
  static T ld(const double* p) { return *p; }
  static double sum(T v) { return v; }
};

// corner differences of the exponent of components [j, j + W): u = sgn k
// dz + i k D.(dx)
template <int W>
static inline void cornerU(const KernIn& in, int j, typename Vec<W>::T ur[2],
                           typename Vec<W>::T ui[2]) {
  typedef typename Vec<W>::T V;
  typedef Vec<W> L;
  const V k = L::ld(in.k + j), kdx = L::ld(in.kdx + j), kdy = L::ld(in.kdy + j);
  const V gm = L::ld(in.gm + j);
  for (int c = 0; c < 2; c++) {
    V X = in.dp[c][0] + gm * (in.dl[c][0] - in.dp[c][0]);
    V Y = in.dp[c][1] + gm * (in.dl[c][1] - in.dp[c][1]);
    ur[c] = (in.sgn * in.dz[c]) * k;
    ui[c] = kdx * X + kdy * Y;
  }
}

// components [j, j + W)'s S, T times e^L0 and their weights, into acc[7]
template <int W, bool MOM>
static inline void addWeighted(const KernIn& in, int j, const typename Vec<W>::T S[2],
                               const typename Vec<W>::T T[6], typename Vec<W>::T* acc) {
  typedef typename Vec<W>::T V;
  typedef Vec<W> L;
  const V er = L::ld(in.e0r + j), ei = L::ld(in.e0i + j);
  const V wp = L::ld(in.wp + j);
  const V Ir = er * S[0] - ei * S[1], Ii = er * S[1] + ei * S[0];
  acc[0] += wp * Ir;
  if (MOM) {
    acc[1] += wp * (er * T[0] - ei * T[1]);
    acc[2] += wp * (er * T[2] - ei * T[3]);
    acc[3] += wp * (er * T[4] - ei * T[5]);
  }
  acc[4] += L::ld(in.wux + j) * Ir;
  acc[5] += L::ld(in.wuy + j) * Ir;
  acc[6] += L::ld(in.wz + j) * Ii;
}

// components [j, j + W): their series to the degree the widest needs
// (the last: k ascending; *N the count so far, seriesTerms'), accumulated
// into acc[7]; MOM false: S only; ID: seriesLoop's sum rule
template <int W, bool MOM, bool ID>
static inline void seriesChunk(const KernIn& in, int j, const double* R, int* N,
                               typename Vec<W>::T* acc) {
  typedef typename Vec<W>::T V;
  V ur[2], ui[2], S[2], T[6];
  cornerU<W>(in, j, ur, ui);
  *N = termsFrom(*N, in.k[j + W - 1] * in.rho, R);
  // h_m(u1, u2) = u1 h_(m-1) + u2^m; g_m = h_m(u1, u1, u2) = u1 g_(m-1) + h_m;
  // f_m = h_m(u1, u2, u2) = u2 f_(m-1) + h_m; h_m(0, 0, u1, u2) = h_m
  seriesLoop<V, MOM, ID>(ur, ui, *N, S, T);
  addWeighted<W, MOM>(in, j, S, T, acc);
}

// components [j, j + 2 W) without the moments, two chunks in flight
// (seriesPair), to the degree the last needs
template <int W>
static inline void seriesChunk2(const KernIn& in, int j, const double* R, int* N,
                                typename Vec<W>::T* acc) {
  typedef typename Vec<W>::T V;
  V ur[2][2], ui[2][2], S[2][2], T[6] = {};
  cornerU<W>(in, j, ur[0], ui[0]);
  cornerU<W>(in, j + W, ur[1], ui[1]);
  *N = termsFrom(*N, in.k[j + 2 * W - 1] * in.rho, R);
  seriesPair<V>(ur, ui, *N, S);
  addWeighted<W, false>(in, j, S[0], T, acc);
  addWeighted<W, false>(in, j + W, S[1], T, acc);
}

// [j0, j1): chunks of W (two at a time without the moments when W > 1),
// the rest one at a time; W > 1 (the vector levels) with the sum rule and
// the lanes' term counts (kSeriesRv)
template <int W>
static void seriesRange(const KernIn& in, int j0, int j1, double out[7]) {
  const bool id = W > 1;
  const double* R = W > 1 ? kSeriesRv : kSeriesR;
  typename Vec<W>::T acc[7] = {};
  typename Vec<1>::T acc1[7] = {};
  int j = j0, N = 1;
  if (in.mom) {
    for (; j + W <= j1; j += W) seriesChunk<W, true, id>(in, j, R, &N, acc);
    for (; j < j1; j++) seriesChunk<1, true, id>(in, j, R, &N, acc1);
  } else {
    if (W > 1) {
      for (; j + 2 * W <= j1; j += 2 * W) seriesChunk2<W>(in, j, R, &N, acc);
    }
    for (; j + W <= j1; j += W) seriesChunk<W, false, false>(in, j, R, &N, acc);
    for (; j < j1; j++) seriesChunk<1, false, false>(in, j, R, &N, acc1);
  }
  for (int i = 0; i < 7; i++) out[i] += Vec<W>::sum(acc[i]) + Vec<1>::sum(acc1[i]);
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_WAVEINT_KERN_H_
