// mjbuoy.radiation.group: bodies solved together at attach (docs/physics.md
// section 14, "Interaction"; docs/mjcf.md, "Radiation")
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testutil.h"

namespace {

using mjbt::Scene;

// floating 1 m cubes (half immersed at rest: mass rho / 2) "a", "b", "c"
// at x = 0, gap and -gap [m] (the row symmetric about both vertical
// planes: the group solve keeps its mirror symmetry); extra: more custom
// entries
std::string cubes(double gap, const std::string& extra) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.005\"/><custom>"
    << "<text name=\"mjbuoy.hulls\" data=\"ha hb hc\"/>"
    << "<numeric name=\"mjbuoy.sea.density\" data=\"1000\"/>"
    << "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>"
    << "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0\"/>"
    << "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0\"/>"
    << "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
    << "<text name=\"mjbuoy.radiation.drift\" data=\"off\"/>"
    << "<numeric name=\"mjbuoy.radiation.refine\" data=\"0\"/>"
    << "<numeric name=\"mjbuoy.radiation.omega\" data=\"0.9 9 12\"/>" << extra
    << "</custom><worldbody>";
  const double at[3][2] = {{0, 0}, {gap, 0}, {-gap, 0}};
  const char* n[3] = {"a", "b", "c"};
  for (int k = 0; k < 3; k++) {
    s << "<body name=\"" << n[k] << "\" pos=\"" << at[k][0] << " " << at[k][1]
      << " 0\"><freejoint/><inertial pos=\"0 0 -0.2\" mass=\"500\" diaginertia=\"100 100 100\"/>"
      << "<geom name=\"h" << n[k] << "\" type=\"box\" size=\"0.5 0.5 0.5\" contype=\"0\" "
      << "conaffinity=\"0\"/></body>";
  }
  s << "<body name=\"dry\" pos=\"0 0 5\"><freejoint/><geom size=\"0.1\"/></body>"
    << "</worldbody></mujoco>";
  return s.str();
}

std::string group(const char* text) {
  return std::string("<text name=\"mjbuoy.radiation.group\" data=\"") + text + "\"/>";
}

// each bad group is refused at attach with the field, the body and the fix
TEST(RadGroup, BadGroupsAreRefusedByName) {
  struct Case { std::string extra, want; };
  const std::string field = "<text name=\"mjbuoy.radiation.group\"> names body ";
  const Case cs[] = {
      {group("a nobody"), field + "\"nobody\", which does not exist; give the name of a body"},
      {group("a dry"), field + "\"dry\", which carries no hull; list its geoms in mjbuoy.hulls"},
      {group("a c") + "<text name=\"mjbuoy.radiation.body.c\" data=\"off\"/>",
       field + "\"c\", which has no radiation (off, or it cannot move); turn its radiation on"},
      {group("a b; b c"), field + "\"b\", which is in two groups (or twice in one); name each"},
      {group("a a"), field + "\"a\", which is in two groups"},
      {group("a b; c"), field + "\"c\", alone in its group; a group solves 2 or more bodies"},
      {group("a b;; c a"), "<text name=\"mjbuoy.radiation.group\"> data = \"a b;; c a\" has an "
                           "empty group; give body names separated by spaces"},
  };
  for (const Case& c : cs) {
    Scene s(cubes(4, c.extra));
    EXPECT_FALSE(s.ok()) << c.extra;
    EXPECT_NE(s.err.find(c.want), std::string::npos) << c.extra << "\n" << s.err;
  }
}

// body a's heave [m] over T seconds from 5 cm below its rest, the others at rest
std::vector<double> heaveA(Scene& s, double T) {
  const int a = s.body("a");
  const int q = s.m->jnt_qposadr[s.m->body_jntadr[a]];
  s.d->qpos[q + 2] = -0.05;
  mj_forward(s.m, s.d);
  std::vector<double> z;
  while (s.d->time < T) {
    mj_step(s.m, s.d);
    z.push_back(s.d->qpos[q + 2]);
  }
  return z;
}

// 50 cube widths apart, in a row (k d = 45 at the lowest frequency solved, 0.9 rad/s)
// the wave a body radiates and the other scatters back is O(1 / (k d)) of
// its own at the body and arrives after the decay is over (group velocity
// g / (2 omega) = 2.5 m/s at the 2 rad/s heave frequency: 20 s for 50 m
// each way): the grouped decay is the ungrouped one (docs/physics.md
// section 13, "Interaction between bodies": the separation limit)
TEST(RadGroup, FarApartDecayIsTheUngroupedOne) {
  Scene one(cubes(50, "")), two(cubes(50, group("a b c")));
  ASSERT_TRUE(one.ok()) << one.err;
  ASSERT_TRUE(two.ok()) << two.err;
  std::vector<double> z1 = heaveA(one, 8), z2 = heaveA(two, 8);
  ASSERT_EQ(z1.size(), z2.size());
  double worst = 0, amp = 0;
  for (size_t i = 0; i < z1.size(); i++) {
    worst = std::max(worst, std::fabs(z1[i] - z2[i]));
    amp = std::max(amp, std::fabs(z1[i]));
  }
  std::printf("[radgroup] 50 m apart: largest heave difference %.3g m of %.3g m\n", worst, amp);
  EXPECT_LT(worst, 0.01 * amp);
}

}  // namespace
