// deep-water free-surface Green function (docs/physics.md section 13)
#include "radiation/green.h"

#include <cmath>

#include "util/gauss.h"

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
  // the exponent X sinh(t) - Y rises by Y over [0, T]: pieces of at most
  // 0.75 in t and 3 in the exponent keep the 8-point rule near 1e-9
  int np = 1 + (int)(T / 0.75) + (int)(Y / 3);
  double h = T / np, si = 0, sj = 0;
  for (int p = 0; p < np; p++) {
    for (int i = 0; i < g.n; i++) {
      double t = h * (p + 0.5 * (g.x[i] + 1));
      double et = std::exp(t), sh = 0.5 * (et - 1 / et), c = 0.5 * (et + 1 / et);
      double e = 0.5 * h * g.w[i] * std::exp(X * sh - Y);
      si += e;
      sj += e / (c * c);
    }
  }
  *I = si;
  *J = sj / X;
}

// I and J for Y > kDeep by parts from the upper end, int_0^Y e^(s-Y) f ds
// = f(Y) - f'(Y) + f''(Y) - f'''(Y) + O(4! / rho^5) (terms of e^-Y
// dropped): a body kDeep / K below the surface (docs/physics.md section 14,
// "Deep bodies"), where the quadrature would need Y / 3 pieces
const double kDeep = 100;
void deepIntegrals(double X, double Y, double* I, double* J) {
  const double r2 = X * X + Y * Y, r = std::sqrt(r2), r3 = r2 * r, r5 = r3 * r2, r7 = r5 * r2;
  const double X2 = X * X, Y2 = Y * Y;
  *I = 1 / r + Y / r3 + (2 * Y2 - X2) / r5 + 3 * Y * (2 * Y2 - 3 * X2) / r7;
  *J = X / r3 + 3 * X * Y / r5 - 3 * X * (X2 - 4 * Y2) / r7;
}

}  // namespace

void bessel01(double x, double* j0, double* j1, double* y0, double* y1) {
  if (x < 8) {
    // J0 = sum (-q)^k / k!^2, J1 = (x/2) sum (-q)^k / (k! (k+1)!), q = x^2/4;
    // Y0 = (2/pi)((ln(x/2) + gamma) J0 + sum (-1)^{k+1} H_k q^k / k!^2),
    // Y1 = -2/(pi x) + (2/pi) ln(x/2) J1
    //      - (x/2)/pi sum (-q)^k (psi(k+1) + psi(k+2)) / (k! (k+1)!)
    const double g = 0.57721566490153286;
    double q = 0.25 * x * x, t0 = 1, t1 = 1, a0 = 1, a1 = 1, hk = 0, s0 = 0;
    double psi1 = -g, psi2 = 1 - g;  // psi(k+1), psi(k+2) at k = 0
    double s1 = psi1 + psi2;
    for (int k = 1; k < 40; k++) {
      t0 *= -q / ((double)k * k);
      t1 *= -q / ((double)k * (k + 1));
      hk += 1.0 / k;
      psi1 += 1.0 / k;
      psi2 += 1.0 / (k + 1);
      a0 += t0;
      a1 += t1;
      s0 -= t0 * hk;
      s1 += t1 * (psi1 + psi2);
      if (std::fabs(t0) + std::fabs(t1) < 1e-17) break;
    }
    double l = std::log(0.5 * x);
    *j0 = a0;
    *j1 = 0.5 * x * a1;
    *y0 = (2 / kPi) * ((l + g) * a0 + s0);
    *y1 = -2 / (kPi * x) + (2 / kPi) * l * (*j1) - 0.5 * x / kPi * s1;
    return;
  }
  // P, Q of order nu: a_k = prod_{m<=k} (4 nu^2 - (2m-1)^2) / (k! 8^k)
  double p[2], qq[2];
  for (int nu = 0; nu < 2; nu++) {
    double mu = 4.0 * nu * nu, a = 1, P = 1, Q = 0, prev = 1e300;
    for (int k = 1; k < 30; k++) {
      a *= (mu - (2 * k - 1.0) * (2 * k - 1.0)) / (k * 8.0 * x);
      if (std::fabs(a) > prev) break;  // asymptotic: stop at the smallest term
      prev = std::fabs(a);
      // terms k: sign (-1)^{k/2} into P (k even) or (-1)^{(k-1)/2} into Q
      if (k % 2 == 0)
        P += ((k / 2) % 2 ? -a : a);
      else
        Q += (((k - 1) / 2) % 2 ? -a : a);
      if (prev < 1e-17) break;
    }
    p[nu] = P;
    qq[nu] = Q;
  }
  double r = std::sqrt(2 / (kPi * x));
  double c0 = x - 0.25 * kPi, c1 = x - 0.75 * kPi;
  *j0 = r * (p[0] * std::cos(c0) - qq[0] * std::sin(c0));
  *y0 = r * (p[0] * std::sin(c0) + qq[0] * std::cos(c0));
  *j1 = r * (p[1] * std::cos(c1) - qq[1] * std::sin(c1));
  *y1 = r * (p[1] * std::sin(c1) + qq[1] * std::cos(c1));
}

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
  // the axis form only where X is negligible next to Y: at Y = 0 (two
  // points on the free surface) Ei(0) is infinite while F(X, 0) is finite
  // for every X > 0, and a long wave (omega 1e-3 rad/s: K = 1e-7 / m) makes
  // X = K R below any absolute threshold
  if (X == 0 || X < 1e-9 * Y) {
    // on the axis: PV int e^{-uY}/(u-1) du = -e^{-Y} Ei(Y); dF/dX = 0
    if (Y > kDeep) {
      // e^-Y Ei(Y) = sum k! / Y^(k+1) asymptotically (A&S 5.1.51); Ei overflows
      double t = 1 / Y, sum = 0;
      for (int k = 0; k < 12; k++) sum += t, t *= (k + 1) / Y;
      r.F = -sum;
    } else {
      r.F = -ey * std::expint(Y);
    }
    r.FX = 0;
    r.J0 = 1;
    r.J1 = 0;
  } else {
    double I = 0, J = 0;
    if (Y > kDeep) {
      deepIntegrals(X, Y, &I, &J);
    } else if (Y > 0) {
      surfaceIntegrals(X, Y, &I, &J);
    }
    double y0, y1;
    bessel01(X, &r.J0, &r.J1, &y0, &y1);
    r.F = -0.5 * kPi * ey * (struveH0(X) + y0) - I;
    // d/dX (H0 + Y0) = 2/pi - H1 - Y1 (A&S 12.1.10 and 9.1.28)
    r.FX = -ey * (1 - 0.5 * kPi * (struveH1(X) + y1)) + J;
  }
  // dF/dZ = F + 1/rho with Z = -Y
  r.FY = -r.F - 1 / rho;
  return r;
}

}  // namespace mjb
