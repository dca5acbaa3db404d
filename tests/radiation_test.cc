// radiation in the time domain (docs/physics.md section 14): added mass
// inside MuJoCo's inertia, Kirchhoff terms, the memory of Cummins' equation
#include <complex>
#include <cstring>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "api/buoy.h"
#include "radiation/hydrocoef.h"
#include "radiation/radiation.h"
#include "testutil.h"

namespace mjbt {
namespace {

// a 10 kg body on a 1000 N/m vertical slide spring, gravity off, no hull
std::string slide(const char* integrator, double dt) {
  char x[1024];
  std::snprintf(x, sizeof(x),
                "<mujoco><option timestep=\"%g\" integrator=\"%s\"><flag gravity=\"disable\"/></option>"
                "<worldbody><body name=\"b\"><joint type=\"slide\" axis=\"0 0 1\" stiffness=\"1000\"/>"
                "<geom type=\"sphere\" size=\"0.1\" mass=\"10\" contype=\"0\" conaffinity=\"0\"/>"
                "</body></worldbody></mujoco>", dt, integrator);
  return x;
}

// heave-only coefficients: A_inf33 = a, no damping
mjb::HydroCoef heave(double a) {
  mjb::HydroCoef c;
  c.Ainf[14] = a;
  return c;
}

// mean period [s] between upward zero crossings of x(t) over T seconds of mj_step
double period(Scene& s, double T, int q = 0) {
  std::vector<double> up;
  double prev = s.d->qpos[q], tprev = s.d->time;
  for (long k = 0, n = stepsTo(s.m, s.d, T); k < n; k++) {
    mj_step(s.m, s.d);
    double x = s.d->qpos[q];
    if (!std::isfinite(x)) return NAN;
    if (prev < 0 && x >= 0) up.push_back(tprev + (s.d->time - tprev) * (-prev) / (x - prev));
    prev = x;
    tprev = s.d->time;
  }
  return up.size() < 2 ? NAN : (up.back() - up.front()) / (up.size() - 1);
}

TEST(Radiation, AddedMassSetsTheSpringPeriod) {
  // T = 2 pi sqrt((m + a) / k) for a mass-spring whose mass is m + a, with
  // a = 0, m, 10 m (the last: added mass ten times the body's own, where an
  // explicit added-mass force is unstable)
  for (const char* integ : {"Euler", "RK4"}) {
    for (double a : {0.0, 10.0, 100.0}) {
      Scene s(slide(integ, 0.001));
      ASSERT_TRUE(s.ok()) << s.err;
      ASSERT_EQ(mjb::setHydroCoef(s.b, s.body("b"), heave(a), -1), "");
      s.d->qpos[0] = 0.01;
      double T = period(s, 12), Tp = 2 * M_PI * std::sqrt((10 + a) / 1000);
      EXPECT_NEAR(T, Tp, 1e-3 * Tp) << integ << " a = " << a;
      std::printf("[radiation] spring %s a = %g kg: period %.6f s (predicted %.6f)\n", integ, a, T, Tp);
      EXPECT_LT(std::fabs(s.d->qpos[0]), 0.0101) << integ << " a = " << a;
    }
  }
}

// skew(r) x = r x x
Eigen::Matrix3d skew(const double* r) {
  Eigen::Matrix3d S;
  S << 0, -r[2], r[1], r[2], 0, -r[0], -r[1], r[0], 0;
  return S;
}

TEST(Radiation, CoupledAddedMassAcceleratesAsMPlusAInverseF) {
  // a free body (10 kg, diagonal inertia, COM at its origin: MuJoCo treats
  // it as "simple", diagonal) with a full symmetric A_inf about a point r
  // off the COM, turned, at rest, pushed by a constant wrench F at the COM.
  // By hand: nu_ref = Phi nu_com with Phi = [I -S(r); 0 I] (v_ref = v + w x r),
  // so the added mass about the COM is Phi^T A Phi and the body-frame
  // acceleration solves (M + Phi^T A Phi) a = R^T F
  Scene s("<mujoco><option timestep=\"0.001\"><flag gravity=\"disable\"/></option><worldbody>"
          "<body name=\"b\" quat=\"0.9 0.2 -0.3 0.1\"><freejoint/>"
          "<inertial pos=\"0 0 0\" mass=\"10\" diaginertia=\"1 2 3\"/>"
          "<geom type=\"sphere\" size=\"0.1\" contype=\"0\" conaffinity=\"0\" mass=\"0\"/>"
          "</body></worldbody></mujoco>");
  ASSERT_TRUE(s.ok()) << s.err;
  ASSERT_GT(s.m->dof_simplenum[0], 0);  // the case MuJoCo factors as diagonal
  Eigen::Matrix<double, 6, 6> G;
  G << 3, 1, 0, 0.5, 0, 0.2,
       0, 2, 1, 0, 0.3, 0,
       1, 0, 4, 0, 0, 0.4,
       0, 0.2, 0, 1, 0.1, 0,
       0.3, 0, 0, 0, 1.5, 0.2,
       0, 0, 0.1, 0.2, 0, 0.8;
  Eigen::Matrix<double, 6, 6> A = G.transpose() * G;  // symmetric positive definite
  mjb::HydroCoef c;
  c.ref[0] = 0.3; c.ref[1] = -0.2; c.ref[2] = 0.1;
  for (int i = 0; i < 36; i++) c.Ainf[i] = A(i / 6, i % 6);
  int b = s.body("b");
  ASSERT_EQ(mjb::setHydroCoef(s.b, b, c, -1), "");
  double F[6] = {5, -3, 2, 1, 0.5, -2};
  std::memcpy(s.d->xfrc_applied + 6 * b, F, sizeof(F));
  mj_forward(s.m, s.d);

  Eigen::Matrix3d R;
  for (int i = 0; i < 9; i++) R(i / 3, i % 3) = s.d->xmat[9 * b + i];
  Eigen::Matrix<double, 6, 6> Phi = Eigen::Matrix<double, 6, 6>::Identity();
  Phi.block<3, 3>(0, 3) = -skew(c.ref);
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  M.diagonal() << 10, 10, 10, 1, 2, 3;
  Eigen::Matrix<double, 6, 1> f;
  f << R.transpose() * Eigen::Vector3d(F[0], F[1], F[2]), R.transpose() * Eigen::Vector3d(F[3], F[4], F[5]);
  Eigen::Matrix<double, 6, 1> acc = (M + Phi.transpose() * A * Phi).ldlt().solve(f);
  // the free joint: world-frame linear, body-frame angular acceleration
  Eigen::Vector3d lin = R * acc.head<3>();
  for (int i = 0; i < 3; i++) {
    EXPECT_NEAR(s.d->qacc[i], lin(i), 1e-9 * acc.norm()) << i;
    EXPECT_NEAR(s.d->qacc[3 + i], acc(3 + i), 1e-9 * acc.norm()) << i;
  }
  // without the added mass it would be M^-1 f: the test can tell
  EXPECT_GT(std::fabs(s.d->qacc[3] - f(3) / 1), 0.05 * std::fabs(f(3)));
}

TEST(Radiation, MunkMomentOfObliqueMotion) {
  // Kirchhoff's equations (Newman 1977 section 4.13; Fossen 2011 section
  // 6.3, -C_A(nu) nu): a body with surge and sway added mass A11 != A22
  // moving with body-frame velocity (u, v) and no rotation feels no force
  // and the yaw moment N = -(A22 - A11) u v: for A22 > A11 it turns the
  // body further from its path (the destabilising Munk moment)
  for (double yaw : {0.0, 0.7}) {
    Scene s("<mujoco><option><flag gravity=\"disable\"/></option><worldbody><body name=\"b\"><freejoint/>"
            "<inertial pos=\"0 0 0\" mass=\"10\" diaginertia=\"1 2 3\"/>"
            "<geom type=\"sphere\" size=\"0.1\" contype=\"0\" conaffinity=\"0\" mass=\"0\"/>"
            "</body></worldbody></mujoco>");
    ASSERT_TRUE(s.ok()) << s.err;
    mjb::HydroCoef c;
    const double A11 = 50, A22 = 200;
    c.Ainf[0] = A11; c.Ainf[7] = A22; c.Ainf[14] = 300;
    c.Ainf[21] = 10; c.Ainf[28] = 20; c.Ainf[35] = 30;
    ASSERT_EQ(mjb::setHydroCoef(s.b, 1, c, -1), "");
    s.d->qpos[3] = std::cos(yaw / 2);
    s.d->qpos[6] = std::sin(yaw / 2);
    const double u = 2, v = 0.5;  // body frame
    s.d->qvel[0] = u * std::cos(yaw) - v * std::sin(yaw);
    s.d->qvel[1] = u * std::sin(yaw) + v * std::cos(yaw);
    mj_forward(s.m, s.d);
    // free joint: qfrc[3..5] is the moment about the COM in body axes
    for (int i = 0; i < 5; i++) EXPECT_NEAR(s.d->qfrc_passive[i], 0, 1e-9) << i;
    EXPECT_NEAR(s.d->qfrc_passive[5], -(A22 - A11) * u * v, 1e-9);
  }
}

TEST(Radiation, MunkMomentOfABodyHeldInACurrent) {
  // a body at rest in a uniform current U at angle beta to its x axis is
  // the body moving at -U through still water (Galilean; docs/physics.md
  // section 14, "Current"): with (u, v) = -U (cos beta, sin beta) the
  // Munk moment is N = -(A22 - A11) u v = -(A22 - A11) U^2 cos beta sin beta
  // (Newman 1977 section 4.13), and no force
  const double A11 = 50, A22 = 200, U = 0.5;
  for (double beta : {0.3, 1.1}) {
    char x[1024];
    std::snprintf(x, sizeof(x),
                  "<mujoco><option><flag gravity=\"disable\"/></option><custom>"
                  "<numeric name=\"mjbuoy.sea.current\" data=\"%.17g %.17g\"/></custom>"
                  "<worldbody><body name=\"b\"><freejoint/>"
                  "<inertial pos=\"0 0 0\" mass=\"10\" diaginertia=\"1 2 3\"/>"
                  "<geom type=\"sphere\" size=\"0.1\" contype=\"0\" conaffinity=\"0\" mass=\"0\"/>"
                  "</body></worldbody></mujoco>", U * std::cos(beta), U * std::sin(beta));
    Scene s(x);
    ASSERT_TRUE(s.ok()) << s.err;
    mjb::HydroCoef c;
    c.Ainf[0] = A11; c.Ainf[7] = A22; c.Ainf[14] = 300;
    c.Ainf[21] = 10; c.Ainf[28] = 20; c.Ainf[35] = 30;
    ASSERT_EQ(mjb::setHydroCoef(s.b, 1, c, -1), "");
    mj_forward(s.m, s.d);
    const double N = -(A22 - A11) * U * U * std::cos(beta) * std::sin(beta);
    std::printf("[radiation] held in a %.2f m/s current at %.2f rad: N %.9g N m (expected %.9g)\n",
                U, beta, s.d->qfrc_passive[5], N);
    for (int i = 0; i < 5; i++) EXPECT_NEAR(s.d->qfrc_passive[i], 0, 1e-9) << i;
    EXPECT_NEAR(s.d->qfrc_passive[5], N, 1e-9 * std::fabs(N));
  }
}

TEST(Radiation, SpinningSphereFeelsNoVelocityForce) {
  // isotropic added mass a I (a sphere's) carries no Kirchhoff force: the
  // fluid force is -a times the centre's acceleration (Newman 1977 section
  // 4.13). The free joint's linear dofs are world-frame, so the
  // body-frame terms must cancel: a body spinning and moving gets exactly
  // its own accelerations, as without added mass (none here: zero)
  Scene s("<mujoco><option><flag gravity=\"disable\"/></option><worldbody><body name=\"b\" quat=\"0.8 0.3 0.1 -0.5\">"
          "<freejoint/><inertial pos=\"0 0 0\" mass=\"10\" diaginertia=\"2 2 2\"/>"
          "<geom type=\"sphere\" size=\"0.1\" contype=\"0\" conaffinity=\"0\" mass=\"0\"/>"
          "</body></worldbody></mujoco>");
  ASSERT_TRUE(s.ok()) << s.err;
  mjb::HydroCoef c;
  c.Ainf[0] = c.Ainf[7] = c.Ainf[14] = 7;
  ASSERT_EQ(mjb::setHydroCoef(s.b, 1, c, -1), "");
  double qv[6] = {1, -2, 0.5, 3, -1, 2};
  std::memcpy(s.d->qvel, qv, sizeof(qv));
  mj_forward(s.m, s.d);
  for (int i = 0; i < 6; i++) EXPECT_NEAR(s.d->qacc[i], 0, 1e-9) << i;
}

TEST(Radiation, LightFlatFloatHeavesWithItsAddedMass) {
  // a 1 m x 1 m x 0.1 m float of 20 kg (draft 0.02 m) with a heave added
  // mass ten times its mass, on mjbuoy's hydrostatics (drag terms off):
  // linear heave period 2 pi sqrt((m + a) / (rho g A_wp)) (wall-sided)
  Scene s("<mujoco><option timestep=\"0.002\"/><custom>"
          "<text name=\"mjbuoy.hulls\" data=\"hull\"/>"
          "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>"
          "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0.5\"/>"
          "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0.5\"/>"
          "<numeric name=\"mjbuoy.hull.slamming\" data=\"0 100 2\"/></custom>"
          "<worldbody><body name=\"f\" pos=\"0 0 0.035\"><freejoint/>"
          "<geom name=\"hull\" type=\"box\" size=\"0.5 0.5 0.05\" mass=\"20\"/>"
          "</body></worldbody></mujoco>");
  ASSERT_TRUE(s.ok()) << s.err;
  mjb::HydroCoef c;
  const double m = 20, a = 200;
  c.Ainf[0] = c.Ainf[7] = 20;
  c.Ainf[14] = a;
  c.Ainf[21] = c.Ainf[28] = 17;  // ten times the roll and pitch inertia
  c.Ainf[35] = 2;
  ASSERT_EQ(mjb::setHydroCoef(s.b, 1, c, -1), "");
  const double zeq = 0.05 - m / (kRho * 1.0);
  s.d->qpos[2] = zeq + 0.005;
  std::vector<double> up;
  double prev = s.d->qpos[2] - zeq, tprev = 0, peak = 0;
  for (long k = 0, n = stepsTo(s.m, s.d, 10); k < n; k++) {
    mj_step(s.m, s.d);
    double x = s.d->qpos[2] - zeq;
    ASSERT_TRUE(std::isfinite(x)) << "step " << k;
    peak = std::max(peak, std::fabs(x));
    if (prev < 0 && x >= 0) up.push_back(tprev + (s.d->time - tprev) * (-prev) / (x - prev));
    prev = x;
    tprev = s.d->time;
  }
  ASSERT_GE(up.size(), 5u);
  double T = (up.back() - up.front()) / (up.size() - 1);
  double expect = 2 * M_PI * std::sqrt((m + a) / (kRho * kG * 1.0));
  EXPECT_NEAR(T, expect, 0.02 * expect);
  std::printf("[radiation] flat float: heave period %.5f s (predicted %.5f)\n", T, expect);
  EXPECT_LT(peak, 0.0051);  // energy bounded
  EXPECT_STREQ(mjb_notices(s.b, s.d), "");
}

// a causal pair with closed forms: K(t) = k0 (1 - a t) e^{-a t}. From the
// Laplace transforms L{e^{-at}} = 1/(s + a), L{t e^{-at}} = 1/(s + a)^2 at
// s = -i w: int_0^inf K e^{i w t} dt = -i w k0 / (a - i w)^2, whose real
// part is B(w) = 2 k0 a w^2 / (a^2 + w^2)^2 and whose imaginary part is
// w (A_inf - A(w)): A(w) = A_inf - k0 (w^2 - a^2) / (a^2 + w^2)^2
// (Cummins 1962; Ogilvie 1964, the relations of docs/physics.md section 14)
struct Pair {
  double k0 = 400, a = 8, Ainf = 5;
  double K(double t) const { return k0 * (1 - a * t) * std::exp(-a * t); }
  double B(double w) const { return 2 * k0 * a * w * w / std::pow(a * a + w * w, 2); }
  double A(double w) const { return Ainf - k0 * (w * w - a * a) / std::pow(a * a + w * w, 2); }
  // -i w int K e^{i w t}, continued to complex w
  std::complex<double> Z(std::complex<double> w) const {
    std::complex<double> q = a - std::complex<double>(0, 1) * w;
    return -w * w * k0 / (q * q);
  }
  mjb::HydroCoef coef() const {
    mjb::HydroCoef c;
    c.Ainf[14] = Ainf;
    // geometric grid 0.05 .. 2000 rad/s: B linear in between to 1e-4, and
    // the truncated tail int_wmax^inf B < 0.5% of k0
    for (double w = 0.05; w <= 2000; w *= 1.018) {
      c.omega.push_back(w);
      for (int i = 0; i < 36; i++) {
        c.A.push_back(i == 14 ? A(w) : 0);
        c.B.push_back(i == 14 ? B(w) : 0);
      }
    }
    return c;
  }
};

TEST(Radiation, RetardationFunctionAndKramersKronig) {
  Pair P;
  mjb::HydroCoef c = P.coef();
  const double dt = 0.001;
  const int n = 5001;
  std::vector<double> K(n);
  mjb::retardation(c, 2, 2, dt, n, K.data());
  for (int k = 0; k < n; k += 50) EXPECT_NEAR(K[k], P.K(k * dt), 0.01 * P.k0) << "t = " << k * dt;
  // Kramers-Kronig (Ogilvie 1964): A(w) = A_inf - (1/w) int_0^inf K sin(w t) dt
  for (double w : {1.0, 2.0, 4.0, 8.0, 16.0, 32.0}) {
    double s = 0;
    for (int k = 0; k < n; k++) s += (k == 0 || k == n - 1 ? 0.5 : 1) * K[k] * std::sin(w * k * dt);
    double A = P.Ainf - s * dt / w;
    EXPECT_NEAR(A, P.A(w), 0.02 * P.A(w)) << "w = " << w;
  }
}

// free decay of x'' (m + A_inf) + int K x' + C x = 0 and its prediction:
// the root w of -w^2 (m + A_inf) + Z(w) + C = 0 (e^{-i w t}), by complex Newton
std::complex<double> root(const Pair& P, double m, double C) {
  std::complex<double> w(std::sqrt(C / (m + P.Ainf)), -0.1);
  auto f = [&](std::complex<double> x) { return -x * x * (m + P.Ainf) + P.Z(x) + C; };
  for (int i = 0; i < 50; i++) {
    std::complex<double> h = 1e-7 * std::abs(w), df = (f(w + h) - f(w - h)) / (2.0 * h);
    w -= f(w) / df;
  }
  EXPECT_LT(std::abs(f(w)), 1e-9 * C);
  return w;
}

TEST(Radiation, FreeDecayMatchesTheFrequencyDomain) {
  Pair P;
  const double m = 10, C = 1000;
  std::complex<double> w = root(P, m, C);
  const double Tp = 2 * M_PI / w.real(), delta = 2 * M_PI * -w.imag() / w.real();
  for (const char* integ : {"Euler", "RK4"}) {
    Scene s(slide(integ, 0.001));
    ASSERT_TRUE(s.ok()) << s.err;
    ASSERT_EQ(mjb::setHydroCoef(s.b, 1, P.coef(), 3.0), "");
    s.d->qpos[0] = 0.01;
    std::vector<double> up, peak;
    double x0 = s.d->qpos[0], x1 = x0, t1 = 0;
    for (long k = 0, n = stepsTo(s.m, s.d, 4); k < n; k++) {
      mj_step(s.m, s.d);
      double x2 = s.d->qpos[0];
      ASSERT_TRUE(std::isfinite(x2));
      if (x1 < 0 && x2 >= 0) up.push_back(t1 + (s.d->time - t1) * (-x1) / (x2 - x1));
      if (x1 > x0 && x1 >= x2) peak.push_back(x1);
      x0 = x1;
      x1 = x2;
      t1 = s.d->time;
    }
    ASSERT_GE(up.size(), 3u) << integ;
    ASSERT_GE(peak.size(), 3u) << integ;
    double T = (up.back() - up.front()) / (up.size() - 1);
    double dec = std::log(peak.front() / peak.back()) / (peak.size() - 1);
    EXPECT_NEAR(T, Tp, 0.05 * Tp) << integ;
    EXPECT_NEAR(dec, delta, 0.05 * delta) << integ;
    std::printf("[radiation] %s: period %.5f s (predicted %.5f), log decrement %.5f (predicted %.5f)\n",
                integ, T, Tp, dec, delta);
  }
}

}  // namespace
}  // namespace mjbt

