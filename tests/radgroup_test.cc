// mjbuoy.radiation.group: bodies solved together at attach (docs/physics.md
// section 14, "Interaction"; docs/mjcf.md, "Radiation")
#include <cmath>
#include <cstdlib>
#include <complex>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "api/radgroup.h"
#include "hull/hull.h"
#include "radiation/coupgain.h"
#include "radiation/panel.h"
#include "radiation/panelmesh.h"

#include "testutil.h"

namespace {

using mjbt::Scene;

// fresh water, no Kerner drag or viscous terms, radiation on, no drift,
// unrefined panels: the cubes feel hydrostatics and potential flow only
const char* const kPotentialOnly =
    "<numeric name=\"mjbuoy.sea.density\" data=\"1000\"/>"
    "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>"
    "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0\"/>"
    "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0\"/>"
    "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
    "<text name=\"mjbuoy.radiation.drift\" data=\"off\"/>"
    "<numeric name=\"mjbuoy.radiation.refine\" data=\"0\"/>";

// floating 1 m cubes (half immersed at rest: mass rho / 2) "a", "b", "c"
// at x = 0, gap and -gap [m] (the row symmetric about both vertical
// planes: the group solve keeps its mirror symmetry); extra: more custom
// entries
std::string cubes(double gap, const std::string& extra) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.005\"/><custom>"
    << "<text name=\"mjbuoy.hulls\" data=\"ha hb hc\"/>"
    << kPotentialOnly
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

// two cubes on vertical slides, "a" at x = 0 and "b" at x = gap [m]
std::string slides(double gap) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.005\"/><custom>"
    << "<text name=\"mjbuoy.hulls\" data=\"ha hb\"/>"
    << kPotentialOnly
    << "<numeric name=\"mjbuoy.radiation.omega\" data=\"0.4 12 40\"/>"
    << "<text name=\"mjbuoy.radiation.group\" data=\"a b\"/>"
    << "</custom><worldbody>";
  const char* n[2] = {"a", "b"};
  for (int k = 0; k < 2; k++) {
    s << "<body name=\"" << n[k] << "\" pos=\"" << k * gap << " 0 0\">"
      << "<joint type=\"slide\" axis=\"0 0 1\"/>"
      << "<inertial pos=\"0 0 -0.2\" mass=\"500\" diaginertia=\"100 100 100\"/>"
      << "<geom name=\"h" << n[k] << "\" type=\"box\" size=\"0.5 0.5 0.5\" contype=\"0\" "
      << "conaffinity=\"0\"/></body>";
  }
  s << "</worldbody></mujoco>";
  return s.str();
}

