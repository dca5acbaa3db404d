// MuJoCo glue: forces go to qfrc_passive, xfrc_applied stays the user's,
// callbacks chain, several mjData and models live side by side
#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

// radiation off: these test the plumbing of mjbuoy's forces into MuJoCo,
// and the readable wrench leaves radiation out (docs/physics.md section 14)
const char kBarge[] =
    "<mujoco><option timestep=\"0.002\"/><custom>"
    "<text name=\"mjbuoy.hulls\" data=\"hull\"/><text name=\"mjbuoy.radiation\" data=\"off\"/>"
    "<numeric name=\"mjbuoy.hull.damping\" data=\"3000 300\"/></custom>"
    "<worldbody><body name=\"barge\" pos=\"0 0 0.1\"><freejoint/>"
    "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/>"
    "</body></worldbody></mujoco>";

TEST(Glue, UserForceInXfrcAppliedStillActs) {
  // 1000 N down on a wall-sided box: it sinks F / (rho g A_wp) = 0.050968 m
  // deeper, and mjbuoy's force grows to m g + F
  Scene s(kBarge);
  ASSERT_TRUE(s.ok()) << s.err;
  int b = s.body("barge");
  s.d->xfrc_applied[6 * b + 2] = -1000;
  double z = s.settle(30, 5, [&] { return s.d->xipos[3 * b + 2]; });
  EXPECT_NEAR(z, -1000 / (kRho * kG * 2), 0.005 * 0.050968);
  EXPECT_NEAR(s.wrench(b)[2], 500 * kG + 1000, 1e-3 * 500 * kG);
  EXPECT_EQ(s.d->xfrc_applied[6 * b + 2], -1000);  // untouched
}

TEST(Glue, ReadableWrenchIsWhatWasApplied) {
  // qfrc_passive holds only mjbuoy's force here (no joint springs or
  // damping): it must equal J^T of the readable wrench at the COM
  Scene s(kBarge);
  ASSERT_TRUE(s.ok()) << s.err;
  int b = s.body("barge");
  double* q = s.d->qpos;
  q[2] = -0.05;
  q[3] = 0.98; q[4] = 0.1; q[5] = -0.15; q[6] = 0.05;
  mju_normalize4(q + 3);
  for (int i = 0; i < 6; i++) s.d->qvel[i] = 0.3 * (i - 2.5);
  mj_forward(s.m, s.d);
  mjtNum expect[6] = {0};
  const mjtNum* w = s.wrench(b);
  mj_applyFT(s.m, s.d, w, w + 3, s.d->xipos + 3 * b, b, expect);
  for (int i = 0; i < 6; i++) EXPECT_NEAR(s.d->qfrc_passive[i], expect[i], 1e-9);
  EXPECT_GT(w[2], 0);
}

// a user's own passive force: 5 N along x on the free joint
void userForce(const mjModel*, mjData* d) { d->qfrc_passive[0] += 5; }

TEST(Glue, ChainsAndRestoresPreviousCallback) {
  mjfGeneric saved = mjcb_passive;
  mjcb_passive = userForce;
  {
    Scene s(kBarge);
    ASSERT_TRUE(s.ok()) << s.err;
    s.d->qpos[2] = 0;
    mj_forward(s.m, s.d);
    // both act: mjbuoy's wrench mapped through J^T, plus the user's 5 N
    mjtNum own[6] = {0};
    const mjtNum* w = s.wrench(1);
    mj_applyFT(s.m, s.d, w, w + 3, s.d->xipos + 3, 1, own);
    EXPECT_NEAR(s.d->qfrc_passive[0], own[0] + 5, 1e-9);
    EXPECT_NEAR(s.d->qfrc_passive[2], kRho * kG * 0.5, 1e-6);
  }
  EXPECT_EQ(mjcb_passive, userForce);  // restored at detach
  mjcb_passive = saved;
}

TEST(Glue, SeveralDataAndModelsKeepTheirOwnState) {
  // two mjData of one model at different depths, and a second model with a
  // denser sea: each gets rho g V_sub of its own pose
  Scene s(kBarge);
  ASSERT_TRUE(s.ok()) << s.err;
  std::string salty = kBarge;
  salty.replace(salty.find("<custom>"), 8,
                "<custom><numeric name=\"mjbuoy.sea.density\" data=\"1025\"/>");
  Scene t(salty);
  ASSERT_TRUE(t.ok()) << t.err;
  mjData* d2 = mj_makeData(s.m);
  ASSERT_TRUE(mjb_bindData(s.b, d2));
  int b = s.body("barge");
  s.d->qpos[2] = 0;      // draft 0.25: V = 0.5
  d2->qpos[2] = 0.1;     // draft 0.15: V = 0.3
  t.d->qpos[2] = 0;
  mj_forward(s.m, s.d);
  mj_forward(s.m, d2);
  mj_forward(t.m, t.d);
  EXPECT_NEAR(mjb_wrench(s.b, s.d)[6 * b + 2], kRho * kG * 0.5, 1e-9);
  EXPECT_NEAR(mjb_wrench(s.b, d2)[6 * b + 2], kRho * kG * 0.3, 1e-9);
  EXPECT_NEAR(mjb_wrench(t.b, t.d)[6 * b + 2], 1025 * kG * 0.5, 1e-9);
  EXPECT_EQ(mjb_wrench(t.b, d2), nullptr);  // never stepped with that model
  mjb_unbindData(s.b, d2);
  EXPECT_EQ(mjb_wrench(s.b, d2), nullptr);
  mj_deleteData(d2);
}

}  // namespace
}  // namespace mjbt
