// user sensors that mjbuoy fills (mjbuoy/api/sensor.cc, docs/mjcf.md "Sensors",
// docs/physics.md section 9), each against a hand value or an independent
// formula
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "testutil.h"

namespace {

using mjbt::Scene;

// the 2 x 1 x 0.5 m box barge of 500 kg of models/barge.xml, held at its
// draft T = m / (rho L B) = 500 / (1000 * 2 * 1) = 0.25 m (centre at z = 0),
// with a gauge site on it and sensors bound to it
std::string barge(const std::string& custom, const std::string& sensors,
                  const std::string& extra = "") {
  return R"(<mujoco>
  <custom>
    <text name="mjbuoy.hulls" data="hull"/>
    <numeric name="mjbuoy.hull.damping" data="3000 300"/>
    )" + custom + R"(
  </custom>
  <worldbody>
    <body name="barge">
      <freejoint/>
      <geom name="hull" type="box" size="1 0.5 0.25" mass="500"/>
      <site name="bow" pos="1 0 0.25"/>
    </body>
    )" + extra + R"(
  </worldbody>
  <sensor>)" + sensors + R"(</sensor>
</mujoco>)";
}

double sensor(const Scene& s, const char* name, int i = 0) {
  int id = mj_name2id(s.m, mjOBJ_SENSOR, name);
  EXPECT_GE(id, 0) << name;
  return id < 0 ? NAN : s.d->sensordata[s.m->sensor_adr[id] + i];
}

// still water at level 0.2 m: a gauge reads the level wherever it is, and
// the surface stands level - z above a site at height z
TEST(Sensor, GaugeOnFlatWaterReadsTheLevel) {
  Scene s(barge(R"(<numeric name="mjbuoy.sea.level" data="0.2"/>
    <text name="mjbuoy.sensor.gauge" data="elevation"/>
    <text name="mjbuoy.sensor.wet" data="relative_elevation"/>)",
                R"(<user name="gauge" objtype="site" objname="bow" dim="1" datatype="real" needstage="pos"/>
    <user name="wet" objtype="site" objname="bow" dim="1" datatype="real" needstage="acc"/>)"));
  ASSERT_TRUE(s.ok()) << s.err;
  s.d->qpos[0] = 3.7;  // anywhere
  s.d->qpos[1] = -1.1;
  s.d->qpos[2] = 0.1;  // bow site at z = 0.1 + 0.25
  mj_forward(s.m, s.d);
  EXPECT_NEAR(sensor(s, "gauge"), 0.2, 1e-12);
  EXPECT_NEAR(sensor(s, "wet"), 0.2 - 0.35, 1e-12);
}

// a Gerstner wave (docs/mjcf.md): the particle labelled a sits at
// x = a - Q A D sin(theta), z = A cos(theta), theta = k D.a - omega t, with
// omega^2 = g k (deep water). A gauge moved to that particle's x, y reads its
// z, and mjb_seaHeight there; the gauge rides a body on two slide joints
TEST(Sensor, GaugeOnGerstnerWaveFollowsTheSite) {
  const double A = 0.3, lambda = 8, beta = 30, Q = 0.5;
  std::string xml = barge(
      R"(<numeric name="mjbuoy.wave.w" data="0.3 8 30 0 0.5"/>
    <numeric name="mjbuoy.sea.ramp" data="0"/>
    <text name="mjbuoy.sensor.gauge" data="elevation"/>)",
      R"(<user name="gauge" objtype="site" objname="probe" dim="1" datatype="real" needstage="pos"/>)",
      R"(<body name="cart" pos="0 0 2">
      <joint name="px" type="slide" axis="1 0 0"/>
      <joint name="py" type="slide" axis="0 1 0"/>
      <geom type="sphere" size="0.05" mass="1" contype="0" conaffinity="0"/>
      <site name="probe"/>
    </body>)");
  Scene s(xml);
  ASSERT_TRUE(s.ok()) << s.err;
  const double k = 2 * M_PI / lambda, omega = std::sqrt(mjbt::kG * k);
  const double D[2] = {std::cos(beta * M_PI / 180), std::sin(beta * M_PI / 180)};
  const double cases[][3] = {{1.3, -0.4, 0.0}, {-2.0, 0.7, 1.25}, {0.5, 3.0, 7.9}};
  for (const auto& c : cases) {
    double th = k * (D[0] * c[0] + D[1] * c[1]) - omega * c[2];
    double x = c[0] - Q * A * D[0] * std::sin(th), y = c[1] - Q * A * D[1] * std::sin(th);
    s.d->time = c[2];
    s.d->qpos[7] = x;  // after the barge's 7 free-joint coordinates
    s.d->qpos[8] = y;
    mj_forward(s.m, s.d);
    EXPECT_NEAR(s.d->site_xpos[3 * mj_name2id(s.m, mjOBJ_SITE, "probe")], x, 1e-12);
    EXPECT_NEAR(sensor(s, "gauge"), A * std::cos(th), 1e-8) << "t = " << c[2];
    EXPECT_NEAR(sensor(s, "gauge"), mjb_seaHeight(s.b, x, y, c[2]), 1e-12);
  }
}

