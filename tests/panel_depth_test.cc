// the panel solver in water of finite depth (docs/physics.md section 13,
// "Finite depth"): the Green function against John's eigenfunction series
// (an independent evaluation), the solver against its deep-water solution
// as the depth grows, and Haskind's relation with the finite-depth group
// velocity (radiation against diffraction)
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "radiation/greenfd.h"
#include "radiation/panel.h"
#include "radiation/panelmesh.h"
#include "sea/spectra.h"

namespace {

using mjb::HydroCoef;
using mjb::PanelMesh;
typedef std::complex<double> cplx;

const double kPi = 3.14159265358979323846;
const double kRho = 1000, kG = 9.81;

// John (1950) "On the motion of floating bodies II", Comm. Pure Appl. Math.
// 3:45-101, eq. (13.19) of Wehausen and Laitone (1960) "Surface waves",
// Handbuch der Physik 9, in the e^{-i omega t} convention (outgoing H0^(1)):
//   G = 2 pi C0 cosh k0(z+h) cosh k0(zeta+h) (i J0(k0 R) - Y0(k0 R))
//     + 4 sum_n Cn cos kn(z+h) cos kn(zeta+h) K0(kn R),
//   C0 = (k0^2 - K^2) / ((k0^2 - K^2) h + K), Cn = (kn^2 + K^2) / ((kn^2 + K^2) h - K),
//   k0 tanh(k0 h) = K, kn tan(kn h) = -K, kn h in ((n - 1/2) pi, n pi);
// with its R and z derivatives. Converges as e^{-n pi R / h}: R >= 0.05 h
struct John {
  cplx G, GR, Gz;
};
John johnSeries(double K, double h, double R, double z, double zeta) {
  double k0 = mjb::waveNumber(std::sqrt(K * kG), kG, h);
  // k0^2 - K^2 = k0^2 / cosh^2(k0 h) (K = k0 tanh k0 h): no cancellation at large k0 h
  double ch = std::cosh(k0 * h), dk = k0 * k0 / (ch * ch);
  double C0 = dk / (dk * h + K);
  double cz = std::cosh(k0 * (z + h)), sz = std::sinh(k0 * (z + h)), cs = std::cosh(k0 * (zeta + h));
  double j0 = std::cyl_bessel_j(0, k0 * R), j1 = std::cyl_bessel_j(1, k0 * R);
  double y0 = std::cyl_neumann(0, k0 * R), y1 = std::cyl_neumann(1, k0 * R);
  John o;
  o.G = 2 * kPi * C0 * cz * cs * cplx(-y0, j0);
  o.GR = 2 * kPi * C0 * cz * cs * k0 * cplx(y1, -j1);
  o.Gz = 2 * kPi * C0 * sz * cs * k0 * cplx(-y0, j0);
  for (int n = 1; n < 2000; n++) {
    // kn h by bisection: y tan y + K h rises from -inf to K h on the interval
    double lo = (n - 0.5) * kPi + 1e-12, hi = n * kPi;
    for (int it = 0; it < 100; it++) {
      double mid = 0.5 * (lo + hi);
      (mid * std::tan(mid) + K * h < 0 ? lo : hi) = mid;
    }
    double kn = 0.5 * (lo + hi) / h;
    if (kn * R > 700) break;
    double Cn = (kn * kn + K * K) / ((kn * kn + K * K) * h - K);
    double a = std::cos(kn * (z + h)), b = std::cos(kn * (zeta + h)), s = std::sin(kn * (z + h));
    double k0v = std::cyl_bessel_k(0, kn * R), k1v = std::cyl_bessel_k(1, kn * R);
    o.G += 4 * Cn * a * b * k0v;
    o.GR += -4 * Cn * a * b * kn * k1v;
    o.Gz += -4 * Cn * kn * s * b * k0v;
    if (4 * Cn * k0v < 1e-14) break;
  }
  return o;
}

// the library's G (greenfd.h plus 1/r + 1/r'), direct (no table)
John libraryG(const mjb::GreenFd& g, double R, double z, double zeta) {
  mjb::WaveFd w = mjb::greenFdWave(g, nullptr, R, z, zeta);
  double r = std::hypot(R, z - zeta), ri = std::hypot(R, z + zeta);
  John o;
  o.G = w.G + 1 / r + 1 / ri;
  o.GR = w.GR - R / (r * r * r) - R / (ri * ri * ri);
  o.Gz = w.Gz - (z - zeta) / (r * r * r) - (z + zeta) / (ri * ri * ri);
  return o;
}

// the Green function against John's series from shallow (K h = 1e-4) to
// deep (K h = 15: images beyond the table, Y > 40), points from the
// surface to near the seabed, R from 0.05 h to 3 h: value and both
// derivatives within 3e-6 of the largest (measured 1.2e-6 at most: the
// Prony fit's error, docs/physics.md section 13)
TEST(PanelDepth, GreenMatchesJohnSeries) {
  const double h = 10;
  double worst = 0;
  for (double Kh : {1e-4, 0.003, 0.1, 0.5, 1.0, 2.0, 6.0, 15.0}) {
    mjb::GreenFd g;
    ASSERT_TRUE(mjb::greenFdInit(Kh / h, h, &g));
    for (double R : {0.5, 1.5, 4.0, 12.0, 30.0})
      for (double z : {0.0, -1.0, -5.0, -9.0})
        for (double zeta : {-0.5, -3.0, -8.0}) {
          double K = Kh / h;
          John j = johnSeries(K, h, R, z, zeta), l = libraryG(g, R, z, zeta);
          double scale = std::abs(j.G) + std::abs(j.GR) * h + std::abs(j.Gz) * h;
          double e = std::max({std::abs(l.G - j.G), std::abs(l.GR - j.GR) * h,
                               std::abs(l.Gz - j.Gz) * h}) / scale;
          worst = std::max(worst, e);
          EXPECT_LT(e, 3e-6) << "Kh " << Kh << " R " << R << " z " << z << " zeta " << zeta
                             << " G " << l.G << " john " << j.G << " GR " << l.GR << " " << j.GR
                             << " Gz " << l.Gz << " " << j.Gz;
        }
  }
  std::printf("finite-depth G against John's series: worst relative error %.2e\n", worst);
}

// floating hemisphere of radius 1 (nt x na panels, lid) at depth h (0:
// deep), reference at the waterplane centre, one heading
HydroCoef solveHemi(int nt, int na, const std::vector<double>& kr, double h) {
  PanelMesh body, lid;
  mjb::hemisphereMesh(1, nt, na, &body, &lid);
  HydroCoef c;
  c.rho = kRho;
  c.g = kG;
  c.depth = h;
  std::vector<double> om;
  for (double k : kr) om.push_back(std::sqrt(k * kG));  // deep-water K a
  std::string err;
  EXPECT_TRUE(mjb::panelSolve(body, lid, om, {0.0}, &c, &err)) << err;
  return c;
}

// as the depth grows the finite-depth solution tends to the deep-water one
// (the seabed's images recede, k0 -> K): at h = 20 a every added mass,
// damping and exciting force in surge, heave and pitch within 1% of the
// deep-water solve's (of the largest entry of its kind), and closer than at
// h = 4 a
TEST(PanelDepth, DeepLimit) {
  const std::vector<double> kr = {0.3, 1.0, 2.0};
  HydroCoef d = solveHemi(8, 16, kr, 0), near = solveHemi(8, 16, kr, 4), far = solveHemi(8, 16, kr, 20);
  double en = 0, ef = 0;
  const int ij[4][2] = {{0, 0}, {2, 2}, {4, 4}, {0, 4}};
  for (int w = 0; w < d.nw(); w++) {
    for (auto& p : ij) {
      int o = 36 * w + 6 * p[0] + p[1];
      double sa = std::fabs(d.A[36 * w + 14]) + std::fabs(d.A[36 * w]);
      double sb = std::fabs(d.B[36 * w + 14]) + std::fabs(d.B[36 * w]);
      double a = std::fabs(far.A[o] - d.A[o]) / sa, b = std::fabs(far.B[o] - d.B[o]) / sb;
      EXPECT_LT(a, 0.01) << "A" << p[0] + 1 << p[1] + 1 << " kR " << kr[w];
      EXPECT_LT(b, 0.01) << "B" << p[0] + 1 << p[1] + 1 << " kR " << kr[w];
      ef = std::max({ef, a, b});
      en = std::max({en, std::fabs(near.A[o] - d.A[o]) / sa, std::fabs(near.B[o] - d.B[o]) / sb});
    }
    for (int k : {0, 2, 4}) {
      int o = 6 * w + k;
      double s = std::hypot(d.Xre[6 * w], d.Xim[6 * w]) + std::hypot(d.Xre[6 * w + 2], d.Xim[6 * w + 2]);
      double x = std::hypot(far.Xre[o] - d.Xre[o], far.Xim[o] - d.Xim[o]) / s;
      EXPECT_LT(x, 0.01) << "X" << k + 1 << " kR " << kr[w];
      ef = std::max(ef, x);
      en = std::max(en, std::hypot(near.Xre[o] - d.Xre[o], near.Xim[o] - d.Xim[o]) / s);
    }
  }
  EXPECT_LT(ef, en);
  std::printf("hemisphere, largest change from deep water: h = 4 a %.4f, h = 20 a %.5f\n", en, ef);
  for (double a : far.Ainf) (void)a;
  for (int k = 0; k < 36; k++) EXPECT_NEAR(far.Ainf[k], d.Ainf[k], 0.01 * std::fabs(d.Ainf[14]));
}

// Haskind's relation at finite depth (Newman 1977 "Marine Hydrodynamics"
// 6.19; the energy flux with the group velocity of depth h, Cg = (omega /
// 2 k0) (1 + 2 k0 h / sinh(2 k0 h))): B33 = k0 |X3|^2 / (4 rho g Cg) for an
// axisymmetric body, B33 from the radiation solve and X3 from the
// diffraction solve (incident wave cosh k0 (z + h) / cosh k0 h), within 2%
// as the deep-water test (panel_test.cc); h = 1.5 a, shallow for every
// frequency here (k0 h 0.2 to 3)
TEST(PanelDepth, HaskindShallow) {
  const double h = 1.5;
  HydroCoef c = solveHemi(10, 20, {0.1, 0.5, 1.0, 2.0}, h);
  for (int w = 0; w < c.nw(); w++) {
    double om = c.omega[w], k0 = mjb::waveNumber(om, kG, h);
    double cg = om / (2 * k0) * (1 + 2 * k0 * h / std::sinh(2 * k0 * h));
    double x2 = c.Xre[6 * w + 2] * c.Xre[6 * w + 2] + c.Xim[6 * w + 2] * c.Xim[6 * w + 2];
    double bh = k0 * x2 / (4 * kRho * kG * cg);
    EXPECT_NEAR(c.B[36 * w + 14] / bh, 1, 0.02) << "omega " << om << " k0 h " << k0 * h;
    std::printf("h = 1.5 a, k0 h %.3f: A33 %.4f B33 %.4f (rho V, rho V omega) Haskind %.4f\n", k0 * h,
                c.A[36 * w + 14] / (kRho * 2 * kPi / 3), c.B[36 * w + 14] / (kRho * 2 * kPi / 3 * om),
                c.B[36 * w + 14] / bh);
  }
}

// ---- truncated cylinder in finite depth: Yeung's eigenfunction expansion ----
// Yeung, R. W. (1981) "Added mass and damping of a vertical cylinder in
// finite-depth waters", Applied Ocean Research 3(3):119-133: heave of a
// floating cylinder (radius a, draft d, depth h) by matched eigenfunction
// expansions, an independent semi-analytic method. Interior (r < a, under
// the body, c = h - d, s = z + h): phi1 = (s^2 - r^2/2) / (2c) + sum_n A_n
// I0(l_n r) / I0(l_n a) cos(l_n s), l_n = n pi / c; exterior: phi2 = sum_m
// B_m R_m(r) / R_m(a) Z_m(s), Z_0 = cosh(k0 s), R_0 = H0^(1)(k0 r) (outgoing
// for e^{-i omega t}), Z_m = cos(k_m s), R_m = K0(k_m r). Matching phi at r = a
// (projected on cos(l_n s), s < c) and phi_r (on Z_m, s < h, phi_r = 0 on
// the side). Returns A33, B33 per rho a^3 and rho a^3 omega
void yeungHeave(double a, double d, double h, double K, int nn, int nm, double* A33, double* B33) {
  const double c = h - d;
  double k0 = mjb::waveNumber(std::sqrt(K * kG), kG, h);
  std::vector<double> km(nm), lam(nn);
  km[0] = k0;
  for (int m = 1; m < nm; m++) {
    double lo = (m - 0.5) * kPi + 1e-12, hi = m * kPi;
    for (int it = 0; it < 100; it++) {
      double mid = 0.5 * (lo + hi);
      (mid * std::tan(mid) + K * h < 0 ? lo : hi) = mid;
    }
    km[m] = 0.5 * (lo + hi) / h;
  }
  for (int n = 0; n < nn; n++) lam[n] = n * kPi / c;
  auto sgn = [](int n) { return n % 2 ? -1.0 : 1.0; };
  // L(n, m) = int_0^c Z_m cos(l_n s) ds (sin(l_n c) = 0)
  Eigen::MatrixXd L(nn, nm);
  for (int n = 0; n < nn; n++)
    for (int m = 0; m < nm; m++)
      L(n, m) = m == 0 ? k0 * std::sinh(k0 * c) * sgn(n) / (k0 * k0 + lam[n] * lam[n])
                       : km[m] * std::sin(km[m] * c) * sgn(n) / (km[m] * km[m] - lam[n] * lam[n]);
  Eigen::MatrixXcd M = Eigen::MatrixXcd::Zero(nn + nm, nn + nm);
  Eigen::VectorXcd r = Eigen::VectorXcd::Zero(nn + nm);
  // potential: A_n c eps_n - sum_m B_m L(n, m) = -int phi_p cos(l_n s) ds
  for (int n = 0; n < nn; n++) {
    M(n, n) = c * (n ? 0.5 : 1.0);
    for (int m = 0; m < nm; m++) M(n, nn + m) = -L(n, m);
    double pp = n ? 2 * c * sgn(n) / (lam[n] * lam[n]) : c * c * c / 3 - 0.5 * a * a * c;
    r(n) = -pp / (2 * c);
  }
  // velocity: B_m R_m'/R_m N_m - sum_n A_n l_n I1/I0 L(n, m) = int phi_p,r Z_m ds
  for (int m = 0; m < nm; m++) {
    double k = km[m];
    cplx ratio;
    double N;
    if (m == 0) {
      cplx h0(std::cyl_bessel_j(0, k * a), std::cyl_neumann(0, k * a));
      cplx h1(std::cyl_bessel_j(1, k * a), std::cyl_neumann(1, k * a));
      ratio = -k * h1 / h0;
      N = 0.5 * h + std::sinh(2 * k * h) / (4 * k);
    } else {
      ratio = -k * std::cyl_bessel_k(1, k * a) / std::cyl_bessel_k(0, k * a);
      N = 0.5 * h + std::sin(2 * k * h) / (4 * k);
    }
    M(nn + m, nn + m) = ratio * N;
    for (int n = 1; n < nn; n++) {
      // I1/I0 of a large argument: 1 - 1/(2x) - ... (no overflow)
      double x = lam[n] * a, q = x < 500 ? std::cyl_bessel_i(1, x) / std::cyl_bessel_i(0, x)
                                          : 1 - 0.5 / x - 0.125 / (x * x);
      M(nn + m, n) = -lam[n] * q * L(n, m);
    }
    double zi = m == 0 ? std::sinh(k * c) / k : std::sin(k * c) / k;
    r(nn + m) = -a / (2 * c) * zi;
  }
  Eigen::VectorXcd x = M.partialPivLu().solve(r);
  // int over the bottom (s = c) of phi1 2 pi r dr; A33 + i B33 / omega = rho that
  cplx f = kPi * (a * a * c * c - 0.25 * a * a * a * a) / (2 * c) + x(0) * kPi * a * a;
  for (int n = 1; n < nn; n++) {
    double xl = lam[n] * a, q = xl < 500 ? std::cyl_bessel_i(1, xl) / std::cyl_bessel_i(0, xl)
                                         : 1 - 0.5 / xl - 0.125 / (xl * xl);
    f += x(n) * (sgn(n) * 2 * kPi * a * q / lam[n]);
  }
  *A33 = f.real() / (a * a * a);
  *B33 = f.imag() / (a * a * a);
}

// the panel cylinder (radius 1, draft 0.5) at depth h: A33, B33 per rho a^3
// (and rho a^3 omega), reference at the waterplane centre
void panelCylHeave(int nz, int nr, int na, double h, const std::vector<double>& K,
                   std::vector<double>* A, std::vector<double>* B) {
  PanelMesh body, lid;
  mjb::cylinderMesh(1, 0.5, nz, nr, na, &body, &lid);
  HydroCoef c;
  c.rho = kRho;
  c.g = kG;
  c.depth = h;
  std::vector<double> om;
  for (double k : K) om.push_back(std::sqrt(k * kG));
  std::string err;
  ASSERT_TRUE(mjb::panelSolve(body, lid, om, {}, &c, &err)) << err;
  for (int w = 0; w < c.nw(); w++) {
    A->push_back(c.A[36 * w + 14] / kRho);
    B->push_back(c.B[36 * w + 14] / (kRho * om[w]));
  }
}

// the reference's own convergence: 60 + 100 against 120 + 200 terms
TEST(PanelDepth, YeungExpansionConverges) {
  for (double K : {0.2, 1.0, 2.0}) {
    double a1, b1, a2, b2;
    yeungHeave(1, 0.5, 1.5, K, 60, 100, &a1, &b1);
    yeungHeave(1, 0.5, 1.5, K, 120, 200, &a2, &b2);
    EXPECT_NEAR(a1 / a2, 1, 0.003) << K;
    EXPECT_NEAR(b1 / b2, 1, 0.003) << K;
  }
}

// the cylinder of radius a = 1, draft 0.5 in water h = 1.5 deep (a / h =
// 0.67, d / h = 0.33; k0 h 0.55 to 3) against Yeung's expansion: the
// default suite's coarse mesh (3 x 5 x 32 panels and its lid, as
// panel_cyl_test.cc) within 4% (measured: 2.6% at most, the O(h) panel
// error of docs/physics.md section 13)
TEST(PanelDepth, CylinderHeaveVsYeungCoarse) {
  const std::vector<double> K = {0.2, 0.5, 1.0, 2.0};
  std::vector<double> A, B;
  panelCylHeave(3, 5, 32, 1.5, K, &A, &B);
  for (size_t w = 0; w < K.size(); w++) {
    double ya, yb;
    yeungHeave(1, 0.5, 1.5, K[w], 120, 200, &ya, &yb);
    std::printf("K a %.2f: A33 %.4f (Yeung %.4f) B33 %.4f (Yeung %.4f) rho a^3\n", K[w], A[w], ya, B[w], yb);
    EXPECT_NEAR(A[w] / ya, 1, 0.04) << "K " << K[w];
    EXPECT_NEAR(B[w] / yb, 1, 0.04) << "K " << K[w];
  }
}

// the same at a converged panel count (6 x 10 x 64, 1024 panels and its
// lid; label panel, opt-in): within 3% of Yeung's expansion at K a 0.1 to 3
TEST(PanelDepthConverged, CylinderHeaveVsYeung) {
  const std::vector<double> K = {0.1, 0.2, 0.5, 1.0, 1.5, 2.0, 3.0};
  std::vector<double> A, B;
  panelCylHeave(6, 10, 64, 1.5, K, &A, &B);
  for (size_t w = 0; w < K.size(); w++) {
    double ya, yb;
    yeungHeave(1, 0.5, 1.5, K[w], 120, 200, &ya, &yb);
    std::printf("K a %.2f: A33 %.4f (Yeung %.4f, %+.2f%%) B33 %.4f (Yeung %.4f, %+.2f%%) rho a^3\n",
                K[w], A[w], ya, 100 * (A[w] / ya - 1), B[w], yb, 100 * (B[w] / yb - 1));
    EXPECT_NEAR(A[w] / ya, 1, 0.03) << "K " << K[w];
    EXPECT_NEAR(B[w] / yb, 1, 0.03) << "K " << K[w];
  }
}

}  // namespace
