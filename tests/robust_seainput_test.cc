// sea inputs: one validator per kind (wave component, spectrum incl.
// tables, wind, current) serves MJCF and mjb_setSea alike, and bounds the
// sea a spectrum makes (Hs, steepness, shortest component)
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

// a 2 x 1 x 0.5 m box of 500 kg, radiation off; extra entries in custom
std::string box(const std::string& custom) {
  return "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
         "<text name=\"mjbuoy.radiation\" data=\"off\"/>" + custom +
         "</custom><worldbody><body name=\"box\"><freejoint/>"
         "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body>"
         "</worldbody></mujoco>";
}

// attach; "" on success, else the error
std::string attachError(const std::string& xml) {
  std::string err;
  mjModel* m = loadXML(xml, &err);
  if (!m) return "load: " + err;
  char e[2000] = "";
  mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof(e));
  if (b) mjb_detach(b);
  mj_deleteModel(m);
  return b ? "" : e;
}

std::string table(const char* data) {
  return std::string("<text name=\"mjbuoy.spectrum.t.type\" data=\"table\"/>"
                     "<numeric name=\"mjbuoy.spectrum.t.table\" data=\"") + data + "\"/>";
}

TEST(RobustSeaInput, TableSpectrumHsIsBounded) {
  // S a triangle of peak S0 over omega 0.5 to 1.5 rad/s: m0 = 0.5 * 1 * S0,
  // Hs = 4 sqrt(m0). S0 = 1e4: Hs = 283 m (was accepted); S0 = 1e308: m0
  // overflows (was a NaN surface and no force, silently)
  std::string e = attachError(box(table("0.5 0 0.8 1e4 1.5 0")));
  EXPECT_NE(e.find("Hs = 4 sqrt(m0) = 282.8"), std::string::npos) << e;
  EXPECT_NE(e.find("mjbuoy.spectrum.t"), std::string::npos) << e;
  e = attachError(box(table("0.5 0 0.8 1e308 1.5 0")));
  EXPECT_NE(e.find("Hs = 4 sqrt(m0) = inf"), std::string::npos) << e;
  // S0 = 1.2: m0 = 0.6, Hs = 3.10 m, a sea, accepted; its components carry
  // m0 = sum A^2 / 2 (equal-energy bins, spectra.cc), within the
  // trapezoids' error on a triangle sampled at 4096 points
  Scene s(box(table("0.5 0 0.8 1.2 1.5 0")));
  ASSERT_TRUE(s.ok()) << s.err;
  int n = mjb_waves(s.b, nullptr, 0);
  std::vector<double> w(6 * n);
  mjb_waves(s.b, w.data(), n);
  double m0 = 0;
  for (int i = 0; i < n; i++) m0 += 0.5 * w[6 * i] * w[6 * i];
  EXPECT_NEAR(m0, 0.6, 1e-4);
}

TEST(RobustSeaInput, SpectrumSteepnessAndShortestComponentAreBounded) {
  auto jonswap = [](const char* hs, const char* tp) {
    return std::string("<text name=\"mjbuoy.spectrum.j.type\" data=\"jonswap\"/>"
                       "<numeric name=\"mjbuoy.spectrum.j.hs\" data=\"") + hs + "\"/>"
           "<numeric name=\"mjbuoy.spectrum.j.tp\" data=\"" + tp + "\"/>";
  };
  // hs 10 m at tp 2 s: Lp = g Tp^2 / (2 pi) = 6.2 m, Hs / Lp = 1.6, far past
  // the breaking limit 1/7
  std::string e = attachError(box(jonswap("10", "2")));
  EXPECT_NE(e.find("steeper than the breaking limit 1/7"), std::string::npos) << e;
  // tp 0.05 s (was accepted, then minutes a step): wmax = 4 wp = 503 rad/s,
  // wavelength 2 pi g / wmax^2 = 0.24 mm
  e = attachError(box(jonswap("0.00001", "0.05")));
  EXPECT_NE(e.find("components as short as 0.000243"), std::string::npos) << e;
  EXPECT_NE(e.find("raise tp"), std::string::npos) << e;
  // an ordinary sea passes: hs 2 m, tp 8 s (Hs / Lp = 0.02)
  EXPECT_EQ(attachError(box(jonswap("2", "8"))), "");
}

TEST(RobustSeaInput, WindDirectionIsBounded) {
  std::string e = attachError(box("<numeric name=\"mjbuoy.wind.speed\" data=\"10\"/>"
                                  "<numeric name=\"mjbuoy.wind.direction\" data=\"1e308\"/>"));
  EXPECT_NE(e.find("mjbuoy.wind.direction"), std::string::npos) << e;
  EXPECT_NE(e.find("<= 360"), std::string::npos) << e;
}

