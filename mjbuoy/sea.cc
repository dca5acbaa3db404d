// sea surface: Gerstner height by inverting the horizontal displacement
#include "sea.h"

#include <cmath>
#include <algorithm>
#include <cstring>

namespace mjb {

static const double kDeg = M_PI / 180;

void Sea::derive() {
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

double Sea::fold() const {
  double s = 0;
  for (const Wave& w : waves) s += w.steep * w.k * w.amp;
  return s;
}

void Sea::label(double x, double y, double t, double a[2]) const {
  // Newton on F(a) = a - Q A D sin(theta(a)) - x = 0, with
  // J = I - sum Q A k cos(theta) D D^T. The fold check (sum Q k A < 1)
  // keeps J positive definite, so the root is unique and Newton converges
  // from any guess; the step is halved if it ever fails to reduce |F|.
  double f0, f1, j00, j01, j11, r2;
  auto eval = [&](const double* p) {
    f0 = p[0] - x;
    f1 = p[1] - y;
    j00 = 1; j01 = 0; j11 = 1;
    for (const Wave& w : waves) {
      if (w.steep == 0 || w.amp == 0) continue;
      double th = w.k * (w.dx * p[0] + w.dy * p[1]) - w.omega * t + w.ph;
      double s = std::sin(th), c = std::cos(th), qa = w.steep * w.amp;
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

double Sea::heightOf(const double a[2], double t) const {
  double z = level;
  for (const Wave& w : waves) {
    double th = w.k * (w.dx * a[0] + w.dy * a[1]) - w.omega * t + w.ph;
    z += w.amp * std::cos(th);
  }
  return z;
}

double Sea::height(double x, double y, double t) const {
  if (waves.empty()) return level;
  double a[2] = {x, y};
  label(x, y, t, a);
  return heightOf(a, t);
}

void Sea::velocity(const double p[3], double t, double v[3]) const {
  double a[2] = {p[0], p[1]};
  if (!waves.empty()) label(p[0], p[1], t, a);
  velocityOf(a, t, std::fmin(p[2] - heightOf(a, t), 0.0), v);
}

void Sea::velocityOf(const double a[2], double t, double zb, double v[3]) const {
  v[0] = current[0];
  v[1] = current[1];
  v[2] = 0;
  if (depth > 0) zb = std::fmax(zb, -depth);  // not below the sea bed
  for (const Wave& w : waves) {
    double th = w.k * (w.dx * a[0] + w.dy * a[1]) - w.omega * t + w.ph;
    // particle velocity: d/dt of x = a - Q A D sin(theta), z = A cos(theta)
    double uh = w.steep * w.amp * w.omega * std::cos(th);
    double uz = w.amp * w.omega * std::sin(th);
    double fh, fz;
    depthRatios(w.k, zb, &fh, &fz);
    v[0] += uh * fh * w.dx;
    v[1] += uh * fh * w.dy;
    v[2] += uz * fz;
  }
}

void Sea::depthRatios(double k, double zb, double* fh, double* fz) const {
  if (!(depth > 0)) {
    *fh = *fz = std::exp(k * zb);
    return;
  }
  // finite depth Airy profile, 1 at the surface
  double kd = k * depth, kz = k * (zb + depth);
  if (kd < 20) {
    *fh = std::cosh(kz) / std::cosh(kd);
    *fz = std::sinh(kz) / std::sinh(kd);
  } else {
    // cosh, sinh overflow past 710 (inf / inf = NaN, e.g. a 7 m chop in
    // 1000 m of water); the same ratios as e^(kz-kd) (1 +- e^-2kz) / (1 +- e^-2kd)
    double e = std::exp(kz - kd), z2 = std::exp(-2 * kz), d2 = std::exp(-2 * kd);
    *fh = e * (1 + z2) / (1 + d2);
    *fz = e * (1 - z2) / (1 - d2);
  }
}

void Sea::now(double t, WaveNow* w) const {
  for (size_t i = 0; i < waves.size(); i++) {
    const Wave& W = waves[i];
    double qa = W.steep * W.amp;
    w[i] = WaveNow{W.k, W.dx, W.dy, W.omega * t, W.ph, qa * W.dx, qa * W.dy, qa * W.k,
                   W.amp, qa * W.omega, W.amp * W.omega};
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
                     double* sc, double* tmp) {
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
  for (int it = 0; it < 50 && r2 > 1e-24; it++) {
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
    if (r2 >= prev) break;  // no further progress in double
  }
  double z = level;
  for (int i = 0; i < n; i++) z += w[i].amp * cur[2 * i + 1];
  if (N > 0) {
    for (int i = 0; i < 2 * n; i++) sc[i] = cur[i];
  }
  return z;
}

double Sea::solve(const WaveNow* w, double x, double y, double a[2], double* sc,
                  double* tmp) const {
  const int n = waves.size();
  switch (n) {
    case 0: return level;
    case 1: return solveN<1>(w, n, level, x, y, a, sc, tmp);
    case 2: return solveN<2>(w, n, level, x, y, a, sc, tmp);
    case 3: return solveN<3>(w, n, level, x, y, a, sc, tmp);
    case 4: return solveN<4>(w, n, level, x, y, a, sc, tmp);
    default: return solveN<0>(w, n, level, x, y, a, sc, tmp);
  }
}

void Sea::solveMany(const WaveNow* w, int m, const double* x, const double* y, double* a0,
                    double* a1, double* z, double* sc, double* tmp) const {
  // one point after the other: a lockstep version over SSE2 lanes (the
  // masked Newton updates in GCC vector types) measured no faster, the
  // out-of-order core already overlaps the independent solves
  const int n = waves.size();
  for (int i = 0; i < m; i++) {
    double a[2] = {a0[i], a1[i]};
    z[i] = solve(w, x[i], y[i], a, sc + 2 * n * i, tmp);
    a0[i] = a[0];
    a1[i] = a[1];
  }
}

void Sea::velocitySC(const WaveNow* w, const double* sc, double zb, double v[3]) const {
  v[0] = current[0];
  v[1] = current[1];
  v[2] = 0;
  if (depth > 0) zb = std::fmax(zb, -depth);
  for (size_t i = 0; i < waves.size(); i++) {
    double uh = w[i].qao * sc[2 * i + 1];
    double uz = w[i].ao * sc[2 * i];
    double fh, fz;
    depthRatios(w[i].k, zb, &fh, &fz);
    v[0] += uh * fh * w[i].dx;
    v[1] += uh * fh * w[i].dy;
    v[2] += uz * fz;
  }
}

}  // namespace mjb
