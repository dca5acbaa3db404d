// the threading contract of mjbuoy.h: what replaces or frees a model's data
// (mjb_setSea, mjb_detach) waits for a callback of that model already
// running on another thread, and is refused from inside one. The callback
// is held inside mjbuoy's trampoline by a user callback it chains to; all
// shared flags are atomics, so the test itself has no data race
#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "radiation/radiation.h"
#include "testutil.h"

namespace mjbt {
namespace {

// a 2 x 1 x 0.5 m box of 500 kg, centre on the water, radiation off (fast
// attach), room for 4 wave components: at rest the force is buoyancy
// rho g V = 1000 * 9.81 * 0.5 N
const char kBox[] =
    "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
    "<text name=\"mjbuoy.radiation\" data=\"off\"/>"
    "<numeric name=\"mjbuoy.sea.capacity\" data=\"4\"/></custom><worldbody>"
    "<body name=\"box\" pos=\"0 0 0\"><freejoint/>"
    "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body>"
    "</worldbody></mujoco>";
const double kBuoy = kRho * kG * 0.5;

std::atomic<bool> ghold{false}, ginside{false}, gdone{false}, gsawDone{false};
mjbBuoy* gself = nullptr;  // set before the stepping thread starts
std::string gselfErr;

// the user's passive callback, installed before mjb_attach: mjbuoy's
// trampoline calls it first, inside its own run. While held it waits
// (at most 0.5 s) for the other thread's call to return
void holder(const mjModel*, mjData*) {
  if (!ghold) return;
  ginside = true;
  for (int i = 0; i < 500 && !gdone; i++) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  gsawDone = gdone.load();
}

struct Held {
  mjfGeneric old = mjcb_passive;
  Held() {
    mjcb_passive = holder;
    ghold = ginside = gdone = gsawDone = false;
  }
  ~Held() { mjcb_passive = old; }
};

void waitInside() {
  while (!ginside) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

TEST(RobustThreads, SetSeaWaitsForACallbackRunningOnAnotherThread) {
  Held h;
  Scene s(kBox);
  ASSERT_TRUE(s.ok()) << s.err;
  ghold = true;
  std::thread stepper([&] { mj_forward(s.m, s.d); });
  waitInside();
  double wave[5] = {0.1, 20, 0, 0, 0};
  mjbSea sea = {};
  sea.wave = wave;
  sea.nwave = 1;
  char e[500];
  int ok = mjb_setSea(s.b, &sea, e, sizeof(e));
  gdone = true;
  stepper.join();
  EXPECT_EQ(ok, 1) << e;
  // was: mjb_setSea rewrote the components while the callback ran
  EXPECT_FALSE(gsawDone) << "mjb_setSea returned while a callback of the model was running";
  // the step that was running saw the old, still sea: buoyancy rho g V
  EXPECT_NEAR(s.d->qfrc_passive[2], kBuoy, 1e-9 * kBuoy);
}

TEST(RobustThreads, DetachWaitsForACallbackRunningOnAnotherThread) {
  Held h;
  mjModel* m = loadXML(kBox);
  ASSERT_TRUE(m);
  char e[500];
  mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  mjData* d = mj_makeData(m);
  ghold = true;
  std::thread stepper([&] { mj_forward(m, d); });
  waitInside();
  mjb_detach(b);  // was: freed b while the callback went on to use it
  gdone = true;
  stepper.join();
  EXPECT_FALSE(gsawDone) << "mjb_detach returned while a callback of the model was running";
  // the running callback finished its work on the live handle
  EXPECT_NEAR(d->qfrc_passive[2], kBuoy, 1e-9 * kBuoy);
  mj_deleteData(d);
  mj_deleteModel(m);
}

// replacing the radiation coefficients (mjb::setHydroCoef, used by the
// tools) frees and reallocates what a running callback reads: it waits too
TEST(RobustThreads, NewCoefficientsWaitForACallbackRunningOnAnotherThread) {
  Held h;
  Scene s(kBox);
  ASSERT_TRUE(s.ok()) << s.err;
  ghold = true;
  std::thread stepper([&] { mj_forward(s.m, s.d); });
  waitInside();
  mjb::HydroCoef c;
  c.Ainf[14] = 100;  // heave added mass [kg]
  std::string e = mjb::setHydroCoef(s.b, s.body("box"), c, -1);
  gdone = true;
  stepper.join();
  EXPECT_EQ(e, "");
  EXPECT_FALSE(gsawDone) << "setHydroCoef returned while a callback of the model was running";
}

// the user calls mjb_setSea from its own passive callback, which mjbuoy's
// trampoline runs: refused with a message, not a deadlock
void setter(const mjModel*, mjData*) {
  if (!gself) return;
  mjbSea sea = {};
  char e[500] = "";
  if (!mjb_setSea(gself, &sea, e, sizeof(e))) gselfErr = e;
}

TEST(RobustThreads, SetSeaInsideACallbackIsRefused) {
  mjfGeneric old = mjcb_passive;
  mjcb_passive = setter;
  {
    Scene s(kBox);
    ASSERT_TRUE(s.ok()) << s.err;
    gself = s.b;
    gselfErr.clear();
    mj_forward(s.m, s.d);
    gself = nullptr;
    EXPECT_NE(gselfErr.find("mjb_setSea was called from inside"), std::string::npos)
        << gselfErr;
    EXPECT_NEAR(s.d->qfrc_passive[2], kBuoy, 1e-9 * kBuoy);
  }
  mjcb_passive = old;
}

}  // namespace
}  // namespace mjbt
