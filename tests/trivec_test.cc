// the triangle stage's wholly wet triangles and cut triangles' wet pieces
// in lanes (AVX2, AVX-512; trivec.h) against the scalar reference (cpupass.cc's per-triangle loop) and
// against Archimedes, on every instruction set this cpu has
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "simdlevels.h"
#include "testutil.h"
#include "cpu/trisort.h"
#include "util/vmath.h"

namespace mjbt {
namespace {

// a 2 m x 1 m x 0.5 m box (V = 1 m^3) with its centre at depth z0 on flat
// water; hull triangles are the box's 12, all wholly wet below the surface
std::string submergedBox(double z0) {
  std::ostringstream s;
  s << "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h*\"/></custom><worldbody>"
    << "<body pos=\"0.3 -0.2 " << z0 << "\" euler=\"20 -35 60\"><freejoint/>"
    << "<geom name=\"h\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body>"
    << "</worldbody></mujoco>";
  return s.str();
}

// the box with its centre at height z0 on flat water: the pressure force
// on every path (scalar and each vector level) within 1e-12 of rho g vol
// upward, and with torque also no torque about the COM (its centre)
void expectArchimedes(double z0, double vol, bool torque) {
  Scene sc(submergedBox(z0));
  ASSERT_TRUE(sc.ok()) << sc.err;
  const int prev = mjb::simdLevel();
  std::vector<int> lv = vectorLevels("trivec");
  lv.insert(lv.begin(), mjb::kSimdScalar);
  const double F = kRho * kG * vol;
  for (int level : lv) {
    mjb::simdSet(level);
    mj_forward(sc.m, sc.d);
    const mjtNum* p = mjb_wrenchPart(sc.b, sc.d, mjbPART_PRESSURE) + 6;
    EXPECT_NEAR(p[0], 0, 1e-12 * F) << mjb::simdName(level);
    EXPECT_NEAR(p[1], 0, 1e-12 * F) << mjb::simdName(level);
    EXPECT_NEAR(p[2], F, 1e-12 * F) << mjb::simdName(level);
    for (int j = 3; j < (torque ? 6 : 3); j++) {
      EXPECT_NEAR(p[j], 0, 1e-12 * F) << mjb::simdName(level);
    }
  }
  mjb::simdSet(prev);
}

// Archimedes: a closed body wholly below flat water feels rho g V upward
// through its centre of buoyancy (here the box's centre, its COM), whatever
// its orientation; the exact integrals of pressure.h give it to round-off
// (a few ulp of rho g V per triangle). Every path, every triangle in lanes
TEST(TriVec, SubmergedBoxFeelsArchimedesOnEveryPath) { expectArchimedes(-2, 1.0, true); }

// the same box with its centre on flat water: the plane through the centre
// of a box (centrally symmetric) halves it, so Archimedes gives rho g V / 2
// upward whatever the orientation (its centre of buoyancy is off the COM:
// the torque is not checked); its wetted triangles are wholly wet or cut,
// the cut ones of both kinds in lanes on the vector paths (trivec_kern.h
// cutChunk)
TEST(TriVec, HalfSunkBoxFeelsHalfItsVolumeOnEveryPath) { expectArchimedes(0, 0.5, false); }

// a Wigley hull (576 triangles) heeled and pitched, and a box, on sea s
// with pressure model pm, threads th
std::string scene(const std::string& sea, const char* pm, int th) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
    << "/meshes/wigley_576.obj\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"h*\"/>"
    << sea << "<text name=\"mjbuoy.sea.pressure\" data=\"" << pm << "\"/>"
    // radiation is no triangle lane's work: off, so no case solves panels
    << "<text name=\"mjbuoy.radiation\" data=\"off\"/>"
    << "<numeric name=\"mjbuoy.threads\" data=\"" << th << "\"/></custom><worldbody>"
    << "<body pos=\"0 0 -0.02\" euler=\"6 -3 30\"><freejoint/><inertial pos=\"0 0 -0.08\" "
    << "mass=\"176.2\" diaginertia=\"6.02 237.28 238.6\"/><geom name=\"h0\" type=\"mesh\" "
    << "mesh=\"w\" contype=\"0\" conaffinity=\"0\"/></body>"
    << "<body pos=\"-6 2 0\" euler=\"0 10 0\"><freejoint/><geom name=\"h1\" type=\"box\" "
    << "size=\"1.5 0.6 0.3\" mass=\"600\"/></body></worldbody></mujoco>";
  return s.str();
}

// every wrench part of every body after 10 steps (the slamming history on)
std::vector<double> parts(Scene& s) {
  mj_resetData(s.m, s.d);
  for (int i = 0; i < 10; i++) mj_step(s.m, s.d);
  std::vector<double> out;
  for (int p = 0; p < mjbNPART; p++) {
    const mjtNum* w = mjb_wrenchPart(s.b, s.d, p);
    out.insert(out.end(), w, w + 6 * s.m->nbody);
  }
  return out;
}

// The lanes do the scalar path's arithmetic for a wholly wet triangle and
// for each piece of a cut one (same formulas, same components summed) and
// differ by rounding only: FMA contraction, the order of the sums over
// triangles and pieces, and series terms past
// the scalar's count (each below 2^-54 of the first, waveint.cc). A
// series about corner 0 loses at most e^kRMax = e^4 of relative precision
// (waveker.h), so a triangle's integrals differ by about 64 e^4 eps, 1e-12,
// of their size. The vertex stage's lanes move labels by up to 2e-12 / (1 -
// fold) m (tests/seavec_test.cc), 4e-11 m at fold 0.95, and heights with
// them: against the hull's 0.1 m of draft and the swell's amplitude, a
// relative 4e-10 of the pressure. 10 steps carry these rounding-level
// differences in the state. Bound: each family's parts within 1e-9 of that
// family's largest part (plus 1e-9 N for a family that is near zero)
TEST(TriVec, LanesMatchTheScalarTriangles) {
  struct Case {
    const char* name;
    std::string sea;
    const char* pm;
  };
  const std::string steep = "<numeric name=\"mjbuoy.wave.a\" data=\"0.6 4 20 0 1\"/>";
  const std::string jonswap =
      "<text name=\"mjbuoy.spectrum.sea.type\" data=\"jonswap\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.hs\" data=\"0.6\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.tp\" data=\"5\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.components\" data=\"64\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.spreading\" data=\"10\"/>";
  const std::string shallow =
      "<numeric name=\"mjbuoy.sea.depth\" data=\"3\"/>"
      "<numeric name=\"mjbuoy.wave.a\" data=\"0.3 12 20 0 0.6\"/>"
      "<numeric name=\"mjbuoy.wave.b\" data=\"0.1 5 -50 40 0.5\"/>"
      "<numeric name=\"mjbuoy.airy.c\" data=\"0.1 8 -120 10\"/>";
  // long-crested: every component along one direction, so the lanes share
  // one series per piece among them (trivec_kern.h familyShared); a deep
  // and a 3 m JONSWAP (two exponent families) and two Gerstner components
  const std::string longcrested =
      "<text name=\"mjbuoy.spectrum.sea.type\" data=\"jonswap\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.hs\" data=\"0.6\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.tp\" data=\"5\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.components\" data=\"64\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.direction\" data=\"20\"/>";
  const std::string lcshallow = longcrested + "<numeric name=\"mjbuoy.sea.depth\" data=\"3\"/>";
  const std::string lcgerstner =
      "<numeric name=\"mjbuoy.wave.a\" data=\"0.3 12 20 0 0.6\"/>"
      "<numeric name=\"mjbuoy.wave.b\" data=\"0.1 5 20 40 0.5\"/>";
  const std::string swell = "<numeric name=\"mjbuoy.wave.a\" data=\"0.3 20 20 0 0.6\"/>";
  const std::string expo =
      "<numeric name=\"mjbuoy.hull.drag\" data=\"100 400 1\"/>"
      "<numeric name=\"mjbuoy.hull.suction\" data=\"100 200 2\"/>"
      "<numeric name=\"mjbuoy.hull.slamming\" data=\"1 0.5 ";
  const Case cases[] = {{"steep Gerstner (Q 1, fold 0.94), linear", steep, "linear"},
                        {"steep Gerstner, kerner", steep, "kerner"},
                        {"JONSWAP 64, linear", jonswap, "linear"},
                        {"long-crested JONSWAP 64, linear", longcrested, "linear"},
                        {"long-crested JONSWAP 64, kerner", longcrested, "kerner"},
                        {"long-crested JONSWAP 64, 3 m deep, linear", lcshallow, "linear"},
                        {"2 Gerstner along one direction, linear", lcgerstner, "linear"},
                        {"finite depth 3 m, 2 Gerstner + Airy, linear", shallow, "linear"},
                        {"flat", "", "linear"},
                        {"swell, drag exponent 1, suction 2, slamming power 1",
                         swell + expo + "1\"/>", "linear"},
                        {"swell, slamming power 3 (hydrodynamics on the scalar path)",
                         swell + expo + "3\"/>", "linear"}};
  const int prev = mjb::simdLevel();
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Scene one(scene(c.sea, c.pm, 1)), two(scene(c.sea, c.pm, 2));
    ASSERT_TRUE(one.ok() && two.ok()) << c.name << ": " << one.err << two.err;
    mjb::simdSet(mjb::kSimdScalar);
    const std::vector<double> ref = parts(one);
    const int n6 = 6 * one.m->nbody;
    for (int level : vectorLevels("trivec")) {
      mjb::simdSet(level);
      const std::vector<double> a = parts(one);
      EXPECT_EQ(parts(one), a) << c.name << ", " << mjb::simdName(level);
      EXPECT_EQ(parts(two), a) << c.name << ", " << mjb::simdName(level);
      double worst = 0;
      for (int p = 0; p < mjbNPART; p++) {
        double big = 0, diff = 0;
        for (int i = 0; i < n6; i++) {
          big = std::fmax(big, std::fabs(ref[p * n6 + i]));
          diff = std::fmax(diff, std::fabs(a[p * n6 + i] - ref[p * n6 + i]));
        }
        EXPECT_LE(diff, 1e-9 * big + 1e-9) << c.name << ", " << mjb::simdName(level)
                                           << ", family " << p;
        if (p == mjbPART_PRESSURE) {
          EXPECT_GT(big, 100) << c.name;
        }
        worst = std::fmax(worst, diff / (big + 1e-300));
      }
      std::printf("[trivec] %s, %s: parts within %.3g of scalar (relative)\n", c.name,
                  mjb::simdName(level), worst);
    }
  }
  mjb::simdSet(prev);
}

