// gl backend against the cpu reference: randomized scenes, whole runs,
// backend selection
#include <cstdlib>
#include <random>
#include <sstream>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

// a random scene: a Wigley boat, a box and a capsule, random sea
std::string randomScene(std::mt19937* rng) {
  std::uniform_real_distribution<double> U(0, 1);
  const int res[] = {64, 256, 576, 2800, 7744};
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
    << "/meshes/wigley_" << res[(*rng)() % 5] << ".obj\"/></asset><custom>"
    << "<text name=\"mjbuoy.hulls\" data=\"h*\"/>"
    // radiation and diffraction are computed on the cpu for both backends
    // (WholeRunsAgree runs them): off here, so each random hull and depth
    // costs no panel solve
    << "<text name=\"mjbuoy.radiation\" data=\"off\"/>";
  if (U(*rng) < 0.6) {
    s << "<numeric name=\"mjbuoy.wave.a\" data=\"" << 0.1 + 0.4 * U(*rng) << " "
      << 8 + 20 * U(*rng) << " " << 360 * U(*rng) << " " << 360 * U(*rng) << " "
      << U(*rng) << "\"/>";
    if (U(*rng) < 0.5) {
      s << "<numeric name=\"mjbuoy.wave.b\" data=\"0.05 " << 3 + 3 * U(*rng) << " "
        << 360 * U(*rng) << " 0 0.5\"/>";
    }
  }
  // linear (Airy) components, alone or mixed with Gerstner ones; the
  // pressure is linear wave theory (the default) or Kerner's; finite depth
  if (U(*rng) < 0.5) {
    s << "<numeric name=\"mjbuoy.airy.c\" data=\"" << 0.05 + 0.3 * U(*rng) << " "
      << 4 + 20 * U(*rng) << " " << 360 * U(*rng) << " " << 360 * U(*rng) << "\"/>";
    if (U(*rng) < 0.5) {
      s << "<numeric name=\"mjbuoy.airy.d\" data=\"0.04 " << 2 + 3 * U(*rng) << " "
        << 360 * U(*rng) << " 90\"/>";
    }
  }
  if (U(*rng) < 0.25) s << "<text name=\"mjbuoy.sea.pressure\" data=\"kerner\"/>";
  if (U(*rng) < 0.3) s << "<numeric name=\"mjbuoy.sea.depth\" data=\"" << 2 + 10 * U(*rng) << "\"/>";
  if (U(*rng) < 0.5) {
    s << "<numeric name=\"mjbuoy.sea.current\" data=\"" << U(*rng) - 0.5 << " "
      << U(*rng) - 0.5 << "\"/>";
  }
  if (U(*rng) < 0.3) s << "<numeric name=\"mjbuoy.hull.damping\" data=\"500 50\"/>";
  s << "</custom><worldbody>"
       "<body name=\"w\"><freejoint/><inertial pos=\"0 0 -0.08\" mass=\"176\" "
       "diaginertia=\"6 237 238\"/><geom name=\"hw\" type=\"mesh\" mesh=\"w\"/></body>"
       "<body name=\"b\" pos=\"6 0 0\"><freejoint/>"
       "<geom name=\"hb\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body>"
       "<body name=\"c\" pos=\"0 5 0\"><freejoint/>"
       "<geom name=\"hc\" type=\"capsule\" size=\"0.3 0.8\" euler=\"0 90 0\" mass=\"150\"/>"
       "</body></worldbody></mujoco>";
  return s.str();
}

// the same xml compiled twice, one copy per backend
struct Pair {
  mjModel *mc = nullptr, *mg = nullptr;
  mjData *dc = nullptr, *dg = nullptr;
  mjbBuoy *bc = nullptr, *bg = nullptr;
  explicit Pair(const std::string& xml) {
    std::string e;
    mc = loadXML(xml, &e);
    mg = loadXML(xml, &e);
    EXPECT_TRUE(mc && mg) << e;
    char err[1024];
    bc = mjb_attach(mc, "cpu", err, sizeof(err));
    EXPECT_TRUE(bc) << err;
    bg = mjb_attach(mg, "gl", err, sizeof(err));
    EXPECT_TRUE(bg) << err;
    dc = mj_makeData(mc);
    dg = mj_makeData(mg);
  }
  ~Pair() {
    mj_deleteData(dc);
    mj_deleteData(dg);
    mjb_detach(bc);
    mjb_detach(bg);
    mj_deleteModel(mc);
    mj_deleteModel(mg);
  }
};

