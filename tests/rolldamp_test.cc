// viscous roll damping of the radiating bodies (docs/physics.md section 14,
// "Viscous roll damping"; mjbuoy.radiation.rolldamping): free decay of a
// roll oscillator against the hand-computed decrements, and bad input
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "radiation/hydrocoef.h"
#include "radiation/radiation.h"
#include "testutil.h"

namespace mjbt {
namespace {

const double kI = 6, kA = 0.5, kK = 120;  // roll inertia, A44_inf [kg m^2], stiffness [N m/rad]

// a body rolling on a hinge along its x axis through its COM with a
// torsion spring kK, gravity off, no hull; rolldamping given as data
std::string roller(const char* data) {
  char x[1024];
  std::snprintf(x, sizeof(x),
                "<mujoco><option timestep=\"0.001\" integrator=\"RK4\"><flag gravity=\"disable\"/></option>"
                "<custom><numeric name=\"mjbuoy.radiation.rolldamping\" data=\"%s\"/></custom>"
                "<worldbody><body name=\"b\"><joint type=\"hinge\" axis=\"1 0 0\" stiffness=\"%g\"/>"
                "<inertial pos=\"0 0 0\" mass=\"10\" diaginertia=\"%g 20 20\"/>"
                "</body></worldbody></mujoco>", data, kK, kI);
  return x;
}

// roll amplitudes at the successive maxima of a free decay from 0.2 rad
std::vector<double> peaks(const char* data, double T) {
  Scene s(roller(data));
  EXPECT_TRUE(s.ok()) << s.err;
  if (!s.ok()) return {};
  mjb::HydroCoef c;
  c.Ainf[21] = kA;
  EXPECT_EQ(mjb::setHydroCoef(s.b, s.body("b"), c, -1), "");
  s.d->qpos[0] = 0.2;
  std::vector<double> p;
  double x0 = 0, x1 = s.d->qpos[0];
  for (long k = 0, n = stepsTo(s.m, s.d, T); k < n; k++) {
    mj_step(s.m, s.d);
    const double x = s.d->qpos[0];
    if (k > 1 && x1 > x0 && x1 >= x) p.push_back(x1);
    x0 = x1;
    x1 = x;
  }
  return p;
}

TEST(RollDamping, LinearTermGivesTheDampedOscillatorsDecrement) {
  // I_t theta'' + b theta' + k theta = 0 with I_t = I + A44 (the added
  // inertia in MuJoCo's inertia matrix): log decrement per period
  // delta = 2 pi zeta / sqrt(1 - zeta^2), zeta = b / (2 sqrt(k I_t))
  // (the viscously damped linear oscillator; W. T. Thomson, "Theory of
  // Vibration with Applications", ch. 2)
  const double b = 2.7;
  const double zeta = b / (2 * std::sqrt(kK * (kI + kA)));
  const double pred = 2 * M_PI * zeta / std::sqrt(1 - zeta * zeta);
  std::vector<double> p = peaks("2.7 0", 12), p0 = peaks("0 0", 12);
  ASSERT_GE(p.size(), 6u);
  ASSERT_GE(p0.size(), 6u);
  const double delta = std::log(p[0] / p[5]) / 5;
  std::printf("[rolldamp] linear b = %g N m s/rad (zeta %.4f): log decrement %.5f, predicted %.5f; "
              "undamped peaks %.6f .. %.6f rad\n", b, zeta, delta, pred, p0[0], p0[5]);
  EXPECT_NEAR(delta, pred, 0.01 * pred);
  // without it the oscillator keeps its amplitude (no other damping here)
  EXPECT_NEAR(p0[5], p0[0], 1e-4 * p0[0]);
}

TEST(RollDamping, QuadraticTermLowersTheInverseAmplitudeLinearly) {
  // I_t theta'' + c |theta'| theta' + k theta = 0, light damping: the
  // energy lost per cycle at amplitude a, (8/3) c w^2 a^3, against the
  // energy 1/2 I_t w^2 a^2 gives d(1/a) = 8 c / (3 I_t) per cycle, so 1/a
  // grows linearly (the equivalent linear damping (8 / 3 pi) c w a of
  // Y. Himeno, "Prediction of ship roll damping: state of the art",
  // University of Michigan, Dept. of Naval Architecture and Marine
  // Engineering, report 239, 1981)
  const double c = 1.5;
  const double pred = 8 * c / (3 * (kI + kA));
  std::vector<double> p = peaks("0 1.5", 12);
  ASSERT_GE(p.size(), 6u);
  const double step = (1 / p[5] - 1 / p[0]) / 5;
  std::printf("[rolldamp] quadratic c = %g N m s^2/rad^2: d(1/a) per cycle %.5f, predicted %.5f "
              "(peaks %.4f .. %.4f rad)\n", c, step, pred, p[0], p[5]);
  EXPECT_NEAR(step, pred, 0.03 * pred);
}

TEST(RollDamping, WithoutRadiationItWarns) {
  // the term belongs to the radiating bodies: a floating box with radiation
  // off would silently get none
  Scene s("<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
          "<text name=\"mjbuoy.radiation\" data=\"off\"/>"
          "<numeric name=\"mjbuoy.radiation.rolldamping\" data=\"2.7 0\"/></custom>"
          "<worldbody><body name=\"box\"><freejoint/><geom name=\"hull\" type=\"box\" "
          "size=\"0.5 0.5 0.5\" mass=\"500\" contype=\"0\" conaffinity=\"0\"/></body>"
          "</worldbody></mujoco>");
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_NE(std::string(mjb_warnings(s.b)).find("mjbuoy.radiation.rolldamping acts only"),
            std::string::npos) << mjb_warnings(s.b);
}

TEST(RollDamping, BadEntriesAreNamed) {
  for (const char* bad : {"-1 0", "1", "0 -2", "1e16 0"}) {
    Scene s(roller(bad));
    EXPECT_FALSE(s.ok()) << bad;
    EXPECT_NE(s.err.find("mjbuoy.radiation.rolldamping"), std::string::npos) << s.err;
  }
}

}  // namespace
}  // namespace mjbt
