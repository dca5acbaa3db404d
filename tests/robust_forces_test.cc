// issue 11, forces: nothing lost, nothing silently wrong (docs/robustness.md)
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "radiation/hydrocoef.h"
#include "radiation/radiation.h"
#include "sea/sea.h"
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
  for (const char* be : {"cpu", "gl"}) {
    std::string x = kDrop;
    x.replace(x.find("</custom>"), 0,
              std::string("<text name=\"mjbuoy.backend\" data=\"") + be + "\"/>");
    Scene a(x), b(x);
    ASSERT_TRUE(a.ok() && b.ok()) << a.err << b.err;
    ASSERT_STREQ(mjb_info(a.b).backend, be);
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
    EXPECT_GT(most, 1e3) << be << ": slamming never acted: the test shows nothing";
    EXPECT_LE(worst, 1e-6 * most) << be << ": mj_forward + mj_Euler slams unlike mj_step";
    EXPECT_LE(again, 1e-6 * most) << be << ": a repeated mj_forward moved the slamming history on";
  }
}

// a 1 m cube of 500 kg afloat (draft 0.5 m) in a 7 m, 0.2 m chop (or still
// water); depth "" is deep water
std::string chop(const std::string& depth, bool waves = true) {
  return "<mujoco><option timestep=\"0.002\"/><custom>"
         "<text name=\"mjbuoy.hulls\" data=\"hull\"/>" + depth +
         (waves ? "<numeric name=\"mjbuoy.wave.a\" data=\"0.2 7 30 0 0.5\"/>" : "") +
         "</custom><worldbody>"
         "<body name=\"cube\"><freejoint/>"
         "<geom name=\"hull\" type=\"box\" size=\"0.5 0.5 0.5\" mass=\"500\"/></body>"
         "</worldbody></mujoco>";
}

TEST(RobustForces, VeryDeepFiniteDepthIsDeepWater) {
  // k h = 2 pi / 7 x 1000 = 898 > 710, where cosh and sinh overflow: the
  // Airy ratios cosh k(z+h) / cosh kh -> exp(k z) (the deep-water limit,
  // tanh kh = 1 to double precision), so every force family must equal
  // deep water's to round-off. Before, the water velocity at each wet
  // centroid was inf / inf = NaN and viscous, drag and slamming were 0
  for (const char* be : {"cpu", "gl"}) {
    std::string e;
    mjModel* md = loadXML(chop(""), &e);
    mjModel* mf = loadXML(chop("<numeric name=\"mjbuoy.sea.depth\" data=\"1000\"/>"), &e);
    ASSERT_TRUE(md && mf) << e;
    char err[1024];
    mjbBuoy* bd = mjb_attach(md, be, err, sizeof(err));
    ASSERT_TRUE(bd) << err;
    mjbBuoy* bf = mjb_attach(mf, be, err, sizeof(err));
    ASSERT_TRUE(bf) << err;
    mjData* dd = mj_makeData(md);
    mjData* df = mj_makeData(mf);
    for (mjData* d : {dd, df}) {
      // surging and heaving through the water, two steps so slamming has a history
      d->qpos[2] = -0.05;
      d->qvel[0] = 1.5;
      d->qvel[2] = -0.5;
      d->qvel[4] = 0.3;
    }
    for (int k = 0; k < 3; k++) {
      mj_step(md, dd);
      mj_step(mf, df);
    }
    // Wheeler's finite-depth stretch z' = (z - eta) h / (h + eta) differs
    // from the deep one, z - eta, by |z - eta| |eta| / h: with k = 0.9 /m,
    // |z - eta| <= 1.1 m (cube and wave) and |eta| <= 0.2 m the profiles
    // e^(k z') differ by at most k 1.1 0.2 / 1000 = 2e-4 relative (physics.md
    // section 11); the overflowing cosh ratios gave NaN and zero forces
    const double tol = 3e-4;
    for (int p = 0; p < mjbNPART; p++) {
      const mjtNum* wd = mjb_wrenchPart(bd, dd, p) + 6;
      const mjtNum* wf = mjb_wrenchPart(bf, df, p) + 6;
      double scale = 1e-9;
      for (int j = 0; j < 6; j++) scale = std::fmax(scale, std::fabs(wd[j]));
      for (int j = 0; j < 6; j++) {
        EXPECT_NEAR(wf[j], wd[j], tol * scale) << be << " part " << p << " component " << j;
      }
      if (p == mjbPART_VISCOUS || p == mjbPART_DRAG) {
        EXPECT_GT(scale, 1) << be << " part " << p << " barely acts: the test shows nothing";
      }
    }
    EXPECT_STREQ(mjb_notices(bf, df), "") << be;
    mj_deleteData(dd);
    mj_deleteData(df);
    mjb_detach(bd);
    mjb_detach(bf);
    mj_deleteModel(md);
    mj_deleteModel(mf);
  }
}

