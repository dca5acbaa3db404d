// the default viscous roll damping as a fraction of critical
// (mjbuoy.radiation.rollzeta; docs/physics.md section 14, "Viscous roll
// damping"): the hydrostatic roll stiffness of wet panels against the
// closed form of a floating box, the free roll decay of a floating box
// against the damped oscillator, the entry's defaults and bad input
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "radiation/hydrostatic.h"
#include "radiation/panelmesh.h"
#include "testutil.h"

namespace mjbt {
namespace {

// the box: L x B x H [m] along x, y, z, floating at draft kT with its
// mass rho L B kT; its COM at the centre, kKG above the keel
const double kL = 2, kB = 1, kH = 0.6, kT = 0.2, kKG = kH / 2;
const double kMass = kRho * kL * kB * kT;  // 400 kg

// C44 of a wall-sided box about a longitudinal axis through G: rho g V GM,
// GM = KB + BM - KG, KB = T / 2, BM = I_wp / V = B^2 / (12 T): rho g
// (L B^3 / 12 + L B T (T / 2 - KG)) (metacentric stability; e.g. K. J.
// Rawson and E. C. Tupper, "Basic Ship Theory", ch. 4)
double boxC44(double kg) { return kRho * kG * (kL * kB * kB * kB / 12 + kL * kB * kT * (kT / 2 - kg)); }

// the box's wet panels, centred at the origin horizontally, draft kT
// (hullPanels on its 12 triangles, counterclockwise from outside)
mjb::PanelMesh boxPanels(int refine) {
  std::vector<float> v;
  for (int i = 0; i < 8; i++) {
    v.push_back((i & 1 ? 0.5f : -0.5f) * kL);
    v.push_back((i & 2 ? 0.5f : -0.5f) * kB);
    v.push_back((i & 4 ? 0.5f : -0.5f) * kH);
  }
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<int> f;
  for (const auto& a : q) f.insert(f.end(), {a[0], a[1], a[2], a[0], a[2], a[3]});
  const double pos[3] = {0, 0, kH / 2 - kT}, quat[4] = {1, 0, 0, 0};
  mjb::PanelMesh body, lid;
  std::string note;
  EXPECT_TRUE(mjb::hullPanels(v.data(), 8, f.data(), 12, pos, quat, refine, &body, &lid, &note))
      << note;
  return body;
}

TEST(RollZeta, BoxRollStiffnessIsRhoGVGM) {
  for (int refine : {0, 2}) {
    mjb::PanelMesh p = boxPanels(refine);
    for (double kg : {kKG, 0.1}) {
      // the COM in the panel frame: the waterline at z = 0, the keel at -T
      const double G[3] = {0, 0, kg - kT}, ex[3] = {1, 0, 0};
      double C[9], V = 0;
      mjb::rotStiffness(p, G, kRho * kG, C, &V);
      const double c44 = mjb::axisStiffness(C, ex), want = boxC44(kg);
      std::printf("[rollzeta] box refine %d KG %g m: C44 %.6g N m/rad, closed form %.6g; V %.6g m^3\n",
                  refine, kg, c44, want, V);
      EXPECT_NEAR(V, kL * kB * kT, 1e-6 * kL * kB * kT);  // float vertices
      EXPECT_NEAR(c44, want, 0.01 * std::fabs(want));
    }
  }
}

TEST(RollZeta, TiltedAxisAboutAnOffCentrePoint) {
  // about a point G off the box's centre by (gx, gy) and an axis e at
  // angle a in the waterplane: the waterplane's second moments about G by
  // the parallel axis theorem (int y'^2 dA = L B^3 / 12 + L B gy^2, int x'^2
  // dA = B L^3 / 12 + L B gx^2, int x'y' dA = L B gx gy) and the buoyancy's
  // V (z_B - z_G) about both horizontal axes: C = rho g (cos^2 a (Iyy + Vh)
  // + sin^2 a (Ixx + Vh) - 2 sin a cos a Ixy) (the restoring coefficients
  // C44, C45, C55 of O. M. Faltinsen, "Sea Loads on Ships and Offshore
  // Structures", 1990, ch. 2, about an axis at angle a)
  mjb::PanelMesh p = boxPanels(1);
  const double gx = 0.3, gy = -0.2, a = M_PI / 6;
  const double G[3] = {gx, gy, kKG - kT}, e[3] = {std::cos(a), std::sin(a), 0};
  const double A = kL * kB, V = A * kT, Vh = V * (-kT / 2 - G[2]);
  const double iy = kL * kB * kB * kB / 12 + A * gy * gy, ix = kB * kL * kL * kL / 12 + A * gx * gx;
  const double ixy = A * gx * gy;
  const double want = kRho * kG * (e[0] * e[0] * (iy + Vh) + e[1] * e[1] * (ix + Vh) -
                                   2 * e[0] * e[1] * ixy);
  double C[9];
  mjb::rotStiffness(p, G, kRho * kG, C);
  const double got = mjb::axisStiffness(C, e);
  std::printf("[rollzeta] tilted axis: %.6g N m/rad, closed form %.6g\n", got, want);
  EXPECT_NEAR(got, want, 0.01 * std::fabs(want));
  // a vertical axis has no hydrostatic restoring (yaw)
  const double ez[3] = {0, 0, 1};
  EXPECT_NEAR(mjb::axisStiffness(C, ez), 0, 1e-9 * std::fabs(want));
}

// the box floating upright at its draft with radiation on (refine 2; no
// Kerner drag: radiation and the roll damping are its only damping), the
// custom entries given as extra
std::string boxXML(const std::string& extra) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.005\"/><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
    << "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>"
    << "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0.5\"/>"
    << "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0.5\"/>"
    << "<numeric name=\"mjbuoy.hull.slamming\" data=\"0 100 2\"/>"
    << "<numeric name=\"mjbuoy.radiation.refine\" data=\"2\"/>"
    << "<numeric name=\"mjbuoy.radiation.omega\" data=\"0.8 10 14\"/>" << extra
    << "</custom><worldbody><body name=\"box\" pos=\"0 0 " << kH / 2 - kT << "\"><freejoint/>"
    << "<geom name=\"hull\" type=\"box\" size=\"" << kL / 2 << " " << kB / 2 << " " << kH / 2
    << "\" mass=\"" << kMass << "\" contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>";
  return s.str();
}

// the solid box's roll inertia about its COM: m (B^2 + H^2) / 12
const double kI44 = kMass * (kB * kB + kH * kH) / 12;

struct Decay {
  double delta = 0, omega = 0, a44 = 0;  // log decrement, frequency [rad/s], A44_inf
  bool ok = false;
};

// free roll decay from 0.05 rad: the mean log decrement over the first
// n periods and the mean frequency between its maxima
Decay rollDecay(const std::string& extra, int n) {
  Decay r;
  Scene s(boxXML(extra));
  EXPECT_TRUE(s.ok()) << s.err;
  if (!s.ok()) return r;
  const mjb::Buoy* B = mjb::buoyOf(s.b);
  EXPECT_EQ(B->coef.size(), 1u) << mjb_warnings(s.b);
  if (B->coef.size() != 1) return r;
  r.a44 = B->coef[0].second.Ainf[21];
  const double a0 = 0.05;
  s.d->qpos[3] = std::cos(a0 / 2);
  s.d->qpos[4] = std::sin(a0 / 2);
  std::vector<double> pk, tk;
  const int b = s.body("box");
  double x0 = 0, x1 = a0;
  for (long k = 0, N = stepsTo(s.m, s.d, 12); k < N && int(pk.size()) <= n; k++) {
    mj_step(s.m, s.d);
    const double x = roll(s.d, b);
    if (k > 1 && x1 > x0 && x1 >= x && x1 > 0) pk.push_back(x1), tk.push_back(s.d->time - s.m->opt.timestep);
    x0 = x1;
    x1 = x;
  }
  EXPECT_GT(int(pk.size()), n);
  if (int(pk.size()) <= n) return r;
  r.delta = std::log(pk[0] / pk[n]) / n;
  r.omega = 2 * M_PI * n / (tk[n] - tk[0]);
  r.ok = true;
  return r;
}

TEST(RollZeta, FreeRollDecayGainsTheDecrementOfTheAddedDamping) {
  // I theta'' + b theta' + C44 theta = 0, light damping: the log decrement
  // is delta = 2 pi zeta / sqrt(1 - zeta^2) ~ pi b / (I w) = pi b w / C44
  // with I = C44 / w^2 the oscillator's inertia at its frequency w (W. T.
  // Thomson, "Theory of Vibration with Applications", ch. 2). rollzeta
  // adds b = 2 zeta sqrt(C44 (I44 + A44_inf)), so the decrement grows by
  // 2 pi zeta w / w_inf, w_inf = sqrt(C44 / (I44 + A44_inf)): the inertia
  // at infinite frequency over the roll's own (its added inertia at w and
  // the sway it carries along), taken from the measured w. C44 and I44
  // are the closed forms, A44_inf the panel solver's. Tolerance 5%: the
  // box's roll is coupled to sway (A24) and its potential damping varies
  // with frequency, so it is a 1-dof oscillator only to a few per cent,
  // and the small-damping form's 1 / sqrt(1 - zeta^2) is 0.5% at zeta 0.1
  // (measured: 2% above the prediction, docs/physics.md section 14)
  const int n = 3;
  Decay d0 = rollDecay("<numeric name=\"mjbuoy.radiation.rollzeta\" data=\"0\"/>", n);
  Decay d1 = rollDecay("<numeric name=\"mjbuoy.radiation.rollzeta\" data=\"0.1\"/>", n);
  ASSERT_TRUE(d0.ok && d1.ok);
  const double c44 = boxC44(kKG), winf = std::sqrt(c44 / (kI44 + d1.a44));
  const double pred = 2 * M_PI * 0.1 * d1.omega / winf;
  std::printf("[rollzeta] box roll decay: zeta 0: delta %.5f, w %.4f rad/s; zeta 0.1: delta %.5f, "
              "w %.4f rad/s; A44_inf %.4g kg m^2, w_inf %.4f rad/s; increase %.5f, predicted %.5f\n",
              d0.delta, d0.omega, d1.delta, d1.omega, d1.a44, winf, d1.delta - d0.delta, pred);
  EXPECT_NEAR(d1.delta - d0.delta, pred, 0.05 * pred);
}

// the RadBody of the box with these entries
bool rollOf(const std::string& extra, double roll[2], double* c44, double* a44,
            std::string* warn = nullptr) {
  Scene s(boxXML(extra));
  EXPECT_TRUE(s.ok()) << s.err;
  if (!s.ok()) return false;
  const mjb::Buoy* B = mjb::buoyOf(s.b);
  EXPECT_EQ(B->rad.rb.size(), 1u);
  if (B->rad.rb.size() != 1 || B->coef.size() != 1) return false;
  roll[0] = B->rad.rb[0].roll[0];
  roll[1] = B->rad.rb[0].roll[1];
  *c44 = B->rad.rb[0].c44;
  *a44 = B->coef[0].second.Ainf[21];
  if (warn) *warn = mjb_warnings(s.b);
  return true;
}

TEST(RollZeta, DefaultIsTenPercentAndGivenDampingReplacesIt) {
  // B_1 = 2 zeta sqrt(C44 (I44 + A44_inf)) with the closed-form C44 and
  // I44 (above): 10% without entries (docs/mjcf.md section 11); rolldamping alone replaces it (the
  // user's numbers); both add
  double r[2], c44, a44;
  ASSERT_TRUE(rollOf("", r, &c44, &a44));
  const double crit = 2 * std::sqrt(boxC44(kKG) * (kI44 + a44));
  std::printf("[rollzeta] box: C44 %.6g N m/rad (closed form %.6g), critical %.6g N m s/rad, "
              "default B_1 %.6g\n", c44, boxC44(kKG), crit, r[0]);
  EXPECT_NEAR(c44, boxC44(kKG), 0.01 * boxC44(kKG));
  EXPECT_NEAR(r[0], 0.10 * crit, 0.01 * 0.10 * crit);
  EXPECT_EQ(r[1], 0);
  ASSERT_TRUE(rollOf("<numeric name=\"mjbuoy.radiation.rolldamping\" data=\"3 1\"/>", r, &c44, &a44));
  EXPECT_EQ(r[0], 3);
  EXPECT_EQ(r[1], 1);
  ASSERT_TRUE(rollOf("<numeric name=\"mjbuoy.radiation.rolldamping\" data=\"3 1\"/>"
                     "<numeric name=\"mjbuoy.radiation.rollzeta\" data=\"0.1\"/>", r, &c44, &a44));
  EXPECT_NEAR(r[0], 3 + 0.1 * crit, 0.01 * 0.1 * crit);
  EXPECT_EQ(r[1], 1);
}

TEST(RollZeta, WeldedBodiesMakeOneGroup) {
  // the box's mass split: 300 kg in the hull geom (its centre), 100 kg on
  // a body welded to it 0.2 m below the centre. The group's COM is 0.05 m
  // below the centre (KG 0.25 m), its roll inertia about that COM by the
  // parallel axis theorem 300 (B^2 + H^2) / 12 + 300 0.05^2 + 100 0.15^2
  // (+ the child's own 0.01): C44 and I44 of the whole group, not the root's
  std::string x = boxXML("");
  const std::string geom = "mass=\"" + std::to_string(int(kMass)) + "\" contype";
  x.replace(x.find(geom), geom.size(), "mass=\"300\" contype");
  x.replace(x.find("</body>"), 0, "<body name=\"keel\" pos=\"0 0 -0.2\"><inertial pos=\"0 0 0\" "
            "mass=\"100\" diaginertia=\"0.01 0.01 0.01\"/></body>");
  Scene s(x);
  ASSERT_TRUE(s.ok()) << s.err;
  const mjb::Buoy* B = mjb::buoyOf(s.b);
  ASSERT_EQ(B->rad.rb.size(), 1u);
  ASSERT_EQ(B->coef.size(), 1u);
  const double i44 = 300 * (kB * kB + kH * kH) / 12 + 300 * 0.05 * 0.05 + 100 * 0.15 * 0.15 + 0.01;
  const double c44 = boxC44(kKG - 0.05), a44 = B->coef[0].second.Ainf[21];
  const double want = 0.10 * 2 * std::sqrt(c44 * (i44 + a44));  // the default zeta
  std::printf("[rollzeta] welded group: C44 %.6g N m/rad (closed form %.6g), B_1 %.6g (predicted %.6g)\n",
              B->rad.rb[0].c44, c44, B->rad.rb[0].roll[0], want);
  EXPECT_NEAR(B->rad.rb[0].c44, c44, 0.01 * c44);
  EXPECT_NEAR(B->rad.rb[0].roll[0], want, 0.01 * want);
}

TEST(RollZeta, NoRollRestoringGetsNoneAndAWarningWhenAsked) {
  // the 1 m cube at half draft with its COM at the centre: GM = 0.25 +
  // 1/6 - 0.5 < 0, C44 = rho g (1/12 - 0.125) = -408.75 N m/rad (closed
  // form above): no critical damping to take a fraction of
  const std::string xml =
      "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
      "<numeric name=\"mjbuoy.radiation.omega\" data=\"1 9 6\"/>%s</custom><worldbody>"
      "<body name=\"box\"><freejoint/><geom name=\"hull\" type=\"box\" size=\"0.5 0.5 0.5\" "
      "mass=\"500\" contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>";
  for (bool given : {false, true}) {
    char x[1024];
    std::snprintf(x, sizeof x, xml.c_str(),
                  given ? "<numeric name=\"mjbuoy.radiation.rollzeta\" data=\"0.1\"/>" : "");
    Scene s(x);
    ASSERT_TRUE(s.ok()) << s.err;
    const mjb::Buoy* B = mjb::buoyOf(s.b);
    ASSERT_EQ(B->rad.rb.size(), 1u);
    EXPECT_NEAR(B->rad.rb[0].c44, kRho * kG * (1.0 / 12 - 0.125), 0.01 * 408.75);
    EXPECT_EQ(B->rad.rb[0].roll[0], 0);
    const bool warned = std::string(mjb_warnings(s.b)).find("no roll restoring") != std::string::npos;
    EXPECT_EQ(warned, given) << mjb_warnings(s.b);
  }
}

TEST(RollZeta, WithoutRadiationItWarns) {
  Scene s("<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
          "<text name=\"mjbuoy.radiation\" data=\"off\"/>"
          "<numeric name=\"mjbuoy.radiation.rollzeta\" data=\"0.1\"/></custom>"
          "<worldbody><body name=\"box\"><freejoint/><geom name=\"hull\" type=\"box\" "
          "size=\"0.5 0.5 0.5\" mass=\"500\" contype=\"0\" conaffinity=\"0\"/></body>"
          "</worldbody></mujoco>");
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_NE(std::string(mjb_warnings(s.b)).find("mjbuoy.radiation.rollzeta acts only"),
            std::string::npos) << mjb_warnings(s.b);
}

TEST(RollZeta, BadEntriesAreNamed) {
  for (const char* bad : {"-0.1", "2.5", "0.05 0.1", "nan"}) {
    std::string x = "<mujoco><custom><numeric name=\"mjbuoy.radiation.rollzeta\" data=\"" +
                    std::string(bad) + "\"/></custom><worldbody><body name=\"b\"><freejoint/>"
                    "<geom type=\"sphere\" size=\"0.1\"/></body></worldbody></mujoco>";
    Scene s(x);
    EXPECT_FALSE(s.ok()) << bad;
    EXPECT_NE(s.err.find("mjbuoy.radiation.rollzeta"), std::string::npos) << s.err;
    EXPECT_NE(s.err.find("e.g. data=\"0.1\""), std::string::npos) << s.err;
    if (std::string(bad).find(' ') == std::string::npos) {
      EXPECT_NE(s.err.find(">= 0 and <= 2"), std::string::npos) << s.err;
    }
  }
}

}  // namespace
}  // namespace mjbt
