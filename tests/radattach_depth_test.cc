// finite water depth at attach (docs/physics.md section 13, "Finite
// depth"): mjbuoy.sea.depth reaches the panel solver, and a hull that
// reaches the seabed is an error naming it
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "api/buoy.h"
#include "testutil.h"

namespace {

using mjbt::Scene;

// a 1 m box of 500 kg (draft 0.49 m at rho 1025) with radiation on, at
// depth (empty: deep water)
std::string boxModel(const std::string& depth) {
  return "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h\"/>"
         "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
         "<numeric name=\"mjbuoy.radiation.omega\" data=\"0.5 4 4\"/>" +
         (depth.empty() ? std::string() : "<numeric name=\"mjbuoy.sea.depth\" data=\"" + depth + "\"/>") +
         "</custom><worldbody><body name=\"box\" pos=\"0 0 0.012\"><freejoint/>"
         "<geom name=\"h\" type=\"box\" size=\"0.5 0.5 0.5\" mass=\"500\" contype=\"0\" "
         "conaffinity=\"0\"/></body></worldbody></mujoco>";
}

// in water 1 m deep (0.5 m under the keel) at omega = 0.5 rad/s the wave
// is long (k0 h = 0.16, k0 = 6.3 K: omega^2 = g k0 tanh(k0 h)), so the
// heave damping, which carries the radiated wave's energy flux, cannot be
// deep water's: they differ by more than 10% (the finite-depth solution
// itself is checked against Yeung's expansion in tests/panel_depth_test.cc);
// the attach's coefficients carry the depth
TEST(RadAttachDepth, SeaDepthReachesThePanelSolver) {
  Scene deep(boxModel("")), shallow(boxModel("1"));
  ASSERT_TRUE(deep.ok()) << deep.err;
  ASSERT_TRUE(shallow.ok()) << shallow.err;
  const mjb::HydroCoef& d = mjb::buoyOf(deep.b)->coef[0].second;
  const mjb::HydroCoef& s = mjb::buoyOf(shallow.b)->coef[0].second;
  EXPECT_EQ(d.depth, 0);
  EXPECT_EQ(s.depth, 1);
  std::printf("box heave at 0.5 rad/s: deep A33 %.1f kg B33 %.1f kg/s; 1 m deep A33 %.1f B33 %.1f\n",
              d.A[14], d.B[14], s.A[14], s.B[14]);
  EXPECT_GT(std::fabs(s.B[14] / d.B[14] - 1), 0.1);
}

TEST(RadAttachDepth, HullThroughTheSeabedIsAnError) {
  Scene s(boxModel("0.3"));
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.err.find("seabed"), std::string::npos) << s.err;
  EXPECT_NE(s.err.find("box"), std::string::npos) << s.err;
}

}  // namespace