TEST(RobustForces, NonFiniteForceIsANoticeNotASilentZero) {
  // a finite state whose forces are not: 1e200 m/s squared overflows double
  // (cpu) and 1e200 is inf in float (gl). The viscous and drag forces of
  // the wet cube are then not finite: each is named in the notices with the
  // body and left out, and the wrench stays finite (before, both came out
  // as exactly 0 with no notice)
  for (const char* be : {"cpu", "gl"}) {
    std::string e;
    mjModel* m = loadXML(chop("", false), &e);
    ASSERT_TRUE(m) << e;
    char err[1024];
    mjbBuoy* b = mjb_attach(m, be, err, sizeof(err));
    ASSERT_TRUE(b) << err;
    mjData* d = mj_makeData(m);
    d->qvel[0] = 1e200;
    mj_forward(m, d);
    std::string n = mjb_notices(b, d);
    for (const char* fam : {"viscous", "drag"}) {
      EXPECT_NE(n.find(std::string("body \"cube\": ") + fam + " force not finite"),
                std::string::npos) << be << ": " << n;
    }
    EXPECT_EQ(n.find("pressure"), std::string::npos) << be << ": " << n;
    // the pressure still acts: rho g V at draft 0.5 m, the cube's weight
    EXPECT_NEAR(mjb_wrenchPart(b, d, mjbPART_PRESSURE)[6 + 2], 500 * kG, 1e-3 * 500 * kG) << be;
    for (int j = 0; j < 6; j++) EXPECT_TRUE(std::isfinite(mjb_wrench(b, d)[6 + j])) << be;
    // reported once: a second call adds nothing
    mj_forward(m, d);
    EXPECT_EQ(n, mjb_notices(b, d)) << be;
    mj_deleteData(d);
    mjb_detach(b);
    mj_deleteModel(m);
  }
}

TEST(RobustForces, UnnamedBodyIsNamedByItsId) {
  // a body without a name (MJCF allows it) is named by its id in the
  // notices, not as body ""
  std::string x = chop("", false), from = "<body name=\"cube\">";
  x.replace(x.find(from), from.size(), "<body>");
  std::string e;
  mjModel* m = loadXML(x, &e);
  ASSERT_TRUE(m) << e;
  char err[1024];
  mjbBuoy* b = mjb_attach(m, "cpu", err, sizeof(err));
  ASSERT_TRUE(b) << err;
  mjData* d = mj_makeData(m);
  d->qvel[0] = 1e200;
  mj_forward(m, d);
  std::string n = mjb_notices(b, d);
  EXPECT_NE(n.find("body 1 (no name): viscous force not finite"), std::string::npos) << n;
  EXPECT_EQ(n.find("body \"\""), std::string::npos) << n;
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
}

// the barge of docs (2 x 1 x 0.5 m, 500 kg) with its inertia from an
// <inertial> (diagonal I per axis) and a massless hull geom, bottom 5 cm
// above still water, slightly tilted so the impact is off-centre
std::string barge(double I) {
  char in[128];
  std::snprintf(in, sizeof(in), "<inertial pos=\"0 0 0\" mass=\"500\" diaginertia=\"%g %g %g\"/>",
                I, I, I);
  return std::string("<mujoco><option timestep=\"0.002\"/><custom>"
                     "<text name=\"mjbuoy.hulls\" data=\"hull\"/></custom><worldbody>"
                     "<body name=\"barge\" pos=\"0 0 0.3\" euler=\"2 1 0\"><freejoint/>") + in +
         "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"0\"/></body>"
         "</worldbody></mujoco>";
}

