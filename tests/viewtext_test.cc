// mjbuoy-view's overlay text and actuator keys (tools/view/viewtext.h): the
// sea named by its components' kinds, counted from the MJCF by hand and
// checked against the attached model's own component list (mjb_waves,
// whose steepness is the Gerstner Q, 0 for linear components); the keys'
// control steps against the actuator's ctrlrange
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "mjbuoy.h"
#include "viewtext.h"

namespace {

mjModel* load(const char* xml) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "m.xml", (int)std::strlen(xml));
  std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "m.xml")], xml, std::strlen(xml));
  char err[512] = "";
  mjModel* m = mj_loadXML("m.xml", &vfs, err, sizeof(err));
  mj_deleteVFS(&vfs);
  EXPECT_NE(m, nullptr) << err;
  return m;
}

// two Gerstner waves (steepness 0.5 and 0.3), one Airy component and a
// spectrum of 8 linear components: 11 components, 2 Gerstner and 9 linear
const char* kMixed = R"(<mujoco><custom>
  <numeric name="mjbuoy.wave.a" data="0.2 20 0 0 0.5"/>
  <numeric name="mjbuoy.wave.b" data="0.1 10 30 0 0.3"/>
  <numeric name="mjbuoy.airy.c" data="0.05 15 60 0"/>
  <text name="mjbuoy.spectrum.s.type" data="jonswap"/>
  <numeric name="mjbuoy.spectrum.s.hs" data="0.5"/>
  <numeric name="mjbuoy.spectrum.s.tp" data="4"/>
  <numeric name="mjbuoy.spectrum.s.components" data="8"/>
  <text name="mjbuoy.hulls" data="h"/>
  <text name="mjbuoy.radiation" data="off"/>
</custom><worldbody><body pos="0 0 0"><freejoint/>
  <geom name="h" type="box" size="1 0.5 0.25" mass="500"/></body></worldbody></mujoco>)";

TEST(ViewText, SeaNamesComponentKinds) {
  mjModel* m = load(kMixed);
  ASSERT_NE(m, nullptr);
  std::string s = mjbview::describeSea(m);
  EXPECT_EQ(s.rfind("11 (2 Gerstner, 9 linear) wave components", 0), 0u) << s;
  EXPECT_NE(s.find("JONSWAP Hs 0.5 m Tp 4 s"), std::string::npos) << s;
  // the attached sea: the same 11 components, 2 of them with a Gerstner steepness
  char err[512] = "";
  mjbBuoy* b = mjb_attach(m, "cpu", err, sizeof(err));
  ASSERT_NE(b, nullptr) << err;
  int n = mjb_waves(b, nullptr, 0);
  std::vector<double> w(6 * n);
  mjb_waves(b, w.data(), n);
  int ngerstner = 0;
  for (int i = 0; i < n; i++) ngerstner += w[6 * i + 5] > 0;
  EXPECT_EQ(n, 11);
  EXPECT_EQ(ngerstner, 2);
  mjb_detach(b);
  mj_deleteModel(m);
}

TEST(ViewText, SpectraAreLinearAndCalmIsCalm) {
  // only spectra: every component linear (no "Gerstner" in the sentence)
  mjModel* m = load(R"(<mujoco><custom>
    <text name="mjbuoy.spectrum.s.type" data="pm"/>
    <numeric name="mjbuoy.spectrum.s.hs" data="0.3"/>
    <numeric name="mjbuoy.spectrum.s.tp" data="7"/>
    <numeric name="mjbuoy.spectrum.s.components" data="5"/>
    <numeric name="mjbuoy.wind.speed" data="6"/>
    <text name="mjbuoy.wind.gust" data="froya"/>
  </custom></mujoco>)");
  ASSERT_NE(m, nullptr);
  std::string s = mjbview::describeSea(m);
  EXPECT_EQ(s.rfind("5 linear wave components (PM Hs 0.3 m Tp 7 s)", 0), 0u) << s;
  EXPECT_EQ(s.find("Gerstner"), std::string::npos) << s;
  EXPECT_EQ(mjbview::describeWind(m), "6 m/s at 10 m towards 0 deg, Froya gusts");
  mj_deleteModel(m);
  m = load("<mujoco/>");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(mjbview::describeSea(m), "calm, level 0 m");
  EXPECT_EQ(mjbview::describeWind(m), "none");
  mj_deleteModel(m);
}

// the motorboat's thrust (models/motorboat.xml): ctrlrange -300 300 N, so a
// key press moves the control by 600 / 20 = 30 N, never past the range
TEST(ViewText, KeysStepControlWithinRange) {
  mjModel* m = load(R"(<mujoco><worldbody><body><freejoint/><geom size="0.1"/>
    <site name="s"/></body></worldbody><actuator>
    <motor name="thrust" site="s" gear="1 0 0 0 0 0" ctrllimited="true" ctrlrange="-300 300"/>
    <motor name="free" site="s" gear="0 1 0 0 0 0" ctrllimited="false"/>
  </actuator></mujoco>)");
  ASSERT_NE(m, nullptr);
  double c = 0;
  c = mjbview::nudgeCtrl(m, 0, c, +1);
  EXPECT_DOUBLE_EQ(c, 30);
  for (int i = 0; i < 15; i++) c = mjbview::nudgeCtrl(m, 0, c, +1);
  EXPECT_DOUBLE_EQ(c, 300);  // 16 presses would be 480: held at the range's top
  c = mjbview::nudgeCtrl(m, 0, -290, -1);
  EXPECT_DOUBLE_EQ(c, -300);
  EXPECT_EQ(mjbview::describeCtrl(m, 0, 150), "thrust = 150 in [-300, 300]");
  // no range: a fixed step either way
  EXPECT_DOUBLE_EQ(mjbview::nudgeCtrl(m, 1, 1, -1), 1 - mjbview::kFreeStep);
  EXPECT_DOUBLE_EQ(mjbview::nudgeCtrl(m, 2, 7, +1), 7);  // no actuator 2: unchanged
  mj_deleteModel(m);
}

}  // namespace
