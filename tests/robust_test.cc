// faults: bad states stay contained, results are reproducible and
// independent across threads, data and models
#include <thread>

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

const char kTwo[] =
    "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"ha hb\"/>"
    "<numeric name=\"mjbuoy.wave.w\" data=\"0.2 10 20 0 0.5\"/></custom><worldbody>"
    "<body name=\"a\" pos=\"0 0 0\"><freejoint/>"
    "<geom name=\"ha\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body>"
    "<body name=\"b\" pos=\"5 0 0.1\" euler=\"5 3 0\"><freejoint/>"
    "<geom name=\"hb\" type=\"capsule\" size=\"0.3 1\" euler=\"0 90 0\" mass=\"200\"/></body>"
    "</worldbody></mujoco>";

TEST(Robust, NonFiniteBodyGetsNoForceAndDoesNotSpread) {
  Scene s(kTwo);
  ASSERT_TRUE(s.ok()) << s.err;
  int a = s.body("a"), b = s.body("b");
  mj_forward(s.m, s.d);
  double fb[6];
  std::memcpy(fb, s.wrench(b), sizeof(fb));
  s.d->qvel[1] = NAN;  // body a
  for (int i = 0; i < 3; i++) mj_forward(s.m, s.d);
  for (int j = 0; j < 6; j++) {
    EXPECT_EQ(s.wrench(a)[j], 0);
    EXPECT_EQ(s.wrench(b)[j], fb[j]);
  }
  std::string n = mjb_notices(s.b, s.d);
  EXPECT_NE(n.find("body \"a\""), std::string::npos) << n;
  EXPECT_EQ(n.find("body \"a\""), n.rfind("body \"a\"")) << "reported more than once: " << n;
  EXPECT_EQ(n.find("body \"b\""), std::string::npos) << n;

  // an infinite position on another mjData: the same
  mjData* d2 = mj_makeData(s.m);
  d2->qpos[7] = INFINITY;  // body b's x
  mj_forward(s.m, d2);
  for (int j = 0; j < 6; j++) EXPECT_EQ(mjb_wrench(s.b, d2)[6 * b + j], 0);
  EXPECT_NE(mjb_wrench(s.b, d2)[6 * a + 2], 0);
  n = mjb_notices(s.b, d2);
  EXPECT_NE(n.find("body \"b\""), std::string::npos) << n;
  EXPECT_EQ(n.find("body \"a\""), std::string::npos) << n;
  mjb_unbindData(s.b, d2);
  mj_deleteData(d2);
}

// run a scene for T seconds (counting steps, see Scene::settle), returning qpos
std::vector<double> run(const mjModel* m, mjData* d, double T) {
  for (long k = 0, n = std::lround(T / m->opt.timestep); k < n; k++) mj_step(m, d);
  return std::vector<double>(d->qpos, d->qpos + m->nq);
}

TEST(Robust, CpuIsBitIdenticalAcrossRunsDataAndThreads) {
  Scene s(kTwo);
  ASSERT_TRUE(s.ok()) << s.err;
  std::vector<double> ref = run(s.m, s.d, 3);
  // again on the same data after a reset (slamming history restarts)
  mj_resetData(s.m, s.d);
  EXPECT_EQ(run(s.m, s.d, 3), ref);
  // four mjData stepped in parallel threads
  const int n = 4;
  std::vector<mjData*> d(n);
  std::vector<std::vector<double>> out(n);
  for (int i = 0; i < n; i++) d[i] = mj_makeData(s.m);
  std::vector<std::thread> th;
  for (int i = 0; i < n; i++) th.emplace_back([&, i] { out[i] = run(s.m, d[i], 3); });
  for (auto& t : th) t.join();
  for (int i = 0; i < n; i++) {
    EXPECT_EQ(out[i], ref) << "thread " << i;
    mjb_unbindData(s.b, d[i]);
    mj_deleteData(d[i]);
  }
}

TEST(Robust, TwoModelsInOneProcessDoNotMix) {
  // the same scene twice, one with a current: the first is unaffected
  Scene s(kTwo);
  std::string cur = kTwo;
  cur.replace(cur.find("<custom>"), 8,
              "<custom><numeric name=\"mjbuoy.sea.current\" data=\"1 0\"/>");
  Scene t(cur);
  ASSERT_TRUE(s.ok() && t.ok());
  Scene alone(kTwo);
  std::vector<double> a = run(s.m, s.d, 2), c = run(t.m, t.d, 2), r = run(alone.m, alone.d, 2);
  EXPECT_EQ(a, r);
  EXPECT_NE(c, r);
}

