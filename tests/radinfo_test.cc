// the public radiation queries (mjbuoy.h: mjb_radiationBodies before
// attach, mjb_radiationInfo after), which the tools' radiation lines use
#include <string>

#include <gtest/gtest.h>

#include "floatbox.h"
#include "mjbuoy.h"
#include "testutil.h"

namespace {

// the floating cube with mjbuoy.radiation set to value
std::string cubeWith(const std::string& value) {
  std::string x = mjbt::floatingCubeXML();
  const std::string on = "name=\"mjbuoy.radiation\" data=\"on\"";
  x.replace(x.find(on), on.size(), "name=\"mjbuoy.radiation\" data=\"" + value + "\"");
  return x;
}

// three free boxes, the third's radiation off by its body override: two
// bodies radiate (docs/mjcf.md, mjbuoy.radiation.body.<body>)
const char* kThree = R"(<mujoco><custom>
  <text name="mjbuoy.hulls" data="h1 h2 h3"/>
  <text name="mjbuoy.radiation" data="on"/>
  <text name="mjbuoy.radiation.body.b3" data="off"/>
</custom><worldbody>
  <body name="b1" pos="0 0 0"><freejoint/><geom name="h1" type="box" size="1 1 0.5"/></body>
  <body name="b2" pos="5 0 0"><freejoint/><geom name="h2" type="box" size="1 1 0.5"/></body>
  <body name="b3" pos="10 0 0"><freejoint/><geom name="h3" type="box" size="1 1 0.5"/></body>
</worldbody></mujoco>)";

TEST(RadInfo, BodiesBeforeAttach) {
  struct Case {
    std::string xml;
    int want;  // counted by hand from the model
  } cases[] = {{cubeWith("on"), 1}, {cubeWith("off"), 0}, {kThree, 2}};
  for (const Case& c : cases) {
    std::string err;
    mjModel* m = mjbt::loadXML(c.xml, &err);
    ASSERT_TRUE(m) << err;
    EXPECT_EQ(mjb_radiationBodies(m), c.want) << c.xml;
    mj_deleteModel(m);
  }
}

TEST(RadInfo, InvalidEntriesAndNull) {
  std::string err;
  mjModel* m = mjbt::loadXML(cubeWith("sideways"), &err);
  ASSERT_TRUE(m) << err;
  EXPECT_EQ(mjb_radiationBodies(m), -1);  // mjb_attach refuses it and names the fault
  char e[512];
  EXPECT_EQ(mjb_attach(m, nullptr, e, sizeof(e)), nullptr);
  mj_deleteModel(m);
  EXPECT_EQ(mjb_radiationBodies(nullptr), -1);
  const mjbRadInfo none = mjb_radiationInfo(nullptr);
  EXPECT_EQ(none.nbody + none.nmode + none.nsample, 0);
}

TEST(RadInfo, AttachedModel) {
  mjbt::Scene off(cubeWith("off"));
  ASSERT_TRUE(off.ok()) << off.err;
  const mjbRadInfo r0 = mjb_radiationInfo(off.b);
  EXPECT_EQ(r0.nbody + r0.nmode + r0.nsample, 0);
  mjbt::Scene on(cubeWith("on"));
  ASSERT_TRUE(on.ok()) << on.err;
  const mjbRadInfo r1 = mjb_radiationInfo(on.b);
  EXPECT_EQ(r1.nbody, 1);  // the one free cube
  // one memory or the other: state-space modes, or a convolution kernel
  EXPECT_TRUE((r1.nmode > 0) != (r1.nsample > 0)) << r1.nmode << " " << r1.nsample;
}

}  // namespace
