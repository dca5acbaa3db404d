// API faults (issue 11): the mjcb_passive chain, handles after detach,
// per-mjData state of new, reset and copied data, copied models
#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

// a 2 x 1 x 0.5 m box of 500 kg held with its centre on the water: at rest
// the only force is buoyancy rho g V, V = 2 * 1 * 0.25 = 0.5 m^3 (hydrostatics)
const char kBox[] =
    "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/></custom><worldbody>"
    "<body name=\"box\" pos=\"0 0 0\"><freejoint/>"
    "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body>"
    "</worldbody></mujoco>";
const double kBuoy = kRho * kG * 0.5;  // 4905 N

// mju_user_warning capture
std::vector<std::string> gwarn;
void keepWarning(const char* msg) { gwarn.push_back(msg); }
struct CaptureWarnings {
  void (*old)(const char*);
  CaptureWarnings() : old(mju_user_warning) {
    gwarn.clear();
    mju_user_warning = keepWarning;
  }
  ~CaptureWarnings() { mju_user_warning = old; }
  int count(const std::string& what) const {
    int n = 0;
    for (const std::string& w : gwarn) n += w.find(what) != std::string::npos;
    return n;
  }
};

// a user's passive callback that chains to whatever it replaced
mjfGeneric guserPrev = nullptr;
int guserCalls = 0;
void userPassive(const mjModel* m, mjData* d) {
  guserCalls++;
  if (guserPrev) guserPrev(m, d);
}