namespace mjbt {
namespace {

TEST(Radiation, DampedSpringUnderEulerAndImplicit) {
  // a joint damper c takes Euler's implicit-damping path (qM + h c) and
  // mj_implicit's (qM - h dqfrc/dqvel): both must see m + a. Damped period
  // 2 pi / sqrt(k / (m + a) - (c / (2 (m + a)))^2)
  for (const char* integ : {"Euler", "implicit"}) {
    std::string x = slide(integ, 0.001);
    x.replace(x.find("stiffness"), 9, "damping=\"20\" stiffness");
    Scene s(x);
    ASSERT_TRUE(s.ok()) << s.err;
    ASSERT_EQ(mjb::setHydroCoef(s.b, 1, heave(100), -1), "");
    s.d->qpos[0] = 0.01;
    const double M = 110, wd = std::sqrt(1000 / M - std::pow(20 / (2 * M), 2));
    EXPECT_NEAR(period(s, 12), 2 * M_PI / wd, 1e-3 * 2 * M_PI / wd) << integ;
  }
}

TEST(Radiation, ConstraintSolverSeesTheAddedMass) {
  // two slide bodies tied by a nearly hard joint equality, at rest, the
  // second pushed by 30 N: both accelerate at F / (m1 + a + m2) = 1 m/s^2
  // only if the constraint's projection J (M + A)^-1 J^T (mj_projectConstraint,
  // dual solvers) and the solver's M both hold the added mass
  for (const char* solver : {"PGS", "CG", "Newton"}) {
    char x[1024];
    std::snprintf(x, sizeof(x),
        "<mujoco><option timestep=\"0.001\" solver=\"%s\" tolerance=\"1e-12\" iterations=\"500\">"
        "<flag gravity=\"disable\"/></option><worldbody>"
        "<body name=\"a\"><joint name=\"ja\" type=\"slide\" axis=\"1 0 0\"/>"
        "<geom type=\"sphere\" size=\"0.1\" mass=\"10\" contype=\"0\" conaffinity=\"0\"/></body>"
        "<body name=\"b\" pos=\"0 1 0\"><joint name=\"jb\" type=\"slide\" axis=\"1 0 0\"/>"
        "<geom type=\"sphere\" size=\"0.1\" mass=\"5\" contype=\"0\" conaffinity=\"0\"/></body>"
        "</worldbody><equality><joint joint1=\"ja\" joint2=\"jb\" solimp=\"0.99999 0.99999 0.001\"/>"
        "</equality></mujoco>", solver);
    Scene s(x);
    ASSERT_TRUE(s.ok()) << s.err;
    mjb::HydroCoef c;
    c.Ainf[0] = 15;
    ASSERT_EQ(mjb::setHydroCoef(s.b, s.body("a"), c, -1), "");
    s.d->qfrc_applied[1] = 30;
    mj_forward(s.m, s.d);
    ASSERT_GT(s.d->nefc, 0);
    EXPECT_NEAR(s.d->qacc[0], 1, 1e-3) << solver;
    EXPECT_NEAR(s.d->qacc[1], 1, 1e-3) << solver;
  }
}

TEST(Radiation, ForwardFromTheVelocityStageAddsNoSecondAddedMass) {
  // mj_forwardSkip(mjSTAGE_POS) reruns the callback on the qM of the last
  // mj_fwdPosition, which holds A_inf already: same accelerations
  Scene s(slide("Euler", 0.001));
  ASSERT_TRUE(s.ok()) << s.err;
  ASSERT_EQ(mjb::setHydroCoef(s.b, 1, heave(30), -1), "");
  s.d->qpos[0] = 0.01;
  mj_forward(s.m, s.d);
  EXPECT_NEAR(s.d->qacc[0], -1000 * 0.01 / 40, 1e-12);
  mj_forwardSkip(s.m, s.d, mjSTAGE_POS, 0);
  EXPECT_NEAR(s.d->qacc[0], -1000 * 0.01 / 40, 1e-12);
  mj_forward(s.m, s.d);
  EXPECT_NEAR(s.d->qacc[0], -1000 * 0.01 / 40, 1e-12);
}

// the slide body with the memory of Pair, started 1 cm out
// model: mjbuoy.radiation.memorymodel (docs/physics.md section 14), "" the default
std::string withModel(std::string x, const char* model) {
  if (*model)
    x.replace(x.find("<worldbody>"), 11, std::string("<custom><text name=\"mjbuoy.radiation."
              "memorymodel\" data=\"") + model + "\"/></custom><worldbody>");
  return x;
}

struct Decay {
  Scene s;
  explicit Decay(const char* integ, const char* model = "")
      : s(withModel(slide(integ, 0.001), model)) {
    if (!s.ok() || mjb::setHydroCoef(s.b, 1, Pair().coef(), 1.0) != "") s.err += " setup";
  }
  // the memory is the fitted state-space model (radfit.h), not the convolution
  bool ss() const { return mjb::buoyOf(s.b)->rad.rb[0].ss.size() > 0; }
};

void run(const mjModel* m, mjData* d, int n) {
  for (int i = 0; i < n; i++) mj_step(m, d);
}

TEST(Radiation, ResetEmptiesTheMemory) {
  // a rerun after mj_resetData repeats the first run bit for bit: with a
  // remembered history the memory force would differ; for both memory
  // models (the state-space states empty as the history does)
  for (const char* model : {"convolution", "statespace"}) {
  SCOPED_TRACE(model);
  Decay D("RK4", model);
  Scene& s = D.s;
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_EQ(D.ss(), model[0] == 's');
  s.d->qpos[0] = 0.01;
  run(s.m, s.d, 400);
  double x1 = s.d->qpos[0], v1 = s.d->qvel[0];
  mj_resetData(s.m, s.d);
  s.d->qpos[0] = 0.01;
  run(s.m, s.d, 400);
  EXPECT_EQ(std::memcmp(&x1, &s.d->qpos[0], sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&v1, &s.d->qvel[0], sizeof(double)), 0);
  // and the memory acts: without it the state would differ
  Scene t(slide("RK4", 0.001));
  ASSERT_EQ(mjb::setHydroCoef(t.b, 1, heave(Pair().Ainf), -1), "");
  t.d->qpos[0] = 0.01;
  run(t.m, t.d, 400);
  EXPECT_GT(std::fabs(t.d->qpos[0] - x1), 1e-4);
  }
}

TEST(Radiation, ResetAfterAForwardRepeatsTheRun) {
  // mj_resetData, then mj_forward (a viewer or a sensor read after the
  // reset), then mj_resetData again and the run: it must repeat the first
  // run bit for bit. mj_resetData zeroes MuJoCo's timer counts, so the
  // first step repeats the forward's mjTIMER_POSITION count while its
  // mj_fwdPosition has rebuilt qM without A_inf (before the fix the added
  // mass was left out of that step)
  Scene s(slide("Euler", 0.001));
  ASSERT_TRUE(s.ok()) << s.err;
  ASSERT_EQ(mjb::setHydroCoef(s.b, 1, heave(30), -1), "");
  auto go = [&]() {
    mj_resetData(s.m, s.d);
    s.d->qpos[0] = 0.01;
    run(s.m, s.d, 400);
    return s.d->qpos[0];
  };
  const double x1 = go();
  mj_resetData(s.m, s.d);
  mj_forward(s.m, s.d);
  const double x2 = go();
  EXPECT_EQ(std::memcmp(&x1, &x2, sizeof(double)), 0) << x1 << " " << x2;
}

TEST(Radiation, CopiedStateContinuesIdentically) {
  // mj_copyData + mjb_copyData halfway: the copy's second half is the
  // original's bit for bit (history included), under RK4 and Euler, and with
  // an extra mj_forward between steps (a viewer's) changing nothing
  for (const char* model : {"convolution", "statespace"})
  for (const char* integ : {"RK4", "Euler"}) {
    SCOPED_TRACE(model);
    Decay D(integ, model);
    Scene& s = D.s;
    ASSERT_TRUE(s.ok()) << s.err;
    EXPECT_EQ(D.ss(), model[0] == 's');
    s.d->qpos[0] = 0.01;
    run(s.m, s.d, 300);
    mjData* c = mj_makeData(s.m);
    mj_copyData(c, s.m, s.d);
    ASSERT_EQ(mjb_copyData(s.b, c, s.d), 1);
    run(s.m, s.d, 300);
    for (int i = 0; i < 300; i++) {
      mj_forward(s.m, c);
      mj_step(s.m, c);
    }
    EXPECT_EQ(std::memcmp(s.d->qpos, c->qpos, sizeof(double)), 0) << integ;
    EXPECT_EQ(std::memcmp(s.d->qvel, c->qvel, sizeof(double)), 0) << integ;
    mjb_unbindData(s.b, c);
    mj_deleteData(c);
  }
}

TEST(Radiation, BadCoefficientsAreRefusedByName) {
  Scene s(slide("Euler", 0.001));
  ASSERT_TRUE(s.ok()) << s.err;
  mjb::HydroCoef c;
  c.Ainf[1] = 5;  // not symmetric
  EXPECT_NE(mjb::setHydroCoef(s.b, 1, c, -1).find("not symmetric"), std::string::npos);
  c.Ainf[6] = 5;  // symmetric, indefinite
  EXPECT_NE(mjb::setHydroCoef(s.b, 1, c, -1).find("positive semi-definite"), std::string::npos);
  mjb::HydroCoef e = heave(1);
  e.omega = {1, 0.5};
  e.B.assign(72, 0);
  EXPECT_NE(mjb::setHydroCoef(s.b, 1, e, -1).find("omega[1] = 0.5"), std::string::npos);
  e.omega = {1, 2};
  e.B.assign(71, 0);
  EXPECT_NE(mjb::setHydroCoef(s.b, 1, e, -1).find("need 72 values of B"), std::string::npos);
  EXPECT_NE(mjb::setHydroCoef(s.b, 0, heave(1), -1).find("out of range"), std::string::npos);
  EXPECT_NE(mjb::setHydroCoef(s.b, 1, heave(1), 1e9).find("memory length"), std::string::npos);
}

}  // namespace
}  // namespace mjbt

