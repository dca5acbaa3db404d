// radiation of hulls on slide and hinge joints by default, about their
// equilibrium along the joints (mjbuoy/radiation/radattach.cc jointPose,
// mjbuoy/hull/jointeq.h; docs/physics.md section 14, "Equilibrium along
// joints")
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "api/buoy.h"
#include "hemisphere.h"
#include "hull/jointeq.h"
#include "testutil.h"

namespace mjbt {
namespace {

// a 2 x 1 x 0.8 m box of mass rho L B T (T = 0.4 m: it floats with its
// centre at the sea level) on `joint`, drag, viscous and slamming terms
// off, no mjbuoy.radiation entry (the default)
std::string boxModel(const std::string& joint) {
  std::ostringstream x;
  x.precision(17);
  x << "<mujoco><option timestep=\"0.002\"/><custom><text name=\"mjbuoy.hulls\" data=\"h\"/>"
    << "<numeric name=\"mjbuoy.sea.density\" data=\"" << kRho << "\"/>" << "<numeric name=\"mjbuoy.sea.capacity\" data=\"2\"/>" << kNoDragEntries
    << "</custom><worldbody><body name=\"hull\">" << joint
    << "<geom name=\"h\" type=\"box\" size=\"1 0.5 0.4\" mass=\"" << kRho * 2 * 1 * 0.4
    << "\" contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>";
  return x.str();
}

// the 4 x 0.5 m Wigley hull of models/wigley.xml (576 triangles, 176.2 kg,
// COM 0.08 m below the design waterline) on `joint`, drag off, default
// radiation
std::string wigleyModel(const std::string& joint) {
  std::ostringstream x;
  x << "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
       "/meshes/wigley_576.obj\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"h\"/>"
    << "<numeric name=\"mjbuoy.sea.density\" data=\"1000\"/>" << "<numeric name=\"mjbuoy.sea.capacity\" data=\"2\"/>" << kNoDragEntries
    << "</custom><worldbody><body name=\"hull\" pos=\"0 0 0.034\">" << joint
    << "<inertial pos=\"0 0 -0.08\" mass=\"176.2\" diaginertia=\"6.020 237.28 238.60\"/>"
    << "<geom name=\"h\" type=\"mesh\" mesh=\"w\" contype=\"0\" conaffinity=\"0\"/>"
    << "</body></worldbody></mujoco>";
  return x.str();
}

// free decay in calm water from the COM lifted by dz: the heave period
// [s] as the mean spacing of the first three up-crossings of the mean
// level of the last 5 s of 25 s (linear interpolation between steps)
double heavePeriod(Scene& s, int b, bool slide, double dz) {
  mj_resetData(s.m, s.d);
  s.d->qpos[slide ? 0 : 2] += dz;
  const long n = stepsTo(s.m, s.d, 25);
  std::vector<double> t, z;
  for (long i = 0; i < n; i++) {
    mj_step(s.m, s.d);
    t.push_back(s.d->time);
    z.push_back(s.d->xipos[3 * b + 2]);
  }
  double mean = 0;
  int m = 0;
  for (size_t i = 0; i < z.size(); i++)
    if (t[i] > 20) mean += z[i], m++;
  mean /= m;
  std::vector<double> up;
  for (size_t i = 1; i < z.size() && up.size() < 3; i++)
    if (z[i - 1] < mean && z[i] >= mean)
      up.push_back(t[i - 1] + (t[i] - t[i - 1]) * (mean - z[i - 1]) / (z[i] - z[i - 1]));
  if (up.size() < 3) return NAN;
  return 0.5 * (up[2] - up[0]);
}

// heave RAO of the COM at frequency w [rad/s]: one Airy component of
// steepness k A = 0.02 along +x set by mjb_setSea (docs/physics.md section
// 6), or with `standing` two, along +x and -x, in phase at the origin (a
// standing wave of amplitude 2 A there, whose mean drift forces on a
// fore-aft symmetric hull cancel), 20 s of transient, then z = c0 + c1
// cos(w t) + c2 sin(w t) by least squares over whole periods covering at
// least 8 s; sqrt(c1^2 + c2^2) over the elevation amplitude at the origin
double heaveRAO(Scene& s, int b, double w, bool standing) {
  const double k = w * w / kG, A = 0.02 / k, T = 2 * M_PI / w;
  mj_resetData(s.m, s.d);
  const double wave[10] = {A, 2 * M_PI / k, 0, 0, 0, A, 2 * M_PI / k, 180, 0, 0};
  mjbSea sea = {};
  sea.wave = wave;
  sea.nwave = standing ? 2 : 1;
  char err[256] = "";
  EXPECT_EQ(mjb_setSea(s.b, &sea, err, sizeof err), 1) << err;
  const double t0 = 20, t1 = t0 + T * std::ceil(8 / T);
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  const long n = stepsTo(s.m, s.d, t1);
  for (long i = 0; i < n; i++) {
    mj_step(s.m, s.d);
    if (s.d->time < t0 - 1e-9) continue;
    Eigen::Vector3d f(1, std::cos(w * s.d->time), std::sin(w * s.d->time));
    N += f * f.transpose();
    r += f * s.d->xipos[3 * b + 2];
  }
  Eigen::Vector3d c = N.ldlt().solve(r);
  return std::hypot(c[1], c[2]) / (standing ? 2 * A : A);
}

// the jointed hull's heave period and RAO within 2% of the free hull's.
// Reference: the same hull free (a freejoint), whose radiation is the
// 6-dof panel solution at its floating equilibrium, validated against
// Hulme (1982) in tests/radattach_test.cc and tests/diffract_test.cc;
// heave of a fore-aft symmetric hull about its COM does not couple with
// surge or pitch (Newman 1977, sec. 7.4), so restraining those leaves its
// heave equation unchanged. Without radiation the jointed hull's period is
// that of its bare mass, sqrt(m / (m + A33)) of the free one's (the box:
// 2 pi sqrt(800 / (rho g 2)) = 1.27 s), far outside 2%
// w(T_free): the wave frequency [rad/s] from the free heave period [s]
void expectSameHeave(const std::string& freeXml, const std::string& jointXml, const char* what,
                     double (*freq)(double), bool standing) {
  Scene f(freeXml), j(jointXml);
  ASSERT_TRUE(f.ok()) << f.err;
  ASSERT_TRUE(j.ok()) << j.err;
  const mjb::Buoy* B = mjb::buoyOf(j.b);
  ASSERT_EQ(B->coef.size(), 1u) << "no radiation on the jointed hull: " << mjb_warnings(j.b);
  EXPECT_EQ(std::string(mjb_warnings(j.b)).find("equilibrium"), std::string::npos)
      << mjb_warnings(j.b);
  const int bf = f.body("hull"), bj = j.body("hull");
  const double Tf = heavePeriod(f, bf, false, 0.03), Tj = heavePeriod(j, bj, true, 0.03);
  const double w = freq(Tf);
  const double Rf = heaveRAO(f, bf, w, standing), Rj = heaveRAO(j, bj, w, standing);
  std::printf("[radjoint] %s: heave period free %.4f s, jointed %.4f s; RAO at %.3f rad/s "
              "free %.4f, jointed %.4f\n", what, Tf, Tj, w, Rf, Rj);
  EXPECT_NEAR(Tj, Tf, 0.02 * Tf) << what;
  EXPECT_NEAR(Rj, Rf, 0.02 * Rf) << what;
}

TEST(RadJoint, HeaveOnlyBoxMatchesTheFreeBox) {
  // at 0.8 of the heave natural frequency, where added mass and damping
  // both matter, in a standing wave: in one progressive wave the free box
  // drifts upwave at about 4 cm/s (the second-order drift force, nothing
  // holds it), and the Doppler shift k U of its encounter frequency moves
  // its RAO there by 2%, which is not radiation
  expectSameHeave(boxModel("<freejoint/>"),
                  boxModel("<joint type=\"slide\" axis=\"0 0 1\"/>"), "box on a slide",
                  [](double T) { return 0.8 * 2 * M_PI / T; }, true);
}

TEST(RadJoint, HeaveAndPitchWigleyMatchesTheFreeWigley) {
  // slide and hinge through the COM (0.08 m below the body origin), so
  // pitch turns about the point the free hull pitches about; head waves
  // 1.5 hull lengths long (6 m), where it heaves and pitches most
  expectSameHeave(wigleyModel("<freejoint/>"),
                  wigleyModel("<joint type=\"slide\" axis=\"0 0 1\" pos=\"0 0 -0.08\"/>"
                              "<joint type=\"hinge\" axis=\"0 1 0\" pos=\"0 0 -0.08\"/>"),
                  "Wigley on slide + hinge", [](double) { return std::sqrt(2 * M_PI * kG / 6); },
                  false);
}

// the flat-water hulls of an attached model, for jointEquilibrium
mjb::EqWater water(const mjb::Buoy& B) {
  mjb::EqWater w;
  w.vert = B.vert.data();
  w.face = B.face.data();
  w.level = B.cfg.sea.level;
  w.rho = B.cfg.sea.rho;
  w.g = B.cfg.sea.g;
  for (const mjb::Hull& h : B.hull) w.hull.push_back({h.body, h.t0, h.nt});
  return w;
}

TEST(RadJoint, SlideWithASpringFindsTheAnalyticDraft) {
  // the 800 kg box above on a vertical slide spring k = 1e4 N/m whose rest
  // length would hold it 0.1 m high (springref 0.1): at slide q the draft
  // is 0.4 - q and rho g L B (0.4 - q) = m g + k (q - 0.1), so q =
  // (rho g L B 0.4 - m g + 0.1 k) / (rho g L B + k) = 0.1 k / (2 rho g + k)
  // = 0.0337580 m (Archimedes and Hooke)
  Scene s(boxModel("<joint type=\"slide\" axis=\"0 0 1\" stiffness=\"1e4\" springref=\"0.1\"/>"));
  ASSERT_TRUE(s.ok()) << s.err;
  const double q = 0.1 * 1e4 / (2 * kRho * kG + 1e4);
  for (double q0 : {0.5, 0.0, -0.3}) {  // dry, at T, deep
    mj_resetData(s.m, s.d);
    s.d->qpos[0] = q0;
    std::string why = mjb::jointEquilibrium(s.m, s.d, water(*mjb::buoyOf(s.b)), {0});
    EXPECT_EQ(why, "") << q0;
    EXPECT_NEAR(s.d->qpos[0], q, 1e-6) << q0;
  }
}

TEST(RadJoint, HingedArmFindsTheAnalyticAngle) {
  // the always-submerged arm of tests/robust_model_test.cc: buoyancy rho V
  // = 200 kg at the box centre, 1 m out along the arm, weight 100 kg at
  // e = 0.5 m below the arm's axis; moments about the hinge balance at
  // tan(th) = (rho V - m) L / (2 m e) = 2 (th = 63.43 deg up)
  Scene s("<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
          "<numeric name=\"mjbuoy.sea.density\" data=\"1000\"/></custom><worldbody>"
          "<body name=\"arm\" pos=\"0 0 -5\"><joint type=\"hinge\" axis=\"0 1 0\"/>"
          "<inertial pos=\"1 0 -0.5\" mass=\"100\" diaginertia=\"10 40 40\"/>"
          "<geom name=\"hull\" type=\"box\" pos=\"1 0 0\" size=\"1 0.25 0.1\"/></body>"
          "</worldbody></mujoco>");
  ASSERT_TRUE(s.ok()) << s.err;
  mj_resetData(s.m, s.d);
  EXPECT_EQ(mjb::jointEquilibrium(s.m, s.d, water(*mjb::buoyOf(s.b)), {0}), "");
  // a hinge about +y turns +x towards -z: the arm up is a negative angle
  EXPECT_NEAR(-s.d->qpos[0], std::atan(2.0), 1e-6);
  EXPECT_EQ(std::string(mjb_warnings(s.b)).find("equilibrium"), std::string::npos)
      << mjb_warnings(s.b);
}

TEST(RadJoint, NoEquilibriumAlongTheJointsIsWarnedNamingTheBody) {
  // 2.5 times the box's full displacement (rho 2 x 1 x 0.8 m^3) on a
  // vertical slide: it sinks, no balance exists along the slide; started at
  // the draft 0.4 m it still radiates, about qpos0, with the warning
  std::string x = boxModel("<joint type=\"slide\" axis=\"0 0 1\"/>");
  x.replace(x.find("mass=\"800\""), 10, "mass=\"4000\"");
  Scene s(x);
  ASSERT_TRUE(s.ok()) << s.err;
  const std::string w = mjb_warnings(s.b);
  EXPECT_NE(w.find("radiation of body \"hull\": no equilibrium along its joints"),
            std::string::npos) << w;
  EXPECT_EQ(mjb::buoyOf(s.b)->coef.size(), 1u) << w;
}

}  // namespace
}  // namespace mjbt
