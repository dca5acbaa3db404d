// Gerstner surface height at a fixed point, against physics.md section 6
// and against the forward particle map
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "sea/sea.h"
#include "testutil.h"

namespace mjbt {
namespace {

// (no start-up ramp: the surface at full amplitude from t = 0, as the
// analytic values below)
std::string seaXML(const std::string& waves) {
  return "<mujoco><custom>" + waves + "<numeric name=\"mjbuoy.sea.ramp\" data=\"0\"/>" +
         "<text name=\"mjbuoy.hulls\" data=\"h\"/></custom><worldbody><body>"
         "<freejoint/><geom name=\"h\" type=\"sphere\" size=\"0.1\"/></body></worldbody></mujoco>";
}

TEST(Sea, GerstnerHeightCheckValue) {
  // A = 1, lambda = 20, Q = 1, D = +x, phi = 0, deep water, t = 1.3, x = 3.7
  Scene s(seaXML("<numeric name=\"mjbuoy.wave.a\" data=\"1 20 0 0 1\"/>"));
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_NEAR(mjb_seaHeight(s.b, 3.7, 0, 1.3), 0.1394445806, 1e-9);
  // the same wave travelling along +y, probed along y
  Scene r(seaXML("<numeric name=\"mjbuoy.wave.a\" data=\"1 20 90 0 1\"/>"));
  ASSERT_TRUE(r.ok()) << r.err;
  EXPECT_NEAR(mjb_seaHeight(r.b, -2.5, 3.7, 1.3), 0.1394445806, 1e-9);
}

TEST(Sea, FlatAndLevel) {
  Scene s(seaXML("<numeric name=\"mjbuoy.sea.level\" data=\"-1.25\"/>"));
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_EQ(mjb_seaHeight(s.b, 10, -3, 7), -1.25);
}

TEST(Sea, HeightInvertsTheParticleMap) {
  // three components, finite depth: move particles forward, then ask for the
  // height where each particle landed
  const double A[3] = {0.5, 0.2, 0.1}, L[3] = {30, 11, 5}, dir[3] = {0, 50, -120};
  const double ph[3] = {0, 30, 200}, Q[3] = {0.8, 0.6, 0.9}, h = 8, lvl = 0.3;
  Scene s(seaXML("<numeric name=\"mjbuoy.wave.a\" data=\"0.5 30 0 0 0.8\"/>"
                 "<numeric name=\"mjbuoy.wave.b\" data=\"0.2 11 50 30 0.6\"/>"
                 "<numeric name=\"mjbuoy.wave.c\" data=\"0.1 5 -120 200 0.9\"/>"
                 "<numeric name=\"mjbuoy.sea.depth\" data=\"8\"/>"
                 "<numeric name=\"mjbuoy.sea.level\" data=\"0.3\"/>"));
  ASSERT_TRUE(s.ok()) << s.err;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-50, 50);
  for (int i = 0; i < 200; i++) {
    double a0 = U(rng), a1 = U(rng), t = std::fabs(U(rng));
    double x = a0, y = a1, z = lvl;
    for (int k = 0; k < 3; k++) {
      double kk = 2 * M_PI / L[k], w = std::sqrt(kG * kk * std::tanh(kk * h));
      double dx = std::cos(dir[k] * M_PI / 180), dy = std::sin(dir[k] * M_PI / 180);
      double th = kk * (dx * a0 + dy * a1) - w * t + ph[k] * M_PI / 180;
      x -= Q[k] * A[k] * dx * std::sin(th);
      y -= Q[k] * A[k] * dy * std::sin(th);
      z += A[k] * std::cos(th);
    }
    ASSERT_NEAR(mjb_seaHeight(s.b, x, y, t), z, 1e-9) << "particle " << i;
  }
}

TEST(Sea, MeanOfSteepSurfaceSitsBelowOrbitCentres) {
  // Q = 1: the mean height over a wavelength is k A^2 / 2 below the level
  Scene s(seaXML("<numeric name=\"mjbuoy.wave.a\" data=\"0.8 20 0 0 1\"/>"));
  ASSERT_TRUE(s.ok()) << s.err;
  const int n = 20000;
  double sum = 0;
  for (int i = 0; i < n; i++) sum += mjb_seaHeight(s.b, 20.0 * (i + 0.5) / n, 0, 0.7);
  double k = 2 * M_PI / 20;
  EXPECT_NEAR(sum / n, -k * 0.8 * 0.8 / 2, 1e-6);
}

// the flow of 300 Airy components on deep water (more than the 256 whose
// sin and cos Sea::velocity keeps) at points below and above the level,
// against linear theory written out (Dean & Dalrymple 1991, ch. 4; Wheeler
// stretching, sea.h): eta = sum A cos th, zs = min(z - eta, 0),
// u = sum A w e^{k zs} cos th (dx, dy), w = sum A w e^{k zs} sin th,
// du/dt = sum A w^2 e^{k zs} sin th (dx, dy), dw/dt = -sum A w^2 e^{k zs} cos th
TEST(Sea, VelocityOfManyComponentsIsLinearTheory) {
  mjb::Sea sea;
  sea.depth = 0;
  sea.level = 0.2;
  sea.ramp = 0;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0, 1);
  for (int i = 0; i < 300; i++) {
    mjb::Wave w{};
    w.kind = 1;
    w.amp = 0.002 + 0.004 * U(rng);
    w.omega = 0.3 + 1.5 * U(rng);
    w.k = w.omega * w.omega / kG;
    w.dir = 360 * U(rng);
    w.dx = std::cos(w.dir * M_PI / 180), w.dy = std::sin(w.dir * M_PI / 180);
    w.ph = 2 * M_PI * U(rng);
    sea.waves.push_back(w);
  }
  for (double z : {-4.0, -0.5, 0.9}) {
    const double p[3] = {3.1, -7.4, z}, t = 12.3;
    double v[3], acc[3];
    sea.velocity(p, t, v, acc);
    long double eta = 0;
    for (const mjb::Wave& w : sea.waves)
      eta += w.amp * cosl(w.k * (w.dx * p[0] + w.dy * p[1]) - w.omega * t + w.ph);
    const long double zs = std::min((long double)(z - sea.level) - eta, 0.0L);
    long double want[6] = {0, 0, 0, 0, 0, 0};
    for (const mjb::Wave& w : sea.waves) {
      const long double th = w.k * (w.dx * p[0] + w.dy * p[1]) - w.omega * t + w.ph;
      const long double f = w.amp * w.omega * expl(w.k * zs), c = cosl(th), s = sinl(th);
      want[0] += f * c * w.dx, want[1] += f * c * w.dy, want[2] += f * s;
      want[3] += f * w.omega * s * w.dx, want[4] += f * w.omega * s * w.dy;
      want[5] -= f * w.omega * c;
    }
    double big = 0;
    for (long double x : want) big = std::max(big, (double)fabsl(x));
    ASSERT_GT(big, 0.01);
    for (int k = 0; k < 3; k++) {
      EXPECT_NEAR(v[k], (double)want[k], 1e-12 * big) << "z " << z << " v " << k;
      EXPECT_NEAR(acc[k], (double)want[k + 3], 1e-12 * big) << "z " << z << " acc " << k;
    }
  }
}

}  // namespace
}  // namespace mjbt