// body b's gl wrench against the cpu reference: forces within 1e-4
// relative or 1e-4 of its weight [N], torques likewise (weight x 1 m)
::testing::AssertionResult wrenchesMatch(const Pair& p, int b, const std::string& where) {
  const mjtNum* wc = mjb_wrench(p.bc, p.dc) + 6 * b;
  const mjtNum* wg = mjb_wrench(p.bg, p.dg) + 6 * b;
  double weight = p.mc->body_mass[b] * kG, fn = 0, tn = 0;
  for (int j = 0; j < 3; j++) {
    fn += wc[j] * wc[j];
    tn += wc[3 + j] * wc[3 + j];
  }
  double ftol = std::max(1e-4 * std::sqrt(fn), 1e-4 * weight);
  double ttol = std::max(1e-4 * std::sqrt(tn), 1e-4 * weight);
  for (int j = 0; j < 6; j++) {
    if (std::fabs(wg[j] - wc[j]) > (j < 3 ? ftol : ttol)) {
      return ::testing::AssertionFailure()
             << where << " body " << b << " component " << j << ": gl " << wg[j] << ", cpu "
             << wc[j] << ", tolerance " << (j < 3 ? ftol : ttol);
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(GlParity, RandomScenesMatchTheCpuReference) {
  // 25 scenes x 8 random states, each stepped 3 times from the same state
  // on both backends (so slamming history is exercised): forces within
  // 1e-4 relative or 1e-4 of the body's weight, torques likewise (weight x 1 m)
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> U(-1, 1);
  int checked = 0, wet = 0;
  for (int sc = 0; sc < 25; sc++) {
    Pair p(randomScene(&rng));
    ASSERT_TRUE(p.bc && p.bg);
    ASSERT_STREQ(mjb_info(p.bg).backend, "gl");
    for (int st = 0; st < 8; st++) {
      mj_resetData(p.mc, p.dc);
      for (int b = 0; b < 3; b++) {
        double* q = p.dc->qpos + 7 * b;
        q[2] = 0.25 * U(rng);
        Eigen::Quaterniond r(Eigen::AngleAxisd(0.5 * U(rng), Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(0.4 * U(rng), Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(3.0 * U(rng), Eigen::Vector3d::UnitZ()));
        q[3] = r.w(); q[4] = r.x(); q[5] = r.y(); q[6] = r.z();
        for (int j = 0; j < 6; j++) p.dc->qvel[6 * b + j] = (j < 3 ? 1.5 : 0.8) * U(rng);
      }
      p.dc->time = 10 * (U(rng) + 1);
      mj_resetData(p.mg, p.dg);
      for (int k = 0; k < 3; k++) {
        // same state on both, then one step each
        mju_copy(p.dg->qpos, p.dc->qpos, p.mc->nq);
        mju_copy(p.dg->qvel, p.dc->qvel, p.mc->nv);
        p.dg->time = p.dc->time;
        mj_step(p.mc, p.dc);
        mj_step(p.mg, p.dg);
        const mjtNum* wc = mjb_wrench(p.bc, p.dc);
        for (int b = 1; b <= 3; b++) {
          std::ostringstream where;
          where << "scene " << sc << " state " << st << " step " << k;
          ASSERT_TRUE(wrenchesMatch(p, b, where.str()));
          double fn = 0;
          for (int j = 0; j < 3; j++) fn += wc[6 * b + j] * wc[6 * b + j];
          wet += fn > 0;
          checked++;
        }
      }
    }
  }
  EXPECT_GT(wet, checked / 2);
}

// run a model file for T s on backend be, sampling body 1's pose
std::vector<double> trajectory(const char* file, const char* be, double T) {
  char e[1024];
  mjModel* m = mj_loadXML((std::string(MJB_MODELS "/") + file).c_str(), nullptr, e, sizeof(e));
  EXPECT_TRUE(m) << e;
  mjbBuoy* b = mjb_attach(m, be, e, sizeof(e));
  EXPECT_TRUE(b) << e;
  mjData* d = mj_makeData(m);
  std::vector<double> out;
  for (long step = 0, nstep = mjbt::stepsTo(m, d, T); step < nstep; step++) {
    mj_step(m, d);
    out.insert(out.end(), d->qpos, d->qpos + 7);
  }
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
  return out;
}

TEST(GlParity, PiecesBeyondTheFirstSeriesBoundRepeatTheStep) {
  // the gl backend sizes each component's series to a reach first guessed
  // from the longest hull edge (docs/physics.md section 11, Cost, gl); a
  // steep Gerstner wave (k = 1 rad/m, Q k A = 0.95) stretches the labels
  // up to 1 / (1 - 0.95) = 20 times the positions, so pieces reach k r
  // of 2.4 where the guess gave 0.94 (checked): series sized to the guess
  // miss this tolerance (checked with the step's repeat disabled), the
  // repeated step matches the cpu reference to the random scenes' tolerance
  std::string xml =
      "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
      "/meshes/wigley_64.obj\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"h*\"/>"
      "<numeric name=\"mjbuoy.wave.a\" data=\"0.95 6.2831853 30 0 1\"/></custom><worldbody>"
      "<body name=\"w\"><freejoint/><inertial pos=\"0 0 -0.08\" mass=\"176\" "
      "diaginertia=\"6 237 238\"/><geom name=\"hw\" type=\"mesh\" mesh=\"w\"/></body>"
      "</worldbody></mujoco>";
  Pair p(xml);
  ASSERT_TRUE(p.bc && p.bg);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int st = 0; st < 8; st++) {
    mj_resetData(p.mc, p.dc);
    mj_resetData(p.mg, p.dg);
    p.dc->qpos[2] = 0.3 * U(rng);
    p.dc->qvel[2] = 0.5 * U(rng);
    p.dc->time = 5 * (U(rng) + 1);
    mju_copy(p.dg->qpos, p.dc->qpos, p.mc->nq);
    mju_copy(p.dg->qvel, p.dc->qvel, p.mc->nv);
    p.dg->time = p.dc->time;
    mj_step(p.mc, p.dc);
    mj_step(p.mg, p.dg);
    EXPECT_TRUE(wrenchesMatch(p, 1, "state " + std::to_string(st)));
  }
}

TEST(GlParity, SpectralSeaDeepAndFiniteDepth) {
  // a 63-component JONSWAP sea (odd: the table's last texel holds one
  // component, sea.glsl expTexel) in deep water and at 8 m depth (the
  // profiles' second exponential, tris.comp expAt), with the linear
  // pressure and Kerner's (the programs without pressure moments, gl.cc
  // kVNomom: the water velocity alone); the cpu backend's direct sum is the
  // reference, to the random scenes' tolerance
  for (int cs = 0; cs < 4; cs++) {
    const char* depth = cs & 1 ? "<numeric name=\"mjbuoy.sea.depth\" data=\"8\"/>" : "";
    const char* press = cs & 2 ? "<text name=\"mjbuoy.sea.pressure\" data=\"kerner\"/>" : "";
    std::string xml =
        std::string("<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
                    "/meshes/wigley_576.obj\"/></asset><custom><text name=\"mjbuoy.hulls\" "
                    "data=\"h*\"/><text name=\"mjbuoy.spectrum.sea.type\" data=\"jonswap\"/>"
                    "<numeric name=\"mjbuoy.spectrum.sea.hs\" data=\"0.6\"/>"
                    "<numeric name=\"mjbuoy.spectrum.sea.tp\" data=\"5\"/>"
                    "<numeric name=\"mjbuoy.spectrum.sea.components\" data=\"63\"/>"
                    "<numeric name=\"mjbuoy.spectrum.sea.spreading\" data=\"10\"/>") +
        depth + press +
        "</custom><worldbody><body name=\"w\" pos=\"0 0 0.03\"><freejoint/>"
        "<inertial pos=\"0 0 -0.08\" mass=\"176\" diaginertia=\"6 237 238\"/>"
        "<geom name=\"hw\" type=\"mesh\" mesh=\"w\"/></body></worldbody></mujoco>";
    Pair p(xml);
    ASSERT_TRUE(p.bc && p.bg);
    for (int st = 0; st < 4; st++) {
      mj_resetData(p.mc, p.dc);
      mj_resetData(p.mg, p.dg);
      p.dc->time = p.dg->time = 1.7 * st;
      mj_step(p.mc, p.dc);
      mj_step(p.mg, p.dg);
      EXPECT_TRUE(wrenchesMatch(p, 1, std::string(depth) + press + " state " + std::to_string(st)));
    }
  }
}

TEST(GlParity, WholeRunsAgree) {
  // 10 s: positions within 1 mm, orientation within 0.1 deg
  for (const char* f : {"barge.xml", "wigley.xml"}) {
    std::vector<double> c = trajectory(f, "cpu", 10), g = trajectory(f, "gl", 10);
    ASSERT_EQ(c.size(), g.size());
    double dp = 0, da = 0;
    for (size_t i = 0; i < c.size(); i += 7) {
      for (int j = 0; j < 3; j++) dp = std::max(dp, std::fabs(c[i + j] - g[i + j]));
      double dot = 0;
      for (int j = 3; j < 7; j++) dot += c[i + j] * g[i + j];
      da = std::max(da, 2 * std::acos(std::min(1.0, std::fabs(dot))) * 180 / M_PI);
    }
    EXPECT_LT(dp, 1e-3) << f;
    EXPECT_LT(da, 0.1) << f;
    RecordProperty(f, std::to_string(dp) + " m " + std::to_string(da) + " deg");
  }
}

TEST(GlParity, PastTheWorkgroupLimit) {
  // GL guarantees only 65535 workgroups per dispatch; with one vertex and
  // one triangle per workgroup (MJBUOY_GL_GROUPS) 17 Wigley 7744 hulls need
  // 65841 vertex and 131580 triangle workgroups, so the stages must loop
  // past the limit (before, such a dispatch silently did nothing)
  std::ostringstream s;
  s << "<mujoco><asset><mesh name=\"w\" file=\"" MJB_MODELS "/meshes/wigley_7744.obj\"/>"
    << "</asset><custom><text name=\"mjbuoy.hulls\" data=\"h*\"/>"
    << "<text name=\"mjbuoy.radiation\" data=\"off\"/>"
    << "<numeric name=\"mjbuoy.wave.swell\" data=\"0.3 20 20 0 0.5\"/></custom><worldbody>";
  for (int i = 0; i < 17; i++) {
    s << "<body pos=\"" << 6 * (i % 5) << " " << 2 * (i / 5) << " " << 0.02 * (i % 3)
      << "\" euler=\"" << 3 * (i % 4) << " 0 " << 10 * i << "\"><freejoint/>"
      << "<inertial pos=\"0 0 -0.08\" mass=\"176.2\" diaginertia=\"6.02 237.28 238.6\"/>"
      << "<geom name=\"h" << i << "\" type=\"mesh\" mesh=\"w\"/></body>";
  }
  s << "</worldbody></mujoco>";
  setenv("MJBUOY_GL_GROUPS", "1 1 1 1", 1);
  Pair p(s.str());
  unsetenv("MJBUOY_GL_GROUPS");
  ASSERT_TRUE(p.bc && p.bg);
  EXPECT_EQ(mjb_info(p.bg).ntri, 17 * 7740);
  for (mjData* d : {p.dc, p.dg}) {
    for (int j = 0; j < 17 * 6; j++) d->qvel[j] = 0.3 * std::sin(1.7 * j);
  }
  mj_step(p.mc, p.dc);
  mj_step(p.mg, p.dg);
  const mjtNum* wc = mjb_wrench(p.bc, p.dc);
  const mjtNum* wg = mjb_wrench(p.bg, p.dg);
  double lift = 0;
  for (int b = 1; b <= 17; b++) {
    double weight = p.mc->body_mass[b] * kG;
    lift += wc[6 * b + 2] / weight / 17;
    for (int j = 0; j < 6; j++) {
      EXPECT_NEAR(wg[6 * b + j], wc[6 * b + j], 1e-4 * std::max(std::fabs(wc[6 * b + j]), weight))
          << "body " << b << " component " << j;
    }
  }
  EXPECT_GT(lift, 0.5);  // most of the fleet floats: the comparison means something
}

TEST(GlBackend, BadWorkgroupSizesAreNamed) {
  setenv("MJBUOY_GL_GROUPS", "64 48 4 8", 1);
  mjModel* m = mj_loadXML(MJB_MODELS "/barge.xml", nullptr, nullptr, 0);
  ASSERT_TRUE(m);
  char e[1024];
  EXPECT_FALSE(mjb_attach(m, "gl", e, sizeof(e)));
  unsetenv("MJBUOY_GL_GROUPS");
  EXPECT_NE(std::string(e).find("MJBUOY_GL_GROUPS=\"64 48 4 8\""), std::string::npos) << e;
  EXPECT_NE(std::string(e).find("powers of two"), std::string::npos) << e;
  mj_deleteModel(m);
}

// the per-vertex e^(i theta) table (vertices x reserved components, two a
// texel) must fit a buffer texture: two hulls of 3872 vertices x 65536
// components = 2.5e8 texels is past llvmpipe's 2^27 (and GL's guaranteed
// 65536); attach fails naming the field
TEST(GlBackend, TooManyReservedComponentsAreNamed) {
  std::string xml = "<mujoco><asset><mesh name=\"w\" file=\"" MJB_MODELS
                    "/meshes/wigley_7744.obj\"/></asset><custom>"
                    "<text name=\"mjbuoy.hulls\" data=\"h*\"/>"
                    "<numeric name=\"mjbuoy.airy.a\" data=\"0.1 10 0 0\"/>"
                    "<numeric name=\"mjbuoy.sea.capacity\" data=\"65536\"/>"
                    "</custom><worldbody><body><freejoint/>"
                    "<geom name=\"h\" type=\"mesh\" mesh=\"w\" mass=\"100\"/></body>"
                    "<body pos=\"0 5 0\"><freejoint/>"
                    "<geom name=\"h2\" type=\"mesh\" mesh=\"w\" mass=\"100\"/></body>"
                    "</worldbody></mujoco>";
  std::string e;
  mjModel* m = loadXML(xml, &e);
  ASSERT_TRUE(m) << e;
  char err[1024];
  EXPECT_FALSE(mjb_attach(m, "gl", err, sizeof(err)));
  EXPECT_NE(std::string(err).find("mjbuoy.sea.capacity"), std::string::npos) << err;
  EXPECT_NE(std::string(err).find("7744 vertices x 65536"), std::string::npos) << err;
  // the cpu backend has no texture, but its per-mjData scratch (65536 x
  // 7744 x 2 phases x 8 bytes = 8 GB alone) is past the state bound: also
  // refused, naming the size (RobustEdges.OversizedStateIsRefusedAtAttach)
  EXPECT_FALSE(mjb_attach(m, "cpu", err, sizeof(err)));
  EXPECT_NE(std::string(err).find("MB of state"), std::string::npos) << err;
  mj_deleteModel(m);
}

TEST(GlBackend, AutoFallsBackAndGlFailsWithoutDisplay) {
  // MJBUOY_EGL=none simulates a machine without an EGL display
  setenv("MJBUOY_EGL", "none", 1);
  mjModel* m = mj_loadXML(MJB_MODELS "/barge.xml", nullptr, nullptr, 0);
  ASSERT_TRUE(m);
  char e[1024];
  mjbBuoy* b = mjb_attach(m, "auto", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  EXPECT_STREQ(mjb_info(b).backend, "cpu");
  EXPECT_NE(std::string(mjb_warnings(b)).find("backend auto: no usable GL"), std::string::npos)
      << mjb_warnings(b);
  mjb_detach(b);
  EXPECT_FALSE(mjb_attach(m, "gl", e, sizeof(e)));
  EXPECT_NE(std::string(e).find("backend gl is not available"), std::string::npos) << e;
  EXPECT_NE(std::string(e).find("MJBUOY_EGL=none"), std::string::npos) << e;
  unsetenv("MJBUOY_EGL");
  b = mjb_attach(m, "auto", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  EXPECT_STREQ(mjb_info(b).backend, "gl");
  mjb_detach(b);
  mj_deleteModel(m);
}

}  // namespace
}  // namespace mjbt
