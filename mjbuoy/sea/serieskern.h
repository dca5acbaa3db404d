// serieskern: the series recurrence of docs/physics.md "Dynamic part in
// closed form", shared by waveint_kern.h (components in lanes) and
// trivec_kern.h (triangles in lanes); an unnamed namespace, so each
// instruction set's file keeps its own copy (see waveker.h)
#ifndef MJBUOY_SERIESKERN_H_
#define MJBUOY_SERIESKERN_H_

#include "sea/waveker.h"

namespace mjb {
namespace {

// a *= u, complex, (re, im) in vectors: the powers u2^m
template <class V>
__attribute__((always_inline)) inline void mulBy(V& ar, V& ai, V ur, V ui) {
  const V t = ar * ur - ai * ui;
  ai = ar * ui + ai * ur;
  ar = t;
}

// a = a u + b, complex: one step of the h, g and f chains, grouped so each
// part is two dependent FMAs (the chain's latency)
template <class V>
__attribute__((always_inline)) inline void mulAdd(V& ar, V& ai, V ur, V ui, V br, V bi) {
  const V t = ar * ur + (br - ai * ui);
  ai = ar * ui + (bi + ai * ur);
  ar = t;
}

// for corner differences u_c = ur[c] + i ui[c] (c = 0, 1) and N terms:
// S = sum_m kInvF2[m] h_m and, when MOM, T = sum_m kInvF3[m] (h_m, g_m, f_m)
// with h_m = u1 h_(m-1) + u2^m, g_m = u1 g_(m-1) + h_m, f_m = u2 f_(m-1) + h_m;
// S = (re, im), T = (T0, T1, T2) as (re, im) pairs, T left at m = 0 without
// MOM. ID: T2 by the moments' sum rule T0 + T1 + T2 = S (the barycentric
// weights add up to 1, so sum_c h_m(u_c, 0, u1, u2) / (m+3)! = h_m(u1, u2)
// / (m+2)! term by term; docs/physics.md "Dynamic part in closed form")
// instead of the f chain, a quarter of the work per term; its sums start
// at m = 1 and the m = 0 terms come last, so coincident corners still give
// 1/2 and 1/6 exactly
template <class V, bool MOM, bool ID>
__attribute__((always_inline)) inline void seriesLoop(const V ur[2], const V ui[2], int N, V S[2],
                                                      V T[6]) {
  const double s0 = ID ? 0 : kInvF2[0], t0 = ID ? 0 : kInvF3[0];
  V pr = V{} + 1, pi = V{}, hr = pr, hi = pi, gr = pr, gi = pi, fr = pr, fi = pi;
  V Sr = V{} + s0, Si = V{}, T0r = V{} + t0, T0i = V{};
  V T1r = T0r, T1i = V{}, T2r = T0r, T2i = V{};
  // the first term (m = 1) from p = h = g = f = 1 without the loop's
  // products by 1 and 0: p = u2, h = u1 + u2, g = u1 + h, f = u2 + h, the
  // same sums up to a zero's sign in fewer operations (a lane series has
  // about 7 terms)
  int m1 = 1;
  if (N > 1) {
    pr = ur[1];
    pi = ui[1];
    hr = ur[0] + pr;
    hi = ui[0] + pi;
    Sr += kInvF2[1] * hr;
    Si += kInvF2[1] * hi;
    if (MOM) {
      gr = ur[0] + hr;
      gi = ui[0] + hi;
      T0r += kInvF3[1] * hr;
      T0i += kInvF3[1] * hi;
      T1r += kInvF3[1] * gr;
      T1i += kInvF3[1] * gi;
      if (!ID) {
        fr = ur[1] + hr;
        fi = ui[1] + hi;
        T2r += kInvF3[1] * fr;
        T2i += kInvF3[1] * fi;
      }
    }
    m1 = 2;
  }
  for (int m = m1; m < N; m++) {
    mulBy(pr, pi, ur[1], ui[1]);
    mulAdd(hr, hi, ur[0], ui[0], pr, pi);
    const double c2 = kInvF2[m];
    Sr += c2 * hr;
    Si += c2 * hi;
    if (!MOM) continue;
    mulAdd(gr, gi, ur[0], ui[0], hr, hi);
    const double c3 = kInvF3[m];
    T0r += c3 * hr;
    T0i += c3 * hi;
    T1r += c3 * gr;
    T1i += c3 * gi;
    if (ID) continue;
    mulAdd(fr, fi, ur[1], ui[1], hr, hi);
    T2r += c3 * fr;
    T2i += c3 * fi;
  }
  if (ID) {
    T2r = Sr - T0r - T1r + kInvF3[0];
    T2i = Si - T0i - T1i;
    Sr += kInvF2[0];
    T0r += kInvF3[0];
    T1r += kInvF3[0];
  }
  S[0] = Sr;
  S[1] = Si;
  T[0] = T0r;
  T[1] = T0i;
  T[2] = T1r;
  T[3] = T1i;
  T[4] = T2r;
  T[5] = T2i;
}

// S alone for two sets of corner differences a = 0, 1 at once (seriesLoop
// without MOM, the same operations in the same order for each): the h
// recurrence waits on its own latency (two dependent FMAs a term), so two
// independent ones keep the FMA units busy
template <class V>
__attribute__((always_inline)) inline void seriesPair(const V ur[2][2], const V ui[2][2], int N,
                                                      V S[2][2]) {
  V pr[2], pi[2], hr[2], hi[2], Sr[2], Si[2];
  for (int a = 0; a < 2; a++) {
    pr[a] = hr[a] = V{} + 1;
    pi[a] = hi[a] = Si[a] = V{};
    Sr[a] = V{} + kInvF2[0];
  }
  int m1 = 1;
  if (N > 1) {
    // the first term without the products by 1 and 0 (seriesLoop)
    for (int a = 0; a < 2; a++) {
      pr[a] = ur[a][1];
      pi[a] = ui[a][1];
      hr[a] = ur[a][0] + pr[a];
      hi[a] = ui[a][0] + pi[a];
      Sr[a] += kInvF2[1] * hr[a];
      Si[a] += kInvF2[1] * hi[a];
    }
    m1 = 2;
  }
  for (int m = m1; m < N; m++) {
    const double c2 = kInvF2[m];
    for (int a = 0; a < 2; a++) {
      mulBy(pr[a], pi[a], ur[a][1], ui[a][1]);
      mulAdd(hr[a], hi[a], ur[a][0], ui[a][0], pr[a], pi[a]);
      Sr[a] += c2 * hr[a];
      Si[a] += c2 * hi[a];
    }
  }
  for (int a = 0; a < 2; a++) {
    S[a][0] = Sr[a];
    S[a][1] = Si[a];
  }
}

// the series' terms m = 1 .. N-1 without the powers of k, for corner
// differences that are k times w_c = wr[c] + i wi[c] for every component
// of a long-crested sea: h_m is homogeneous of degree m, h_m(k w1, k w2) =
// k^m h_m(w1, w2) (and g_m likewise), so C[m] = (kInvF2[m] h_m, and with
// MOM kInvF3[m] h_m, kInvF3[m] g_m) as (re, im) pairs serve every k
// (docs/physics.md "Dynamic part in closed form"); seriesLoop's steps
// (mulBy, mulAdd), C[0] unused
template <class V, bool MOM>
__attribute__((always_inline)) inline void seriesCoefs(const V wr[2], const V wi[2], int N,
                                                       V (*C)[6]) {
  V pr = V{} + 1, pi = V{}, hr = pr, hi = pi, gr = pr, gi = pi;
  for (int m = 1; m < N; m++) {
    mulBy(pr, pi, wr[1], wi[1]);
    mulAdd(hr, hi, wr[0], wi[0], pr, pi);
    C[m][0] = kInvF2[m] * hr;
    C[m][1] = kInvF2[m] * hi;
    if (!MOM) continue;
    mulAdd(gr, gi, wr[0], wi[0], hr, hi);
    C[m][2] = kInvF3[m] * hr;
    C[m][3] = kInvF3[m] * hi;
    C[m][4] = kInvF3[m] * gr;
    C[m][5] = kInvF3[m] * gi;
  }
}

// S and T (seriesLoop's with ID: T2 by the sum rule, the m = 0 terms
// added last) of the component of wave number k from seriesCoefs' C, N
// terms: k sum_(m=1)^(N-1) C[m] k^(m-1) by Horner, one multiply-add a
// term and sum (2, with MOM 6, a term where seriesLoop takes 10 and 18)
template <class V, bool MOM>
__attribute__((always_inline)) inline void hornerSums(const V (*C)[6], int N, double k, V S[2],
                                                      V T[6]) {
  const int nv = MOM ? 6 : 2;
  V a[6] = {};
  for (int m = N - 1; m >= 1; m--) {
    for (int i = 0; i < nv; i++) a[i] = a[i] * k + C[m][i];
  }
  for (int i = 0; i < nv; i++) a[i] *= k;
  S[0] = a[0] + kInvF2[0];
  S[1] = a[1];
  if (!MOM) return;
  T[0] = a[2] + kInvF3[0];
  T[1] = a[3];
  T[2] = a[4] + kInvF3[0];
  T[3] = a[5];
  T[4] = a[0] - a[2] - a[4] + kInvF3[0];
  T[5] = a[1] - a[3] - a[5];
}

// the term count for radius r by the radii R (kSeriesR, kSeriesRv) for r
// at or above the r that gave N (the radii rise with N): the search
// resumes at N, so a loop over ascending k pays for it once
__attribute__((always_inline)) inline int termsFrom(int N, double r, const double* R) {
  while (N < kNMax && !(r <= R[N])) N++;
  return N;
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_SERIESKERN_H_
