// cpu backend speed-ups keep the physics: threads, warm-started surface
// search, the body-local generalized force and the above-crest skip give
// what the plain methods give
#include <cmath>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "sea/sea.h"
#include "testutil.h"

namespace mjbt {
namespace {

// n boats of three hull shapes on a two-component sea, some airborne
// (above every crest), with mjbuoy.threads set to `threads`
std::string fleet(int n, int threads) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.005\"/><custom><text name=\"mjbuoy.hulls\" data=\"h*\"/>"
    << "<numeric name=\"mjbuoy.wave.a\" data=\"0.3 12 20 0 0.5\"/>"
    << "<numeric name=\"mjbuoy.wave.b\" data=\"0.1 5 -40 30 0.4\"/>"
    << "<numeric name=\"mjbuoy.threads\" data=\"" << threads << "\"/></custom><worldbody>";
  const char* g[3] = {"type=\"box\" size=\"1 0.5 0.25\"", "type=\"capsule\" size=\"0.3 1\"",
                      "type=\"ellipsoid\" size=\"1 0.4 0.3\""};
  for (int i = 0; i < n; i++) {
    double z = i % 5 == 4 ? 3.0 : 0.05 * (i % 3);  // every fifth starts in the air
    s << "<body pos=\"" << 4 * (i % 4) << " " << 3 * (i / 4) << " " << z << "\" euler=\"" << 3 * i
      << " 2 " << 7 * i << "\"><freejoint/><geom name=\"h" << i << "\" " << g[i % 3]
      << " mass=\"300\"/></body>";
  }
  s << "</worldbody></mujoco>";
  return s.str();
}

std::vector<double> trajectory(const mjModel* m, mjData* d, int steps) {
  std::vector<double> out;
  for (int i = 0; i < steps; i++) {
    mj_step(m, d);
    out.insert(out.end(), d->qpos, d->qpos + m->nq);
  }
  return out;
}

TEST(Cpu, ThreadsGiveTheBitsOfOneThread) {
  // a fleet with several chunks per thread: 1, 2 and 3 threads agree
  // exactly, also when users step several mjData at once (the pool serves
  // one of them, the others run alone)
  Scene one(fleet(12, 1)), two(fleet(12, 2)), three(fleet(12, 3));
  ASSERT_TRUE(one.ok() && two.ok() && three.ok()) << one.err << two.err << three.err;
  std::vector<double> ref = trajectory(one.m, one.d, 300);
  EXPECT_EQ(trajectory(two.m, two.d, 300), ref);
  EXPECT_EQ(trajectory(three.m, three.d, 300), ref);
  const int n = 3;
  std::vector<mjData*> d(n);
  std::vector<std::vector<double>> out(n);
  for (int i = 0; i < n; i++) d[i] = mj_makeData(two.m);
  std::vector<std::thread> th;
  for (int i = 0; i < n; i++) th.emplace_back([&, i] { out[i] = trajectory(two.m, d[i], 300); });
  for (auto& t : th) t.join();
  for (int i = 0; i < n; i++) {
    EXPECT_EQ(out[i], ref) << "user thread " << i;
    mjb_unbindData(two.b, d[i]);
    mj_deleteData(d[i]);
  }
}

// one Wigley hull of 7740 triangles (4 chunks of 1935, mjb::hullChunks)
// on a steep sea: fewer bodies than two per thread, so
// with threads > 1 each hull's stages are split among the threads
std::string lone(int threads) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
    << "/meshes/wigley_7744.obj\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"h*\"/>"
    << "<numeric name=\"mjbuoy.wave.a\" data=\"0.4 10 20 0 0.8\"/>"
    << "<numeric name=\"mjbuoy.wave.b\" data=\"0.15 6 -50 40 0.6\"/>"
    << "<numeric name=\"mjbuoy.threads\" data=\"" << threads << "\"/></custom><worldbody>"
    << "<body pos=\"0 0 0.03\" euler=\"0 0 30\"><freejoint/><inertial pos=\"0 0 -0.08\" "
    << "mass=\"176.2\" diaginertia=\"6.02 237.28 238.6\"/><geom name=\"h0\" type=\"mesh\" "
    << "mesh=\"w\" contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>";
  return s.str();
}

