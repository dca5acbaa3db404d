// finite-depth free-surface Green function (docs/physics.md section 13,
// "Finite depth")
#include "radiation/greenfd.h"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "sea/spectra.h"

namespace mjb {

namespace {

const double kPi = 3.14159265358979323846;
const int kFitPts = 4000;      // samples of the remainder in x = k h
const double kFitMax = 2000;   // ... on [0, kFitMax], x = kFitMax t^3
const double kBmin = 0.01, kBmax = 40;  // exponents b_j, geometric (at least)

// the kernel's remainder at x = k h (nu = K h, x0 = k0 h, gam = c h):
//   Phi(x) - 1 - gam / (x - x0) - (2 nu - gam) (1 - e^-x) / x,
//   Phi = (x + nu) / ((x - nu) - (x + nu) e^{-2x}),
// smooth on [0, inf) (Phi's only pole is x0, residue gam), O(1/x^2)
double remainder(double x, double nu, double x0, double gam) {
  double phi = (x + nu) / ((x - nu) - (x + nu) * std::exp(-2 * x));
  double g = x > 1e-12 ? -std::expm1(-x) / x : 1.0;
  return phi - 1 - gam / (x - x0) - (2 * nu - gam) * g;
}

// int_0^inf (1 - e^{-k b}) / k e^{k v} J0(k R) dk = int_0^b ds / sqrt(R^2 + (v - s)^2)
// (v <= 0) and its derivatives by R and v
void logPart(double R, double v, double b, double* L, double* LR, double* Lv) {
  double u1 = -v, u2 = b - v;
  double s1 = std::sqrt(R * R + u1 * u1), s2 = std::sqrt(R * R + u2 * u2);
  *L = std::log((u2 + s2) / (u1 + s1));
  // -(1/R) [u / s] from u1 to u2, with u / s - 1 = -R^2 / (s (u + s))
  *LR = R / (s2 * (u2 + s2)) - R / (s1 * (u1 + s1));
  *Lv = 1 / s1 - 1 / s2;
}

// F and FX beyond the table (Y > kFarY): the e^-Y terms of green.h's
// F = -(pi/2) e^-Y (H0 + Y0) - I, FX = -e^-Y (...) + J are below 1e-17 and
// dropped; I = int_0^Y e^(s-Y) / sqrt(X^2 + s^2) ds by parts from the upper
// end, sum_n (-1)^n d^n/dY^n (1/rho) = sum_n n! P_n(mu) / rho^(n+1) (mu =
// Y / rho, Legendre's generating function), and J = -dI/dX = sum_n n! X
// P'_(n+1)(mu) / rho^(n+3) (d/dX of the solid harmonic). Asymptotic: 13
// terms leave 13! / rho^13 of I, 1e-11 at rho = 40. An image this far
// below costs no quadrature
const double kFarY = 40;
void farWave(double X, double Y, double* F, double* FX) {
  const double rho = std::sqrt(X * X + Y * Y), mu = Y / rho;
  double p0 = 1, p1 = mu, d1 = 1;  // P_n, P_(n+1), P'_(n+1) at n = 0
  double fac = 1, rn = 1 / rho, I = 0, J = 0;  // n!, 1 / rho^(n+1)
  for (int n = 0; n <= 12; n++) {
    I += fac * p0 * rn;
    J += fac * X * d1 * rn / (rho * rho);
    // P_(n+2) = ((2n+3) mu P_(n+1) - (n+1) P_n) / (n+2); P'_(n+2) = mu P'_(n+1) + (n+2) P_(n+1)
    double p2 = ((2 * n + 3) * mu * p1 - (n + 1) * p0) / (n + 2);
    d1 = mu * d1 + (n + 2) * p1;
    p0 = p1;
    p1 = p2;
    fac *= n + 1;
    rn /= rho;
  }
  *F = -I;
  *FX = J;
}

}  // namespace

bool greenFdInit(double K, double h, GreenFd* g) {
  g->K = K;
  g->h = h;
  g->k0 = waveNumber(std::sqrt(K), 1.0, h);  // omega^2 / g = K with g = 1
  double k0 = g->k0;
  // residue of (k + K) / ((k - K) - (k + K) e^{-2kh}) at k0, using
  // e^{-2 k0 h} = (k0 - K) / (k0 + K)
  g->c = (k0 + K) * (k0 + K) / (2 * K + 2 * h * (k0 * k0 - K * K));
  double nu = K * h, x0 = k0 * h, gam = g->c * h;
  // least squares on fixed exponents, weights sqrt(dx): the integral of
  // the error over k bounds the error of the potential at R = v = 0
  std::vector<double> xs;
  for (int i = 0; i < kFitPts; i++) {
    double t = (double)i / (kFitPts - 1), x = kFitMax * t * t * t;
    if (std::fabs(x - x0) > 1e-4 * (1 + x0)) xs.push_back(x);
  }
  int n = (int)xs.size();
  Eigen::MatrixXd A(n, kProny);
  Eigen::VectorXd y(n);
  // long waves (x0 = k0 h small): the remainder varies on the scale x0,
  // which exponents up to 4 / x0 resolve (integrated error under 1e-4 / h
  // down to K h = 1e-5)
  double bmax = std::fmax(kBmax, 4 / x0);
  for (int j = 0; j < kProny; j++) g->b[j] = kBmin * std::pow(bmax / kBmin, j / (kProny - 1.0));
  for (int i = 0; i < n; i++) {
    double dx = (i + 1 < n ? xs[i + 1] : xs[i]) - (i > 0 ? xs[i - 1] : xs[i]);
    double w = std::sqrt(0.5 * dx + 1e-12);
    y(i) = w * remainder(xs[i], nu, x0, gam);
    for (int j = 0; j < kProny; j++) A(i, j) = w * std::exp(-g->b[j] * xs[i]);
  }
  Eigen::BDCSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
  svd.setThreshold(1e-14);
  Eigen::VectorXd a = svd.solve(y);
  bool ok = std::isfinite(g->c) && std::isfinite(k0);
  for (int j = 0; j < kProny; j++) {
    g->a[j] = a(j);
    ok = ok && std::isfinite(a(j));
  }
  return ok;
}

WaveFd greenFdWave(const GreenFd& g, const GreenTable* tab, double R, double z, double zeta) {
  typedef std::complex<double> cplx;
  const double h = g.h, k0 = g.k0, c = g.c, tail = 2 * g.K - g.c;
  // the four images' vertical offsets and dv/dz
  const double v[4] = {z + zeta, -(z + zeta) - 4 * h, z - zeta - 2 * h, -(z - zeta) - 2 * h};
  const double sv[4] = {1, -1, 1, -1};
  WaveFd o{0, 0, 0};
  // 1/r2, the image in the seabed, at zeta' = -2h - zeta
  double u = z + zeta + 2 * h, r2 = std::sqrt(R * R + u * u), r3 = r2 * r2 * r2;
  o.G += 1 / r2;
  o.GR += -R / r3;
  o.Gz += -u / r3;
  for (int i = 0; i < 4; i++) {
    double vi = std::fmin(v[i], 0.0);
    double Gv = 0, GR = 0, Gvi = 0;  // real parts: value, d/dR, d/dv
    if (i > 0) {
      double r = std::sqrt(R * R + vi * vi), rr = r * r * r;
      Gv += 1 / r;
      GR += -R / rr;
      Gvi += -vi / rr;
    }
    double X = k0 * R, Y = -k0 * vi;
    WaveF f;
    if (Y > kFarY) {
      farWave(X, Y, &f.F, &f.FX);
      f.FY = -f.F - 1 / std::sqrt(X * X + Y * Y);
      f.J0 = f.J1 = 0;  // times e^-Y: below 1e-17
    } else {
      f = greenWaveTab(tab, X, Y);
    }
    double e = std::exp(k0 * vi);
    Gv += c * f.F;
    GR += c * k0 * f.FX;
    Gvi += -c * k0 * f.FY;
    double L, LR, Lv;
    logPart(R, vi, h, &L, &LR, &Lv);
    Gv += tail * L;
    GR += tail * LR;
    Gvi += tail * Lv;
    for (int j = 0; j < kProny; j++) {
      double w = g.b[j] * h - vi, r = std::sqrt(R * R + w * w), rr = r * r * r;
      Gv += g.a[j] / r;
      GR += -g.a[j] * R / rr;
      Gvi += g.a[j] * w / rr;
    }
    double im = kPi * c * e;
    o.G += cplx(Gv, im * f.J0);
    o.GR += cplx(GR, -im * k0 * f.J1);
    o.Gz += sv[i] * cplx(Gvi, im * k0 * f.J0);
  }
  return o;
}

void greenFdInfinite(double h, double dx, double dy, double z, double zeta, double* G,
                     double grad[3]) {
  // the terms m and -m together fall as zeta z / (|m| h)^3 and alternate in
  // sign: the error is below the first pair left out (1e-5 zeta z / h^3 at
  // kM = 30)
  const int kM = 30;
  double R2 = dx * dx + dy * dy, s = 0, gR = 0, gz = 0;
  for (int m = -kM; m <= kM; m++) {
    if (m == 0) continue;
    double sg = (m % 2) ? -1.0 : 1.0;
    double p[2] = {zeta + 2 * m * h, -zeta + 2 * m * h}, q[2] = {1, -1};
    for (int k = 0; k < 2; k++) {
      double w = z - p[k], r = std::sqrt(R2 + w * w), r3 = r * r * r;
      s += sg * q[k] / r;
      gR += -sg * q[k] / r3;  // times dx, dy below
      gz += -sg * q[k] * w / r3;
    }
  }
  *G = s;
  grad[0] = gR * dx;
  grad[1] = gR * dy;
  grad[2] = gz;
}

void depthFactor(double k, double h, double z, double* f, double* fz) {
  if (!(h > 0)) {
    *f = *fz = std::exp(k * z);
    return;
  }
  // cosh(k (z+h)) / cosh(k h) = e^{kz} (1 + e^{-2k(z+h)}) / (1 + e^{-2kh}):
  // no overflow at large k h
  double e = std::exp(k * z), a = std::exp(-2 * k * (z + h)), b = std::exp(-2 * k * h);
  *f = e * (1 + a) / (1 + b);
  *fz = e * (1 - a) / (1 + b);
}

}  // namespace mjb