// body a forced in heave, x_a = X sin(w t), body b held at rest 3 m away
// (3 widths, k d = 2.8): the force on b is the coupling block's,
// F_b = -(A_ba(w) x_a'' + B_ba(w) x_a') = X w^2 A_ba sin(w t) - X w B_ba cos(w t)
// (docs/physics.md section 14, "Interaction"). The expected A_ba, B_ba
// come from panelSolveGroup at w itself on the hulls' panels (the
// frequency domain); the simulation has only A_ba(inf) and the kernel
// K_ba(t) from the tabulated B_ba (the time domain), so agreement checks
// the coupling's memory, its added mass and the frame change
TEST(RadGroup, ForcedHeaveGivesTheCouplingForce) {
  const double gap = 3, X = 0.02, w = 3;
  Scene s(slides(gap));
  ASSERT_TRUE(s.ok()) << s.err;
  // the frequency domain: the same wet panels (hullPanels at the floating
  // pose, z = 0: mass = half the displacement), b's moved by gap
  std::vector<mjb::PanelMesh> body(2), lid(2);
  for (int k = 0; k < 2; k++) {
    std::vector<std::string> warn;
    mjb::Mesh mesh = mjb::hullMesh(s.m, k, &warn);
    std::vector<float> v(mesh.v.begin(), mesh.v.end());
    const double pos[3] = {0, 0, 0}, quat[4] = {1, 0, 0, 0};
    std::string note;
    ASSERT_TRUE(mjb::hullPanels(v.data(), mesh.nv(), mesh.f.data(), mesh.nf(), pos, quat, 0,
                                &body[k], &lid[k], &note)) << note;
  }
  for (size_t i = 0; i < body[1].vert.size(); i += 3) body[1].vert[i] += gap;
  for (size_t i = 0; i < lid[1].vert.size(); i += 3) lid[1].vert[i] += gap;
  mjb::PanelGroupCoef g;
  g.rho = 1000;
  g.g = s.m->opt.gravity[2] ? -s.m->opt.gravity[2] : 9.81;
  g.ref = {0, 0, 0, gap, 0, 0};
  std::string err;
  ASSERT_TRUE(mjb::panelSolveGroup(body, lid, {w}, {}, &g, &err)) << err;
  const int nm = g.nm();
  const double Aba = g.A[nm * 8 + 2], Bba = g.B[nm * 8 + 2];
  // the time domain: a prescribed, b at rest, 40 s; the force on b's slide
  // less its rest value, fitted to c0 + c1 sin + c2 cos over the last 10 s
  const int qa = s.m->jnt_qposadr[0], qb = s.m->jnt_qposadr[1];
  const int va = s.m->jnt_dofadr[0], vb = s.m->jnt_dofadr[1];
  double S[3][3] = {{0}}, r[3] = {0};
  while (s.d->time < 40) {
    const double t = s.d->time;
    s.d->qpos[qa] = X * std::sin(w * t);
    s.d->qvel[va] = X * w * std::cos(w * t);
    s.d->qpos[qb] = 0, s.d->qvel[vb] = 0;
    mj_step(s.m, s.d);
    if (t < 30) continue;
    const double f[3] = {1, std::sin(w * t), std::cos(w * t)}, F = s.d->qfrc_passive[vb];
    for (int i = 0; i < 3; i++) {
      r[i] += f[i] * F;
      for (int j = 0; j < 3; j++) S[i][j] += f[i] * f[j];
    }
  }
  // the 3 x 3 normal equations by Cramer's rule
  auto det = [](double M[3][3]) {
    return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
           M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
           M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  };
  double c[3], D = det(S);
  for (int k = 0; k < 3; k++) {
    double T[3][3];
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) T[i][j] = j == k ? r[i] : S[i][j];
    c[k] = det(T) / D;
  }
  const std::complex<double> got(c[1], c[2]), want(X * w * w * Aba, -X * w * Bba);
  std::printf("[radgroup] forced heave at %g rad/s, %g m apart: A_ba %.4g kg, B_ba %.4g kg/s; "
              "force on b sin %.4g cos %.4g N, expected %.4g %.4g N (|error| %.2f%%)\n", w, gap,
              Aba, Bba, c[1], c[2], want.real(), want.imag(),
              100 * std::abs(got - want) / std::abs(want));
  EXPECT_LT(std::abs(got - want), 0.05 * std::abs(want));
}

// the cache holds a group by every member's panels at their relative
// placement: the same model reads it back (the couplings equal), a
// member moved by 1 m solves the group again
TEST(RadGroup, CacheMissesWhenABodyMoves) {
  char tmpl[] = "/tmp/mjbuoy-radgroup-XXXXXX";
  ASSERT_NE(mkdtemp(tmpl), nullptr);
  const std::string dir = tmpl;
  const std::string extra = group("a b") + "<text name=\"mjbuoy.radiation.cache\" data=\"" +
                            dir + "\"/>";
  Scene s1(cubes(4, extra)), s2(cubes(4, extra)), s3(cubes(5, extra));
  ASSERT_TRUE(s1.ok() && s2.ok() && s3.ok()) << s1.err << s2.err << s3.err;
  const mjb::Buoy* b1 = mjb::buoyOf(s1.b);
  const mjb::Buoy* b2 = mjb::buoyOf(s2.b);
  const mjb::Buoy* b3 = mjb::buoyOf(s3.b);
  EXPECT_EQ(b1->radcache.miss, 3);  // the group's two bodies and "c", solved alone
  EXPECT_EQ(b2->radcache.miss, 0);
  EXPECT_EQ(b2->radcache.hit, 3);
  EXPECT_EQ(b3->radcache.miss, 2);  // b moved: the group again; c alone is still cached
  ASSERT_EQ(b1->rad.cp.size(), 2u);
  ASSERT_EQ(b2->rad.cp.size(), 2u);
  for (int k = 0; k < 36; k++) EXPECT_EQ(b1->rad.cp[0].A[k], b2->rad.cp[0].A[k]);
  EXPECT_NE(b1->rad.cp[0].A[14], b3->rad.cp[0].A[14]);  // heave-heave coupling moved
  std::system(("rm -rf '" + dir + "'").c_str());
}

}  // namespace

