// API edges: NULL outputs, callbacks of the user's during attach, one model
// attached twice, the sensor trampoline across re-attach, sensor messages
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

// a 2 x 1 x 0.5 m box of 500 kg with its centre on the water, radiation on
// (the default for a free hull): buoyancy rho g V = 1000 * 9.81 * 0.5 N
// at rest, and a user sensor for mjcb_sensor
const char kBox[] =
    "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
    "<text name=\"mjbuoy.sensor.vol\" data=\"submerged_volume\"/></custom><worldbody>"
    "<body name=\"box\" pos=\"0 0 0\"><freejoint/>"
    "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body>"
    "</worldbody><sensor>"
    "<user name=\"vol\" objtype=\"body\" objname=\"box\" dim=\"1\" datatype=\"real\" "
    "needstage=\"vel\"/></sensor></mujoco>";
const double kBuoy = kRho * kG * 0.5;

TEST(RobustEdges, WindVelocityWithNullOutputIsANoOp) {
  Scene s(kBox);
  ASSERT_TRUE(s.ok()) << s.err;
  mjb_windVelocity(s.b, 0, nullptr);  // was: SIGSEGV
  mjtNum v[2] = {7, 7};
  mjb_windVelocity(nullptr, 0, v);
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[1], 0);
}

// user callbacks that record every mjData they are called with
std::vector<const mjData*> gseen;
void seePassive(const mjModel*, mjData* d) { gseen.push_back(d); }
void seeControl(const mjModel*, mjData* d) { gseen.push_back(d); }
void seeSensor(const mjModel*, mjData* d, int) { gseen.push_back(d); }

TEST(RobustEdges, AttachCallsNoUserCallback) {
  mjModel* m = loadXML(kBox);
  ASSERT_TRUE(m);
  mjfGeneric p0 = mjcb_passive, c0 = mjcb_control;
  mjfSensor s0 = mjcb_sensor;
  mjcb_passive = seePassive;
  mjcb_control = seeControl;
  mjcb_sensor = seeSensor;
  gseen.clear();
  char e[1000];
  mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  // attach builds what it needs from the model: no user code runs on
  // mjData the user never made
  EXPECT_EQ(gseen.size(), 0u);
  mjData* d = mj_makeData(m);
  gseen.clear();
  mj_forward(m, d);
  for (const mjData* x : gseen) EXPECT_EQ(x, d);
  EXPECT_GE(gseen.size(), 3u);  // passive, control, sensor (vel stage)
  mj_deleteData(d);
  mjb_detach(b);
  mjcb_passive = p0;
  mjcb_control = c0;
  mjcb_sensor = s0;
  mj_deleteModel(m);
}

TEST(RobustEdges, OneModelAttachedTwiceKeepsItsDofFlagsUntilTheLastDetach) {
  mjModel* m = loadXML(kBox);
  ASSERT_TRUE(m);
  std::vector<int> orig(m->dof_simplenum, m->dof_simplenum + m->nv);
  char e[1000];
  mjbBuoy* a = mjb_attach(m, "cpu", e, sizeof(e));
  ASSERT_TRUE(a) << e;
  // radiation's added mass couples the free dofs: MuJoCo's diagonal
  // "simple" shortcut must be off for them (docs/physics.md section 14)
  std::vector<int> cleared(m->dof_simplenum, m->dof_simplenum + m->nv);
  ASSERT_NE(cleared, orig) << "the test needs a model whose flags radiation clears";
  mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  mjb_detach(a);
  std::vector<int> now(m->dof_simplenum, m->dof_simplenum + m->nv);
  EXPECT_EQ(now, cleared) << "b is live: its added mass still needs the flags off";
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  EXPECT_NEAR(d->qfrc_passive[2], kBuoy, 1e-9 * kBuoy);  // b still acts
  mj_deleteData(d);
  mjb_detach(b);
  now.assign(m->dof_simplenum, m->dof_simplenum + m->nv);
  EXPECT_EQ(now, orig) << "the last detach gives the model back as it was";
  mj_deleteModel(m);
}

// a user's sensor callback that chains to whatever it replaced
mjfSensor gsensPrev = nullptr;
int gsensCalls = 0;
void userSensor(const mjModel* m, mjData* d, int stage) {
  gsensCalls++;
  if (gsensPrev) gsensPrev(m, d, stage);
}