TEST(Robust, FarAwayBoatFloatsLikeAtTheOrigin) {
  // 1e6 m from the origin on flat water: the same draft to 1e-6 m
  std::string xml =
      "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h\"/></custom><worldbody>"
      "<body name=\"a\" pos=\"POS\"><freejoint/>"
      "<geom name=\"h\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body></worldbody></mujoco>";
  auto at = [&](const char* pos) {
    std::string x = xml;
    x.replace(x.find("POS"), 3, pos);
    Scene s(x);
    EXPECT_TRUE(s.ok()) << s.err;
    run(s.m, s.d, 5);
    return s.d->qpos[2];
  };
  EXPECT_NEAR(at("1e6 -1e6 0.1"), at("0 0 0.1"), 1e-6);
}

TEST(Robust, FullySubmergedAndAirborne) {
  // submerged: buoyancy is rho g V; airborne: no force at all
  Scene s(kTwo);
  ASSERT_TRUE(s.ok()) << s.err;
  int a = s.body("a");
  // 2 x 1 x 0.5 m; 30 m under 10 m waves, whose linear-theory pressure has
  // decayed by e^{-k d} = 7e-9 (Froude-Krylov rho V A w^2 e^{-kd} < 1e-5 N)
  s.d->qpos[2] = -30;
  mj_forward(s.m, s.d);
  EXPECT_NEAR(s.wrench(a)[2], kRho * kG * 1.0, 1e-3);
  s.d->qpos[2] = 10;
  mj_forward(s.m, s.d);
  for (int j = 0; j < 6; j++) EXPECT_EQ(s.wrench(a)[j], 0);
}

TEST(Robust, TimeGoingBackwardsRestartsTheSlammingHistory) {
  // a box dropped onto waves (slamming acts); at t = 1.5 s its clock is set
  // back to 0.2 s. From there it runs bit for bit like a fresh mjData given
  // the same state at 0.2 s: no slamming history from the old timeline
  Scene s(kTwo);
  ASSERT_TRUE(s.ok()) << s.err;
  s.d->qpos[2] = 0.6;
  run(s.m, s.d, 1.5);
  mjData* fresh = mj_makeData(s.m);
  mju_copy(fresh->qpos, s.d->qpos, s.m->nq);
  mju_copy(fresh->qvel, s.d->qvel, s.m->nv);
  s.d->time = fresh->time = 0.2;
  double slam = 0;
  for (int k = 0; k < 500; k++) {
    mj_step(s.m, s.d);
    mj_step(s.m, fresh);
    for (int j = 0; j < 6 * s.m->nbody; j++) {
      ASSERT_EQ(mjb_wrench(s.b, s.d)[j], mjb_wrench(s.b, fresh)[j]) << "step " << k;
    }
    slam = std::fmax(slam, std::fabs(mjb_wrenchPart(s.b, s.d, mjbPART_SLAM)[6 * 1 + 2]));
  }
  EXPECT_GT(slam, 0) << "slamming never acted: the test shows nothing";
  mjb_unbindData(s.b, fresh);
  mj_deleteData(fresh);
}

TEST(Robust, SettleStopsWhenMuJoCoResets) {
  // tests/testutil.h Scene::settle counts steps: when MuJoCo resets a
  // diverging state (time back to 0) it reports it and returns, where a
  // `while (d->time < T)` loop would start over
  Scene s(kTwo);
  ASSERT_TRUE(s.ok()) << s.err;
  s.d->qvel[2] = NAN;
  double z = 0;
  EXPECT_NONFATAL_FAILURE(z = s.settle(1, 0.5, [&] { return s.d->qpos[2]; }),
                          "MuJoCo reset the diverging simulation in step 0");
  EXPECT_TRUE(std::isnan(z));
  EXPECT_EQ(s.resets(), 1);
}

TEST(Robust, GlIsRepeatableOnOneDriver) {
  // the gl backend sums in a fixed order (no atomics), so the same scene
  // run twice on the same driver gives the same bits; across drivers only
  // the GlParity tolerance (1e-4 of the cpu reference) holds
  auto runGl = [](std::vector<double>* q) {
    mjModel* m = loadXML(kTwo);
    ASSERT_TRUE(m);
    char e[1024];
    mjbBuoy* b = mjb_attach(m, "gl", e, sizeof(e));
    ASSERT_TRUE(b) << e;
    ASSERT_STREQ(mjb_info(b).backend, "gl");
    mjData* d = mj_makeData(m);
    *q = run(m, d, 2);
    mj_deleteData(d);
    mjb_detach(b);
    mj_deleteModel(m);
  };
  std::vector<double> a, b;
  runGl(&a);
  runGl(&b);
  ASSERT_EQ(a.size(), 14u);
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace mjbt