namespace mjbt {
namespace {

TEST(Radiation, AutomaticMemoryLengthIsWhereKHasDecayed) {
  // default memory: the time after which |K| stays below 1% of its peak.
  // For K = k0 (1 - a t) e^{-a t} with the table ending at W = 200 rad/s
  // the peak is K(0) = k0 - (2/pi) (int_W^inf B dw - B(W) W / (p - 1)):
  // the tail B(W) (W / w)^p of docs/physics.md section 14 stands for B
  // beyond W, with p = 2 here (B ~ 2 k0 a / w^2 for w >> a: the slope of
  // the last three frequencies, the table having no A; it differs from 2
  // by O(a^2 / W^2)), and int_W^inf w^2 / (a^2 + w^2)^2 dw =
  // (pi/2 - atan(W/a) + a W / (a^2 + W^2)) / (2 a); the time is the root of
  // k0 (a t - 1) e^{-a t} = 0.01 K(0) past the zero crossing at 1/a (bisection),
  // found on a grid of pi / (4 W)
  Pair P;
  const double W = 200, a = P.a;
  mjb::HydroCoef c;
  c.Ainf[14] = P.Ainf;
  for (double w = 0.05; w <= W; w *= 1.03) {
    c.omega.push_back(w);
    for (int i = 0; i < 36; i++) c.B.push_back(i == 14 ? P.B(w) : 0);
  }
  c.omega.back() = W;  // the table ends at W exactly
  for (int i = 0; i < 36; i++) c.B[c.B.size() - 36 + i] = i == 14 ? P.B(W) : 0;
  const double tail = (M_PI / 2 - std::atan(W / a) + a * W / (a * a + W * W)) / (2 * a);
  const double K0 = P.k0 - 2 / M_PI * (2 * P.k0 * a * tail - P.B(W) * W);
  double t = bisect([&](double x) { return P.k0 * (a * x - 1) * std::exp(-a * x) - 0.01 * K0; },
                    2 / a, 5);
  EXPECT_NEAR(mjb::memoryLength(c), t, M_PI / (4 * W) + 0.002 * t);
}

}  // namespace
}  // namespace mjbt