// two free floating 1 m cubes of mass [kg] (draft mass / rho) side by side
// along x, centres gap apart [m]
std::string pairOf(double gap, double mass) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.005\"/><custom>"
    << "<text name=\"mjbuoy.hulls\" data=\"ha hb\"/>" << kPotentialOnly
    << "<numeric name=\"mjbuoy.radiation.omega\" data=\"0.9 9 12\"/>"
    << "<text name=\"mjbuoy.radiation.group\" data=\"a b\"/></custom><worldbody>";
  const char* n[2] = {"a", "b"};
  for (int k = 0; k < 2; k++) {
    s << "<body name=\"" << n[k] << "\" pos=\"" << k * gap << " 0 0\"><freejoint/>"
      << "<inertial pos=\"0 0 -0.2\" mass=\"" << mass << "\" diaginertia=\"" << mass / 5 << " "
      << mass / 5 << " " << mass / 5 << "\"/><geom name=\"h" << n[k]
      << "\" type=\"box\" size=\"0.5 0.5 0.5\" contype=\"0\" conaffinity=\"0\"/></body>";
  }
  s << "</worldbody></mujoco>";
  return s.str();
}

// the explicit coupling's gain, spectral radius of D^-1 O, by hand:
// identical blocks D = d I and O_ij = c I (i != j) give (c / d) (J - I)
// per dof, J all ones, whose eigenvalues are n - 1 and -1: gain (n - 1) c
// / d; two bodies with D_1 = d1 I, D_2 = d2 I, O_12 = c12 I, O_21 = c21 I:
// lambda^2 = c12 c21 / (d1 d2)
TEST(CouplingGain, HandCases) {
  auto blocks = [](int n, const std::vector<double>& d, const std::vector<double>& c,
                   std::vector<double>* D, std::vector<double>* O) {
    D->assign(36 * n, 0);
    O->assign(36 * n * n, 0);
    for (int i = 0; i < n; i++)
      for (int a = 0; a < 6; a++) {
        (*D)[36 * i + 7 * a] = d[i];
        for (int j = 0; j < n; j++)
          if (i != j) (*O)[36 * (n * i + j) + 7 * a] = c[n * i + j];
      }
  };
  std::vector<double> D, O;
  blocks(3, {900, 900, 900}, {0, 120, 120, 120, 0, 120, 120, 120, 0}, &D, &O);
  EXPECT_NEAR(mjb::couplingGain(3, D, O), 2 * 120.0 / 900, 1e-12);
  blocks(2, {400, 900}, {0, 150, 60, 0}, &D, &O);
  EXPECT_NEAR(mjb::couplingGain(2, D, O), std::sqrt(150.0 * 60 / (400 * 900)), 1e-12);
  // one coupled dof (heave): the others' zero rows do not matter
  blocks(2, {400, 900}, {0, 0, 0, 0}, &D, &O);
  O[36 * 1 + 7 * 2] = 500, O[36 * 2 + 7 * 2] = 800;
  EXPECT_NEAR(mjb::couplingGain(2, D, O), std::sqrt(500.0 * 800 / (400 * 900)), 1e-12);
  // singular or not finite: -1
  D[0] = 0;
  EXPECT_EQ(mjb::couplingGain(2, D, O), -1);
  D[0] = 400;
  O[36 * 1 + 7 * 2] = NAN;
  EXPECT_EQ(mjb::couplingGain(2, D, O), -1);
}

// two free cubes side by side: the pair's A(inf) is positive definite (the
// water's kinetic energy), and so is its mirror image with one body's
// coordinates reversed, so D - O and D + O are positive definite and the
// gain of two bodies stays below 1 (docs/physics.md section 14,
// "Interaction"); the coupling falls with the gap (the separation limit)
TEST(RadGroup, PairGainBelowOneAndFallsWithTheGap) {
  double prev = 2;
  for (double gap : {1.05, 1.25, 3.0}) {
    Scene s(pairOf(gap, 500));
    ASSERT_TRUE(s.ok()) << s.err;
    mj_forward(s.m, s.d);
    const std::vector<int> roots = {s.body("a"), s.body("b")};
    const double g = mjb::groupGain(*mjb::buoyOf(s.b), s.d, roots);
    std::printf("[radgroup] cubes %.2f m apart: coupling gain %.4f\n", gap, g);
    EXPECT_GT(g, 0);
    EXPECT_LT(g, 1);
    EXPECT_LT(g, prev);
    prev = g;
    // below kCoupleGainWarn: no warning names the group
    EXPECT_EQ(std::string(mjb_warnings(s.b)).find("explicit coupling"), std::string::npos);
  }
}