// the barge at rest at its draft: submerged volume m / rho = 0.5 m^3, wetted
// area L B + 2 (L + B) T = 2 + 2 * 3 * 0.25 = 3.5 m^2
TEST(Sensor, BargeVolumeAndWettedAreaAtRest) {
  Scene s(barge(R"(<text name="mjbuoy.sensor.vol" data="submerged_volume"/>
    <text name="mjbuoy.sensor.area" data="wetted_area"/>)",
                R"(<user name="vol" objtype="body" objname="barge" dim="1" datatype="real" needstage="vel"/>
    <user name="area" objtype="xbody" objname="barge" dim="1" datatype="real" needstage="acc"/>)"));
  ASSERT_TRUE(s.ok()) << s.err;
  mj_forward(s.m, s.d);
  EXPECT_NEAR(sensor(s, "vol"), 500 / mjbt::kRho, 1e-12);
  EXPECT_NEAR(sensor(s, "area"), 3.5, 1e-12);
  // lifted 0.1 m: T = 0.15, V = 2 * 1 * 0.15 = 0.3 m^3, S = 2 + 6 * 0.15 = 2.9 m^2
  s.d->qpos[2] = 0.1;
  mj_forward(s.m, s.d);
  EXPECT_NEAR(sensor(s, "vol"), 0.3, 1e-12);
  EXPECT_NEAR(sensor(s, "area"), 2.9, 1e-12);
}

// wrench sensors, total and by family, carry what mjb_wrench and
// mjb_wrenchPart report for the same call, while the barge moves
TEST(Sensor, WrenchByFamilyEqualsWrenchPart) {
  const char* fam[mjbNPART] = {"pressure", "viscous", "drag", "slam", "damping", "wind"};
  // a 10 m/s wind, so that the wind family acts on the dry sides too
  std::string custom = R"(<text name="mjbuoy.sensor.total" data="wrench"/>)"
                       R"(<numeric name="mjbuoy.wind.speed" data="10"/>)", sens =
      R"(<user name="total" objtype="body" objname="barge" dim="6" datatype="real" needstage="acc"/>)";
  for (const char* f : fam) {
    custom += std::string("<text name=\"mjbuoy.sensor.") + f + "\" data=\"wrench " + f + "\"/>";
    sens += std::string("<user name=\"") + f +
            "\" objtype=\"body\" objname=\"barge\" dim=\"6\" datatype=\"real\" needstage=\"vel\"/>";
  }
  Scene s(barge(custom, sens));
  ASSERT_TRUE(s.ok()) << s.err;
  s.d->qpos[2] = 0.3;  // dropped from 0.3 m, moving ahead and rolling: every family acts
  s.d->qvel[0] = 2;
  s.d->qvel[3] = 1;
  int bd = s.body("barge");
  double seen[mjbNPART] = {0};
  for (int i = 0; i < 400; i++) {
    mj_step(s.m, s.d);
    for (int p = 0; p < mjbNPART; p++) {
      const mjtNum* w = mjb_wrenchPart(s.b, s.d, p) + 6 * bd;
      for (int j = 0; j < 6; j++) {
        ASSERT_EQ(sensor(s, fam[p], j), w[j]) << fam[p] << " step " << i;
        seen[p] = std::fmax(seen[p], std::fabs(w[j]));
      }
    }
    for (int j = 0; j < 6; j++) ASSERT_EQ(sensor(s, "total", j), s.wrench(bd)[j]);
  }
  for (int p = 0; p < mjbNPART; p++) EXPECT_GT(seen[p], 0) << fam[p] << " never acted";
}

