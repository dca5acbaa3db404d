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
    if (depth > 0) {
      // finite depth Airy profile, 1 at the surface
      double kd = w.k * depth, kz = w.k * (zb + depth);
      fh = std::cosh(kz) / std::cosh(kd);
      fz = std::sinh(kz) / std::sinh(kd);
    } else {
      fh = fz = std::exp(w.k * zb);
    }
    v[0] += uh * fh * w.dx;
    v[1] += uh * fh * w.dy;
    v[2] += uz * fz;
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
// caller evaluates the phase directly
static const double kShift = 0.05;
static inline void shift(double s, double c, double d, double* out) {
  double d2 = d * d;
  double sd = d * (1 + d2 * (-1.0 / 6 + d2 * (1.0 / 120 + d2 * (-1.0 / 5040 + d2 * (1.0 / 362880)))));
  double cm = d2 * (-0.5 + d2 * (1.0 / 24 + d2 * (-1.0 / 720 + d2 * (1.0 / 40320 +
                                                                      d2 * (-1.0 / 3628800)))));
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

// solveMany() for N components on one block of nb <= kBlock points, four
// lanes at a time in GCC vector types (SSE2 pairs on any x86-64; GCC's
// if-conversion does not vectorise the masked updates from plain loops)
static const int kBlock = 32;
// static helpers only: the AVX-argument ABI note does not concern callers
#pragma GCC diagnostic ignored "-Wpsabi"
typedef double vd __attribute__((vector_size(32)));
typedef long long vm __attribute__((vector_size(32)));

static inline vd ld(const double* p) {
  vd v;
  std::memcpy(&v, p, sizeof(v));
  return v;
}
static inline void st(double* p, vd v) { std::memcpy(p, &v, sizeof(v)); }

template <int N>
static void solveBlock(const WaveNow* w, int nb, double level, const double* x,
                       const double* y, double* a0, double* a1, double* z, double* sc,
                       double* redo) {
  double X[kBlock], Y[kBlock], A0[kBlock], A1[kBlock], S[N][kBlock], C[N][kBlock];
  double F0[kBlock], F1[kBlock], J00[kBlock], J01[kBlock], J11[kBlock], R2[kBlock];
  double bad[kBlock];
  const int nv = (nb + 3) / 4 * 4;
  for (int i = 0; i < nv; i++) {
    // padding lanes: converged at the origin
    X[i] = i < nb ? x[i] : 0;
    Y[i] = i < nb ? y[i] : 0;
    A0[i] = i < nb ? a0[i] : 0;
    A1[i] = i < nb ? a1[i] : 0;
    bad[i] = i < nb ? 0 : 1;
  }
  for (int j = 0; j < N; j++) {
    for (int i = 0; i < nv; i++) {
      double th = w[j].k * (w[j].dx * A0[i] + w[j].dy * A1[i]) - w[j].wt + w[j].ph;
      S[j][i] = std::sin(th);
      C[j][i] = std::cos(th);
    }
  }
  // residual and Jacobian at the guess (the arithmetic of solveN's eval)
  for (int i = 0; i < nv; i++) {
    double f0 = A0[i] - X[i], f1 = A1[i] - Y[i], j00 = 1, j01 = 0, j11 = 1;
    for (int j = 0; j < N; j++) {
      f0 -= w[j].qx * S[j][i];
      f1 -= w[j].qy * S[j][i];
      double jc = w[j].qk * C[j][i];
      j00 -= jc * w[j].dx * w[j].dx;
      j01 -= jc * w[j].dx * w[j].dy;
      j11 -= jc * w[j].dy * w[j].dy;
    }
    F0[i] = f0; F1[i] = f1; J00[i] = j00; J01[i] = j01; J11[i] = j11;
    R2[i] = f0 * f0 + f1 * f1;
  }
  // full Newton steps in lockstep; a point is done when converged, and
  // marked for redo when solveN would halve the step or evaluate the phase
  // directly (the step fails to reduce |F|, or |d| >= kShift)
  const vd one = {1, 1, 1, 1};
  for (int it = 0; it < 50; it++) {
    vm any = {0, 0, 0, 0};
    for (int i = 0; i < nv; i += 4) {
      vd a0v = ld(A0 + i), a1v = ld(A1 + i), r2o = ld(R2 + i), bd = ld(bad + i);
      vd f0o = ld(F0 + i), f1o = ld(F1 + i);
      vd j00o = ld(J00 + i), j01o = ld(J01 + i), j11o = ld(J11 + i);
      vm act = (r2o > 1e-24) & (bd == 0);
      vd det = j00o * j11o - j01o * j01o;
      vd s0 = (j11o * f0o - j01o * f1o) / det;
      vd s1 = (j00o * f1o - j01o * f0o) / det;
      vd b0 = a0v - s0, b1 = a1v - s1;
      vd e0 = b0 - a0v, e1 = b1 - a1v;
      vd f0 = b0 - ld(X + i), f1 = b1 - ld(Y + i), j00 = one, j01 = one - one, j11 = one;
      vm near = ~(act & 0);
      vd ns[N], nc[N];
      for (int j = 0; j < N; j++) {
        vd d = w[j].k * (w[j].dx * e0 + w[j].dy * e1);
        near &= (d < kShift) & (d > -kShift);
        vd d2 = d * d;
        vd sd = d * (1 + d2 * (-1.0 / 6 + d2 * (1.0 / 120 + d2 * (-1.0 / 5040 + d2 * (1.0 / 362880)))));
        vd cm = d2 * (-0.5 + d2 * (1.0 / 24 + d2 * (-1.0 / 720 + d2 * (1.0 / 40320 +
                                                                      d2 * (-1.0 / 3628800)))));
        vd sv = ld(S[j] + i), cv = ld(C[j] + i);
        ns[j] = sv + (sv * cm + cv * sd);
        nc[j] = cv + (cv * cm - sv * sd);
        f0 -= w[j].qx * ns[j];
        f1 -= w[j].qy * ns[j];
        vd jc = w[j].qk * nc[j];
        j00 -= jc * w[j].dx * w[j].dx;
        j01 -= jc * w[j].dx * w[j].dy;
        j11 -= jc * w[j].dy * w[j].dy;
      }
      vd r2 = f0 * f0 + f1 * f1;
      vm ok = act & near & (r2 < r2o);
      st(bad + i, (act & ~ok) ? one : bd);
      st(A0 + i, ok ? b0 : a0v);
      st(A1 + i, ok ? b1 : a1v);
      for (int j = 0; j < N; j++) {
        st(S[j] + i, ok ? ns[j] : ld(S[j] + i));
        st(C[j] + i, ok ? nc[j] : ld(C[j] + i));
      }
      st(F0 + i, ok ? f0 : f0o);
      st(F1 + i, ok ? f1 : f1o);
      st(J00 + i, ok ? j00 : j00o);
      st(J01 + i, ok ? j01 : j01o);
      st(J11 + i, ok ? j11 : j11o);
      st(R2 + i, ok ? r2 : r2o);
      any |= ok;
    }
    if (!(any[0] | any[1] | any[2] | any[3])) break;
  }
  for (int i = 0; i < nb; i++) {
    redo[i] = bad[i];
    if (bad[i] != 0) continue;  // the guess stays in a0, a1 for the redo
    a0[i] = A0[i];
    a1[i] = A1[i];
    double h = level;
    for (int j = 0; j < N; j++) {
      h += w[j].amp * C[j][i];
      sc[2 * (N * i + j)] = S[j][i];
      sc[2 * (N * i + j) + 1] = C[j][i];
    }
    z[i] = h;
  }
}

template <int N>
static void solveBlocks(const Sea& sea, const WaveNow* w, int m, const double* x,
                        const double* y, double* a0, double* a1, double* z, double* sc,
                        double* tmp) {
  double redo[kBlock];
  for (int i0 = 0; i0 < m; i0 += kBlock) {
    int nb = std::min(kBlock, m - i0);
    solveBlock<N>(w, nb, sea.level, x + i0, y + i0, a0 + i0, a1 + i0, z + i0, sc + 2 * N * i0,
                  redo);
    for (int i = 0; i < nb; i++) {
      if (redo[i] == 0) continue;
      double a[2] = {a0[i0 + i], a1[i0 + i]};
      z[i0 + i] = sea.solve(w, x[i0 + i], y[i0 + i], a, sc + 2 * N * (i0 + i), tmp);
      a0[i0 + i] = a[0];
      a1[i0 + i] = a[1];
    }
  }
}

void Sea::solveMany(const WaveNow* w, int m, const double* x, const double* y, double* a0,
                    double* a1, double* z, double* sc, double* tmp) const {
  const int n = waves.size();
  switch (n) {
    case 1: return solveBlocks<1>(*this, w, m, x, y, a0, a1, z, sc, tmp);
    case 2: return solveBlocks<2>(*this, w, m, x, y, a0, a1, z, sc, tmp);
    case 3: return solveBlocks<3>(*this, w, m, x, y, a0, a1, z, sc, tmp);
    case 4: return solveBlocks<4>(*this, w, m, x, y, a0, a1, z, sc, tmp);
    default:
      for (int i = 0; i < m; i++) {
        double a[2] = {a0[i], a1[i]};
        z[i] = solve(w, x[i], y[i], a, sc + 2 * n * i, tmp);
        a0[i] = a[0];
        a1[i] = a[1];
      }
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
    if (depth > 0) {
      double kd = w[i].k * depth, kz = w[i].k * (zb + depth);
      fh = std::cosh(kz) / std::cosh(kd);
      fz = std::sinh(kz) / std::sinh(kd);
    } else {
      fh = fz = std::exp(w[i].k * zb);
    }
    v[0] += uh * fh * w[i].dx;
    v[1] += uh * fh * w[i].dy;
    v[2] += uz * fz;
  }
}

}  // namespace mjb