TEST(RobustForces, SlammingNeverThrowsABodyHigherThanItFell) {
  // the barge released from rest with its bottom 5 cm above the water,
  // inertia from nearly a point mass (1 kg m^2: radius of gyration 4.5 cm)
  // through the solid box's (m (b^2 + c^2) / 12 = 52) to a thin shell's
  // (2000): slamming is bounded by the effective mass at each wet point,
  // m_eff = 1 / (1/m + (r x u) . I^-1 (r x u)), so its impulses at most stop
  // each point's motion; a convex combination of such stops cannot raise the
  // kinetic energy (docs/physics.md). Energy bound: released at rest from
  // z0, the COM can never rise above z0 (buoyancy returns at most what it
  // took, drag and slamming only take). Before, the stopping force was
  // sized by the mass alone and the 20 kg m^2 barge was thrown 68 km.
  // (Below 1 kg m^2 the pressure and drag torques alone, slamming off, are
  // too stiff for the explicit 2 ms step: MuJoCo resets the run.)
  const int kNI = 5;
  const double kI[kNI] = {1, 2, 20, 52, 2000};
  double cpuTop[kNI];
  for (const char* be : {"cpu", "gl"}) {
    for (int i = 0; i < kNI; i++) {
      const double I = kI[i];
      std::string e;
      mjModel* m = loadXML(barge(I), &e);
      ASSERT_TRUE(m) << e;
      char err[1024];
      mjbBuoy* b = mjb_attach(m, be, err, sizeof(err));
      ASSERT_TRUE(b) << err;
      mjData* d = mj_makeData(m);
      mj_forward(m, d);
      const double z0 = d->qpos[2];
      double top = -1e9, slam = 0;
      for (int k = 0; k < 1000; k++) {  // 2 s: impact and the rebound
        mj_step(m, d);
        if (k > 50) top = std::fmax(top, d->qpos[2]);
        slam = std::fmax(slam, std::fabs(mjb_wrenchPart(b, d, mjbPART_SLAM)[6 + 2]));
      }
      EXPECT_EQ(d->warning[mjWARN_BADQACC].number, 0) << be << " I " << I << ": MuJoCo reset it";
      EXPECT_LE(top, z0 + 1e-3) << be << " I " << I << ": thrown above its release height";
      EXPECT_GT(slam, 100) << be << " I " << I << ": slamming barely acted";
      if (std::string(be) == "cpu") {
        cpuTop[i] = top;
      } else {  // the same run on both backends (float on gl): same rebound
        EXPECT_NEAR(top, cpuTop[i], 1e-3) << "I " << I << ": gl and cpu disagree";
      }
      mj_deleteData(d);
      mjb_detach(b);
      mj_deleteModel(m);
    }
  }
}

TEST(RobustForces, GlMatchesCpuNearFolding) {
  // a 1 m cube of 500 kg moving through a 4 m wave of amplitude 0.7 m with
  // Q chosen so sum Q k A is 0.99, 0.999, 0.9999 (folding at 1): the
  // surface has a near-cusp at each crest and the label Newton's Jacobian
  // is nearly singular there. The gl wrench must match the cpu reference
  // within the parity tolerance of tests/gl_parity_test.cc (1e-4 of the
  // wrench or of the weight) at 40 positions along the wave. Before, its
  // float Newton had no step control: the pressure force on the cube at
  // rest at z = 0 was up to 46% of the weight off at 0.99, 78% at 0.999
  const double kA = 2 * M_PI / 4 * 0.7, weight = 500 * kG;
  for (double fold : {0.99, 0.999, 0.9999}) {
    char w[256];
    std::snprintf(w, sizeof(w), "<numeric name=\"mjbuoy.wave.a\" data=\"0.7 4 0 0 %.17g\"/>",
                  fold / kA);
    std::string xml = std::string("<mujoco><option timestep=\"0.002\"/><custom>"
                                  "<text name=\"mjbuoy.hulls\" data=\"hull\"/>") + w +
                      "</custom><worldbody><body name=\"cube\"><freejoint/><geom name=\"hull\" "
                      "type=\"box\" size=\"0.5 0.5 0.5\" mass=\"500\"/></body></worldbody></mujoco>";
    std::string e;
    mjModel* mc = loadXML(xml, &e);
    mjModel* mg = loadXML(xml, &e);
    ASSERT_TRUE(mc && mg) << e;
    char err[1024];
    mjbBuoy* bc = mjb_attach(mc, "cpu", err, sizeof(err));
    ASSERT_TRUE(bc) << err;
    mjbBuoy* bg = mjb_attach(mg, "gl", err, sizeof(err));
    ASSERT_TRUE(bg) << err;
    mjData* dc = mj_makeData(mc);
    mjData* dg = mj_makeData(mg);
    for (int i = 0; i < 40; i++) {
      for (mjData* d : {dc, dg}) {
        d->qpos[0] = 0.1 * i;
        d->qpos[2] = 0.1 * std::sin(i);
        d->qvel[0] = 0.8;
        d->qvel[2] = -0.3;
        d->qvel[4] = 0.2;
        d->time = 0.05 * i;
      }
      mj_forward(mc, dc);
      mj_forward(mg, dg);
      const mjtNum* a = mjb_wrench(bc, dc) + 6;
      const mjtNum* b = mjb_wrench(bg, dg) + 6;
      double fn = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
      double tn = std::sqrt(a[3] * a[3] + a[4] * a[4] + a[5] * a[5]);
      for (int j = 0; j < 3; j++) {
        ASSERT_NEAR(b[j], a[j], 1e-4 * std::fmax(fn, weight)) << "fold " << fold << " x " << 0.1 * i;
        ASSERT_NEAR(b[3 + j], a[3 + j], 1e-4 * std::fmax(tn, weight))
            << "fold " << fold << " x " << 0.1 * i;
      }
    }
    mj_deleteData(dc);
    mj_deleteData(dg);
    mjb_detach(bc);
    mjb_detach(bg);
    mj_deleteModel(mc);
    mj_deleteModel(mg);
  }
}