// wholly wet, one corner below, one above, other
const int kNKindTest = 4;

TEST(TriVec, SortsByKindAsTheScalarRule) {
  // 3000 triangles on 500 vertices whose heights are drawn from values that
  // sit on every edge of the rule: 0, -0, the smallest subnormals, +-inf,
  // NaN and ordinary ones (and 343 triangles with every pattern of seven
  // of them over their corners), and a range [t0, t0 + nt) that ends off the
  // lane groups (16 and 8). The kinds, written out from their definitions
  // (docs/physics.md "Cost": dry if no corner is below, h >= 0 at all
  // three; wholly wet if all three are h <= 0 and it is not dry; cut with
  // one corner at or below and two above, or two at or below and one
  // above; a height not finite and none of these: the scalar path), must
  // come out in ascending order on every vector level
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double pick[] = {0.0, -0.0, 4.9e-324, -4.9e-324, inf, -inf, nan, 0.3, -0.3, 1e300, -2.5};
  std::mt19937 rng(7);
  std::vector<double> h(500);
  // mostly ordinary heights, every special value often enough
  for (double& x : h) x = rng() % 3 ? std::ldexp(double(rng() % 2001) - 1000.0, -9) : pick[rng() % 11];
  std::vector<int> face(3 * 3000);
  for (int& f : face) f = rng() % 500;
  const int t0 = 37, nt = 2913;
  // and every pattern of seven values over three corners: 343 triangles
  const double seven[] = {0.0, -0.0, 0.3, -0.3, nan, inf, -inf};
  for (int i = 0; i < 7; i++) h[i] = seven[i];
  for (int p = 0; p < 343; p++) {
    face[3 * (t0 + p)] = p % 7, face[3 * (t0 + p) + 1] = p / 7 % 7, face[3 * (t0 + p) + 2] = p / 49;
  }
  std::vector<int> want[kNKindTest];
  for (int k = t0; k < t0 + nt; k++) {
    double a = h[face[3 * k]], b = h[face[3 * k + 1]], c = h[face[3 * k + 2]];
    int le = (a <= 0) + (b <= 0) + (c <= 0), gt = (a > 0) + (b > 0) + (c > 0);
    bool dry = a >= 0 && b >= 0 && c >= 0;
    if (dry) continue;
    int kind = le == 3 ? 0 : le == 1 && gt == 2 ? 1 : le == 2 && gt == 1 ? 2 : 3;
    want[kind].push_back(k);
  }
  for (int c = 0; c < kNKindTest; c++) EXPECT_GT(want[c].size(), 20u) << "kind " << c;
  for (int level : vectorLevels("trisort")) {
    std::vector<int> got[mjb::kNKind];
    for (auto& g : got) g.assign(nt, -1);
    mjb::TriSort in{face.data(), h.data(), t0, nt,
                    {got[0].data(), got[1].data(), got[2].data(), got[3].data()}, {0, 0, 0, 0}};
    if (level == mjb::kSimdAvx512) {
      mjb::sortKindsAvx512(&in);
    } else {
      mjb::sortKindsAvx2(&in);
    }
    for (int c = 0; c < mjb::kNKind; c++) {
      got[c].resize(in.n[c]);
      EXPECT_EQ(got[c], want[c]) << mjb::simdName(level) << ", kind " << c;
    }
  }
}

}  // namespace
}  // namespace mjbt