TEST(RobustEdges, UserSensorCallbackChainedAcrossReattachDoesNotRecurse) {
  mjfSensor orig = mjcb_sensor;
  mjModel* m = loadXML(kBox);
  ASSERT_TRUE(m);
  char e[1000];
  mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  gsensPrev = mjcb_sensor;  // the user chains to mjbuoy's
  mjcb_sensor = userSensor;
  mjb_detach(b);
  b = mjb_attach(m, "cpu", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  mjData* d = mj_makeData(m);
  gsensCalls = 0;
  mj_forward(m, d);  // was: infinite recursion, stack overflow
  EXPECT_EQ(gsensCalls, 1);  // one user sensor, needstage vel: one call
  // mjbuoy filled its sensor once: the box's submerged volume 0.5 m^3
  int id = mj_name2id(m, mjOBJ_SENSOR, "vol");
  EXPECT_NEAR(d->sensordata[m->sensor_adr[id]], 0.5, 1e-12);
  mjb_detach(b);
  EXPECT_EQ(mjcb_sensor, userSensor);
  gsensCalls = 0;
  mj_forward(m, d);
  EXPECT_EQ(gsensCalls, 1);
  mjcb_sensor = orig;
  gsensPrev = nullptr;
  mj_deleteData(d);
  mj_deleteModel(m);
}

TEST(RobustEdges, UnknownForceFamilyMessageListsWind) {
  std::string xml = kBox;
  xml.replace(xml.find("data=\"submerged_volume\""), 23, "data=\"wrench windage\"");
  xml.replace(xml.find("dim=\"1\""), 7, "dim=\"6\"");
  xml.replace(xml.find("needstage=\"vel\""), 15, "needstage=\"acc\"");
  mjModel* m = loadXML(xml);
  ASSERT_TRUE(m);
  char e[1000];
  mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof(e));
  EXPECT_FALSE(b);
  std::string msg = e;
  // every family mjbPart names, wind included (the word "windage" of the
  // bad value is quoted, so "or wind" is the list's)
  for (const char* f : {"pressure,", "viscous,", "drag,", "slam,", "damping", "or wind"}) {
    EXPECT_NE(msg.find(f), std::string::npos) << f << " in: " << msg;
  }
  if (b) mjb_detach(b);
  mj_deleteModel(m);
}

// per-mjData state grows with threads x components x hull size: a 7744-
// triangle Wigley hull with 65536 components reserved needs 2 phases x
// 65536 x 7744 points x 8 bytes = 8.1 GB of scratch for the surface solve
// alone (was: allocated inside the first step, where nothing catches a
// failure). Refused at attach, naming the size and the settings; with 256
// reserved (32 MB) it attaches and mjb_bindData allocates it up front
TEST(RobustEdges, OversizedStateIsRefusedAtAttach) {
  auto wigley = [](int capacity) {
    return std::string("<mujoco><asset><mesh name=\"w\" file=\"" MJB_MODELS
                       "/meshes/wigley_7744.obj\"/></asset><custom>"
                       "<text name=\"mjbuoy.hulls\" data=\"h\"/>"
                       "<text name=\"mjbuoy.radiation\" data=\"off\"/>"
                       "<numeric name=\"mjbuoy.threads\" data=\"1\"/>"
                       "<numeric name=\"mjbuoy.sea.capacity\" data=\"") +
           std::to_string(capacity) + "\"/></custom><worldbody><body><freejoint/>"
           "<geom name=\"h\" type=\"mesh\" mesh=\"w\" mass=\"100\"/></body>"
           "</worldbody></mujoco>";
  };
  mjModel* m = loadXML(wigley(65536));
  ASSERT_TRUE(m);
  char e[1000];
  EXPECT_FALSE(mjb_attach(m, "cpu", e, sizeof(e)));
  std::string msg = e;
  // at least the 8.1 GB of phases: 7700 MB and more
  size_t at = msg.find("would need about ");
  ASSERT_NE(at, std::string::npos) << msg;
  EXPECT_GE(std::atoi(msg.c_str() + at + 17), 7700) << msg;
  EXPECT_NE(msg.find("mjbuoy.sea.capacity"), std::string::npos) << msg;
  EXPECT_NE(msg.find("mjbuoy.threads"), std::string::npos) << msg;
  mj_deleteModel(m);
  m = loadXML(wigley(256));
  ASSERT_TRUE(m);
  mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  mjData* d = mj_makeData(m);
  EXPECT_EQ(mjb_bindData(b, d), 1);
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
}

}  // namespace
}  // namespace mjbt
