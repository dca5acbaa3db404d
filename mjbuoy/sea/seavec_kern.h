// seavec_kern: Sea::solve for W points at once (GCC vector extensions),
// included by one file per instruction set. Everything here is static: no
// inline function compiled for AVX can be shared with the scalar path.
// Includes nothing but seavec.h.
//
// Each lane runs sea.cc's solveN exactly: the phases at the guess, Newton
// with step halving on F(a) = a - sum Q A D sin(theta(a)) - x, stopping at
// |F|^2 <= 1e-24, after 50 steps or when a step makes no progress; the
// trial phases by angle addition (sea.cc's shift) where the phase moves by
// less than kShift, else directly. Lanes that have stopped are masked, so
// every lane takes the steps its point takes alone; only the rounding
// differs (the lanes' sin and cos, sincoskern.h, or libmvec's; FMA
// contraction).
#ifndef MJBUOY_SEAVEC_KERN_H_
#define MJBUOY_SEAVEC_KERN_H_

#include "sea/seavec.h"
#include "util/sincoskern.h"
#include "util/zipkern.h"

namespace mjb {
namespace {

template <int W>
struct Lanes {
  typedef double V __attribute__((vector_size(8 * W)));
  typedef long I __attribute__((vector_size(8 * W)));  // what comparisons give
  static V ld(const double* p) {
    V v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
  }
  static void st(double* p, V v) { __builtin_memcpy(p, &v, sizeof v); }
  // through a template: GCC checks v[i] of a dependent vector only when
  // instantiated
  template <class U>
  static bool any(U m) {
    for (int i = 0; i < W; i++) if (m[i]) return true;
    return false;
  }
  template <class U>
  static U abs(U v) {
    return v < 0 ? -v : v;
  }
};

// sin and cos of the lanes' phases th: one range reduction for both
// (sincoskern.h), libmvec's two functions for phases beyond its range
template <int W, class M>
static inline void sinCosPhases(typename Lanes<W>::V th, typename Lanes<W>::V* s,
                                typename Lanes<W>::V* c) {
  if (sinCosLanes<typename Lanes<W>::V, typename Lanes<W>::I>(th, s, c)) return;
  *s = M::sin(th);
  *c = M::cos(th);
}

// sea.cc's shift: sin, cos of theta + d from s, c of theta, the series for
// |d| < kShort or the longer one, per lane (same constants and grouping)
template <class V>
static inline void shiftLanes(V s, V c, V d, V* os, V* oc) {
  const V d2 = d * d, ad = d < 0 ? -d : d;
  const V sdS = d * (1 + d2 * (-1.0 / 6 + d2 * (1.0 / 120)));
  const V cmS = d2 * (-0.5 + d2 * (1.0 / 24 + d2 * (-1.0 / 720)));
  const V sdL =
      d * (1 + d2 * (-1.0 / 6 + d2 * (1.0 / 120 + d2 * (-1.0 / 5040 + d2 * (1.0 / 362880)))));
  const V cmL = d2 * (-0.5 + d2 * (1.0 / 24 + d2 * (-1.0 / 720 + d2 * (1.0 / 40320 +
                                                                   d2 * (-1.0 / 3628800)))));
  const V sd = ad < 1e-3 ? sdS : sdL, cm = ad < 1e-3 ? cmS : cmL;
  *os = s + (s * cm + c * sd);
  *oc = c + (c * cm - s * sd);
}

// the residual F, Jacobian J and |F|^2 of the lanes at labels p0, p1 from
// their phases q (sin of component i at q + 2 i W, cos at q + (2 i + 1) W)
template <int W>
struct Eval {
  typedef typename Lanes<W>::V V;
  V f0, f1, j00, j01, j11, r2;
  void at(const WaveNow* w, int ng, V x, V y, V p0, V p1, const double* q) {
    f0 = p0 - x;
    f1 = p1 - y;
    j00 = V{} + 1;
    j01 = V{};
    j11 = V{} + 1;
    for (int i = 0; i < ng; i++) {
      const V s = Lanes<W>::ld(q + 2 * i * W), c = Lanes<W>::ld(q + (2 * i + 1) * W);
      f0 -= w[i].qx * s;
      f1 -= w[i].qy * s;
      const V jc = w[i].qk * c;
      j00 -= jc * w[i].dx * w[i].dx;
      j01 -= jc * w[i].dx * w[i].dy;
      j11 -= jc * w[i].dy * w[i].dy;
    }
    r2 = f0 * f0 + f1 * f1;
  }
};

// one trial of the step halving for the lanes in srch: labels t0, t1 (a
// step of e0, e1 from a0, a1), their phases into nxt where srch
template <int W, class M>
static void trialPhases(const WaveNow* w, int ng, typename Lanes<W>::I srch,
                        typename Lanes<W>::V t0, typename Lanes<W>::V t1,
                        typename Lanes<W>::V e0, typename Lanes<W>::V e1, const double* cur,
                        double* nxt) {
  typedef Lanes<W> L;
  typedef typename L::V V;
  for (int i = 0; i < ng; i++) {
    const V d = w[i].k * (w[i].dx * e0 + w[i].dy * e1);
    V s, c;
    shiftLanes(L::ld(cur + 2 * i * W), L::ld(cur + (2 * i + 1) * W), d, &s, &c);
    const auto far = ~(L::abs(d) < 0.05);  // sea.cc's kShift (NaN: directly)
    if (L::any(far & srch)) {
      const V th = w[i].k * (w[i].dx * t0 + w[i].dy * t1) - w[i].wt + w[i].ph;
      s = far ? M::sin(th) : s;
      c = far ? M::cos(th) : c;
    }
    L::st(nxt + 2 * i * W, srch ? s : L::ld(nxt + 2 * i * W));
    L::st(nxt + (2 * i + 1) * W, srch ? c : L::ld(nxt + (2 * i + 1) * W));
  }
}

// Newton on the Gerstner labels of W lanes from a0, a1, phases in cur (nxt:
// scratch of the same size); the steps each lane took added to it
template <int W, class M>
static void newtonLanes(const WaveNow* w, int ng, typename Lanes<W>::V x,
                        typename Lanes<W>::V y, typename Lanes<W>::V* a0,
                        typename Lanes<W>::V* a1, double* cur, double* nxt,
                        typename Lanes<W>::I* it) {
  typedef Lanes<W> L;
  typedef typename L::V V;
  typedef typename L::I I;
  Eval<W> e;
  e.at(w, ng, x, y, *a0, *a1, cur);
  I act = e.r2 > 1e-24;
  for (int k = 0; k < 50 && L::any(act); k++) {
    const V det = e.j00 * e.j11 - e.j01 * e.j01;
    const V s0 = (e.j11 * e.f0 - e.j01 * e.f1) / det;
    const V s1 = (e.j00 * e.f1 - e.j01 * e.f0) / det;
    const V prev = e.r2;
    V b0 = *a0, b1 = *a1;
    I srch = act;
    double step = 1;
    // each searching lane keeps its last trial: the first that reduces
    // |F|, or the 30th
    for (int h = 0; h < 30 && L::any(srch); h++, step *= 0.5) {
      const V t0 = *a0 - step * s0, t1 = *a1 - step * s1;
      trialPhases<W, M>(w, ng, srch, t0, t1, t0 - *a0, t1 - *a1, cur, nxt);
      Eval<W> t;
      t.at(w, ng, x, y, t0, t1, nxt);
      b0 = srch ? t0 : b0;
      b1 = srch ? t1 : b1;
      e.f0 = srch ? t.f0 : e.f0;
      e.f1 = srch ? t.f1 : e.f1;
      e.j00 = srch ? t.j00 : e.j00;
      e.j01 = srch ? t.j01 : e.j01;
      e.j11 = srch ? t.j11 : e.j11;
      e.r2 = srch ? t.r2 : e.r2;
      srch &= ~(t.r2 < prev);
    }
    *a0 = act ? b0 : *a0;
    *a1 = act ? b1 : *a1;
    for (int i = 0; i < 2 * ng; i++) {
      L::st(cur + i * W, act ? L::ld(nxt + i * W) : L::ld(cur + i * W));
    }
    *it -= act;  // act is -1 where set
    // no further progress in double, or converged
    act &= ~(e.r2 >= prev) & (e.r2 > 1e-24);
  }
}

// the labels a0, a1 and the Gerstner components' sin and cos (cur, 2 ng
// rows of W) of points [p0, p0 + nl) into in
template <int W>
static void storeLabels(const LaneIn& in, int p0, int nl, bool whole,
                        typename Lanes<W>::V a0, typename Lanes<W>::V a1, const double* cur) {
  typedef Lanes<W> L;
  typedef typename L::V V;
  const int ng = in.ng, n = in.n;
  if (whole && n == 1 && ng == 1) {  // one Gerstner component: phases zipped
    L::st(in.a0 + p0, a0);
    L::st(in.a1 + p0, a1);
    zip2<V, W>(in.sc + 2 * p0, L::ld(cur), L::ld(cur + W));
    return;
  }
  for (int l = 0; l < nl; l++) {
    const int q = p0 + l;
    in.a0[q] = a0[l];
    in.a1[q] = a1[l];
    double* sc = in.sc + 2 * n * q;
    for (int i = 0; i < ng; i++) {
      sc[2 * i] = cur[2 * i * W + l];
      sc[2 * i + 1] = cur[(2 * i + 1) * W + l];
    }
  }
}

// the Airy components [ng, n)'s largest k [rad/m] and |wt| + |ph| [rad],
// so that their phases at |x| <= ax, |y| <= ay are at most kc[0] (ax +
// ay) + kc[1] (|D| <= 1); both infinite when one is not finite
static void airyPhaseBound(const LaneIn& in, double kc[2]) {
  double sum = 0;  // (NaN passes through +, not through the maxima)
  kc[0] = kc[1] = 0;
  for (int i = in.ng; i < in.n; i++) {
    const double k = __builtin_fabs(in.w[i].k);
    const double c = __builtin_fabs(in.w[i].wt) + __builtin_fabs(in.w[i].ph);
    kc[0] = kc[0] < k ? k : kc[0];
    kc[1] = kc[1] < c ? c : kc[1];
    sum += k + c;
  }
  if (!(sum < __builtin_inf())) kc[0] = kc[1] = __builtin_inf();
}

// the Airy components [i, n) of points [p0, p0 + nl) at (x, y) in whole
// groups of W / 2: a direct sum at the physical point added to z; their
// sin and cos go to each point's row through a W x W transpose (row l:
// point l's W / 2 pairs, one store) instead of two lane stores each.
// kIn: every phase is known to be within sincoskern.h's range, so the
// lanes' check is skipped (the same operations, so the same bits); kFast
// (with kIn): sinCosFast's reduced polynomials (LaneIn fast).
// Returns the first component not done
template <int W, class M, bool kIn, bool kFast>
static int airyGroups(const LaneIn& in, int p0, int nl, int i, typename Lanes<W>::V x,
                      typename Lanes<W>::V y, typename Lanes<W>::V* z) {
  typedef typename Lanes<W>::V V;
  typedef typename Lanes<W>::I I;
  const WaveNow* w = in.w;
  const int n = in.n;
  // the height summed in registers: *z may alias the stores to sc, so a
  // sum through it waits on memory each time. Exact: one running sum in
  // the components' order (the same bits); fast: W / 2 partial sums
  V zr = *z, zp[W / 2] = {};
  for (; i + W / 2 <= n; i += W / 2) {
    V r[W];
    for (int a = 0; a < W / 2; a++) {
      const WaveNow& wa = w[i + a];
      // (fast: the products of k and the constants taken once per group,
      // two multiply-adds per lane; the phase within 3 ulp of its terms' sum)
      const V th = kFast ? (wa.k * wa.dx) * x + ((wa.k * wa.dy) * y + (wa.ph - wa.wt))
                         : wa.k * (wa.dx * x + wa.dy * y) - wa.wt + wa.ph;
      if (kFast) {
        sinCosFast<V, I>(th, &r[2 * a], &r[2 * a + 1]);
      } else if (kIn) {
        sinCosInRange<V, I>(th, &r[2 * a], &r[2 * a + 1]);
      } else {
        sinCosPhases<W, M>(th, &r[2 * a], &r[2 * a + 1]);
      }
      if (kFast) {
        zp[a] += wa.amp * r[2 * a + 1];
      } else {
        zr += wa.amp * r[2 * a + 1];
      }
    }
    transpose<V, W>(r);
    double* o = in.sc + 2 * n * p0 + 2 * i;
    if (nl == W) {  // (a fixed count: the rows stay in registers)
      for (int l = 0; l < W; l++) Lanes<W>::st(o + 2 * n * l, r[l]);
    } else {
      for (int l = 0; l < nl; l++) Lanes<W>::st(o + 2 * n * l, r[l]);
    }
  }
  if (kFast) {
    for (int a = 0; a < W / 2; a++) zr += zp[a];
  }
  *z = zr;
  return i;
}

// the Airy components of points [p0, p0 + nl) at (x, y) (airyGroups, the
// rest lane by lane). When every phase is bounded by 2^19 (airyPhaseBound's
// kc; far inside sincoskern.h's 2^20 pi/2 with the bound's round-off) the
// lanes' range check is skipped
template <int W, class M>
static void airyLanes(const LaneIn& in, int p0, int nl, typename Lanes<W>::V x,
                      typename Lanes<W>::V y, typename Lanes<W>::V* z, const double kc[2]) {
  typedef typename Lanes<W>::V V;
  const WaveNow* w = in.w;
  const int n = in.n;
  // the largest |x|, |y| (the maxima drop NaN: the sum keeps it)
  double ax = 0, ay = 0, sum = 0;
  for (int l = 0; l < W; l++) {
    const double u = __builtin_fabs(x[l]), v = __builtin_fabs(y[l]);
    ax = ax < u ? u : ax;
    ay = ay < v ? v : ay;
    sum += x[l] + y[l];
  }
  const bool inr = kc[0] * (ax + ay) + kc[1] < 0x1p19 && sum - sum == 0;
  int i = !inr ? airyGroups<W, M, false, false>(in, p0, nl, in.ng, x, y, z)
          : in.fast ? airyGroups<W, M, true, true>(in, p0, nl, in.ng, x, y, z)
                    : airyGroups<W, M, true, false>(in, p0, nl, in.ng, x, y, z);
  for (; i < n; i++) {
    const V th = w[i].k * (w[i].dx * x + w[i].dy * y) - w[i].wt + w[i].ph;
    V s, c;
    sinCosPhases<W, M>(th, &s, &c);
    *z += w[i].amp * c;
    for (int l = 0; l < nl; l++) {
      in.sc[2 * n * (p0 + l) + 2 * i] = s[l];
      in.sc[2 * n * (p0 + l) + 2 * i + 1] = c[l];
    }
  }
}

// points [p0, p0 + nl) of in as W lanes (the last point repeated in the
// lanes past nl, whose results are dropped)
template <int W, class M>
static long solveChunk(const LaneIn& in, int p0, int nl, const double kc[2]) {
  typedef Lanes<W> L;
  typedef typename L::V V;
  typedef typename L::I I;
  const WaveNow* w = in.w;
  const int ng = in.ng;
  double* cur = in.tmp;
  double* nxt = in.tmp + 2 * ng * W;
  V x, y, a0, a1;
  const bool whole = nl == W;  // loaded and stored whole
  if (whole) {
    x = L::ld(in.x + p0);
    y = L::ld(in.y + p0);
    a0 = L::ld(in.a0 + p0);
    a1 = L::ld(in.a1 + p0);
  } else {
    for (int l = 0; l < W; l++) {
      const int q = p0 + (l < nl ? l : nl - 1);
      x[l] = in.x[q];
      y[l] = in.y[q];
      a0[l] = in.a0[q];
      a1[l] = in.a1[q];
    }
  }
  I it = I{};
  if (ng == 0) {
    a0 = x;
    a1 = y;
  } else {
    for (int i = 0; i < ng; i++) {
      const V th = w[i].k * (w[i].dx * a0 + w[i].dy * a1) - w[i].wt + w[i].ph;
      V s, c;
      sinCosPhases<W, M>(th, &s, &c);
      L::st(cur + 2 * i * W, s);
      L::st(cur + (2 * i + 1) * W, c);
    }
    newtonLanes<W, M>(w, ng, x, y, &a0, &a1, cur, nxt, &it);
  }
  V z = V{} + in.level;
  for (int i = 0; i < ng; i++) z += w[i].amp * L::ld(cur + (2 * i + 1) * W);
  long nit = 0;
  for (int l = 0; l < nl; l++) nit += it[l];
  storeLabels<W>(in, p0, nl, whole, a0, a1, cur);
  airyLanes<W, M>(in, p0, nl, x, y, &z, kc);
  if (whole) {
    L::st(in.z + p0, z);
  } else {
    for (int l = 0; l < nl; l++) in.z[p0 + l] = z[l];
  }
  return nit;
}

template <int W, class M>
static long solveLanes(const LaneIn& in) {
  long nit = 0;
  double kc[2];
  airyPhaseBound(in, kc);
  for (int p = 0; p < in.m; p += W) {
    nit += solveChunk<W, M>(in, p, in.m - p < W ? in.m - p : W, kc);
  }
  return nit;
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_SEAVEC_KERN_H_