namespace mjbt {
namespace {

// the Wigley hull alone (L 4, B 0.5, T 0.25 m: 4/9 L B T = 0.2222 m^3 below
// its design waterline, Journee 1992, "Experiments and calculations on four
// Wigley hullforms", TU Delft report 909), heeled and pitched, on sea s
std::string wigleyOn(const std::string& sea) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
    << "/meshes/wigley_576.obj\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"h*\"/>"
    << sea << "</custom><worldbody><body pos=\"0 0 -0.02\" euler=\"6 -3 30\"><freejoint/>"
    << "<inertial pos=\"0 0 -0.08\" mass=\"176.2\" diaginertia=\"6.02 237.28 238.6\"/>"
    << "<geom name=\"h\" type=\"mesh\" mesh=\"w\" contype=\"0\" conaffinity=\"0\"/></body>"
    << "</worldbody></mujoco>";
  return s.str();
}

// the hull's pressure force [N] at time t (mj_forward runs the callback)
std::vector<double> pressureAt(Scene& s, double t) {
  mj_resetData(s.m, s.d);
  s.d->time = t;
  mj_forward(s.m, s.d);
  const mjtNum* w = mjb_wrenchPart(s.b, s.d, mjbPART_PRESSURE);
  return std::vector<double>(w + 6, w + 9);
}

// The loose series (mjbuoy.sea.seriestol = tol) omits, over the hull, at
// most tol rho g V of pressure force, V the mesh's enclosed volume
// (docs/physics.md "Series tolerance"). The mesh reaches 0.15 m above the
// waterline, so V < 2 x 0.2222 m^3 (wall-sided above: 0.2222 + L B F =
// 0.5222 is an upper bound too generous; the parabolic sections' hull
// above the waterline adds under 2/3 L B F = 0.2 m^3): at tol = 4e-5 the
// bound is under 4e-5 x 1000 x 9.81 x 0.4444 = 0.174 N, so every case
// must lie within 1e-4 rho g (4/9 L B T) = 0.218 N of the exact series.
// On the scalar path (no lanes) the mode does nothing: bit for bit
TEST(TriVec, LooseSeriesStaysWithinItsForceBound) {
  const std::string js =
      "<text name=\"mjbuoy.spectrum.sea.type\" data=\"jonswap\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.hs\" data=\"0.6\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.tp\" data=\"5\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.components\" data=\"64\"/>"
      "<numeric name=\"mjbuoy.spectrum.sea.direction\" data=\"20\"/>";
  const std::string seas[] = {js + "<numeric name=\"mjbuoy.spectrum.sea.spreading\" data=\"10\"/>",
                              js, js + "<numeric name=\"mjbuoy.sea.depth\" data=\"3\"/>"};
  const char* names[] = {"short-crested", "long-crested", "long-crested, 3 m deep"};
  const double bound = 1e-4 * 1000 * 9.81 * (4.0 / 9 * 4 * 0.5 * 0.25);
  const int prev = mjb::simdLevel();
  for (int c = 0; c < 3; c++) {
    SCOPED_TRACE(names[c]);
    Scene exact(wigleyOn(seas[c]));
    Scene loose(wigleyOn(seas[c] + "<numeric name=\"mjbuoy.sea.seriestol\" data=\"4e-5\"/>"));
    ASSERT_TRUE(exact.ok() && loose.ok()) << exact.err << loose.err;
    mjb::simdSet(mjb::kSimdScalar);
    EXPECT_EQ(pressureAt(exact, 7.3), pressureAt(loose, 7.3));
    for (int level : vectorLevels("trivec")) {
      mjb::simdSet(level);
      double worst = 0, any = 0;
      for (double t : {2.1, 7.3, 11.9}) {
        const std::vector<double> a = pressureAt(exact, t), b = pressureAt(loose, t);
        const double d = std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
        EXPECT_LE(d, bound) << names[c] << ", " << mjb::simdName(level) << ", t " << t;
        EXPECT_GT(std::fabs(a[2]), 1000) << "the hull floats";
        worst = std::fmax(worst, d);
        any += d;
      }
      // the mode is on: some term is left out
      EXPECT_GT(any, 0) << names[c] << ", " << mjb::simdName(level);
      std::printf("[trivec] loose series, %s, %s: within %.3g N of exact (bound %.3g N)\n",
                  names[c], mjb::simdName(level), worst, bound);
    }
  }
  mjb::simdSet(prev);
}

}  // namespace
}  // namespace mjbt