// one mesh made of axis-aligned boxes (centre x, y, z, half sizes), each a
// closed outward piece, merged without a union
std::string boxes(const std::vector<std::vector<double>>& bx) {
  static const int kF[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  static const int kS[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  std::ostringstream v, f;
  for (size_t b = 0; b < bx.size(); b++) {
    for (const auto& c : kS) {
      for (int j = 0; j < 3; j++) v << bx[b][j] + c[j] * bx[b][3 + j] << " ";
    }
    for (const auto& t : kF) f << 8 * b + t[0] << " " << 8 * b + t[1] << " " << 8 * b + t[2] << " ";
  }
  return "<mujoco><asset><mesh name=\"m\" vertex=\"" + v.str() + "\" face=\"" + f.str() +
         "\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/></custom><worldbody>"
         "<body name=\"b\"><freejoint/><inertial pos=\"0 0 0\" mass=\"300\" "
         "diaginertia=\"30 100 120\"/><geom name=\"hull\" type=\"mesh\" mesh=\"m\"/></body>"
         "</worldbody></mujoco>";
}

TEST(RobustForces, OverlappingClosedPiecesOfOneMeshWarn) {
  // a 2 x 1 x 0.5 m hull and a 1 x 0.6 x 0.6 m deckhouse sunk 0.2 m into it,
  // merged in one mesh: fully submerged, the pressure integrates over both
  // closed surfaces, rho g (V_hull + V_house) with the 0.12 m^3 overlap
  // counted twice (1.36 m^3 instead of the union's 1.24: +10%). The load names the geom and the pieces
  const std::string over = "closed pieces 1 (12 triangles) and 2 (12 triangles) of its mesh overlap";
  Scene a(boxes({{0, 0, 0, 1, 0.5, 0.25}, {0, 0, 0.35, 0.5, 0.3, 0.3}}));
  ASSERT_TRUE(a.ok()) << a.err;
  std::string w = mjb_warnings(a.b);
  EXPECT_NE(w.find("hull geom \"hull\": " + over), std::string::npos) << w;
  // a deckhouse sitting on the deck (touching faces, no shared volume), a
  // catamaran (two hulls apart), and a box wholly inside another (nested:
  // every point inside) are told apart
  Scene b(boxes({{0, 0, 0, 1, 0.5, 0.25}, {0, 0, 0.55, 0.5, 0.3, 0.3}}));
  Scene c(boxes({{0, -1, 0, 1, 0.3, 0.25}, {0, 1, 0, 1, 0.3, 0.25}}));
  Scene d(boxes({{0, 0, 0, 1, 0.5, 0.25}, {0, 0, 0, 0.5, 0.25, 0.1}}));
  ASSERT_TRUE(b.ok() && c.ok() && d.ok()) << b.err << c.err << d.err;
  EXPECT_EQ(std::string(mjb_warnings(b.b)).find("overlap"), std::string::npos) << mjb_warnings(b.b);
  EXPECT_EQ(std::string(mjb_warnings(c.b)).find("overlap"), std::string::npos) << mjb_warnings(c.b);
  EXPECT_NE(std::string(mjb_warnings(d.b)).find(over), std::string::npos) << mjb_warnings(d.b);
  // two long boxes in a plus sign, 4 x 0.6 m each, the second 5 cm higher:
  // they share a 0.6 x 0.6 x 0.45 m block, yet every vertex and face
  // centroid of each lies outside the other (|x| or |y| at least 0.67 m):
  // only their surfaces passing through one another shows it. The same
  // cross with one box lying on the other (touching faces) shares nothing
  Scene e(boxes({{0, 0, 0, 2, 0.3, 0.25}, {0, 0, 0.05, 0.3, 2, 0.25}}));
  Scene f(boxes({{0, 0, 0, 2, 0.3, 0.25}, {0, 0, 0.5, 0.3, 2, 0.25}}));
  ASSERT_TRUE(e.ok() && f.ok()) << e.err << f.err;
  EXPECT_NE(std::string(mjb_warnings(e.b)).find(over), std::string::npos) << mjb_warnings(e.b);
  EXPECT_EQ(std::string(mjb_warnings(f.b)).find("overlap"), std::string::npos) << mjb_warnings(f.b);
  // the double count itself: held 5 m down, the pressure force is
  // rho g (V_hull + V_house) = 1000 9.81 (1 + 0.36) N, not the union's
  // 1000 9.81 (1 + 0.36 - 0.12): the warning is about a real error
  a.d->qpos[2] = -5;
  mj_forward(a.m, a.d);
  EXPECT_NEAR(mjb_wrenchPart(a.b, a.d, mjbPART_PRESSURE)[6 + 2], kRho * kG * 1.36, 1e-6 * kRho * kG);
}

TEST(RobustForces, RadiationKirchhoffTermsSeeTheWaveOrbitalVelocity) {
  // Kirchhoff's velocity terms of the added mass, M = -w x h - v x p with
  // p = A v (Newman 1977, Marine Hydrodynamics, sec. 4.13), hold for the
  // velocity relative to the water: a body carried by a wave's orbital
  // flow has no Munk moment from it, and a body at rest in that flow has
  // the Munk moment of the flow past it (docs/physics.md section 14,
  // "Kirchhoff terms in waves"). Applied to the velocity over the ground,
  // a boat surging with steep waves got a spurious moment that turned it
  // broadside and capsized it (the Wigley scenarios with radiation on).
  // No hulls (no pressure), no gravity, no memory: qfrc_passive is the
  // Kirchhoff wrench alone. Body axes = world axes, centre 0.5 m down in
  // an Airy wave (steepness 0) of 0.5 m on 10 m at phase 45 deg, so
  // surge u and heave w of the water are both about 0.7 A omega e^{kz}
  const char* xml =
      "<mujoco><option timestep=\"0.002\"><flag gravity=\"disable\"/></option><custom>"
      "<numeric name=\"mjbuoy.wave.sea\" data=\"0.5 10 0 45 0\"/>"
      "<numeric name=\"mjbuoy.sea.ramp\" data=\"0\"/></custom><worldbody>"
      "<body name=\"b\" pos=\"0 0 -0.5\"><freejoint/><geom type=\"box\" size=\"1 0.2 0.2\" "
      "mass=\"10\" contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>";
  Scene s(xml);
  ASSERT_TRUE(s.ok()) << s.err;
  mjb::HydroCoef c;
  c.omega = {1, 2};
  c.A.assign(72, 0.0);
  c.B.assign(72, 0.0);
  const double a[6] = {5, 50, 40, 1, 1, 1};  // A11 != A33: a Munk moment in pitch
  for (int i = 0; i < 6; i++) c.Ainf[7 * i] = a[i];
  ASSERT_EQ(mjb::setHydroCoef(s.b, 1, c, -1), "");
  const double p[3] = {0, 0, -0.5};
  double uw[3];
  mjb::buoyOf(s.b)->cfg.sea.velocity(p, 0, uw);
  ASSERT_GT(std::fabs(uw[0]), 0.3);
  ASSERT_GT(std::fabs(uw[2]), 0.3);
  // carried by the water: relative velocity 0, no force
  for (int i = 0; i < 3; i++) s.d->qvel[i] = uw[i];
  mj_forward(s.m, s.d);
  double carried = 0;
  for (int i = 0; i < 6; i++) carried = std::max(carried, std::fabs(s.d->qfrc_passive[i]));
  // at rest: v = -uw, (v x A v)_y = (A11 - A33) v_x v_z, so M_y = (A33 - A11) u w
  mj_resetData(s.m, s.d);
  mj_forward(s.m, s.d);
  const double munk = (a[2] - a[0]) * uw[0] * uw[2];
  std::printf("[robust] Kirchhoff in waves: water (%.4f, %.4f) m/s; carried: largest force %.3g; "
              "at rest: M_y %.6g N m (expected %.6g)\n",
              uw[0], uw[2], carried, s.d->qfrc_passive[4], munk);
  EXPECT_LT(carried, 1e-9);
  EXPECT_NEAR(s.d->qfrc_passive[4], munk, 1e-9 * std::fabs(munk));
  for (int i : {0, 1, 2, 3, 5}) EXPECT_LT(std::fabs(s.d->qfrc_passive[i]), 1e-9) << "dof " << i;
}

}  // namespace
}  // namespace mjbt