// a wrong binding stops mjb_attach with a message naming the sensor
TEST(Sensor, BadBindingIsALoadErrorNamingTheSensor) {
  struct Case {
    const char* custom;
    const char* sensor;
    const char* want;
  } cases[] = {
      {R"(<text name="mjbuoy.sensor.s1" data="height"/>)",
       R"(<user name="s1" objtype="site" objname="bow" dim="1" datatype="real" needstage="pos"/>)",
       "is not a quantity"},
      {R"(<text name="mjbuoy.sensor.s2" data="elevation"/>)",
       R"(<user name="s2" objtype="body" objname="barge" dim="1" datatype="real" needstage="pos"/>)",
       "objtype=\"site\""},
      {R"(<text name="mjbuoy.sensor.s3" data="submerged_volume"/>)",
       R"(<user name="s3" objtype="body" objname="barge" dim="1" datatype="real" needstage="pos"/>)",
       "needstage=\"vel\""},
      {R"(<text name="mjbuoy.sensor.s4" data="wrench"/>)",
       R"(<user name="s4" objtype="body" objname="barge" dim="3" datatype="real" needstage="acc"/>)",
       "dim=\"6\""},
      {R"(<text name="mjbuoy.sensor.s5" data="wrench lift"/>)",
       R"(<user name="s5" objtype="body" objname="barge" dim="6" datatype="real" needstage="acc"/>)",
       "not a force family"},
      {R"(<text name="mjbuoy.sensor.s6" data="wetted_area"/>)",
       R"(<user name="s6" objtype="body" objname="world" dim="1" datatype="real" needstage="acc"/>)",
       "carries no mjbuoy hull"},
      {R"(<text name="mjbuoy.sensor.s7" data="elevation"/>)", "", "has no sensor of that name"},
      {R"(<text name="mjbuoy.sensor.s8" data="elevation"/>)",
       R"(<framepos name="s8" objtype="site" objname="bow"/>)", "not a user sensor"},
  };
  for (const Case& c : cases) {
    Scene s(barge(c.custom, c.sensor));
    EXPECT_FALSE(s.b) << c.custom;
    std::string name = std::string(c.custom).substr(std::string(c.custom).find("sensor.") + 7, 2);
    EXPECT_NE(s.err.find("sensor \"" + name + "\""), std::string::npos) << s.err;
    EXPECT_NE(s.err.find(c.want), std::string::npos) << s.err;
  }
}

// a user's own mjcb_sensor, installed before mjb_attach, still fills its
// sensors, and is back in place after mjb_detach
int gcalls = 0;
void mine(const mjModel* m, mjData* d, int stage) {
  gcalls++;
  int id = mj_name2id(m, mjOBJ_SENSOR, "counter");
  if (id >= 0 && m->sensor_needstage[id] == stage) d->sensordata[m->sensor_adr[id]] = 42;
}

TEST(Sensor, UsersSensorCallbackStillRuns) {
  mjcb_sensor = mine;
  gcalls = 0;
  {
    Scene s(barge(R"(<text name="mjbuoy.sensor.vol" data="submerged_volume"/>)",
                  R"(<user name="counter" objtype="site" objname="bow" dim="1" datatype="real" needstage="acc"/>
      <user name="vol" objtype="body" objname="barge" dim="1" datatype="real" needstage="vel"/>)"));
    ASSERT_TRUE(s.ok()) << s.err;
    gcalls = 0;
    mj_forward(s.m, s.d);
    EXPECT_EQ(sensor(s, "counter"), 42);
    EXPECT_NEAR(sensor(s, "vol"), 0.5, 1e-12);
    EXPECT_EQ(gcalls, 2);  // stages vel and acc
  }
  EXPECT_EQ(mjcb_sensor, &mine);
  mjcb_sensor = nullptr;
}

}  // namespace