// mjb_setSea refuses what the model file refuses, with the same ranges
TEST(RobustSeaInput, SetSeaEnforcesTheModelFilesRanges) {
  Scene s(box("<numeric name=\"mjbuoy.sea.capacity\" data=\"256\"/>"));
  ASSERT_TRUE(s.ok()) << s.err;
  char e[1000];
  struct Case { double v[5]; const char* mjcf; const char* what; };
  const Case bad[] = {
      {{1e308, 20, 0, 0, 0}, "1e308 20 0 0 0", "amplitude"},  // was accepted, then no step ended
      {{0.5, 0.01, 0, 0, 0}, "0.5 0.01 0 0 0", "wavelength"},
      {{0.5, 20, 1e308, 0, 0}, "0.5 20 1e308 0 0", "direction"},
      {{0.5, 20, 0, 0, 2}, "0.5 20 0 0 2", "steepness"},
      {{31, 1e5, 0, 0, 0}, "31 1e5 0 0 0", "amplitude"},
  };
  for (const Case& c : bad) {
    SCOPED_TRACE(c.mjcf);
    mjbSea sea = {};
    sea.wave = c.v;
    sea.nwave = 1;
    EXPECT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 0);
    EXPECT_NE(std::string(e).find(c.what), std::string::npos) << e;
    std::string me = attachError(box(std::string("<numeric name=\"mjbuoy.wave.a\" data=\"") +
                                     c.mjcf + "\"/>"));
    EXPECT_NE(me.find(c.what), std::string::npos) << me;
  }
  // two listed waves of 20 m amplitude: their sum 40 m passes neither entry
  double two[10] = {20, 1e5, 0, 0, 0, 20, 1e5, 0, 0, 0};
  mjbSea sea = {};
  sea.wave = two;
  sea.nwave = 2;
  EXPECT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 0);
  EXPECT_NE(std::string(e).find("add up to 40 m"), std::string::npos) << e;
  // a spectrum of tp 1e-9 s (was accepted, then steps never finished)
  mjbSpectrum sp;
  mjb_defaultSpectrum(&sp);
  sp.tp = 1e-9;
  sp.hs = 1e-12;
  sea = mjbSea{};
  sea.spectrum = &sp;
  sea.nspectrum = 1;
  EXPECT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 0);
  EXPECT_NE(std::string(e).find("components as short as"), std::string::npos) << e;
  // a table of S = 1e308 and a wind towards 1e308 deg
  const double tab[6] = {0.5, 0, 0.8, 1e308, 1.5, 0};
  mjb_defaultSpectrum(&sp);
  sp.type = mjbSPEC_TABLE;
  sp.table = tab;
  sp.ntable = 3;
  EXPECT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 0);
  EXPECT_NE(std::string(e).find("Hs = 4 sqrt(m0) = inf"), std::string::npos) << e;
  sea = mjbSea{};
  sea.wind.speed = 10;
  sea.wind.dir = 1e308;
  EXPECT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 0);
  EXPECT_NE(std::string(e).find("wind direction = 1e+308"), std::string::npos) << e;
  // and a sea inside every range is taken: one 0.5 m wave of 20 m
  double ok[5] = {0.5, 20, 0, 0, 0.5};
  sea = mjbSea{};
  sea.wave = ok;
  sea.nwave = 1;
  EXPECT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 1) << e;
}

// a listed 5 cm wave on the 2 x 1 x 0.5 m box, whose hull mesh cuts each
// face into 4 x 4 cells (hull.cc kBoxDiv): the longest edge is the diagonal
// of a 0.5 x 0.25 m cell, sqrt(0.5^2 + 0.25^2) = 0.559 m, 11 wavelengths;
// force averaged out, cost out of proportion (was: steps about 1000x
// slower, no word). Warned at attach naming wave, edge, hull and the fix;
// a 20 m wave is not
TEST(RobustSeaInput, WaveFarShorterThanTheTrianglesIsWarned) {
  Scene s(box("<numeric name=\"mjbuoy.airy.a\" data=\"0.001 0.05 0 0\"/>"));
  ASSERT_TRUE(s.ok()) << s.err;
  std::string w = mjb_warnings(s.b);
  EXPECT_NE(w.find("wavelength 0.05 m is more than 8 times shorter than the longest edge "
                   "(0.559016"), std::string::npos) << w;
  EXPECT_NE(w.find("hull geom \"hull\""), std::string::npos) << w;
  Scene t(box("<numeric name=\"mjbuoy.airy.a\" data=\"0.1 20 0 0\"/>"));
  ASSERT_TRUE(t.ok()) << t.err;
  EXPECT_EQ(std::string(mjb_warnings(t.b)).find("times shorter"), std::string::npos);
}

// mju_user_warning capture
std::vector<std::string> gwarn;
void keepWarning(const char* msg) { gwarn.push_back(msg); }

// under <compiler angle="radian"> MuJoCo converts its own angles, never
// <custom> data: mjbuoy's directions stay degrees (a wave direction of
// 1.5708 is 1.57 deg, not 90), and reading the file says so
TEST(RobustSeaInput, RadianCompilerWarnsThatMjbuoyAnglesAreDegrees) {
  void (*old)(const char*) = mju_user_warning;
  mju_user_warning = keepWarning;
  std::string dir = testing::TempDir();
  for (const char* angle : {"radian", "degree"}) {
    SCOPED_TRACE(angle);
    std::string xml = box("<numeric name=\"mjbuoy.airy.a\" data=\"0.1 20 1.5708 0\"/>");
    xml.replace(xml.find("<custom>"), 8,
                std::string("<compiler angle=\"") + angle + "\"/><custom>");
    std::string path = dir + "/radian_" + angle + ".xml";
    FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_TRUE(f);
    std::fputs(xml.c_str(), f);
    std::fclose(f);
    gwarn.clear();
    char e[500];
    EXPECT_EQ(mjb_checkModelFile(path.c_str(), e, sizeof(e)), 1) << e;
    bool radian = std::string(angle) == "radian";
    ASSERT_EQ(gwarn.size(), radian ? 1u : 0u);
    if (radian) {
      EXPECT_NE(gwarn[0].find("mjbuoy.airy.a"), std::string::npos) << gwarn[0];
      EXPECT_NE(gwarn[0].find("degrees"), std::string::npos) << gwarn[0];
    }
    // the wave travels at 1.5708 deg either way: its y direction sin(1.5708 deg)
    Scene s(xml);
    ASSERT_TRUE(s.ok()) << s.err;
    double w[6];
    ASSERT_EQ(mjb_waves(s.b, w, 1), 1);
    EXPECT_EQ(w[3], 1.5708);
    std::remove(path.c_str());
  }
  mju_user_warning = old;
}

}  // namespace
}  // namespace mjbt
