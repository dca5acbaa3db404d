// deep-water free-surface Green function (docs/physics.md section 13)
#include "green.h"

#include <cmath>

#include "gauss.h"

namespace mjb {

namespace {

const double kPi = 3.14159265358979323846;
const double kSeries = 12;  // Struve: power series below (< 3 digits lost)
const double kBig = 25;     // quadrature below, asymptotic series above

// int_0^{pi/2} f(theta) dtheta by composite Gauss-Legendre, 4 x 16 points
template <class Fn>
double quarterTurn(Fn f) {
  const GaussRule& g = gaussRule(16);
  double h = 0.5 * kPi / 4, s = 0;
  for (int p = 0; p < 4; p++) {
    for (int i = 0; i < g.n; i++) {
      double t = h * (p + 0.5 * (g.x[i] + 1));
      s += 0.5 * h * g.w[i] * f(t);
    }
  }
  return s;
}

// I(X, Y) = int_0^Y e^(s-Y) / sqrt(X^2 + s^2) ds and
// J(X, Y) = X int_0^Y e^(s-Y) / (X^2 + s^2)^{3/2} ds; with s = X sinh(t)
// both are smooth on [0, asinh(Y/X)]: composite 8-point rules
void surfaceIntegrals(double X, double Y, double* I, double* J) {
  const GaussRule& g = gaussRule(8);
  double T = std::asinh(Y / X);
  int np = (int)std::ceil(T / 0.5) + 1;
  double h = T / np, si = 0, sj = 0;
  for (int p = 0; p < np; p++) {
    for (int i = 0; i < g.n; i++) {
      double t = h * (p + 0.5 * (g.x[i] + 1));
      double c = std::cosh(t);
      double e = 0.5 * h * g.w[i] * std::exp(X * std::sinh(t) - Y);
      si += e;
      sj += e / (c * c);
    }
  }
  *I = si;
  *J = sj / X;
}

}  // namespace

double struveH0(double x) {
  if (x > kBig) {
    // A&S 12.1.31 (H0 - Y0)
    double u = 1 / (x * x);
    double d = (2 / kPi) / x * (1 - u * (1 - u * (9 - u * (225 - u * 11025))));
    return std::cyl_neumann(0.0, x) + d;
  }
  if (x <= kSeries) {
    // A&S 12.1.3: (2/pi) sum (-1)^k x^{2k+1} / ((2k+1)!!)^2
    double t = x, s = x, x2 = x * x;
    for (int k = 1; k < 60 && std::fabs(t) > 1e-17 * std::fabs(s); k++) {
      t *= -x2 / ((2 * k + 1.0) * (2 * k + 1.0));
      s += t;
    }
    return (2 / kPi) * s;
  }
  return (2 / kPi) * quarterTurn([x](double t) { return std::sin(x * std::cos(t)); });
}

double struveH1(double x) {
  if (x > kBig) {
    double u = 1 / (x * x);
    double d = (2 / kPi) * (1 + u * (1 - u * (3 - u * (45 - u * 1575))));
    return std::cyl_neumann(1.0, x) + d;
  }
  if (x <= kSeries) {
    // A&S 12.1.3: (2/pi) sum (-1)^k x^{2k+2} / ((2k+1)!! (2k+3)!!)
    double x2 = x * x, t = x2 / 3, s = t;
    for (int k = 1; k < 60 && std::fabs(t) > 1e-17 * std::fabs(s); k++) {
      t *= -x2 / ((2 * k + 1.0) * (2 * k + 3.0));
      s += t;
    }
    return (2 / kPi) * s;
  }
  return (2 * x / kPi) * quarterTurn([x](double t) {
    double s = std::sin(t);
    return std::sin(x * std::cos(t)) * s * s;
  });
}

WaveF greenWave(double X, double Y) {
  WaveF r;
  double ey = std::exp(-Y);
  double rho = std::sqrt(X * X + Y * Y);
  if (X < 1e-9 * (1 + Y)) {
    // on the axis: PV int e^{-uY}/(u-1) du = -e^{-Y} Ei(Y); dF/dX = 0
    r.F = -ey * std::expint(Y);
    r.FX = 0;
  } else {
    double I = 0, J = 0;
    if (Y > 0) surfaceIntegrals(X, Y, &I, &J);
    double y0 = std::cyl_neumann(0.0, X), y1 = std::cyl_neumann(1.0, X);
    r.F = -0.5 * kPi * ey * (struveH0(X) + y0) - I;
    // d/dX (H0 + Y0) = 2/pi - H1 - Y1 (A&S 12.1.10 and 9.1.28)
    r.FX = -ey * (1 - 0.5 * kPi * (struveH1(X) + y1)) + J;
  }
  // dF/dZ = F + 1/rho with Z = -Y
  r.FY = -r.F - 1 / rho;
  return r;
}

}  // namespace mjb
