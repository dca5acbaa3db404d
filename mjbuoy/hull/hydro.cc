// hydrodynamic forces per wet triangle (formulas: physics.md section 4)
#include "hull/hydro.h"

#include <cmath>

namespace mjb {

static double dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// a non-finite input (a NaN water velocity, |v|^2 overflowing) gives a NaN
// force, never a zero: the caller reports it (mjb_notices)
static void nan3(double f[3]) {
  f[0] = f[1] = f[2] = NAN;
}

// pow(x, p) for x >= 0, with the exponents of the defaults (0.5, 1, 2)
// done without the general pow, which is slow; same value to round-off
static double powp(double x, double p) {
  if (p == 0.5) return std::sqrt(x);
  if (p == 1) return x;
  if (p == 2) return x * x;
  return std::pow(x, p);
}

double ittc57(double rn) {
  double l = std::log10(std::fmax(rn, kRnMin)) - 2;
  return 0.075 / (l * l);
}

void viscousForce(double rho, double cf, double ff, double A, const double n[3],
                  const double v[3], double f[3]) {
  double vn = dot(v, n), t[3];
  for (int j = 0; j < 3; j++) t[j] = v[j] - vn * n[j];
  double v2 = dot(v, v), tl = std::sqrt(dot(t, t));
  if (!std::isfinite(v2) || !std::isfinite(A)) return nan3(f);
  // flow normal to the face (or no flow): no tangential shear
  if (!(tl > 1e-12 * std::sqrt(v2))) {
    f[0] = f[1] = f[2] = 0;
    return;
  }
  double s = -0.5 * rho * cf * ff * A * v2 / tl;
  for (int j = 0; j < 3; j++) f[j] = s * t[j];
}

void dragForce(const double drag[3], const double suction[3], double vr, double A,
               const double n[3], const double v[3], double f[3]) {
  double sp = std::sqrt(dot(v, v));
  f[0] = f[1] = f[2] = 0;
  if (!std::isfinite(sp) || !std::isfinite(A)) return nan3(f);
  if (!(sp > 0)) return;
  double c = dot(v, n) / sp, u = sp / vr, s;
  if (c > 0) {
    s = -(drag[0] * u + drag[1] * u * u) * A * powp(c, drag[2]);
  } else if (c < 0) {
    s = (suction[0] * u + suction[1] * u * u) * A * powp(-c, suction[2]);
  } else {
    return;
  }
  for (int j = 0; j < 3; j++) f[j] = s * n[j];
}

void slamForce(double gain, double gmax, double p, double mass, double shull, double S,
               double A, const double v[3], const double q[3], const double qprev[3],
               const double n[3], double dt, double f[3]) {
  f[0] = f[1] = f[2] = 0;
  double sp = std::sqrt(dot(v, v));
  if (!(gain > 0) || !(dt > 0)) return;
  if (!std::isfinite(sp) || !std::isfinite(A)) return nan3(f);
  if (!(sp > 0) || !(A > 0)) return;
  double c = dot(v, n) / sp;
  if (!(c > 0)) return;
  double dq[3];
  for (int j = 0; j < 3; j++) dq[j] = q[j] - qprev[j];
  double gamma = std::sqrt(dot(dq, dq)) / (S * dt);
  double r = std::fmin(gamma / gmax, 1.0);
  double s = -gain * powp(r, p) * c * mass * 2 * A / shull / dt;
  for (int j = 0; j < 3; j++) f[j] = s * v[j];
}

}  // namespace mjb