TEST(RobustApi, UserCallbackChainedAcrossReattachDoesNotRecurse) {
  CaptureWarnings cw;
  mjfGeneric orig = mjcb_passive;
  mjModel* m = loadXML(kBox);
  ASSERT_TRUE(m);
  char e[1000];
  mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  // the user installs a callback that chains to mjbuoy's
  guserPrev = mjcb_passive;
  mjcb_passive = userPassive;
  mjb_detach(b);
  // the user's callback (still chaining to mjbuoy's) is what a new attach finds
  b = mjb_attach(m, "cpu", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  mjData* d = mj_makeData(m);
  guserCalls = 0;
  mj_forward(m, d);  // was: infinite recursion, SIGSEGV
  EXPECT_EQ(guserCalls, 1);
  // mjbuoy's force acts once: z force on the free joint = rho g V
  EXPECT_NEAR(d->qfrc_passive[2], kBuoy, 1e-9 * kBuoy);
  mjb_detach(b);
  // detach restored the user's callback; it still chains, mjbuoy adds nothing
  EXPECT_EQ(mjcb_passive, userPassive);
  guserCalls = 0;
  mj_forward(m, d);
  EXPECT_EQ(guserCalls, 1);
  EXPECT_EQ(d->qfrc_passive[2], 0);
  mjcb_passive = orig;
  mj_deleteData(d);
  mj_deleteModel(m);
}

TEST(RobustApi, NestedAttachDetachOfTwoModelsRestoresTheChain) {
  CaptureWarnings cw;
  mjfGeneric orig = mjcb_passive;
  mjModel* ma = loadXML(kBox);
  mjModel* mb = loadXML(kBox);
  ASSERT_TRUE(ma && mb);
  char e[1000];
  mjbBuoy* a = mjb_attach(ma, "cpu", e, sizeof(e));
  guserPrev = mjcb_passive;  // a user callback between the two attaches
  mjcb_passive = userPassive;
  mjbBuoy* bb = mjb_attach(mb, "cpu", e, sizeof(e));
  ASSERT_TRUE(a && bb) << e;
  mjData* db = mj_makeData(mb);
  mjb_detach(a);
  guserCalls = 0;
  mj_forward(mb, db);
  EXPECT_EQ(guserCalls, 1);
  EXPECT_NEAR(db->qfrc_passive[2], kBuoy, 1e-9 * kBuoy);
  // attach a again while b is attached, then detach both in attach order
  a = mjb_attach(ma, "cpu", e, sizeof(e));
  ASSERT_TRUE(a) << e;
  mjData* da = mj_makeData(ma);
  guserCalls = 0;
  mj_forward(ma, da);
  mj_forward(mb, db);
  EXPECT_EQ(guserCalls, 2);
  EXPECT_NEAR(da->qfrc_passive[2], kBuoy, 1e-9 * kBuoy);
  EXPECT_NEAR(db->qfrc_passive[2], kBuoy, 1e-9 * kBuoy);
  mjb_detach(bb);
  mjb_detach(a);
  mjcb_passive = orig;
  // without a user callback: two models nested, the original slot comes back
  a = mjb_attach(ma, "cpu", e, sizeof(e));
  bb = mjb_attach(mb, "cpu", e, sizeof(e));
  EXPECT_NE(mjcb_passive, orig);
  mjb_detach(a);
  mj_forward(mb, db);
  EXPECT_NEAR(db->qfrc_passive[2], kBuoy, 1e-9 * kBuoy);
  mjb_detach(bb);
  EXPECT_EQ(mjcb_passive, orig);
  mj_deleteData(da);
  mj_deleteData(db);
  mj_deleteModel(ma);
  mj_deleteModel(mb);
}

TEST(RobustApi, DetachTwiceIsAWarnedNoOp) {
  CaptureWarnings cw;
  mjModel* m = loadXML(kBox);
  ASSERT_TRUE(m);
  char e[1000];
  mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  mjb_detach(b);
  EXPECT_EQ(cw.count("not attached"), 0);
  mjb_detach(b);  // was: double free
  EXPECT_EQ(cw.count("mjb_detach was given a handle that is not attached"), 1);
  mjb_detach(nullptr);
  EXPECT_EQ(gwarn.size(), 1u);
  mj_deleteModel(m);
}

// MuJoCo's allocator hooks, recycling freed blocks: a block freed is
// handed out again by the next allocation of the same size, so a new mjData
// lands at the address of the one deleted before it whatever the system
// allocator (or ASan's quarantine) would do. Blocks are released at the end
struct Recycler {
  static std::vector<std::pair<void*, size_t>>& live() {
    static std::vector<std::pair<void*, size_t>> v;
    return v;
  }
  static std::vector<std::pair<void*, size_t>>& spare() {
    static std::vector<std::pair<void*, size_t>> v;
    return v;
  }
  static void* alloc(size_t n) {
    auto& sp = spare();
    for (size_t i = 0; i < sp.size(); i++) {
      if (sp[i].second == n) {
        void* p = sp[i].first;
        sp.erase(sp.begin() + i);
        live().push_back({p, n});
        return p;
      }
    }
    // 64-byte aligned as mju_malloc's own blocks: mj_makeData lays its
    // arrays out from the buffer's address and checks the total
    void* p = std::aligned_alloc(64, (n + 63) / 64 * 64);
    live().push_back({p, n});
    return p;
  }
  static void release(void* p) {
    auto& lv = live();
    for (size_t i = 0; i < lv.size(); i++) {
      if (lv[i].first == p) {
        spare().push_back(lv[i]);
        lv.erase(lv.begin() + i);
        return;
      }
    }
    std::free(p);  // allocated before the hooks
  }
  Recycler() {
    mju_user_malloc = alloc;
    mju_user_free = release;
  }
  ~Recycler() {
    mju_user_malloc = nullptr;
    mju_user_free = nullptr;
    for (auto& b : spare()) std::free(b.first);
    spare().clear();
  }
};

TEST(RobustApi, FreshDataAtARecycledAddressStartsClean) {
  Scene s(kBox);
  ASSERT_TRUE(s.ok()) << s.err;
  int body = s.body("box"), stale = 0, recycled = 0;
  std::vector<const mjData*> seen;
  {
    Recycler rc;
    for (int ep = 0; ep < 200; ep++) {
      mjData* d = mj_makeData(s.m);
      recycled += std::find(seen.begin(), seen.end(), d) != seen.end();
      seen.push_back(d);
      // before its first step a new mjData has had no force from mjbuoy
      const mjtNum* w = mjb_wrench(s.b, d);
      bool nonzero = false;
      for (int j = 0; w && j < 6 * s.m->nbody; j++) nonzero = nonzero || w[j] != 0;
      stale += nonzero;
      for (int k = 0; k < 2; k++) mj_step(s.m, d);
      // and after stepping, buoyancy near rho g V (it has barely moved)
      EXPECT_NEAR(mjb_wrench(s.b, d)[6 * body + 2], kBuoy, 0.05 * kBuoy);
      mj_deleteData(d);
    }
  }
  EXPECT_EQ(recycled, 199) << "every mjData after the first reuses the address of the last";
  EXPECT_EQ(stale, 0) << "of 200 new mjData, " << recycled << " at recycled addresses";
}

TEST(RobustApi, NoticesAreClearedByResetSoALaterFaultIsReported) {
  Scene s(kBox);
  ASSERT_TRUE(s.ok()) << s.err;
  s.d->qvel[2] = NAN;
  mj_forward(s.m, s.d);
  EXPECT_NE(std::string(mjb_notices(s.b, s.d)).find("body \"box\""), std::string::npos);
  mj_resetData(s.m, s.d);
  EXPECT_EQ(std::string(mjb_notices(s.b, s.d)), "");  // was: the old fault
  for (int k = 0; k < 5; k++) mj_step(s.m, s.d);
  EXPECT_EQ(std::string(mjb_notices(s.b, s.d)), "");
  s.d->qvel[2] = NAN;
  mj_forward(s.m, s.d);
  // the new fault is reported (was: never, the body counted as told)
  EXPECT_NE(std::string(mjb_notices(s.b, s.d)).find("body \"box\""), std::string::npos);
}

TEST(RobustApi, CopyDataCarriesTheSlammingHistory) {
  // the box dropped from 0.3 m above floating: it meets the water at
  // t = sqrt(2 * 0.3 / g) = 0.247 s, where slamming acts; both backends
  // (gl keeps the history in GPU buffers)
  std::string xml = kBox;
  xml.replace(xml.find("pos=\"0 0 0\""), 11, "pos=\"0 0 0.3\"");
  for (const char* backend : {"cpu", "gl"}) {
    SCOPED_TRACE(backend);
    mjModel* m = loadXML(xml);
    ASSERT_TRUE(m);
    char e[1000];
    mjbBuoy* b = mjb_attach(m, backend, e, sizeof(e));
    ASSERT_TRUE(b) << e;
    mjData* d = mj_makeData(m);
    const int body = 1;
    for (int k = 0; k < 130; k++) mj_step(m, d);  // 0.26 s: in the water
    mjData* d1 = mj_makeData(m);
    mjData* d2 = mj_makeData(m);
    mj_copyData(d1, m, d);
    ASSERT_EQ(mjb_copyData(b, d1, d), 1);
    mj_copyData(d2, m, d);  // without mjbuoy's state
    mj_step(m, d);
    mj_step(m, d1);
    mj_step(m, d2);
    double slam = mjb_wrenchPart(b, d, mjbPART_SLAM)[6 * body + 2];
    EXPECT_GT(slam, 0) << "slamming must act at the copy for the test to show anything";
    EXPECT_EQ(mjb_wrenchPart(b, d1, mjbPART_SLAM)[6 * body + 2], slam);
    // mj_copyData alone: no history, so no Gamma and no slamming in that step
    EXPECT_EQ(mjb_wrenchPart(b, d2, mjbPART_SLAM)[6 * body + 2], 0);
    for (int k = 0; k < 100; k++) {
      mj_step(m, d);
      mj_step(m, d1);
    }
    for (int i = 0; i < m->nq; i++) EXPECT_EQ(d1->qpos[i], d->qpos[i]) << i;
    for (mjData* x : {d, d1, d2}) mj_deleteData(x);
    mjb_detach(b);
    mj_deleteModel(m);
  }
}

TEST(RobustApi, CopiedModelWithoutAttachWarnsOnce) {
  Scene s(kBox);
  ASSERT_TRUE(s.ok()) << s.err;
  CaptureWarnings cw;
  mjModel* m2 = mj_copyModel(nullptr, s.m);
  mjData* d2 = mj_makeData(m2);
  for (int k = 0; k < 3; k++) mj_step(m2, d2);
  EXPECT_EQ(cw.count("Attach every copy"), 1);
  EXPECT_EQ(d2->qfrc_passive[2], 0);
  char e[1000];
  mjbBuoy* b2 = mjb_attach(m2, "cpu", e, sizeof(e));
  ASSERT_TRUE(b2) << e;
  mj_resetData(m2, d2);
  mj_forward(m2, d2);
  EXPECT_NEAR(d2->qfrc_passive[2], kBuoy, 1e-9 * kBuoy);
  EXPECT_EQ(cw.count("Attach every copy"), 1);
  mj_deleteData(d2);
  mjb_detach(b2);
  mj_deleteModel(m2);
}

}  // namespace
}  // namespace mjbt
