// issue 11, forces: nothing lost, nothing silently wrong (docs/robustness.md)
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

// a 2 x 1 x 0.5 m box barge of 500 kg (models/barge.xml) held 0.5 m up
const char* kDrop =
    "<mujoco><option timestep=\"0.002\"/><custom>"
    "<text name=\"mjbuoy.hulls\" data=\"hull\"/></custom><worldbody>"
    "<body name=\"barge\" pos=\"0 0 0.75\"><freejoint/>"
    "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body>"
    "</worldbody></mujoco>";

TEST(RobustForces, SlammingActsWhateverLoopStepsTheModel) {
  // the same drop stepped by mj_step and by mj_forward + mj_Euler (what
  // mj_step does for the Euler integrator, so the state sequences are the
  // same): slamming must act the same in both. The second loop calls
  // mj_forward twice per step, which must not move the history on (a
  // second call at the same time is not a new step); MuJoCo's second
  // mj_forward differs from the first by round-off (the pressure too), so
  // the two runs are compared to 1e-6 of the largest slamming force
  Scene a(kDrop), b(kDrop);
  ASSERT_TRUE(a.ok() && b.ok()) << a.err << b.err;
  double most = 0, worst = 0, again = 0;
  for (int k = 0; k < 400; k++) {
    mj_step(a.m, a.d);
    mj_forward(b.m, b.d);
    const double once = mjb_wrenchPart(b.b, b.d, mjbPART_SLAM)[6 + 2];
    mj_forward(b.m, b.d);
    mj_Euler(b.m, b.d);
    const mjtNum* sa = mjb_wrenchPart(a.b, a.d, mjbPART_SLAM) + 6;
    const mjtNum* sb = mjb_wrenchPart(b.b, b.d, mjbPART_SLAM) + 6;
    for (int j = 0; j < 6; j++) worst = std::fmax(worst, std::fabs(sa[j] - sb[j]));
    again = std::fmax(again, std::fabs(sb[2] - once));
    most = std::fmax(most, std::fabs(sa[2]));
  }
  // hitting the water at sqrt(2 g 0.25) = 2.2 m/s the 500 kg barge is
  // stopped over a few steps: kN of slamming, not 0
  EXPECT_GT(most, 1e3) << "slamming never acted: the test shows nothing";
  EXPECT_LE(worst, 1e-6 * most) << "mj_forward + mj_Euler slams unlike mj_step";
  EXPECT_LE(again, 1e-6 * most) << "a repeated mj_forward moved the slamming history on";
}

}  // namespace
}  // namespace mjbt
