// equilibrium drafts and righting arms against analytic naval architecture
// (physics.md section 8); MuJoCo integrates, mjbuoy only adds forces
#include <sstream>

#include <gtest/gtest.h>

#include "testutil.h"
#include "tetclip.h"

namespace mjbt {
namespace {

// one free body with a single hull geom `geom` (MJCF attributes) and damping
std::string floater(const std::string& geom, const std::string& body, const char* damp) {
  return "<mujoco><option timestep=\"0.002\"/><custom>"
         "<text name=\"mjbuoy.hulls\" data=\"hull\"/>"
         "<numeric name=\"mjbuoy.hull.damping\" data=\"" + std::string(damp) + "\"/>"
         "</custom><worldbody><body name=\"b\" " + body + "><freejoint/>"
         "<geom name=\"hull\" " + geom + "/></body></worldbody></mujoco>";
}

TEST(Equilibrium, BoxBargeDraft) {
  // 2 x 1 x 0.5 m, 500 kg: T = m / (rho L B) = 0.25 m, so the COM sits at z = 0
  Scene s(floater("type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"", "pos=\"0 0 0.3\"",
                  "3000 300"));
  ASSERT_TRUE(s.ok()) << s.err;
  int b = s.body("b");
  double z = s.settle(30, 5, [&] { return s.d->xipos[3 * b + 2]; });
  double draft = 0.25 - z;
  EXPECT_NEAR(draft, 0.25, 0.005 * 0.25);
  RecordProperty("barge_draft", std::to_string(draft) + " vs 0.25");
}

TEST(Equilibrium, SphereDraft) {
  // R = 0.5, 300 kg/m^3: pi h^2 (3R - h) / 3 = m / rho
  const double R = 0.5, m = 300 * 4 * M_PI / 3 * R * R * R;
  double h = bisect([&](double x) { return M_PI * x * x * (3 * R - x) / 3 - m / kRho; }, 0, 2 * R);
  std::ostringstream g;
  g.precision(17);
  g << "type=\"sphere\" size=\"0.5\" mass=\"" << m << "\"";
  Scene s(floater(g.str(), "pos=\"0 0 0.4\"", "2000 20"));
  ASSERT_TRUE(s.ok()) << s.err;
  int b = s.body("b");
  double z = s.settle(30, 5, [&] { return s.d->xipos[3 * b + 2]; });
  EXPECT_NEAR(R - z, h, 0.005 * h) << "analytic draft " << h;
  RecordProperty("sphere_draft", std::to_string(R - z) + " vs " + std::to_string(h));
}

TEST(Equilibrium, HorizontalCylinderDraft) {
  // R = 0.3, length 2, 400 kg/m^3: A(h) L = m / rho with the circular segment
  // A(h) = R^2 acos((R - h) / R) - (R - h) sqrt(2 R h - h^2)
  const double R = 0.3, L = 2, m = 400 * M_PI * R * R * L;
  auto A = [&](double x) {
    return R * R * std::acos((R - x) / R) - (R - x) * std::sqrt(2 * R * x - x * x);
  };
  double h = bisect([&](double x) { return A(x) * L - m / kRho; }, 0, 2 * R);
  std::ostringstream g;
  g.precision(17);
  g << "type=\"cylinder\" size=\"0.3 1\" euler=\"0 90 0\" mass=\"" << m << "\"";
  Scene s(floater(g.str(), "pos=\"0 0 0.3\"", "3000 50"));
  ASSERT_TRUE(s.ok()) << s.err;
  int b = s.body("b");
  double z = s.settle(30, 5, [&] { return s.d->xipos[3 * b + 2]; });
  EXPECT_NEAR(R - z, h, 0.005 * h) << "analytic draft " << h;
  RecordProperty("cylinder_draft", std::to_string(R - z) + " vs " + std::to_string(h));
}

TEST(Equilibrium, WigleyDraftFromItsOwnVolume) {
  // ballasted Wigley hull: the draft where the mesh's clipped volume
  // (tetrahedra, independent of mjbuoy) equals m / rho
  const double m = 120;
  std::string xml =
      "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
      "/meshes/wigley_576.obj\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
      "<numeric name=\"mjbuoy.hull.damping\" data=\"3000 100\"/></custom><worldbody>"
      "<body name=\"b\" pos=\"0 0 0.2\"><freejoint/>"
      "<inertial pos=\"0 0 -0.1\" mass=\"120\" diaginertia=\"5 160 160\"/>"
      "<geom name=\"hull\" type=\"mesh\" mesh=\"w\"/></body></worldbody></mujoco>";
  Scene s(xml);
  ASSERT_TRUE(s.ok()) << s.err;
  int b = s.body("b");
  std::vector<int> f = faces(s.m, 0);
  // body height z at which the upright hull displaces m / rho
  auto excess = [&](double z) {
    mj_resetData(s.m, s.d);
    s.d->qpos[2] = z;
    mj_kinematics(s.m, s.d);
    return submerged(worldVerts(s.m, s.d, 0), f, 0).vol - m / kRho;
  };
  double z0 = bisect(excess, -1, 1);
  // the design draft is 0.25 m (mesh keel at body z = -0.25)
  mj_resetData(s.m, s.d);
  s.d->qpos[2] = z0;
  mj_kinematics(s.m, s.d);
  double keel = 1e9;
  for (const Vector3d& p : worldVerts(s.m, s.d, 0)) keel = std::min(keel, p.z());
  const double draft = -keel;

  mj_resetData(s.m, s.d);
  double z = s.settle(30, 5, [&] { return s.d->xpos[3 * b + 2]; });
  EXPECT_NEAR(z - z0, 0, 0.005 * draft) << "own-volume draft " << draft;
  RecordProperty("wigley_draft", std::to_string(draft - (z - z0)) + " vs " + std::to_string(draft));
  EXPECT_NEAR(roll(s.d, b), 0, 1e-3);
}

// box barge at fixed heel phi: solve the height for F_z = m g, then
// GZ = -tau_x / (m g) about the COM
double righting(Scene* s, double phi, double mass) {
  int b = s->body("b");
  double* q = s->d->qpos;
  auto pose = [&](double z) {
    q[0] = q[1] = 0;
    q[2] = z;
    q[3] = std::cos(phi / 2);
    q[4] = std::sin(phi / 2);
    q[5] = q[6] = 0;
    mj_forward(s->m, s->d);
  };
  double z = bisect([&](double z) { pose(z); return s->wrench(b)[2] - mass * kG; }, -0.3, 0.3);
  pose(z);
  return -s->wrench(b)[3] / (mass * kG);
}

TEST(Stability, BoxRightingArmMatchesWallSidedFormula) {
  // B = 1, T = 0.25, KG = 0.25: GM = T/2 + B^2/(12 T) - KG = 0.208333,
  // GZ = sin(phi) (GM + BM tan^2(phi) / 2), exact while wall-sided
  Scene s(floater("type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"", "", "0 0"));
  ASSERT_TRUE(s.ok()) << s.err;
  const double T = 0.25, BM = 1.0 / (12 * T), GM = T / 2 + BM - 0.25;
  for (double deg : {10.0, 20.0}) {
    double phi = deg * M_PI / 180;
    double gz = std::sin(phi) * (GM + 0.5 * BM * std::tan(phi) * std::tan(phi));
    double got = righting(&s, phi, 500);
    EXPECT_NEAR(got, gz, 0.005 * gz) << deg << " deg";
    RecordProperty(deg == 10 ? "GZ10" : "GZ20", std::to_string(got));
  }
  EXPECT_NEAR(righting(&s, 10 * M_PI / 180, 500), 0.037077, 0.005 * 0.037077);
  EXPECT_NEAR(righting(&s, 20 * M_PI / 180, 500), 0.078806, 0.005 * 0.078806);
}

TEST(Stability, NegativeGMSettlesAtAngleOfLoll) {
  // L 2, B 1, H 1, 440 kg: T = 0.22, BM = B^2/(12 T), GM = T/2 + BM - H/2 < 0;
  // wall-sided loll: tan(phi) = sqrt(-2 GM / BM)
  const double T = 0.22, BM = 1 / (12 * T), GM = T / 2 + BM - 0.5;
  ASSERT_LT(GM, 0);
  const double loll = std::atan(std::sqrt(-2 * GM / BM));
  Scene s(floater("type=\"box\" size=\"1 0.5 0.5\" mass=\"440\"",
                  "pos=\"0 0 0.28\" euler=\"2 0 0\"", "3000 60"));
  ASSERT_TRUE(s.ok()) << s.err;
  int b = s.body("b");
  double phi = s.settle(60, 5, [&] { return roll(s.d, b); });
  EXPECT_NEAR(phi, loll, 0.005 * loll) << "loll " << loll * 180 / M_PI << " deg";
  RecordProperty("loll_deg", std::to_string(phi * 180 / M_PI) + " vs " +
                                 std::to_string(loll * 180 / M_PI));
}

}  // namespace
}  // namespace mjbt
