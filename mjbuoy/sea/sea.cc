// sea surface: Gerstner height by inverting the horizontal displacement,
// Airy height as a direct sum; linear kinematics and pressure below it
#include "sea/sea.h"

#include <cmath>
#include <algorithm>
#include <cstring>

#include "sea/seavec.h"
#include "util/sincoskern.h"
#include "util/vmath.h"

namespace mjb {

static const double kDeg = M_PI / 180;

void Sea::derive() {
  order.clear();
  for (int kind = 0; kind < 2; kind++) {
    for (size_t i = 0; i < waves.size(); i++) {
      if ((waves[i].kind != 0) == (kind != 0)) order.push_back(i);
    }
    if (kind == 0) ng = order.size();
  }
  for (Wave& w : waves) {
    w.k = 2 * M_PI / w.len;
    // dispersion: omega^2 = g k tanh(k h), deep water when h is 0
    double th = depth > 0 ? std::tanh(w.k * depth) : 1.0;
    w.omega = std::sqrt(g * w.k * th);
    w.dx = std::cos(w.dir * kDeg);
    w.dy = std::sin(w.dir * kDeg);
    w.ph = w.phase * kDeg;
  }
}

double Sea::defaultRamp() const {
  const Wave* top = nullptr;
  for (const Wave& w : waves) if (w.omega > 0 && (!top || w.amp > top->amp)) top = &w;
  return top ? kRampPeriods * 2 * M_PI / top->omega : 0;
}

double Sea::fold() const {
  double s = 0;
  for (const Wave& w : waves) if (w.kind == 0) s += w.steep * w.k * w.amp;
  return s;
}

// Wheeler (1970) stretching of a point at height z above the level under a
// surface at eta: the height zs in [-h, 0] at which the linear profiles are
// evaluated, so the surface maps to zs = 0. Deep water: zs = z - eta; depth
// h: zs = (z - eta) h / (h + eta)
double stretch(double depth, double z, double eta) {
  if (!(depth > 0)) return std::fmin(z - eta, 0.0);
  if (!(depth + eta > 0)) return -depth;  // surface at or below the bed: all at the bed
  return std::fmin(std::fmax((z - eta) * depth / (depth + eta), -depth), 0.0);
}

void phaseSinCos(const double* th, int n, double* s, double* c) {
  typedef double V4 __attribute__((vector_size(32)));
  typedef long I4 __attribute__((vector_size(32)));  // what comparisons give
  for (int j = 0; j < n; j += 4) {
    V4 x, vs, vc;
    std::memcpy(&x, th + j, sizeof x);
    if (sinCosLanes<V4, I4>(x, &vs, &vc)) {
      std::memcpy(s + j, &vs, sizeof vs);
      std::memcpy(c + j, &vc, sizeof vc);
    } else {
      for (int l = 0; l < 4; l++) {
        s[j + l] = std::sin(th[j + l]);
        c[j + l] = std::cos(th[j + l]);
      }
    }
  }
}

// linear-theory depth profiles of one component (Dean & Dalrymple 1991,
// ch. 4): ch = cosh(s)/sinh(D), sh = sinh(s)/sinh(D), cc = cosh(s)/cosh(D)
// with s = k (zs + h), D = k h; deep water all three are e^(k zs). Written
// as e^(k zs) = e^(s - D) times factors in [0, 2] (expm1 keeps 1 - e^-2D
// exact for small D), so nothing overflows at any k h (cosh overflows past
// 710) and nothing cancels at large k h
struct Prof {
  double ch, sh, cc;
};
static inline Prof profile(double k, double depth, double zs) {
  double e = std::exp(k * zs);
  if (!(depth > 0)) return Prof{e, e, e};
  double s = k * (zs + depth), D = k * depth;
  double e2s = std::exp(-2 * s), e2d = std::exp(-2 * D), sd = -std::expm1(-2 * D);
  return Prof{e * (1 + e2s) / sd, e * -std::expm1(-2 * s) / sd, e * (1 + e2s) / (1 + e2d)};
}

// one component's linear velocity A w (ch cos, sh sin) and local
// acceleration A w^2 (ch sin, -sh cos) added to v and acc (theta's sin s, cos c)
static inline void addFlow(const Prof& f, double ao, double aoo, double dx, double dy, double s,
                           double c, double* v, double* acc) {
  double uh = ao * f.ch * c;
  v[0] += uh * dx;
  v[1] += uh * dy;
  v[2] += ao * f.sh * s;
  if (acc) {
    double ah = aoo * f.ch * s;
    acc[0] += ah * dx;
    acc[1] += ah * dy;
    acc[2] -= aoo * f.sh * c;
  }
}

void Sea::label(double x, double y, double t, double a[2]) const {
  // Newton on F(a) = a - Q A D sin(theta(a)) - x = 0, with
  // J = I - sum Q A k cos(theta) D D^T. The fold check (sum Q k A < 1)
  // keeps J positive definite, so the root is unique and Newton converges
  // from any guess; the step is halved if it ever fails to reduce |F|.
  double f0, f1, j00, j01, j11, r2;
  const double r = gain(t);
  auto eval = [&](const double* p) {
    f0 = p[0] - x;
    f1 = p[1] - y;
    j00 = 1; j01 = 0; j11 = 1;
    for (const Wave& w : waves) {
      if (w.kind != 0 || w.steep == 0 || w.amp == 0) continue;
      double th = w.k * (w.dx * p[0] + w.dy * p[1]) - w.omega * t + w.ph;
      double s = std::sin(th), c = std::cos(th), qa = w.steep * (r * w.amp);
      f0 -= qa * w.dx * s;
      f1 -= qa * w.dy * s;
      double jc = qa * w.k * c;
      j00 -= jc * w.dx * w.dx;
      j01 -= jc * w.dx * w.dy;
      j11 -= jc * w.dy * w.dy;
    }
    r2 = f0 * f0 + f1 * f1;
  };
  eval(a);
  for (int it = 0; it < 50 && r2 > 1e-24; it++) {
    double det = j00 * j11 - j01 * j01;
    double s0 = (j11 * f0 - j01 * f1) / det;
    double s1 = (j00 * f1 - j01 * f0) / det;
    double prev = r2, b[2];
    double step = 1;
    for (int h = 0; h < 30; h++, step *= 0.5) {
      b[0] = a[0] - step * s0;
      b[1] = a[1] - step * s1;
      eval(b);
      if (r2 < prev) break;
    }
    a[0] = b[0];
    a[1] = b[1];
    if (r2 >= prev) break;  // no further progress in double
  }
}

double Sea::heightOf(const double a[2], double x, double y, double t) const {
  double z = level;
  const double r = gain(t);
  for (const Wave& w : waves) {
    double px = w.kind == 0 ? a[0] : x, py = w.kind == 0 ? a[1] : y;
    double th = w.k * (w.dx * px + w.dy * py) - w.omega * t + w.ph;
    z += r * w.amp * std::cos(th);
  }
  return z;
}

double Sea::height(double x, double y, double t) const {
  if (waves.empty()) return level;
  double a[2] = {x, y};
  label(x, y, t, a);
  return heightOf(a, x, y, t);
}

// components whose phases' sin and cos velocity keeps on the stack
static const size_t kKeep = 256;

void Sea::velocity(const double p[3], double t, double v[3], double acc[3]) const {
  double a[2] = {p[0], p[1]};
  if (!waves.empty()) label(p[0], p[1], t, a);
  // the first kKeep phases' sin and cos in lanes, kept for the height and
  // the flow below
  const size_t nk = waves.size() < kKeep ? waves.size() : kKeep;
  double th[kKeep] = {}, sn[kKeep], cs[kKeep];  // zeros: the last group's padding
  for (size_t i = 0; i < nk; i++) {
    const Wave& w = waves[i];
    double px = w.kind == 0 ? a[0] : p[0], py = w.kind == 0 ? a[1] : p[1];
    th[i] = w.k * (w.dx * px + w.dy * py) - w.omega * t + w.ph;
  }
  phaseSinCos(th, nk, sn, cs);
  // the height as heightOf sums it (its cos within 3 ulp)
  const double r = gain(t);
  double z = level;
  for (size_t i = 0; i < waves.size(); i++) {
    const Wave& w = waves[i];
    double c;
    if (i < kKeep) {
      c = cs[i];
    } else {
      double px = w.kind == 0 ? a[0] : p[0], py = w.kind == 0 ? a[1] : p[1];
      c = std::cos(w.k * (w.dx * px + w.dy * py) - w.omega * t + w.ph);
    }
    z += r * w.amp * c;
  }
  double eta = z - level;
  double zs = stretch(depth, p[2] - level, eta);
  v[0] = current[0];
  v[1] = current[1];
  v[2] = 0;
  if (acc) acc[0] = acc[1] = acc[2] = 0;
  for (size_t i = 0; i < waves.size(); i++) {
    const Wave& w = waves[i];
    double s, c;
    if (i < kKeep) {
      s = sn[i], c = cs[i];
    } else {
      double px = w.kind == 0 ? a[0] : p[0], py = w.kind == 0 ? a[1] : p[1];
      double th = w.k * (w.dx * px + w.dy * py) - w.omega * t + w.ph;
      s = std::sin(th), c = std::cos(th);
    }
    const double A = r * w.amp;
    addFlow(profile(w.k, depth, zs), A * w.omega, A * w.omega * w.omega, w.dx, w.dy, s, c, v,
            acc);
  }
}

double Sea::dynamic(const double p[3], double t) const {
  double a[2] = {p[0], p[1]};
  if (!waves.empty()) label(p[0], p[1], t, a);
  double eta = heightOf(a, p[0], p[1], t) - level;
  double zs = stretch(depth, p[2] - level, eta), pd = 0;
  const double r = gain(t);
  for (const Wave& w : waves) {
    double px = w.kind == 0 ? a[0] : p[0], py = w.kind == 0 ? a[1] : p[1];
    double th = w.k * (w.dx * px + w.dy * py) - w.omega * t + w.ph;
    pd += r * w.amp * profile(w.k, depth, zs).cc * std::cos(th);
  }
  return rho * g * pd;
}

void Sea::now(double t, WaveNow* w) const {
  // the ramp scales every amplitude (1 after it: the same bits as without)
  const double r = gain(t);
  for (size_t i = 0; i < order.size(); i++) {
    const Wave& W = waves[order[i]];
    const double A = r * W.amp;
    double qa = W.kind == 0 ? W.steep * A : 0;
    w[i] = WaveNow{W.k, W.dx, W.dy, W.omega * t, W.ph, qa * W.dx, qa * W.dy, qa * W.k,
                   A, qa * W.omega, A * W.omega, A * W.omega * W.omega};
  }
}

// the phase shifted by d [rad]: sin, cos of theta + d from those of theta by
// angle addition; Taylor series of sin d and cos d - 1 to d^9 and d^10 are
// exact in double for |d| < kShift (next terms below 1e-21), beyond it the
// caller evaluates the phase directly. Newton's later steps are tiny: below
// kShort the series to d^5 and d^6 are already exact (next terms < 1e-25)
static const double kShift = 0.05, kShort = 1e-3;
static inline void shift(double s, double c, double d, double* out) {
  double d2 = d * d, sd, cm;
  if (std::fabs(d) < kShort) {
    sd = d * (1 + d2 * (-1.0 / 6 + d2 * (1.0 / 120)));
    cm = d2 * (-0.5 + d2 * (1.0 / 24 + d2 * (-1.0 / 720)));
  } else {
    sd = d * (1 + d2 * (-1.0 / 6 + d2 * (1.0 / 120 + d2 * (-1.0 / 5040 + d2 * (1.0 / 362880)))));
    cm = d2 * (-0.5 + d2 * (1.0 / 24 + d2 * (-1.0 / 720 + d2 * (1.0 / 40320 +
                                                                d2 * (-1.0 / 3628800)))));
  }
  out[0] = s + (s * cm + c * sd);
  out[1] = c + (c * cm - s * sd);
}

// solve() for n components; N > 0 fixes n at compile time so the loops
// unroll and the phases stay in registers (N = 0: any n, phases in sc/tmp)
template <int N>
static double solveN(const WaveNow* w, int n, double level, double x, double y, double a[2],
                     double* sc, double* tmp, int* nit) {
  if (N > 0) n = N;
  double lc[N > 0 ? 2 * N : 1], ln[N > 0 ? 2 * N : 1];
  double* cur = N > 0 ? lc : sc;
  double* nxt = N > 0 ? ln : tmp;
  for (int i = 0; i < n; i++) {
    double th = w[i].k * (w[i].dx * a[0] + w[i].dy * a[1]) - w[i].wt + w[i].ph;
    cur[2 * i] = std::sin(th);
    cur[2 * i + 1] = std::cos(th);
  }
  // Newton with step halving exactly as in label(), on the phases in q
  double f0, f1, j00, j01, j11, r2;
  auto eval = [&](const double* p, const double* q) {
    f0 = p[0] - x;
    f1 = p[1] - y;
    j00 = 1; j01 = 0; j11 = 1;
    for (int i = 0; i < n; i++) {
      double s = q[2 * i], c = q[2 * i + 1];
      f0 -= w[i].qx * s;
      f1 -= w[i].qy * s;
      double jc = w[i].qk * c;
      j00 -= jc * w[i].dx * w[i].dx;
      j01 -= jc * w[i].dx * w[i].dy;
      j11 -= jc * w[i].dy * w[i].dy;
    }
    r2 = f0 * f0 + f1 * f1;
  };
  eval(a, cur);
  int it = 0;
  for (; it < 50 && r2 > 1e-24; it++) {
    double det = j00 * j11 - j01 * j01;
    double s0 = (j11 * f0 - j01 * f1) / det;
    double s1 = (j00 * f1 - j01 * f0) / det;
    double prev = r2, b[2];
    double step = 1;
    for (int h = 0; h < 30; h++, step *= 0.5) {
      b[0] = a[0] - step * s0;
      b[1] = a[1] - step * s1;
      double e0 = b[0] - a[0], e1 = b[1] - a[1];
      for (int i = 0; i < n; i++) {
        double d = w[i].k * (w[i].dx * e0 + w[i].dy * e1);
        if (std::fabs(d) < kShift) {
          shift(cur[2 * i], cur[2 * i + 1], d, nxt + 2 * i);
        } else {
          double th = w[i].k * (w[i].dx * b[0] + w[i].dy * b[1]) - w[i].wt + w[i].ph;
          nxt[2 * i] = std::sin(th);
          nxt[2 * i + 1] = std::cos(th);
        }
      }
      eval(b, nxt);
      if (r2 < prev) break;
    }
    a[0] = b[0];
    a[1] = b[1];
    for (int i = 0; i < 2 * n; i++) cur[i] = nxt[i];
    if (r2 >= prev) {  // no further progress in double
      it++;
      break;
    }
  }
  if (nit) *nit += it;
  double z = level;
  for (int i = 0; i < n; i++) z += w[i].amp * cur[2 * i + 1];
  if (N > 0) {
    for (int i = 0; i < 2 * n; i++) sc[i] = cur[i];
  }
  return z;
}

double Sea::solve(const WaveNow* w, double x, double y, double a[2], double* sc,
                  double* tmp, int* nit) const {
  double z;
  switch (ng) {
    case 0: a[0] = x; a[1] = y; z = level; break;
    case 1: z = solveN<1>(w, ng, level, x, y, a, sc, tmp, nit); break;
    case 2: z = solveN<2>(w, ng, level, x, y, a, sc, tmp, nit); break;
    case 3: z = solveN<3>(w, ng, level, x, y, a, sc, tmp, nit); break;
    case 4: z = solveN<4>(w, ng, level, x, y, a, sc, tmp, nit); break;
    default: z = solveN<0>(w, ng, level, x, y, a, sc, tmp, nit);
  }
  // Airy components: a direct sum at the physical point, the phases' sin
  // and cos vectorised (vmath.h): th and cos in tmp, sin in tmp + n
  const int n = order.size(), na = n - ng;
  for (int i = ng; i < n; i++) tmp[i - ng] = w[i].k * (w[i].dx * x + w[i].dy * y) - w[i].wt + w[i].ph;
  vSinCos(na, tmp, tmp + n, tmp);
  for (int i = ng; i < n; i++) {
    const double c = tmp[i - ng];
    sc[2 * i] = tmp[n + i - ng];
    sc[2 * i + 1] = c;
    z += w[i].amp * c;
  }
  return z;
}

long Sea::solveMany(const WaveNow* w, int m, const double* x, const double* y, double* a0,
                    double* a1, double* z, double* sc, double* tmp, bool fast) const {
  // AVX2 or AVX-512: lanes of 4 or 8 points in lockstep (seavec.h), whose
  // gain is vector sin and cos of the guesses (a lockstep version over
  // SSE2 lanes, with scalar sin and cos, measured no faster than this loop)
  const int n = waves.size();
  const int lv = simdLevel();
  if (lv != kSimdScalar) {
    const LaneIn in{w, n, ng, m, level, x, y, a0, a1, z, sc, tmp, fast};
    return lv == kSimdAvx512 ? solveLanesAvx512(in) : solveLanesAvx2(in);
  }
  // the reference: one point after the other
  int nit = 0;
  for (int i = 0; i < m; i++) {
    double a[2] = {a0[i], a1[i]};
    z[i] = solve(w, x[i], y[i], a, sc + 2 * n * i, tmp, &nit);
    a0[i] = a[0];
    a1[i] = a[1];
  }
  return nit;
}

void Sea::velocitySC(const WaveNow* w, const double* sc, double z, double eta, double v[3],
                     double acc[3]) const {
  v[0] = current[0];
  v[1] = current[1];
  v[2] = 0;
  if (acc) acc[0] = acc[1] = acc[2] = 0;
  const double zs = stretch(depth, z, eta);
  for (size_t i = 0; i < order.size(); i++) {
    addFlow(profile(w[i].k, depth, zs), w[i].ao, w[i].aoo, w[i].dx, w[i].dy, sc[2 * i],
            sc[2 * i + 1], v, acc);
  }
}

double Sea::dynamicSC(const WaveNow* w, const double* sc, double z, double eta) const {
  const double zs = stretch(depth, z, eta);
  double pd = 0;
  for (size_t i = 0; i < order.size(); i++) {
    pd += w[i].amp * profile(w[i].k, depth, zs).cc * sc[2 * i + 1];
  }
  return rho * g * pd;
}

double Sea::dynamicAt(const WaveNow* w, double x, double y, const double a[2], double z,
                      double eta) const {
  const double zs = stretch(depth, z, eta);
  double pd = 0;
  for (size_t i = 0; i < order.size(); i++) {
    const double kz = w[i].k * zs;
    if (kz < -40) continue;
    const bool ger = (int)i < ng;
    const double px = ger ? a[0] : x, py = ger ? a[1] : y;
    const double th = w[i].k * (w[i].dx * px + w[i].dy * py) - w[i].wt + w[i].ph;
    const double c = std::cos(th);
    if (!(depth > 0)) {
      pd += w[i].amp * std::exp(kz) * c;
    } else {
      pd += w[i].amp * profile(w[i].k, depth, zs).cc * c;
    }
  }
  return rho * g * pd;
}

}  // namespace mjb
