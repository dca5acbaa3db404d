// sea surface: Gerstner height by inverting the horizontal displacement
#include "sea.h"

#include <cmath>

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
      if (kd < 20) {
        fh = std::cosh(kz) / std::cosh(kd);
        fz = std::sinh(kz) / std::sinh(kd);
      } else {
        // cosh, sinh overflow past 710 (inf / inf = NaN, e.g. 1 m waves in
        // 200 m of water); the same ratios as e^(kz-kd) (1 +- e^-2kz) / (1 +- e^-2kd)
        double e = std::exp(kz - kd), z2 = std::exp(-2 * kz), d2 = std::exp(-2 * kd);
        fh = e * (1 + z2) / (1 + d2);
        fz = e * (1 - z2) / (1 - d2);
      }
    } else {
      fh = fz = std::exp(w.k * zb);
    }
    v[0] += uh * fh * w.dx;
    v[1] += uh * fh * w.dy;
    v[2] += uz * fz;
  }
}

}  // namespace mjb
