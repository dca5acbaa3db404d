// the panel budget (mjbuoy.radiation.panels): an explicit value is the
// user's, a hull refined on purpose keeps its panels, and every panel
// warning names the setting and the value to set (docs/physics.md section
// 13, "Coarsened hulls"; mjbuoy/radiation/radattach.cc)
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "hemisphere.h"
#include "testutil.h"

namespace mjbt {
namespace {

// a 2 x 1 x 0.8 m box floating at half its height, yawed 30 degrees in
// its body (no mirror plane in the panel frame, so every wet panel counts
// against the budget), radiation at 3 frequencies; extra: more entries
std::string yawedBox(const std::string& extra) {
  return "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h\"/>"
         "<numeric name=\"mjbuoy.sea.density\" data=\"1000\"/>"
         "<numeric name=\"mjbuoy.radiation.omega\" data=\"1 6 3\"/>" + extra +
         "</custom><worldbody><body name=\"box\"><freejoint/><geom name=\"h\" type=\"box\" "
         "size=\"1 0.5 0.4\" euler=\"0 0 30\" mass=\"800\" contype=\"0\" conaffinity=\"0\"/>"
         "</body></worldbody></mujoco>";
}

// A_inf and B of the model's one radiating body, and its warnings
std::vector<double> coef(const std::string& xml, std::string* warn) {
  Scene s(xml);
  EXPECT_TRUE(s.ok()) << s.err;
  if (!s.ok()) return {};
  const mjb::Buoy* B = mjb::buoyOf(s.b);
  EXPECT_EQ(B->coef.size(), 1u) << mjb_warnings(s.b);
  if (B->coef.size() != 1) return {};
  const mjb::HydroCoef& c = B->coef[0].second;
  std::vector<double> v(c.Ainf, c.Ainf + 36);
  v.insert(v.end(), c.B.begin(), c.B.end());
  *warn = mjb_warnings(s.b);
  return v;
}

double largest(const std::vector<double>& v) {
  double big = 0;
  for (double x : v) big = std::max(big, std::fabs(x));
  return big;
}

TEST(RadBudget, RefinedHullKeepsItsPanels) {
  // refine 1 splits the box's 96 wet triangles in 4: 384 wet panels and
  // the lid, above the default budget of 400. Given alone, refine is the
  // user's choice of panels: the solution is the full refined mesh's (the
  // same coefficients as with the budget off, panels = 0, within 1e-9 of
  // their largest), not a copy coarsened back to 400 (an explicit
  // panels = 400 with refine 1; A_inf and B more than 0.1% apart from the
  // full mesh: a coarser mesh is a different discretisation)
  std::string w0, w1, w2;
  std::vector<double> refined = coef(yawedBox("<numeric name=\"mjbuoy.radiation.refine\" "
                                              "data=\"1\"/>"), &w0);
  std::vector<double> full = coef(yawedBox("<numeric name=\"mjbuoy.radiation.refine\" data=\"1\"/>"
                                           "<numeric name=\"mjbuoy.radiation.panels\" "
                                           "data=\"0\"/>"), &w1);
  std::vector<double> budget = coef(yawedBox("<numeric name=\"mjbuoy.radiation.refine\" "
                                             "data=\"1\"/><numeric name=\"mjbuoy.radiation."
                                             "panels\" data=\"400\"/>"), &w2);
  ASSERT_EQ(refined.size(), full.size());
  ASSERT_EQ(budget.size(), full.size());
  const double big = largest(full);
  double diff = 0;
  for (size_t i = 0; i < full.size(); i++) {
    EXPECT_NEAR(refined[i], full[i], 1e-9 * big) << i;
    diff = std::max(diff, std::fabs(budget[i] - full[i]));
  }
  EXPECT_GT(diff, 1e-3 * big);
  EXPECT_EQ(w0.find("coarsened"), std::string::npos) << w0;
  // the explicit budget coarsens, and its warning names the setting and
  // the value that solves the full mesh
  EXPECT_NE(w2.find("hull coarsened for the panel solver"), std::string::npos) << w2;
  EXPECT_NE(w2.find("<numeric name=\"mjbuoy.radiation.panels\" data=\"0\"/> solves the full "
                    "mesh"), std::string::npos) << w2;
}

// a 20 x 5 m box of 1 m height floating at a draft of 0.25 m (25 t), free,
// drag terms off; extra: more entries
std::string longBox(const std::string& extra) {
  return std::string("<mujoco><option timestep=\"0.002\"/><custom>"
                     "<text name=\"mjbuoy.hulls\" data=\"h\"/>"
                     "<numeric name=\"mjbuoy.sea.density\" data=\"1000\"/>"
                     "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>"
                     "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0.5\"/>"
                     "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0.5\"/>"
                     "<numeric name=\"mjbuoy.hull.slamming\" data=\"0 100 2\"/>"
                     "<numeric name=\"mjbuoy.radiation.omega\" data=\"1.5 2.5 5\"/>") +
         extra + "</custom><worldbody><body name=\"box\" pos=\"0 0 0.25\"><freejoint/>"
         "<geom name=\"h\" type=\"box\" size=\"10 2.5 0.5\" mass=\"25000\" "
         "contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>";
}

// heave decay period [s] from 5 cm above the draft: the mean spacing of
// the first three up-crossings of the rest level (box centre at 0.25 m)
double decayPeriod(const std::string& xml) {
  Scene s(xml);
  EXPECT_TRUE(s.ok()) << s.err;
  if (!s.ok()) return NAN;
  s.d->qpos[2] += 0.05;
  std::vector<double> up;
  double z0 = s.d->qpos[2] - 0.25, t0 = 0;
  const long n = stepsTo(s.m, s.d, 15);
  for (long i = 0; i < n && up.size() < 3; i++) {
    mj_step(s.m, s.d);
    double z = s.d->qpos[2] - 0.25;
    if (z0 < 0 && z >= 0) up.push_back(t0 + (s.d->time - t0) * -z0 / (z - z0));
    z0 = z, t0 = s.d->time;
  }
  return up.size() == 3 ? 0.5 * (up[2] - up[0]) : NAN;
}

TEST(RadBudget, LongShallowBoxGetsPanelsForItsDraft) {
  // the box's tessellation (4 x 4 squares a face) gives bottom panels 5 x
  // 1.25 m, 5 drafts wide: the panel integrals do not resolve the draft.
  // The default refines it until its panels are at most 3 drafts wide
  // (docs/physics.md section 13, "Panel size") while the default budget
  // of 400 holds: once (256 wet panels of 2.5 x 0.63 m; twice, 1024 and
  // the lid, is above it at cost). Reference: the converged
  // solution, an explicit refine 2 with panels 0 (1024 wet panels of 1.25
  // x 0.31 m). Expected:
  // heave damping at the five frequencies around the heave resonance
  // (omega_n = sqrt(rho g A_wp / (m + A33)) = 2.1 rad/s) and the heave
  // decay period within 5%; the unrefined mesh (refine 0 given) is not
  // (B33 at 2.5 rad/s 56% low)
  std::string w;
  std::vector<double> fine = coef(longBox("<numeric name=\"mjbuoy.radiation.refine\" "
                                          "data=\"2\"/><numeric name=\"mjbuoy.radiation."
                                          "panels\" data=\"0\"/>"), &w);
  std::vector<double> def = coef(longBox(""), &w);
  std::vector<double> raw = coef(longBox("<numeric name=\"mjbuoy.radiation.refine\" "
                                         "data=\"0\"/>"), &w);
  ASSERT_EQ(fine.size(), 36u + 5 * 36);
  ASSERT_EQ(def.size(), fine.size());
  ASSERT_EQ(raw.size(), fine.size());
  double rawErr = 0;
  for (int k = 0; k < 5; k++) {
    const double b = fine[36 + 36 * k + 14];
    EXPECT_NEAR(def[36 + 36 * k + 14], b, 0.05 * b) << "B33 at frequency " << k;
    rawErr = std::max(rawErr, std::fabs(raw[36 + 36 * k + 14] / b - 1));
  }
  EXPECT_GT(rawErr, 0.05);
  const double Tf = decayPeriod(longBox("<numeric name=\"mjbuoy.radiation.refine\" data=\"2\"/>"
                                        "<numeric name=\"mjbuoy.radiation.panels\" data=\"0\"/>"));
  const double Td = decayPeriod(longBox(""));
  std::printf("[radbudget] 20 m box: heave period default %.4f s, converged %.4f s; B33 "
              "worst of the unrefined mesh %.1f%%\n", Td, Tf, 100 * rawErr);
  EXPECT_NEAR(Td, Tf, 0.05 * Tf);
}

TEST(RadBudget, SymmetricHullCountsItsMatrices) {
  // the Wigley of models/wigley.xml: 408 wet panels with the lid, mirror
  // symmetric about x = 0 and y = 0, solved as 4 systems of 102 rows.
  // Each influence matrix holds N N / 4 = 408 x 102 = 41616 entries, more
  // than the 180 x 180 = 32400 of an unsymmetric hull at a budget of 180
  // (hand count; docs/physics.md section 13, "Coarsened hulls"): the
  // budget coarsens it to at most 180 panels (counted at the LU's N^3 / 16
  // alone, 408 / 4^(2/3) = 162 panels, it would not be)
  std::string w;
  std::vector<double> c = coef(shippedModel("wigley.xml", "<numeric name=\"mjbuoy.radiation."
                                            "omega\" data=\"2 6 3\"/><numeric name=\"mjbuoy."
                                            "radiation.panels\" data=\"180\"/>"), &w);
  EXPECT_EQ(c.size(), 36u + 3 * 36);
  const std::string key = "hull coarsened for the panel solver from ";
  size_t at = w.find(key);
  ASSERT_NE(at, std::string::npos) << w;
  int from = 0, to = 0;
  ASSERT_EQ(std::sscanf(w.c_str() + at + key.size(), "%d to %d", &from, &to), 2) << w;
  EXPECT_EQ(from, 408) << w;
  EXPECT_LE(to, 180) << w;
}

TEST(RadBudget, CoarseningAHemisphereOnASlideAttaches) {
  // an 8 x 24 hemisphere (R 1 m) on a slide joint under the default budget:
  // the coarsening's later tries ask for more triangles than the mesh has,
  // which the simplifier refuses by aborting the process; attach must
  // succeed with the body's coefficients (the library never aborts)
  std::string xml =
      "<mujoco><asset>" + hemisphereMeshXML(hemisphereAreaScale(24), 8, 24, 0.3) +
      "</asset><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
      "<numeric name=\"mjbuoy.sea.density\" data=\"1025\"/>"
      "<numeric name=\"mjbuoy.radiation.omega\" data=\"0.7 7 6\"/></custom>"
      "<worldbody><body name=\"hemi\"><joint type=\"slide\" axis=\"1 0 0\" "
      "stiffness=\"300\"/><inertial pos=\"0 0 -0.3\" mass=\"2146.8\" "
      "diaginertia=\"858 858 858\"/><geom name=\"hull\" type=\"mesh\" mesh=\"hemi\" "
      "contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>";
  Scene s(xml);
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_EQ(mjb::buoyOf(s.b)->coef.size(), 1u) << mjb_warnings(s.b);
}

}  // namespace
}  // namespace mjbt
