// the shipped scenes: load cleanly, and float where their comments say
#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

struct Model {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  mjbBuoy* b = nullptr;
  explicit Model(const char* file) {
    char e[1024] = "";
    m = mj_loadXML((std::string(MJB_MODELS "/") + file).c_str(), nullptr, e, sizeof(e));
    EXPECT_TRUE(m) << file << ": " << e;
    if (!m) return;
    b = mjb_attach(m, nullptr, e, sizeof(e));
    EXPECT_TRUE(b) << file << ": " << e;
    if (b) {
      EXPECT_STREQ(mjb_warnings(b), "") << file;
    }
    d = mj_makeData(m);
  }
  ~Model() {
    if (d) mj_deleteData(d);
    if (b) mjb_detach(b);
    if (m) mj_deleteModel(m);
  }
};

TEST(Models, SettleAtTheirAnalyticDrafts) {
  // COM heights from the models' comments: barge T = 0.25 (COM at 0),
  // buoy R - h = 0.5 - 0.363258, cylinder R - h = 0.3 - 0.252679
  struct { const char* file; const char* body; double z; } cases[] = {
    {"barge.xml", "barge", 0.0},
    {"buoy.xml", "buoy", 0.136742},
    {"cylinder.xml", "cylinder", 0.047321},
  };
  for (auto& c : cases) {
    Model s(c.file);
    ASSERT_TRUE(s.b);
    int b = mj_name2id(s.m, mjOBJ_BODY, c.body);
    ASSERT_GE(b, 0) << c.file;
    double sum = 0;
    int n = 0;
    for (long step = 0, nstep = mjbt::stepsTo(s.m, s.d, 30); step < nstep; step++) {
      mj_step(s.m, s.d);
      if (s.d->time > 20) {
        sum += s.d->xipos[3 * b + 2];
        n++;
      }
    }
    EXPECT_NEAR(sum / n, c.z, 0.00125) << c.file;
  }
}

TEST(Models, FleetRidesTheWaves) {
  // every free body stays finite, near the surface and upright for 10 s
  Model s("fleet.xml");
  ASSERT_TRUE(s.b);
  for (long step = 0, nstep = mjbt::stepsTo(s.m, s.d, 10); step < nstep; step++) {
    mj_step(s.m, s.d);
    for (int j = 0; j < s.m->njnt; j++) {
      int b = s.m->jnt_bodyid[j];
      const mjtNum* x = s.d->xipos + 3 * b;
      double eta = mjb_seaHeight(s.b, x[0], x[1], s.d->time);
      ASSERT_TRUE(std::isfinite(x[2])) << s.m->names + s.m->name_bodyadr[b];
      ASSERT_NEAR(x[2], eta, 1.0) << s.m->names + s.m->name_bodyadr[b] << " t " << s.d->time;
      ASSERT_GT(s.d->xmat[9 * b + 8], std::cos(60 * M_PI / 180))  // tilt under 60 deg
          << s.m->names + s.m->name_bodyadr[b] << " t " << s.d->time;
    }
  }
}

}  // namespace
}  // namespace mjbt
