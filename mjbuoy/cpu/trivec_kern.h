// trivec_kern: trivec.h's wholly wet and cut triangles for W triangles at
// once (GCC vector extensions), included by one file per instruction set.
// Everything here is static: no inline function compiled for AVX can be
// shared with the scalar path. Includes nothing but trivec.h and waveker.h.
//
// Each lane does what cpupass.cc's scalar loop does for one triangle: for a
// wholly wet one wetTriangle's uncut branch, for a cut one its clip and
// fan (cutChunk: the same cut points and the same fan corner); for each
// piece the linear hydrostatic part (wavepress.cc hydrostaticLevel) or
// Kerner's, and waveint.cc's series about corner 0 for every component
// whose exponent on the piece reaches above -40 (the same set the scalar
// path sums). A triangle
// with a piece too coarse for the series (k rho > kRMax for the largest
// k: the scalar path subdivides) or not finite goes back to the scalar
// path whole. Only the rounding differs: FMA contraction, the order of sums,
// the series' count of terms (cut at 2^-kSeriesBitsV of the first instead
// of the scalar's 2^-54, waveker.h), T_2 by the sum rule T_0 + T_1 +
// T_2 = S (serieskern.h), and on a long-crested sea the powers of k applied
// after the recurrences (familyShared).
#ifndef MJBUOY_TRIVEC_KERN_H_
#define MJBUOY_TRIVEC_KERN_H_

#include "cpu/trivec.h"
#include "util/zipkern.h"
#include "sea/serieskern.h"
#include "sea/waveker.h"

