// the panel budget (mjbuoy.radiation.panels): an explicit value is the
// user's, a hull refined on purpose keeps its panels, and every panel
// warning names the setting and the value to set (docs/physics.md section
// 13, "Coarsened hulls"; mjbuoy/radiation/radattach.cc)
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
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

}  // namespace
}  // namespace mjbt