TEST(Cpu, AHullSplitAmongThreadsGivesTheBitsOfOneThread) {
  // the chunks' sums are added in their order whoever ran them, so 1, 2 and
  // 3 threads agree exactly; so do users stepping several mjData at once
  // (the pool serves one of them, the others run alone)
  ASSERT_EQ(mjb::hullChunks(7740), 4);
  Scene one(lone(1)), two(lone(2)), three(lone(3));
  ASSERT_TRUE(one.ok() && two.ok() && three.ok()) << one.err << two.err << three.err;
  ASSERT_FALSE(mjb::buoyOf(one.b)->splitHulls);
  ASSERT_TRUE(mjb::buoyOf(two.b)->splitHulls && mjb::buoyOf(three.b)->splitHulls);
  ASSERT_EQ(mjb::buoyOf(three.b)->nthreads, 3);
  const std::vector<double> ref = stepRecord(one.m, one.d, one.b, 200);
  EXPECT_EQ(stepRecord(two.m, two.d, two.b, 200), ref);
  EXPECT_EQ(stepRecord(three.m, three.d, three.b, 200), ref);
  double fz = 0;  // the hull floats: the comparison covers wet chunks
  for (size_t i = 0; i < ref.size(); i += 7 + 12) fz = std::fmax(fz, ref[i + 7 + 6 + 2]);
  EXPECT_GT(fz, 1000);
  std::vector<mjData*> d(3);
  std::vector<std::vector<double>> out(3);
  for (int i = 0; i < 3; i++) d[i] = mj_makeData(two.m);
  std::vector<std::thread> th;
  for (int i = 0; i < 3; i++) {
    th.emplace_back([&, i] { out[i] = stepRecord(two.m, d[i], two.b, 200); });
  }
  for (auto& t : th) t.join();
  for (int i = 0; i < 3; i++) {
    EXPECT_EQ(out[i], ref) << "user thread " << i;
    mjb_unbindData(two.b, d[i]);
    mj_deleteData(d[i]);
  }
}

TEST(Cpu, GeneralizedForceMatchesMjApplyFT) {
  // hulls on a hinged arm (dof chain of length 7) and on a body welded to
  // it: qfrc_passive equals MuJoCo's own mj_applyFT of each body's wrench.
  // Radiation off: its forces reach qfrc_passive but not the readable
  // wrench (docs/physics.md section 14), and the mapping is what is tested
  const char* xml =
      "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h*\"/><text name=\"mjbuoy.radiation\" data=\"off\"/>"
      "<numeric name=\"mjbuoy.wave.a\" data=\"0.2 8 30 0 0.5\"/></custom><worldbody>"
      "<body name=\"base\" pos=\"0 0 0.1\"><freejoint/>"
      "<geom name=\"h0\" type=\"box\" size=\"1 0.5 0.2\" mass=\"400\"/>"
      "<body name=\"arm\" pos=\"1.5 0 0\"><joint type=\"hinge\" axis=\"0 1 0\"/>"
      "<geom name=\"h1\" type=\"capsule\" size=\"0.2 0.6\" euler=\"0 90 0\" mass=\"50\"/>"
      "<body name=\"tip\" pos=\"0.9 0 -0.1\">"
      "<geom name=\"h2\" type=\"sphere\" size=\"0.3\" mass=\"20\"/></body></body></body>"
      "<body name=\"other\" pos=\"-4 0 0\"><freejoint/>"
      "<geom name=\"h3\" type=\"box\" size=\"0.5 0.5 0.2\" mass=\"100\"/></body>"
      "</worldbody></mujoco>";
  Scene s(xml);
  ASSERT_TRUE(s.ok()) << s.err;
  for (int i = 0; i < 50; i++) mj_step(s.m, s.d);
  s.d->qvel[6] = 0.7;  // swing the arm
  mj_forward(s.m, s.d);
  std::vector<double> want(s.m->nv, 0);
  for (int bd = 1; bd < s.m->nbody; bd++) {
    const mjtNum* w = s.wrench(bd);
    mj_applyFT(s.m, s.d, w, w + 3, s.d->xipos + 3 * bd, bd, want.data());
  }
  double scale = 0;
  for (double v : want) scale = std::fmax(scale, std::fabs(v));
  ASSERT_GT(scale, 100);
  for (int i = 0; i < s.m->nv; i++) {
    EXPECT_NEAR(s.d->qfrc_passive[i], want[i], 1e-12 * scale) << "dof " << i;
  }
}