namespace mjb {
namespace {

template <int W>
struct TLanes {
  typedef double V __attribute__((vector_size(8 * W)));
  typedef long I __attribute__((vector_size(8 * W)));  // what comparisons give
  typedef float F __attribute__((vector_size(4 * W)));  // the slamming history
  template <class U>
  static double hmax(U v) {
    double r = v[0];
    for (int i = 1; i < W; i++) r = v[i] > r ? v[i] : r;
    return r;
  }
  template <class U>
  static double hsum(U v) {
    double s = 0;
    for (int i = 0; i < W; i++) s += v[i];
    return s;
  }
  template <class U>
  static bool all(U m) {
    for (int i = 0; i < W; i++) if (!m[i]) return false;
    return true;
  }
};

// the lanes' corner differences of component j's exponent (sign sgn of
// the exponent family): u = sgn k dz + i k D.(dx, or the label's)
template <int W>
static inline void laneU(const TriIn& in, int j, double sgn, const typename TLanes<W>::V dz[2],
                         const typename TLanes<W>::V dp[2][2],
                         const typename TLanes<W>::V dl[2][2], typename TLanes<W>::V ur[2],
                         typename TLanes<W>::V ui[2]) {
  typedef typename TLanes<W>::V V;
  const double k = in.k[j], gm = in.gm[j];
  for (int c = 0; c < 2; c++) {
    const V X = dp[c][0] + gm * (dl[c][0] - dp[c][0]);
    const V Y = dp[c][1] + gm * (dl[c][1] - dp[c][1]);
    ur[c] = (sgn * k) * dz[c];
    ui[c] = in.kdx[j] * X + in.kdy[j] * Y;
  }
}

// component j of family f with the lanes' e^L0 = er + i ei: its S, T
// times e^L0 (zero in the lanes outside keep) and its weights, into acc[7]
template <int W, bool MOM>
static inline void laneAddE(const TriIn& in, int f, int j, typename TLanes<W>::V er,
                            typename TLanes<W>::V ei, typename TLanes<W>::I keep,
                            const typename TLanes<W>::V S[2], const typename TLanes<W>::V T[6],
                            typename TLanes<W>::V acc[7]) {
  typedef typename TLanes<W>::V V;
  er = keep ? er : V{};
  ei = keep ? ei : V{};
  const V Ir = er * S[0] - ei * S[1], Ii = er * S[1] + ei * S[0];
  acc[0] += in.wp[f][j] * Ir;
  if (MOM) {
    acc[1] += in.wp[f][j] * (er * T[0] - ei * T[1]);
    acc[2] += in.wp[f][j] * (er * T[2] - ei * T[3]);
    acc[3] += in.wp[f][j] * (er * T[4] - ei * T[5]);
  }
  acc[4] += in.wux[f][j] * Ir;
  acc[5] += in.wuy[f][j] * Ir;
  acc[6] += in.wz[f][j] * Ii;
}

// laneAddE with component j's e^L0 gathered lane by lane
template <int W, bool MOM>
static inline void laneAdd(const TriIn& in, int f, int j, const double* const e0[W],
                           typename TLanes<W>::I keep, const typename TLanes<W>::V S[2],
                           const typename TLanes<W>::V T[6], typename TLanes<W>::V acc[7]) {
  typedef typename TLanes<W>::V V;
  const int eo = 2 * f * in.nw;
  V er, ei;
  for (int l = 0; l < W; l++) {
    er[l] = e0[l][eo + j];
    ei[l] = e0[l][eo + in.nw + j];
  }
  laneAddE<W, MOM>(in, f, j, er, ei, keep, S, T, acc);
}

// e^L0 of components [j, j + W) of family f (j + W <= n): er[i][l] =
// Re e0[l] of component j + i, ei the imaginary parts; one load a lane
// and a transpose (zipkern.h) instead of W lane inserts a component
template <int W>
static inline void laneEBlock(const TriIn& in, int f, int j, const double* const e0[W],
                              typename TLanes<W>::V er[W], typename TLanes<W>::V ei[W]) {
  typedef typename TLanes<W>::V V;
  const int eo = 2 * f * in.nw;
  for (int l = 0; l < W; l++) {
    er[l] = zload<V>(e0[l] + eo + j);
    ei[l] = zload<V>(e0[l] + eo + in.nw + j);
  }
  transpose<V, W>(er);
  transpose<V, W>(ei);
}

// the radii of component j's loose series (TriIn sscale): the table of
// the least b with 2^b >= |wp_j| sscale (b from x's binary exponent e,
// x < 2^(e+1)), at least 1; from kSeriesBitsV on the lanes' own kSeriesRv
template <int W>
static inline const double* looseRadii(const TriIn& in, int j) {
  const double x = __builtin_fabs(in.wp[0][j]) * in.sscale;
  unsigned long u;
  __builtin_memcpy(&u, &x, 8);
  int b = int((u >> 52) & 0x7ff) - 1022;
  if (x < 1) b = 1;
  if (b >= kSeriesBitsV) return kSeriesRv;
  return kSeriesRb + b * (kNMax + 1);
}

// the series sums of one exponent family f for the lanes (waveint_kern.h's
// seriesChunk with lanes over pieces instead of components): acc[7] per
// lane, S and T_c about corner 0 times e^L0, weighted; with the moments
// (MOM) T2 by the sum rule (serieskern.h), without them two components at
// a time (seriesPair); LOOSE: each component's own term count (looseRadii)
template <int W, bool MOM, bool LOOSE>
static void familyLanes(const TriIn& in, int f, const double* const e0[W],
                        typename TLanes<W>::V zx, const typename TLanes<W>::V dz[2],
                        const typename TLanes<W>::V dp[2][2],
                        const typename TLanes<W>::V dl[2][2], double rmax,
                        typename TLanes<W>::V acc[7]) {
  typedef typename TLanes<W>::V V;
  typedef typename TLanes<W>::I I;
  const double sgn = f == 0 ? 1 : -1;
  // components past 40 / zx (k ascending) have e^L below e^-40 on the
  // piece: skipped per lane, as waveint.cc's jsk
  const V lim = zx > 0 ? 40 / zx : V{} + __builtin_inf();
  int N = 1;
  for (int j = 0; j < in.n;) {
    const I keep = in.k[j] <= lim;
    bool any = false;
    for (int l = 0; l < W; l++) any |= keep[l] != 0;
    if (!any) break;
    if (!MOM && j + 1 < in.n) {
      V ur[2][2], ui[2][2], S[2][2], T[6] = {};
      laneU<W>(in, j, sgn, dz, dp, dl, ur[0], ui[0]);
      laneU<W>(in, j + 1, sgn, dz, dp, dl, ur[1], ui[1]);
      if (LOOSE) {
        const int N0 = termsFrom(1, in.k[j] * rmax, looseRadii<W>(in, j));
        const int N1 = termsFrom(1, in.k[j + 1] * rmax, looseRadii<W>(in, j + 1));
        N = N0 > N1 ? N0 : N1;
      } else {
        N = termsFrom(N, in.k[j + 1] * rmax, kSeriesRv);
      }
      seriesPair<V>(ur, ui, N, S);
      laneAdd<W, false>(in, f, j, e0, keep, S[0], T, acc);
      laneAdd<W, false>(in, f, j + 1, e0, in.k[j + 1] <= lim, S[1], T, acc);
      j += 2;
      continue;
    }
    V ur[2], ui[2], S[2], T[6];
    laneU<W>(in, j, sgn, dz, dp, dl, ur, ui);
    N = LOOSE ? termsFrom(1, in.k[j] * rmax, looseRadii<W>(in, j))
              : termsFrom(N, in.k[j] * rmax, kSeriesRv);
    seriesLoop<V, MOM, true>(ur, ui, N, S, T);
    laneAdd<W, MOM>(in, f, j, e0, keep, S, T, acc);
    j++;
  }
}

// the most terms familyShared keeps per piece (27 serve k rho = kRMax at
// 2^-kSeriesBitsV; more: familyLanes)
enum { kShareTerms = 32 };

// familyLanes for a long-crested sea (TriIn lc): every component's
// corner differences are k times the same w_c = sgn dz_c + i D.(dx_c, or
// the labels'), so the series' recurrences run once per piece, up to the
// terms the largest kept k needs (seriesCoefs), and each component costs
// a polynomial in its k (hornerSums): the same terms and term counts as
// familyLanes, so the same accuracy (docs/physics.md "Dynamic part in
// closed form"); LOOSE as familyLanes
template <int W, bool MOM, bool LOOSE>
static void familyShared(const TriIn& in, int f, const double* const e0[W],
                         typename TLanes<W>::V zx, const typename TLanes<W>::V dz[2],
                         const typename TLanes<W>::V dp[2][2],
                         const typename TLanes<W>::V dl[2][2], double rmax,
                         typename TLanes<W>::V acc[7]) {
  typedef typename TLanes<W>::V V;
  const double sgn = f == 0 ? 1 : -1;
  // components past 40 / zx in every lane are skipped (familyLanes)
  const V lim = zx > 0 ? 40 / zx : V{} + __builtin_inf();
  const double lmax = TLanes<W>::hmax(lim);
  int jn = 0;
  while (jn < in.n && in.k[jn] <= lmax) jn++;
  if (jn == 0) return;
  int nmax = termsFrom(1, in.k[jn - 1] * rmax, kSeriesRv);
  if (LOOSE) {
    nmax = 1;
    for (int j = 0; j < jn; j++) {
      const int Nj = termsFrom(1, in.k[j] * rmax, looseRadii<W>(in, j));
      nmax = Nj > nmax ? Nj : nmax;
    }
  }
  if (nmax > kShareTerms) {
    familyLanes<W, MOM, LOOSE>(in, f, e0, zx, dz, dp, dl, rmax, acc);
    return;
  }
  V wr[2], wi[2];
  for (int c = 0; c < 2; c++) {
    const V X = dp[c][0] + in.lgm * (dl[c][0] - dp[c][0]);
    const V Y = dp[c][1] + in.lgm * (dl[c][1] - dp[c][1]);
    wr[c] = sgn * dz[c];
    wi[c] = in.ldx * X + in.ldy * Y;
  }
  V C[kShareTerms][6];
  seriesCoefs<V, MOM>(wr, wi, nmax, C);
  // (sums in locals: acc in memory would chain every component's adds
  // through a store and a load)
  V a[7];
  for (int i = 0; i < 7; i++) a[i] = acc[i];
  int N = 1;
  for (int j = 0; j < jn; j += W) {
    V er[W], ei[W];
    const bool block = j + W <= in.n;
    if (block) laneEBlock<W>(in, f, j, e0, er, ei);
    for (int i = 0; i < W && j + i < jn; i++) {
      const int c = j + i;
      V S[2], T[6] = {};
      N = LOOSE ? termsFrom(1, in.k[c] * rmax, looseRadii<W>(in, c))
                : termsFrom(N, in.k[c] * rmax, kSeriesRv);
      hornerSums<V, MOM>(C, N, in.k[c], S, T);
      if (block) {
        laneAddE<W, MOM>(in, f, c, er[i], ei[i], in.k[c] <= lim, S, T, a);
      } else {
        laneAdd<W, MOM>(in, f, c, e0, in.k[c] <= lim, S, T, a);
      }
    }
  }
  for (int i = 0; i < 7; i++) acc[i] = a[i];
}

// vertex integration's part of laneIntegrals: the linear interpolant f of
// the corner sums integrated exactly over the piece, integral f dA = A (f0
// + f1 + f2) / 3 and integral f r dA = (A / 12) sum_c (f0 + f1 + f2 + f_c)
// p_c (docs/physics.md "Vertex integration"), added to P and Pr (linear
// pressure) and into Vw
template <int W>
static void vertexIntegrals(const TriIn* in, const typename TLanes<W>::V p[3][3],
                            typename TLanes<W>::V A, const typename TLanes<W>::V sv[3][4],
                            typename TLanes<W>::I* good, typename TLanes<W>::V* P,
                            typename TLanes<W>::V Pr[3], typename TLanes<W>::V Vw[3]) {
  typedef typename TLanes<W>::V V;
  V s[4];
  for (int q = 0; q < 4; q++) s[q] = sv[0][q] + sv[1][q] + sv[2][q];
  const V all = s[0] + s[1] + s[2] + s[3];
  *good &= (all - all) == 0;  // a corner the sums did not reach (cpusum.h): exact path
  if (in->linear) {
    *P += in->rg * A * s[0] / 3;
    for (int j = 0; j < 3; j++) {
      const V sr = p[0][j] + p[1][j] + p[2][j];
      Pr[j] += in->rg * A / 12 *
               (s[0] * sr + sv[0][0] * p[0][j] + sv[1][0] * p[1][j] + sv[2][0] * p[2][j]);
    }
  }
  for (int j = 0; j < 3; j++) Vw[j] = A * s[1 + j] / 3;
}

// the vertex sums (cpusum.h) of the lanes' corners gv into sv
template <int W>
static void vertexLoad(const TriIn* in, const int gv[3][W], typename TLanes<W>::V sv[3][4]) {
  for (int c = 0; c < 3; c++) {
    for (int l = 0; l < W; l++) {
      for (int q = 0; q < 4; q++) sv[c][q][l] = in->vs[4 * gv[c][l] + q];
    }
  }
}

// the pressure and wave integrals of W lanes' pieces (corners p relative
// to the COM, Kerner's depths d, stretched heights zs, labels lb, e^L at
// corner 0, area A): P = integral p dA [N], Pr = integral p r dA [N m], Vw
// = integral (u - current) dA [m^3/s]; good cleared in lanes too coarse
// for the series (the scalar path subdivides them); with vertex
// integration (sv: the corners' vertex sums, cpusum.h) the integrals of
// their linear interpolant instead, good cleared where a sum is not finite
template <int W, class M>
static void laneIntegrals(const TriIn* in, const typename TLanes<W>::V p[3][3],
                          typename TLanes<W>::V d[3], const typename TLanes<W>::V zs[3],
                          const typename TLanes<W>::V lb[3][2], const double* const e0[W],
                          typename TLanes<W>::V A, typename TLanes<W>::I* good,
                          typename TLanes<W>::V* P, typename TLanes<W>::V Pr[3],
                          typename TLanes<W>::V Vw[3],
                          const typename TLanes<W>::V (*sv)[4] = nullptr) {
  typedef typename TLanes<W>::V V;
  // depth below the level (linear) or the surface (Kerner), linear over it
  if (in->linear) {
    for (int c = 0; c < 3; c++) d[c] = in->level - (p[c][2] + in->comz);
  }
  const V sd = d[0] + d[1] + d[2];
  *P = in->rg * A * sd / 3;
  for (int j = 0; j < 3; j++) {
    const V sr = p[0][j] + p[1][j] + p[2][j];
    Pr[j] = in->rg * A / 12 * (d[0] * p[0][j] + d[1] * p[1][j] + d[2] * p[2][j] + sd * sr);
    Vw[j] = V{};
  }
  if (in->n == 0) return;
  if (sv) return vertexIntegrals<W>(in, p, A, sv, good, P, Pr, Vw);
  V dz[2], dp[2][2], dl[2][2], r2 = V{};
  for (int c = 0; c < 2; c++) {
    dz[c] = zs[c + 1] - zs[0];
    V hp = V{}, hl = V{};
    for (int j = 0; j < 2; j++) {
      dp[c][j] = p[c + 1][j] - p[0][j];
      dl[c][j] = lb[c + 1][j] - lb[0][j];
      hp += dp[c][j] * dp[c][j];
      hl += dl[c][j] * dl[c][j];
    }
    const V q = dz[c] * dz[c] + (hp > hl ? hp : hl);
    r2 = q > r2 ? q : r2;
  }
  const V rho = M::sqrt(r2);
  *good &= in->k[in->n - 1] * rho <= kRMax;
  // lanes left to the scalar path: no series (zero differences)
  for (int c = 0; c < 2; c++) {
    dz[c] = *good ? dz[c] : V{};
    for (int j = 0; j < 2; j++) {
      dp[c][j] = *good ? dp[c][j] : V{};
      dl[c][j] = *good ? dl[c][j] : V{};
    }
  }
  const double rmax = TLanes<W>::hmax(*good ? rho : V{});
  V zmax = zs[0], zmin = zs[0];
  for (int c = 1; c < 3; c++) {
    zmax = zs[c] > zmax ? zs[c] : zmax;
    zmin = zs[c] < zmin ? zs[c] : zmin;
  }
  V acc[7] = {};
  for (int f = 0; f < (in->finite ? 2 : 1); f++) {
    const V zx = f == 0 ? -zmax : zmin + 2 * in->depth;
    // the loose series (sscale > 0 only with linear pressure) where |e^L0|
    // <= 1 in every lane (zx >= 0; docs/physics.md "Series tolerance")
    if (in->sscale > 0 && TLanes<W>::all(zx >= 0)) {
      if (in->lc) {
        familyShared<W, true, true>(*in, f, e0, zx, dz, dp, dl, rmax, acc);
      } else {
        familyLanes<W, true, true>(*in, f, e0, zx, dz, dp, dl, rmax, acc);
      }
    } else if (in->linear && in->lc) {
      familyShared<W, true, false>(*in, f, e0, zx, dz, dp, dl, rmax, acc);
    } else if (in->linear) {
      familyLanes<W, true, false>(*in, f, e0, zx, dz, dp, dl, rmax, acc);
    } else if (in->lc) {
      familyShared<W, false, false>(*in, f, e0, zx, dz, dp, dl, rmax, acc);
    } else {
      familyLanes<W, false, false>(*in, f, e0, zx, dz, dp, dl, rmax, acc);
    }
  }
  const V a2 = 2 * A;
  if (in->linear) {
    *P += in->rg * a2 * acc[0];
    for (int j = 0; j < 3; j++) {
      Pr[j] += in->rg * a2 * (acc[1] * p[0][j] + acc[2] * p[1][j] + acc[3] * p[2][j]);
    }
  }
  for (int j = 0; j < 3; j++) Vw[j] = a2 * acc[4 + j];
}

// the lanes' triangles p: cross product cr of their edges from corner 0,
// unit normal n (0 where degenerate); returns |cr| (wetTriangle)
template <int W, class M>
static typename TLanes<W>::V laneNormal(const typename TLanes<W>::V p[3][3],
                                        typename TLanes<W>::V cr[3],
                                        typename TLanes<W>::V n[3]) {
  typedef typename TLanes<W>::V V;
  V e1[3], e2[3];
  for (int j = 0; j < 3; j++) {
    e1[j] = p[1][j] - p[0][j];
    e2[j] = p[2][j] - p[0][j];
  }
  cr[0] = e1[1] * e2[2] - e1[2] * e2[1];
  cr[1] = e1[2] * e2[0] - e1[0] * e2[2];
  cr[2] = e1[0] * e2[1] - e1[1] * e2[0];
  const V len = M::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
  const V il = len > 0 ? 1 / len : V{};
  for (int j = 0; j < 3; j++) n[j] = cr[j] * il;
  return len;
}

// x^p for x >= 0 and p = 0.5, 1 or 2 (hydro.cc's powp; others not used)
template <class V, class M>
static inline V powLanes(V x, double p) {
  return p == 0.5 ? M::sqrt(x) : p == 1 ? x : x * x;
}

// w[0..2] += g, w[3..5] += c x g (cpuhull.h add), in the lanes of use
template <class V, class I>
static inline void addLanes(V* w, const V g[3], const V c[3], I use) {
  const V z = V{};
  const V t[3] = {c[1] * g[2] - c[2] * g[1], c[2] * g[0] - c[0] * g[2],
                  c[0] * g[1] - c[1] * g[0]};
  for (int j = 0; j < 3; j++) {
    w[j] += use ? g[j] : z;
    w[3 + j] += use ? t[j] : z;
  }
}

// the lanes' viscous, drag and slamming forces (flowAt) from area A,
// whole area S, centroid c, normal n, flow-relative velocity v and the
// swept-volume rate q = A v as stored and the previous step's qp, summed
// in the lanes of use
template <int W, class M>
static inline void flowForces(const FlowIn* in, typename TLanes<W>::V A, typename TLanes<W>::V S,
                              const typename TLanes<W>::V c[3], const typename TLanes<W>::V n[3],
                              const typename TLanes<W>::V v[3], const typename TLanes<W>::V q[3],
                              const typename TLanes<W>::V qp[3], typename TLanes<W>::I use,
                              typename TLanes<W>::V* wv1, typename TLanes<W>::V* wvd,
                              typename TLanes<W>::V* wd, typename TLanes<W>::V* ws) {
  typedef typename TLanes<W>::V V;
  typedef typename TLanes<W>::I I;
  const V z = V{}, one = V{} + 1, nanv = V{} + __builtin_nan("");
  const V v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const V vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
  const V sp = M::sqrt(v2);
  const I on = sp > 0;
  // a non-finite |v|^2 or area: NaN forces (reported), never zero
  const I fin = ((v2 - v2) == 0) & ((A - A) == 0);
  // one division for 1/|v| and none by a constant (a product with its
  // reciprocal): rounding apart from hydro.cc, whose divisions these are
  const V is = 1 / (on ? sp : one);
  V g[3];
  if (in->visc) {
    V t[3];
    for (int j = 0; j < 3; j++) t[j] = v[j] - vn * n[j];
    const V tl = M::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    const V cd = c[0] * in->dir[0] + c[1] * in->dir[1] + c[2] * in->dir[2];
    const I sh = tl > 1e-12 * sp;
    // the unit viscous force (rho C_F (1+k_i) = 1) and its moment along dir
    const V s = -0.5 * A * v2 / (sh ? tl : one);
    for (int j = 0; j < 3; j++) g[j] = fin ? (sh ? s * t[j] : z) : nanv;
    addLanes(wv1, g, c, use);
    for (int j = 0; j < 3; j++) g[j] *= cd;
    addLanes(wvd, g, c, use);
  }
  const V cs = vn * is;
  {
    const V u = sp * (1 / in->vref);
    const V sa = -(in->drag[0] * u + in->drag[1] * u * u) * A *
                 powLanes<V, M>(cs > 0 ? cs : z, in->drag[2]);
    const V sb = (in->suction[0] * u + in->suction[1] * u * u) * A *
                 powLanes<V, M>(cs < 0 ? -cs : z, in->suction[2]);
    const V s = cs > 0 ? sa : cs < 0 ? sb : z;
    for (int j = 0; j < 3; j++) g[j] = fin ? (on ? s * n[j] : z) : nanv;
    addLanes(wd, g, c, use);
  }
  if (in->slam) {
    // effective mass along v at the centroid (rigid.cc effMass)
    const V u0 = v[0] * is, u1 = v[1] * is, u2 = v[2] * is;
    V d[3];
    for (int j = 0; j < 3; j++) d[j] = c[j] + in->com[j] - in->gcom[j];
    const V e0 = d[1] * u2 - d[2] * u1, e1 = d[2] * u0 - d[0] * u2, e2 = d[0] * u1 - d[1] * u0;
    const double* J = in->iinv;
    const V Je0 = J[0] * e0 + J[3] * e1 + J[4] * e2;
    const V Je1 = J[3] * e0 + J[1] * e1 + J[5] * e2;
    const V Je2 = J[4] * e0 + J[5] * e1 + J[2] * e2;
    const V meff = on ? 1 / (in->minv + e0 * Je0 + e1 * Je1 + e2 * Je2) : z;
    const V mass = in->share * meff;
    V dq[3];
    for (int j = 0; j < 3; j++) dq[j] = q[j] - qp[j];
    // Gamma / Gamma_max = |dq| / (S dt Gamma_max)
    const V rg = M::sqrt(dq[0] * dq[0] + dq[1] * dq[1] + dq[2] * dq[2]) / (S * (in->dt * in->gmax));
    const V r = rg < 1 ? rg : one;  // fmin(NaN, 1) is 1 too
    const double stop = -in->gain * 2 / (in->shull * in->dt);
    const V s = stop * powLanes<V, M>(r, in->pw) * cs * mass * A;
    const I hit = on & (A > 0) & (cs > 0);
    for (int j = 0; j < 3; j++) g[j] = fin ? (hit ? s * v[j] : z) : nanv;
    addLanes(ws, g, c, use);
  }
}

// the W lanes' sums of pass 2: the unit viscous wrench and its first
// moment along the flow, drag, slamming ([force; torque about the COM])
template <int W>
struct FlowAcc {
  typename TLanes<W>::V v1[6], vd[6], d[6], s[6];
};

// pass 2 in the lanes of pass 1 (cpuhull.h passChunk): hydro.cc's
// viscousForce (unit), dragForce and slamForce and rigid.cc's effMass
// (the same tests, the same NaN for a non-finite input) for triangles tk
// of wet area A, centroid c (relative to the COM), normal n and mean
// water velocity u, in the lanes of use, into acc; on a step's first call
// the swept-volume rates into the history. whole: the W triangles are
// consecutive and all in use (loaded and stored whole)
template <int W, class M>
static inline void flowAt(const FlowIn* fl, const int* tk, bool whole, typename TLanes<W>::V A,
                          const typename TLanes<W>::V c[3], const typename TLanes<W>::V n[3],
                          const typename TLanes<W>::V u[3], typename TLanes<W>::I use,
                          FlowAcc<W>* acc) {
  typedef typename TLanes<W>::V V;
  typedef typename TLanes<W>::F F;
  V S, qp[3];
  if (whole) {
    S = zload<V>(fl->tarea + tk[0]);
    F qf[3];
    unzip3<F, W>(fl->prevQ + 3 * tk[0], qf);
    for (int j = 0; j < 3; j++) qp[j] = __builtin_convertvector(qf[j], V);
  } else {  // gathered into plain rows, then loaded (GCC 12 warns of lane stores)
    double g[4][W];
    for (int l = 0; l < W; l++) {
      g[0][l] = fl->tarea[tk[l]];
      for (int j = 0; j < 3; j++) g[1 + j][l] = fl->prevQ[3 * tk[l] + j];
    }
    __builtin_memcpy(&S, g[0], sizeof S);
    for (int j = 0; j < 3; j++) __builtin_memcpy(&qp[j], g[1 + j], sizeof S);
  }
  const double* w = fl->vel;
  const V wc[3] = {w[1] * c[2] - w[2] * c[1], w[2] * c[0] - w[0] * c[2],
                   w[0] * c[1] - w[1] * c[0]};
  V v[3];
  for (int j = 0; j < 3; j++) v[j] = w[3 + j] + wc[j] - u[j];
  // Q = A v rounded to float (hydro.h sweptRate), as the history keeps it
  F qf[3];
  V q[3];
  for (int j = 0; j < 3; j++) {
    qf[j] = __builtin_convertvector(A * v[j], F);
    q[j] = __builtin_convertvector(qf[j], V);
  }
  if (fl->q && whole) {
    zip3<F, W>(fl->q + 3 * tk[0], qf[0], qf[1], qf[2]);
  } else if (fl->q) {
    for (int l = 0; l < W; l++) {
      if (!use[l]) continue;
      for (int j = 0; j < 3; j++) fl->q[3 * tk[l] + j] = qf[j][l];
    }
  }
  flowForces<W, M>(fl, A, S, c, n, v, q, qp, use, acc->v1, acc->vd, acc->d, acc->s);
}

// lane l's results for triangle k into the hull's scratch, for pass 2 to
// read when it does not run in these lanes: wet area A, centroid c
// (relative to the COM), normal n, mean water velocity u
template <class V>
static inline void storeLane(TriIn* in, int k, V A, const V c[3], const V n[3], const V u[3],
                             int l) {
  in->area[k - in->t0] = A[l];
  for (int j = 0; j < 3; j++) {
    const int kl = 3 * (k - in->t0) + j;
    in->c[kl] = c[j][l];
    in->nrm[kl] = n[j][l];
    in->u[kl] = u[j][l];
  }
}

// triangles [p0, p0 + nl) of in.idx as W lanes (the last repeated in the
// lanes past nl, whose results are dropped); sums into f, t, wet, lo, hi;
// pass 2 into acc when in.fl is set, else the per-triangle results stored
template <int W, class M>
static void triChunk(TriIn* in, int p0, int nl, typename TLanes<W>::V* F,
                     typename TLanes<W>::V* Tq, typename TLanes<W>::V* wet,
                     typename TLanes<W>::V* wdir, typename TLanes<W>::V* lo,
                     typename TLanes<W>::V* hi, FlowAcc<W>* acc) {
  typedef typename TLanes<W>::V V;
  typedef typename TLanes<W>::I I;
  V p[3][3], d[3], zs[3], lb[3][2];
  const double* e0[W];
  int tk[W], gv[3][W];
  for (int l = 0; l < W; l++) {
    const int k = in->idx[p0 + (l < nl ? l : nl - 1)];
    tk[l] = k;
    for (int c = 0; c < 3; c++) gv[c][l] = in->face[3 * k + c] - in->v0;
    e0[l] = in->E + in->es * in->nw * gv[0][l];
  }
  for (int c = 0; c < 3; c++) {
    V f[kRec];
    loadRecords<V, W>(in->rec, gv[c], f);
    for (int j = 0; j < 3; j++) p[c][j] = f[j];
    d[c] = -f[3];
    zs[c] = f[4];
    lb[c][0] = f[5];
    lb[c][1] = f[6];
  }
  // wetTriangle's uncut branch: normal, area, centroid
  V cr[3], sr[3], n[3];
  const V len = laneNormal<W, M>(p, cr, n);
  const I ok = len > 0;
  for (int j = 0; j < 3; j++) sr[j] = p[0][j] + p[1][j] + p[2][j];
  const V A = 0.5 * (cr[0] * n[0] + cr[1] * n[1] + cr[2] * n[2]);
  I good = ok;
  V P, Pr[3], Vw[3], sv[3][4];
  if (in->vs) vertexLoad<W>(in, gv, sv);
  laneIntegrals<W, M>(in, p, d, zs, lb, e0, A, &good, &P, Pr, Vw, in->vs ? sv : nullptr);
  // per triangle done, and the sums; the centroid divided in lanes (the
  // same bits as one division a lane), W good triangles in a row stored
  // whole (most of a hull's wholly wet ones)
  const V inv = ok ? 1 / A : V{};
  const V u[3] = {in->cur[0] + Vw[0] * inv, in->cur[1] + Vw[1] * inv, 0 + Vw[2] * inv};
  const V cen[3] = {sr[0] / 3, sr[1] / 3, sr[2] / 3};
  I use = good;
  for (int l = nl; l < W; l++) use[l] = 0;
  const bool whole = nl == W && tk[W - 1] - tk[0] == W - 1 && TLanes<W>::all(good);
  if (!whole) {  // lane by lane: the leftovers, and the results unless fused
    for (int l = 0; l < nl; l++) {
      const int k = tk[l];
      if (!good[l]) {
        if (ok[l] || len[l] != len[l]) in->rest[in->nrest++] = k;
        else if (!in->fl) in->area[k - in->t0] = 0;  // degenerate: no wet part (wetTriangle)
        continue;
      }
      if (!in->fl) storeLane(in, k, A, cen, n, u, l);
    }
  }
  if (in->fl) {
    flowAt<W, M>(in->fl, tk, whole, A, cen, n, u, use, acc);
  } else if (whole) {
    const int o = 3 * (tk[0] - in->t0);
    __builtin_memcpy(in->area + tk[0] - in->t0, &A, sizeof A);
    zip3<V, W>(in->c + o, cen[0], cen[1], cen[2]);
    zip3<V, W>(in->nrm + o, n[0], n[1], n[2]);
    zip3<V, W>(in->u + o, u[0], u[1], u[2]);
  }
  const V zero = V{};
  F[0] -= use ? P * n[0] : zero;
  F[1] -= use ? P * n[1] : zero;
  F[2] -= use ? P * n[2] : zero;
  Tq[0] -= use ? Pr[1] * n[2] - Pr[2] * n[1] : zero;
  Tq[1] -= use ? Pr[2] * n[0] - Pr[0] * n[2] : zero;
  Tq[2] -= use ? Pr[0] * n[1] - Pr[1] * n[0] : zero;
  *wet += use ? A : zero;
  const V sdir = sr[0] * in->dir[0] + sr[1] * in->dir[1] + sr[2] * in->dir[2];
  *wdir += use ? A * sdir / 3 : zero;
  for (int c = 0; c < 3; c++) {
    const V e = p[c][0] * in->dir[0] + p[c][1] * in->dir[1] + p[c][2] * in->dir[2];
    *lo = (use & (e < *lo)) ? e : *lo;
    *hi = (use & (e > *hi)) ? e : *hi;
  }
}

// one wet piece of W lanes' cut triangles, corners q with Kerner's depths
// d, stretched heights zs, labels lb and e^L at corner 0; its area with
// the parent's normal n (wetTriangle's fan: the piece is coplanar), and
// its integrals added to the lanes' sums: area A, first moment rA, force
// F, torque Tq about the COM, wave velocity integral Vw (a piece of no
// area, a cut at a corner, adds nothing, as in wetWaves)
template <int W, class M>
static void cutPiece(const TriIn* in, const typename TLanes<W>::V q[3][3],
                     typename TLanes<W>::V d[3], const typename TLanes<W>::V zs[3],
                     const typename TLanes<W>::V lb[3][2], const double* const e0[W],
                     const typename TLanes<W>::V n[3], typename TLanes<W>::I* good,
                     typename TLanes<W>::V* A, typename TLanes<W>::V rA[3],
                     typename TLanes<W>::V F[3], typename TLanes<W>::V Tq[3],
                     typename TLanes<W>::V Vw[3],
                     const typename TLanes<W>::V (*sv)[4]) {
  typedef typename TLanes<W>::V V;
  typedef typename TLanes<W>::I I;
  V e1[3], e2[3];
  for (int j = 0; j < 3; j++) {
    e1[j] = q[1][j] - q[0][j];
    e2[j] = q[2][j] - q[0][j];
  }
  const V a = 0.5 * ((e1[1] * e2[2] - e1[2] * e2[1]) * n[0] +
                     (e1[2] * e2[0] - e1[0] * e2[2]) * n[1] +
                     (e1[0] * e2[1] - e1[1] * e2[0]) * n[2]);
  const I has = a > 0;
  const V z = V{}, ap = has ? a : z;
  V P, Pr[3], vw[3];
  laneIntegrals<W, M>(in, q, d, zs, lb, e0, ap, good, &P, Pr, vw, sv);
  *A += ap;
  for (int j = 0; j < 3; j++) {
    const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    rA[j] += ap * (q[0][j] + q[1][j] + q[2][j]) / 3;
    F[j] -= has ? P * n[j] : z;
    Tq[j] -= has ? Pr[j1] * n[j2] - Pr[j2] * n[j1] : z;
    Vw[j] += has ? vw[j] : z;
  }
}

// a point on each lane's edge from wet corner w to dry corner e, where
// the surface cuts it: t = h_w / (h_w - h_e) from the wet end (wetTriangle's
// rule, so a shared edge gives both triangles the same point); position
// x and label l
template <int W>
static void cutPoint(const typename TLanes<W>::V pw[3], const typename TLanes<W>::V pe[3],
                     const typename TLanes<W>::V lw[2], const typename TLanes<W>::V le[2],
                     typename TLanes<W>::V hw, typename TLanes<W>::V he,
                     typename TLanes<W>::V x[3], typename TLanes<W>::V l[2]) {
  const typename TLanes<W>::V t = hw / (hw - he);
  for (int j = 0; j < 3; j++) x[j] = pw[j] + t * (pe[j] - pw[j]);
  for (int j = 0; j < 2; j++) l[j] = lw[j] + t * (le[j] - lw[j]);
}

// the vertex sums at cutPoint's point (the same t): linear along the edge
template <int W>
static void cutSums(const typename TLanes<W>::V sw[4], const typename TLanes<W>::V se[4],
                    typename TLanes<W>::V hw, typename TLanes<W>::V he,
                    typename TLanes<W>::V s[4]) {
  const typename TLanes<W>::V t = hw / (hw - he);
  for (int q = 0; q < 4; q++) s[q] = sw[q] + t * (se[q] - sw[q]);
}

// the corners of cut triangles [p0, p0 + nl) of in.idx as W lanes (the
// last repeated past nl), each turned so its odd corner o (the one alone
// on its side of the surface) comes first, winding kept: o, a, b;
// position p, height h, z' zs and label lb of each corner, the lanes
// whose quadrilateral is fanned from b (TWO), each lane's e^L at its
// first wet corner and its triangle
template <int W, bool TWO>
static void cutLoad(const TriIn* in, int p0, int nl, typename TLanes<W>::V p[3][3],
                    typename TLanes<W>::V h[3], typename TLanes<W>::V zs[3],
                    typename TLanes<W>::V lb[3][2], typename TLanes<W>::I* fromB,
                    const double* e0[W], int tk[W], typename TLanes<W>::V sv[3][4]) {
  typedef typename TLanes<W>::V V;
  int gv[3][W];
  *fromB = typename TLanes<W>::I{};
  for (int l = 0; l < W; l++) {
    const int k = in->idx[p0 + (l < nl ? l : nl - 1)];
    const int* fc = in->face + 3 * k;
    tk[l] = k;
    const double h0 = in->h[fc[0]], h1 = in->h[fc[1]];
    const int r = TWO ? (h0 > 0 ? 0 : h1 > 0 ? 1 : 2) : (h0 <= 0 ? 0 : h1 <= 0 ? 1 : 2);
    (*fromB)[l] = TWO && r == 1 ? -1 : 0;
    for (int c = 0; c < 3; c++) gv[c][l] = fc[(r + c) % 3] - in->v0;
    e0[l] = in->E + in->es * in->nw * gv[!TWO ? 0 : r == 1 ? 2 : 1][l];
  }
  for (int c = 0; c < 3; c++) {
    V f[kRec];
    loadRecords<V, W>(in->rec, gv[c], f);
    for (int j = 0; j < 3; j++) p[c][j] = f[j];
    h[c] = f[3];
    zs[c] = f[4];  // read at the wet corners only
    lb[c][0] = f[5];
    lb[c][1] = f[6];
  }
  if (in->vs) vertexLoad<W>(in, gv, sv);
}

// the integrals of the wet part of the lanes' cut triangles (corners from
// cutLoad, parent's normal n) into A, rA, F, Tq and Vw, and its corners x
// (3 used, or 4 when TWO). TWO false: o alone below, one wet piece (o,
// cut oa, cut ob); TWO true: o alone above, a wet quadrilateral a, b, cut
// bo, cut ao in two pieces fanned from a, or from b in the lanes of fromB
template <int W, class M, bool TWO>
static void cutPieces(const TriIn* in, const typename TLanes<W>::V p[3][3],
                      const typename TLanes<W>::V h[3], const typename TLanes<W>::V zs[3],
                      const typename TLanes<W>::V lb[3][2], typename TLanes<W>::I fromB,
                      const double* const e0[W], const typename TLanes<W>::V n[3],
                      typename TLanes<W>::I* good, typename TLanes<W>::V x[4][3],
                      typename TLanes<W>::V* A, typename TLanes<W>::V rA[3],
                      typename TLanes<W>::V Fl[3], typename TLanes<W>::V Tl[3],
                      typename TLanes<W>::V Vw[3], const typename TLanes<W>::V sv[3][4]) {
  typedef typename TLanes<W>::V V;
  const V z = V{};
  const bool vtx = in->vs != nullptr;
  if (!TWO) {
    V l1[2], l2[2];
    cutPoint<W>(p[0], p[1], lb[0], lb[1], h[0], h[1], x[1], l1);
    cutPoint<W>(p[0], p[2], lb[0], lb[2], h[0], h[2], x[2], l2);
    for (int j = 0; j < 3; j++) x[0][j] = x[3][j] = p[0][j];
    const V q[3][3] = {{p[0][0], p[0][1], p[0][2]}, {x[1][0], x[1][1], x[1][2]},
                       {x[2][0], x[2][1], x[2][2]}};
    V d[3] = {-h[0], z, z};
    const V zq[3] = {zs[0], z, z}, lq[3][2] = {{lb[0][0], lb[0][1]}, {l1[0], l1[1]},
                                               {l2[0], l2[1]}};
    V sq[3][4];
    if (vtx) {
      for (int k = 0; k < 4; k++) sq[0][k] = sv[0][k];
      cutSums<W>(sv[0], sv[1], h[0], h[1], sq[1]);
      cutSums<W>(sv[0], sv[2], h[0], h[2], sq[2]);
    }
    cutPiece<W, M>(in, q, d, zq, lq, e0, n, good, A, rA, Fl, Tl, Vw, vtx ? sq : nullptr);
    return;
  }
  // the quadrilateral a, b, cut bo, cut ao fanned as wetWaves fans it:
  // from the first wet corner in the parent's order, b when o is the
  // parent's corner 1, else a (the cut points' labels and z' are linear
  // along the edges only, so the diagonal changes the integrals beyond
  // round-off)
  V la[2], lbo[2];
  cutPoint<W>(p[1], p[0], lb[1], lb[0], h[1], h[0], x[3], la);   // on edge a-o
  cutPoint<W>(p[2], p[0], lb[2], lb[0], h[2], h[0], x[2], lbo);  // on edge b-o
  for (int j = 0; j < 3; j++) {
    x[0][j] = p[1][j];
    x[1][j] = p[2][j];
  }
  // corners a, b, cut bo, cut ao: position, depth, z', label
  V cq[4][3], cd[4], cz[4] = {zs[1], zs[2], z, z}, cl[4][2];
  for (int c = 0; c < 4; c++) {
    for (int j = 0; j < 3; j++) cq[c][j] = x[c][j];
    cd[c] = c == 0 ? -h[1] : c == 1 ? -h[2] : z;
  }
  for (int j = 0; j < 2; j++) {
    cl[0][j] = lb[1][j];
    cl[1][j] = lb[2][j];
    cl[2][j] = lbo[j];
    cl[3][j] = la[j];
  }
  V cs[4][4];  // vertex sums at the four corners (vertex integration)
  if (vtx) {
    for (int k = 0; k < 4; k++) cs[0][k] = sv[1][k], cs[1][k] = sv[2][k];
    cutSums<W>(sv[2], sv[0], h[2], h[0], cs[2]);
    cutSums<W>(sv[1], sv[0], h[1], h[0], cs[3]);
  }
  // pieces (a, b, cut bo), (a, cut bo, cut ao), or from b (b, cut bo,
  // cut ao), (b, cut ao, a): corner indices into the four
  const int fa[2][3] = {{0, 1, 2}, {0, 2, 3}}, fbv[2][3] = {{1, 2, 3}, {1, 3, 0}};
  for (int m = 0; m < 2; m++) {
    V q[3][3], d[3], zq[3], lq[3][2], sq[3][4];
    for (int c = 0; c < 3; c++) {
      const int i = fa[m][c], k = fbv[m][c];
      for (int j = 0; j < 3; j++) q[c][j] = fromB ? cq[k][j] : cq[i][j];
      d[c] = fromB ? cd[k] : cd[i];
      zq[c] = fromB ? cz[k] : cz[i];
      for (int j = 0; j < 2; j++) lq[c][j] = fromB ? cl[k][j] : cl[i][j];
      if (vtx) {
        for (int j = 0; j < 4; j++) sq[c][j] = fromB ? cs[k][j] : cs[i][j];
      }
    }
    cutPiece<W, M>(in, q, d, zq, lq, e0, n, good, A, rA, Fl, Tl, Vw, vtx ? sq : nullptr);
  }
}

// cut triangles [p0, p0 + nl) of in.idx as W lanes (cutLoad), their wet
// parts (cutPieces), then per triangle done (wet area, centroid, normal,
// mean water velocity) and the sums into f, t, wet, wdir, lo, hi as
// triChunk
template <int W, class M, bool TWO>
static void cutChunk(TriIn* in, int p0, int nl, typename TLanes<W>::V* F,
                     typename TLanes<W>::V* Tq, typename TLanes<W>::V* wet,
                     typename TLanes<W>::V* wdir, typename TLanes<W>::V* lo,
                     typename TLanes<W>::V* hi, FlowAcc<W>* acc) {
  typedef typename TLanes<W>::V V;
  typedef typename TLanes<W>::I I;
  V p[3][3], h[3], zs[3], lb[3][2];
  I fromB;  // lanes whose quadrilateral is fanned from b
  const double* e0[W];
  int tk[W];
  V sv[3][4];  // vertex sums at o, a, b (vertex integration)
  cutLoad<W, TWO>(in, p0, nl, p, h, zs, lb, &fromB, e0, tk, sv);
  // the parent's normal (wetTriangle)
  V cr[3], n[3];
  const V len = laneNormal<W, M>(p, cr, n);
  const I ok = len > 0;
  const V hs = h[0] + h[1] + h[2];
  I good = ok & ((hs - hs) == 0);
  V A = V{}, rA[3] = {}, Fl[3] = {}, Tl[3] = {}, Vw[3] = {}, x[4][3];
  const V z = V{};
  cutPieces<W, M, TWO>(in, p, h, zs, lb, fromB, e0, n, &good, x, &A, rA, Fl, Tl, Vw, sv);
  const I has = A > 0;
  const V inv = has ? 1 / A : z;
  I use = good & has;
  for (int l = nl; l < W; l++) use[l] = 0;
  const V c[3] = {rA[0] * inv, rA[1] * inv, rA[2] * inv};
  const V u[3] = {in->cur[0] + Vw[0] * inv, in->cur[1] + Vw[1] * inv, 0 + Vw[2] * inv};
  for (int l = 0; l < nl; l++) {
    const int k = tk[l];
    if (!good[l]) {
      if (ok[l] || len[l] != len[l] || hs[l] != hs[l]) in->rest[in->nrest++] = k;
      continue;  // else degenerate: no wet part, area 0 (wetTriangle)
    }
    if (has[l] && !in->fl) storeLane(in, k, A, c, n, u, l);
  }
  if (in->fl) {
    const bool whole = nl == W && tk[W - 1] - tk[0] == W - 1 && TLanes<W>::all(use);
    flowAt<W, M>(in->fl, tk, whole, A, c, n, u, use, acc);
  }
  for (int j = 0; j < 3; j++) {
    F[j] += use ? Fl[j] : z;
    Tq[j] += use ? Tl[j] : z;
  }
  *wet += use ? A : z;
  *wdir += use ? rA[0] * in->dir[0] + rA[1] * in->dir[1] + rA[2] * in->dir[2] : z;
  for (int c = 0; c < (TWO ? 4 : 3); c++) {
    const V e = x[c][0] * in->dir[0] + x[c][1] * in->dir[1] + x[c][2] * in->dir[2];
    *lo = (use & (e < *lo)) ? e : *lo;
    *hi = (use & (e > *hi)) ? e : *hi;
  }
}

// in.idx's triangles in chunks of W: KIND 0 wholly wet (triChunk), 1 cut
// with one corner below, 2 cut with one corner above (cutChunk)
template <int W, class M, int KIND>
static void triLanes(TriIn* in) {
  typedef typename TLanes<W>::V V;
  V F[3] = {}, Tq[3] = {}, wet = V{}, wdir = V{}, lo = V{} + __builtin_inf(), hi = -lo;
  FlowAcc<W> acc = {};
  in->nrest = 0;
  for (int p = 0; p < in->m; p += W) {
    const int nl = in->m - p < W ? in->m - p : W;
    if (KIND == 0) triChunk<W, M>(in, p, nl, F, Tq, &wet, &wdir, &lo, &hi, &acc);
    if (KIND == 1) cutChunk<W, M, false>(in, p, nl, F, Tq, &wet, &wdir, &lo, &hi, &acc);
    if (KIND == 2) cutChunk<W, M, true>(in, p, nl, F, Tq, &wet, &wdir, &lo, &hi, &acc);
  }
  if (in->fl) {
    for (int j = 0; j < 6; j++) {
      in->fl->wv1[j] = TLanes<W>::hsum(acc.v1[j]);
      in->fl->wvd[j] = TLanes<W>::hsum(acc.vd[j]);
      in->fl->wd[j] = TLanes<W>::hsum(acc.d[j]);
      in->fl->ws[j] = TLanes<W>::hsum(acc.s[j]);
    }
  }
  for (int j = 0; j < 3; j++) {
    in->f[j] = TLanes<W>::hsum(F[j]);
    in->t[j] = TLanes<W>::hsum(Tq[j]);
  }
  in->wet = TLanes<W>::hsum(wet);
  in->wdir = TLanes<W>::hsum(wdir);
  in->lo = -TLanes<W>::hmax(-lo);
  in->hi = TLanes<W>::hmax(hi);
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_TRIVEC_KERN_H_