// regression (tests/fuzz: fuzz_kernel): short waves on deep finite water,
// k depth = 1257 here, gave cosh(kz) / cosh(kd) = inf / inf = NaN. For
// k depth >> 1 the Airy profile is the deep-water exp(k z) (physics.md 6);
// Wheeler's stretch z' = (z - eta) h / (h + eta) differs from the deep
// z - eta by (z - eta) eta / (h + eta), so the profiles agree to
// k |z - eta| |eta| / h = 6.3 * 5 * 0.05 / 1e6 = 1.6e-6 relative at h = 1e6 m
TEST(Sea, FiniteDepthVelocityHasTheDeepWaterLimit) {
  mjb::Sea deep, fin;
  mjb::Wave w{};
  w.amp = 0.05;  // m
  w.len = 1.0;   // m: k = 6.28 rad/m
  w.dir = 30;    // deg
  w.phase = 10;  // deg
  w.steep = 0.5;
  deep.waves.push_back(w);
  fin = deep;
  fin.depth = 1e6;  // k h = 6e6: no cosh may overflow
  deep.derive();
  fin.derive();
  for (double z : {0.0, -0.05, -0.3, -1.0, -5.0}) {
    double p[3] = {0.3, -0.7, z}, vd[3], vf[3];
    deep.velocity(p, 2.1, vd);
    fin.velocity(p, 2.1, vf);
    for (int j = 0; j < 3; j++) EXPECT_NEAR(vf[j], vd[j], 2e-6 * (1 + std::fabs(vd[j]))) << z;
  }
  // the profile is continuous across k depth = 20 (where an earlier
  // version switched formulas)
  mjb::Sea a = fin, b = fin;
  a.depth = 20 / fin.waves[0].k * (1 - 1e-12);
  b.depth = 20 / fin.waves[0].k * (1 + 1e-12);
  a.derive();
  b.derive();
  double p[3] = {0.3, -0.7, -0.2}, va[3], vb[3];
  a.velocity(p, 2.1, va);
  b.velocity(p, 2.1, vb);
  for (int j = 0; j < 3; j++) EXPECT_NEAR(va[j], vb[j], 1e-9 * (1 + std::fabs(va[j])));
}