TEST(Cpu, FastSurfaceSearchMatchesLabel) {
  // Sea::solve (phases by angle addition, any guess) finds the particle
  // Sea::label finds, and its height, for 1, 3 and 6 components
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int nw : {1, 3, 6}) {
    mjb::Sea sea;
    sea.level = 0.4;
    for (int i = 0; i < nw; i++) {
      sea.waves.push_back(mjb::Wave{0.3 / nw * (1 + 0.5 * u(rng)), 6 + 20 * (1 + u(rng)),
                                    90 * u(rng), 180 * u(rng), 0.8, 0, 0, 0, 0, 0});
    }
    sea.derive();
    ASSERT_LT(sea.fold(), 1);
    std::vector<mjb::WaveNow> wn(nw);
    std::vector<double> sc(2 * nw), tmp(2 * nw);
    for (int k = 0; k < 200; k++) {
      double x = 50 * u(rng), y = 50 * u(rng), t = 10 * (1 + u(rng));
      sea.now(t, wn.data());
      double want[2] = {x, y};
      sea.label(x, y, t, want);
      // a cold guess, a near one and a poor one
      for (double off : {0.0, 1e-3, 2.0}) {
        double a[2] = {x + off, y - off};
        double z = sea.solve(wn.data(), x, y, a, sc.data(), tmp.data());
        EXPECT_NEAR(a[0], want[0], 1e-10);
        EXPECT_NEAR(a[1], want[1], 1e-10);
        EXPECT_NEAR(z, sea.heightOf(want, x, y, t), 1e-10);
        EXPECT_NEAR(z, sea.height(x, y, t), 1e-10);
        double v[3], vw[3];
        sea.velocitySC(wn.data(), sc.data(), z - 0.5 - sea.level, z - sea.level, v);
        double pw[3] = {x, y, z - 0.5};
        sea.velocity(pw, t, vw);
        for (int j = 0; j < 3; j++) EXPECT_NEAR(v[j], vw[j], 1e-10);
      }
    }
  }
}

TEST(Cpu, HullAboveEveryCrestGetsNothing) {
  // a box 0.05 m above the highest crest (level + sum of amplitudes) gets
  // no force at all; 0.05 m below its bottom touches the crests and does
  const char* xml =
      "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h\"/>"
      "<numeric name=\"mjbuoy.sea.level\" data=\"0.2\"/>"
      "<numeric name=\"mjbuoy.wave.a\" data=\"0.3 10 0 0 0.5\"/>"
      "<numeric name=\"mjbuoy.wave.b\" data=\"0.2 7 90 0 0.3\"/>"
      // the crests at full height at t = 0: no start-up ramp
      "<numeric name=\"mjbuoy.sea.ramp\" data=\"0\"/></custom><worldbody>"
      "<body name=\"a\" pos=\"0 0 Z\"><freejoint/>"
      "<geom name=\"h\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body>"
      "</worldbody></mujoco>";
  auto force = [&](const char* z) {
    std::string x = xml;
    x.replace(x.find(" Z\""), 2, std::string(" ") + z);
    Scene s(x);
    EXPECT_TRUE(s.ok()) << s.err;
    mj_forward(s.m, s.d);
    double f = 0;
    for (int j = 0; j < 6; j++) f += std::fabs(s.wrench(1)[j]);
    return f;
  };
  // crest 0.7 m; the box reaches 0.25 m below its centre
  EXPECT_EQ(force("1.0"), 0);
  EXPECT_GT(force("0.7"), 0);
}

TEST(Cpu, ThreadsEntryIsChecked) {
  const char* bad[] = {"-1", "65", "1.5", "1 2"};
  for (const char* v : bad) {
    std::string xml = std::string("<mujoco><custom><numeric name=\"mjbuoy.threads\" data=\"") + v +
                      "\"/><text name=\"mjbuoy.hulls\" data=\"h\"/></custom><worldbody><body>"
                      "<freejoint/><geom name=\"h\" type=\"sphere\" size=\"1\"/></body>"
                      "</worldbody></mujoco>";
    Scene s(xml);
    EXPECT_FALSE(s.ok()) << v;
    EXPECT_NE(s.err.find("mjbuoy.threads"), std::string::npos) << v << ": " << s.err;
  }
}

}  // namespace
}  // namespace mjbt