namespace mjbt {
namespace {

TEST(Radiation, Step1Step2LoopMatchesStep) {
  // mj_step1 / mj_step2 (Euler) is mj_step split around the user's input:
  // the same added mass, memory and history, bit for bit
  Decay D("Euler");
  Scene& s = D.s;
  ASSERT_TRUE(s.ok()) << s.err;
  mjData* e = mj_makeData(s.m);
  s.d->qpos[0] = e->qpos[0] = 0.01;
  for (int i = 0; i < 600; i++) {
    mj_step(s.m, s.d);
    mj_step1(s.m, e);
    mj_step2(s.m, e);
  }
  EXPECT_EQ(std::memcmp(s.d->qpos, e->qpos, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(s.d->qvel, e->qvel, sizeof(double)), 0);
  mjb_unbindData(s.b, e);
  mj_deleteData(e);
}

}  // namespace
}  // namespace mjbt

namespace mjbt {
namespace {

// held at constant heave velocity v the memory force is -v int_0^t K,
// and int_0^inf K = B(0) = 0 (K is B's cosine transform: Cummins 1962).
// For Pair's K, int_0^t K = k0 t e^{-a t} (d/dt of t e^{-at}): cut at
// T_m = 0.5 s (a T_m = 4) without correction it would leave
// -v k0 T_m e^{-4} = -3.66 N for ever; docs/physics.md section 14. The
// convolution's sum ends at T_m (zero to round-off after it); the
// state-space modes hold the same steady gain summed to infinity, so
// their force decays with the slowest mode instead: after 3 s within
// 1e-6 of the scale
void steadyVelocity(const char* model, int steps, double tol) {
  Pair P;
  std::string x = slide("Euler", 0.001);
  x.replace(x.find("stiffness=\"1000\""), 16, "stiffness=\"0\"");
  x.replace(0, 8, std::string("<mujoco><custom><text name=\"mjbuoy.radiation.memorymodel\" "
                              "data=\"") + model + "\"/></custom>");
  Scene s(x);
  ASSERT_TRUE(s.ok()) << s.err;
  const double v = 1, Tm = 0.5, scale = P.k0 * v / P.a;  // peak of v k0 t e^{-at}: scale / e
  ASSERT_EQ(mjb::setHydroCoef(s.b, 1, P.coef(), Tm), "");
  double f01 = 0;
  for (int k = 0; k < steps; k++) {
    s.d->qvel[0] = v;
    mj_step(s.m, s.d);
    if (k == 100) f01 = s.d->qfrc_passive[0];
  }
  // t = 0.1 s, before the taper: -v k0 t e^{-at} less the correction's
  // share (at most 2% of the scale here)
  EXPECT_NEAR(f01, -v * P.k0 * 0.1 * std::exp(-P.a * 0.1), 0.03 * scale) << model;
  std::printf("[radiation] steady heave, %s (%d modes): memory force %.3g N after %.1f s "
              "(scale %g N)\n", model, mjb::buoyOf(s.b)->rad.rb.at(0).ss.size(),
              s.d->qfrc_passive[0], s.d->time, scale);
  EXPECT_LT(std::fabs(s.d->qfrc_passive[0]), tol * scale) << model;
}

TEST(Radiation, SteadyVelocityLeavesNoMemoryForce) {
  steadyVelocity("convolution", 800, 1e-9);
  steadyVelocity("statespace", 3000, 1e-6);
}

}  // namespace
}  // namespace mjbt

namespace mjbt {
namespace {

TEST(Radiation, BodyDriftingWithTheCurrentFeelsNoRadiation) {
  // radiation acts on the velocity relative to a uniform current (potential
  // flow in the frame moving with the water, Galilean; docs/physics.md
  // section 14): a free body drifting obliquely at the current's velocity
  // feels neither memory nor Munk moment. Over the ground it would feel
  // M_z = -(A22 - A11) u v = -5.4 N m (Newman 1977, sec. 4.13) and the
  // sway memory -int_0^t K v
  Scene s("<mujoco><option timestep=\"0.002\"><flag gravity=\"disable\"/></option><custom>"
          "<numeric name=\"mjbuoy.sea.current\" data=\"0.3 0.4\"/></custom><worldbody>"
          "<body name=\"b\"><freejoint/><geom type=\"box\" size=\"1 0.2 0.2\" mass=\"10\" "
          "contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>");
  ASSERT_TRUE(s.ok()) << s.err;
  Pair P;
  mjb::HydroCoef c = P.coef();
  for (size_t f = 0; f < c.omega.size(); f++) std::swap(c.B[36 * f + 7], c.B[36 * f + 14]);
  const double a[6] = {5, 50, 5, 1, 1, 1};
  for (int i = 0; i < 6; i++) c.Ainf[7 * i] = a[i];
  ASSERT_EQ(mjb::setHydroCoef(s.b, 1, c, 0.5), "");
  s.d->qvel[0] = 0.3;
  s.d->qvel[1] = 0.4;
  double fmax = 0;
  for (int k = 0; k < 500; k++) {
    mj_step(s.m, s.d);
    for (int i = 0; i < 6; i++) fmax = std::max(fmax, std::fabs(s.d->qfrc_passive[i]));
  }
  std::printf("[radiation] drifting with the current: largest radiation force %.3g, yaw rate %.3g\n",
              fmax, s.d->qvel[5]);
  EXPECT_LT(fmax, 1e-9);
  EXPECT_NEAR(s.d->qvel[0], 0.3, 1e-9);
  EXPECT_NEAR(s.d->qvel[1], 0.4, 1e-9);
  EXPECT_LT(std::fabs(s.d->qvel[5]), 1e-9);
  // spinning about its vertical axis as it drifts: in the water's frame a
  // pure yaw, which with p = 0 and h || w feels no Kirchhoff force
  mj_resetData(s.m, s.d);
  s.d->qvel[0] = 0.3;
  s.d->qvel[1] = 0.4;
  s.d->qvel[5] = 1;
  mj_forward(s.m, s.d);
  double big = 0;
  for (int i = 0; i < 6; i++) big = std::max(big, std::fabs(s.d->qfrc_passive[i]));
  std::printf("[radiation] spinning and drifting: largest radiation force %.3g\n", big);
  EXPECT_LT(big, 1e-9);
}

}  // namespace
}  // namespace mjbt

namespace mjbt {
namespace {

TEST(Radiation, SteadyGainCorrectionKeepsAddedMassAndDamping) {
  // the memory's K after the taper and the steady-gain correction
  // (docs/physics.md section 14) still stands for Pair's A(w) and B(w)
  // (closed forms above) away from w -> 0: Kramers-Kronig
  // A = A_inf - (1/w) int K sin(w t) and B = int K cos(w t) (Ogilvie 1964)
  Pair P;
  Scene s(slide("Euler", 0.001));
  ASSERT_TRUE(s.ok()) << s.err;
  // 0.8 s: about the automatic memory (K below 1% of its peak after a t = 6.6)
  ASSERT_EQ(mjb::setHydroCoef(s.b, 1, P.coef(), 0.8), "");
  const mjb::RadBody& rb = mjb::buoyOf(s.b)->rad.rb[0];
  const int n = rb.nk;
  const double dt = 0.001, Tm = (n - 1) * dt;
  std::vector<double> K0(n);  // uncorrected, for the printout
  mjb::retardation(P.coef(), 2, 2, dt, n, K0.data());
  auto kk = [&](const double* K, double w, double* A, double* B) {
    double sa = 0, sb = 0;
    for (int k = 0; k < n; k++) {
      const double wt = (k == 0 || k == n - 1 ? 0.5 : 1) * K[k] * dt;
      sa += wt * std::sin(w * k * dt);
      sb += wt * std::cos(w * k * dt);
    }
    *A = P.Ainf - sa / w;
    *B = sb;
  };
  for (double w : {4.0, 8.0, 16.0, 32.0}) {
    double A, B, A0, B0;
    kk(rb.K.data(), w, &A, &B);
    kk(K0.data(), w, &A0, &B0);
    std::printf("[radiation] T_m %.3f s, w %g: A %.4f (uncorrected %.4f, exact %.4f), "
                "B %.4f (uncorrected %.4f, exact %.4f)\n", Tm, w, A, A0, P.A(w), B, B0, P.B(w));
    // the correction's window lies below 4 pi / T_m = 16 rad/s here
    if (w < 4 * M_PI / Tm) continue;
    EXPECT_NEAR(A, P.A(w), 0.02 * P.A(w)) << w;
    EXPECT_NEAR(B, P.B(w), 0.02 * P.k0 / P.a) << w;
  }
}

}  // namespace
}  // namespace mjbt
