// serieskern: the series recurrence of docs/physics.md "Dynamic part in
// closed form", shared by waveint_kern.h (components in lanes) and
// trivec_kern.h (triangles in lanes); an unnamed namespace, so each
// instruction set's file keeps its own copy (see waveker.h)
#ifndef MJBUOY_SERIESKERN_H_
#define MJBUOY_SERIESKERN_H_

#include "waveker.h"

namespace mjb {
namespace {

// for corner differences u_c = ur[c] + i ui[c] (c = 0, 1) and N terms:
// S = sum_m kInvF2[m] h_m and, when mom, T = sum_m kInvF3[m] (h_m, g_m, f_m)
// with h_m = u1 h_(m-1) + u2^m, g_m = u1 g_(m-1) + h_m, f_m = u2 f_(m-1) + h_m;
// S = (re, im), T = (T0, T1, T2) as (re, im) pairs, T left at m = 0 without mom
template <class V>
__attribute__((always_inline)) inline void seriesLoop(const V ur[2], const V ui[2], int N,
                                                      bool mom, V S[2], V T[6]) {
  V pr = V{} + 1, pi = V{}, hr = pr, hi = pi, gr = pr, gi = pi, fr = pr, fi = pi;
  V Sr = V{} + kInvF2[0], Si = V{}, T0r = V{} + kInvF3[0], T0i = V{};
  V T1r = T0r, T1i = V{}, T2r = T0r, T2i = V{};
  for (int m = 1; m < N; m++) {
    V t = pr * ur[1] - pi * ui[1];
    pi = pr * ui[1] + pi * ur[1];
    pr = t;
    t = hr * ur[0] - hi * ui[0] + pr;
    hi = hr * ui[0] + hi * ur[0] + pi;
    hr = t;
    const double c2 = kInvF2[m];
    Sr += c2 * hr;
    Si += c2 * hi;
    if (!mom) continue;
    t = gr * ur[0] - gi * ui[0] + hr;
    gi = gr * ui[0] + gi * ur[0] + hi;
    gr = t;
    t = fr * ur[1] - fi * ui[1] + hr;
    fi = fr * ui[1] + fi * ur[1] + hi;
    fr = t;
    const double c3 = kInvF3[m];
    T0r += c3 * hr;
    T0i += c3 * hi;
    T1r += c3 * gr;
    T1i += c3 * gi;
    T2r += c3 * fr;
    T2i += c3 * fi;
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

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_SERIESKERN_H_
