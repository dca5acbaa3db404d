// the surface search starts from labels extrapolated from the last steps
// (three on the cpu backend, two on gl): forces stay those of a cold solve
// within the solver's tolerance, Newton needs about one step per solve
// (cpu), and runs, resets, copies and thread counts repeat the bits
#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "testutil.h"

namespace mjbt {
namespace {

// two Wigley hulls (576 triangles) and a box barge on a steep two-component
// Gerstner sea: sum Q k A = 0.8 (2 pi / 10) 0.4 + 0.6 (2 pi / 6) 0.15 =
// 0.30 (folding at 1), so every hull meets crests and troughs
std::string steep(int threads, const char* backend = "cpu", const char* integ = "Euler") {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.002\" integrator=\"" << integ << "\"/><asset>"
    << "<mesh name=\"w\" file=\"" MJB_MODELS "/meshes/wigley_576.obj\"/></asset><custom>"
    << "<text name=\"mjbuoy.hulls\" data=\"h*\"/>"
    << "<text name=\"mjbuoy.backend\" data=\"" << backend << "\"/>"
    << "<numeric name=\"mjbuoy.wave.a\" data=\"0.4 10 20 0 0.8\"/>"
    << "<numeric name=\"mjbuoy.wave.b\" data=\"0.15 6 -50 40 0.6\"/>"
    << "<numeric name=\"mjbuoy.threads\" data=\"" << threads << "\"/></custom><worldbody>";
  for (int i = 0; i < 2; i++) {
    s << "<body pos=\"" << 7 * i << " " << 3 * i << " 0.03\" euler=\"0 0 " << 40 * i
      << "\"><freejoint/><inertial pos=\"0 0 -0.08\" mass=\"176.2\" "
      << "diaginertia=\"6.02 237.28 238.6\"/><geom name=\"h" << i
      << "\" type=\"mesh\" mesh=\"w\" contype=\"0\" conaffinity=\"0\"/></body>";
  }
  s << "<body pos=\"-6 2 0\"><freejoint/><geom name=\"h2\" type=\"box\" size=\"1.5 0.6 0.3\" "
    << "mass=\"600\"/></body></worldbody></mujoco>";
  return s.str();
}

// steps s 300 times; every 10th step first copies the state into an
// mjData without mjbuoy's history (its surface search starts cold) and
// checks that the families without history (pressure, viscous, drag,
// damping) of the run and the copy differ by at most rel * |family| + abs.
// before(k) runs ahead of step k. Returns the worst relative difference;
// *largest gets the largest pressure wrench norm seen (N, N m)
double coldCompare(Scene& s, double rel, double abs, double* largest,
                   const std::function<void(int)>& before) {
  mjData* c = mj_makeData(s.m);
  double worst = 0;
  *largest = 0;
  for (int k = 0; k < 300; k++) {
    before(k);
    // the copy before the step: mj_step evaluates the forces at its start
    const bool check = k % 10 == 9;
    if (check) {
      mj_copyData(c, s.m, s.d);
      mjb_unbindData(s.b, c);
      mj_forward(s.m, c);
    }
    mj_step(s.m, s.d);
    if (!check) continue;
    for (int p : {mjbPART_PRESSURE, mjbPART_VISCOUS, mjbPART_DRAG, mjbPART_DAMPING}) {
      const mjtNum* w = mjb_wrenchPart(s.b, s.d, p);
      const mjtNum* wc = mjb_wrenchPart(s.b, c, p);
      for (int bd = 1; bd < s.m->nbody; bd++) {
        double n = 0, e = 0;
        for (int j = 0; j < 6; j++) {
          n += wc[6 * bd + j] * wc[6 * bd + j];
          e += (w[6 * bd + j] - wc[6 * bd + j]) * (w[6 * bd + j] - wc[6 * bd + j]);
        }
        n = std::sqrt(n);
        e = std::sqrt(e);
        EXPECT_LE(e, rel * n + abs) << "step " << k << " family " << p << " body " << bd;
        if (n > 0) worst = std::fmax(worst, e / n);
        if (p == mjbPART_PRESSURE) *largest = std::fmax(*largest, n);
      }
    }
  }
  mjb_unbindData(s.b, c);
  mj_deleteData(c);
  return worst;
}

TEST(Guess, ForcesAreThoseOfAColdSolve) {
  // every 10 steps the state is copied into an mjData without mjbuoy's
  // history, whose surface search starts cold (label = position). Both
  // searches stop at a residual |F| <= 1e-12 m (sea.cc), so the labels
  // agree to 1e-12 / (1 - sum Q k A) = 1.4e-12 m and the surface heights to
  // sum k A (1.4e-12) < 1e-12 m: the hydrostatic force moves by rho g S_wet
  // 1e-12 ~ 1e-7 N against forces of 1e3 N, relative 1e-10. The families
  // without history (pressure, viscous, drag, damping) must agree to 1e-9
  // of their size; slamming has history and is left out
  Scene s(steep(1));
  ASSERT_TRUE(s.ok()) << s.err;
  long ns0 = 0, ni0 = 0, ns1 = 0, ni1 = 0;
  double largest = 0;
  const double worst = coldCompare(s, 1e-9, 1e-12, &largest, [&](int k) {
    if (k == 3) {
      EXPECT_TRUE(mjb::newtonStats(s.b, s.d, &ns0, &ni0));
    }
  });
  ASSERT_GT(largest, 1000) << "the hulls must float for the comparison to show anything";
  ASSERT_TRUE(mjb::newtonStats(s.b, s.d, &ns1, &ni1));
  // the guess, quadratic through the last three steps' offsets, is off by
  // about dt^3 Q A w^3 / 6 ... with w = sqrt(g k) = 2.5 rad/s: 8e-9 (0.32)
  // (15.6) / 6 = 7e-9 m, and Newton's quadratic convergence, error ~ K e^2
  // with K ~ Q A k^2 / (1 - sum Q k A) = 0.18 /m, takes that to 1e-17 m,
  // below the 1e-12 m tolerance, in one step; the last step's label (off
  // by dt Q A w = 1.6 mm) took two (K e^2 = 5e-7 m after one)
  const double per = double(ni1 - ni0) / (ns1 - ns0);
  EXPECT_LE(per, 1.1);
  EXPECT_GE(per, 1.0);  // a guess is never exact: at least one step
  std::printf("worst relative difference from a cold solve %.3g; Newton steps per solve %.4f\n",
              worst, per);
}

TEST(Guess, RunsResetsCopiesAndThreadsRepeatTheBits) {
  Scene one(steep(1)), two(steep(2));
  ASSERT_TRUE(one.ok() && two.ok()) << one.err << two.err;
  const std::vector<double> ref = stepRecord(one.m, one.d, one.b, 200);
  // mj_resetData: the history restarts cold, the run repeats
  mj_resetData(one.m, one.d);
  EXPECT_EQ(stepRecord(one.m, one.d, one.b, 200), ref);
  // two threads (the hulls split into chunks) give one thread's bits
  EXPECT_EQ(stepRecord(two.m, two.d, two.b, 200), ref);
  // mj_copyData + mjb_copyData halfway: the copy's continuation is the
  // original's, its guesses' history included
  mj_resetData(one.m, one.d);
  std::vector<double> first = stepRecord(one.m, one.d, one.b, 100);
  mjData* c = mj_makeData(one.m);
  mj_copyData(c, one.m, one.d);
  ASSERT_EQ(mjb_copyData(one.b, c, one.d), 1);
  std::vector<double> rest = stepRecord(one.m, one.d, one.b, 100);
  EXPECT_EQ(stepRecord(one.m, c, one.b, 100), rest);
  first.insert(first.end(), rest.begin(), rest.end());
  EXPECT_EQ(first, ref);
  mjb_unbindData(one.b, c);
  mj_deleteData(c);
}

TEST(Guess, GlRunsResetsAndCopiesRepeatTheBits) {
  // gl keeps its guesses' history per mjData in a GL buffer: a reset starts
  // it cold, mjb_copyData copies it, and RK4's stages read the step's
  // guesses without writing them, so each of these repeats the bits
  for (const char* integ : {"Euler", "RK4"}) {
    Scene g(steep(1, "gl", integ));
    ASSERT_TRUE(g.ok()) << g.err;
    ASSERT_STREQ(mjb_info(g.b).backend, "gl");
    const std::vector<double> ref = stepRecord(g.m, g.d, g.b, 120);
    mj_resetData(g.m, g.d);
    EXPECT_EQ(stepRecord(g.m, g.d, g.b, 120), ref) << integ;
    mj_resetData(g.m, g.d);
    std::vector<double> first = stepRecord(g.m, g.d, g.b, 60);
    mjData* c = mj_makeData(g.m);
    mj_copyData(c, g.m, g.d);
    ASSERT_EQ(mjb_copyData(g.b, c, g.d), 1);
    std::vector<double> rest = stepRecord(g.m, g.d, g.b, 60);
    EXPECT_EQ(stepRecord(g.m, c, g.b, 60), rest) << integ;
    first.insert(first.end(), rest.begin(), rest.end());
    EXPECT_EQ(first, ref) << integ;
    mjb_unbindData(g.b, c);
    mj_deleteData(c);
  }
}

TEST(Guess, GlForcesAreThoseOfAColdSolve) {
  // as ForcesAreThoseOfAColdSolve on gl, in float: every 10 steps a copy
  // without history (labels start at the positions) against the run's
  // guessed ones. Both stop once a Newton step is below 0.1 mm (after it
  // the error is ~ K st^2 = 0.18 (1e-4)^2 = 2e-9 m), so what is left is
  // float's resolution of a label a few metres from the COM, 3 m 2^-24 =
  // 2e-7 m, which moves a vertex height by up to that times (1 + sum k A)
  // and the pressure force by about rho g S_wet dh, relative dh / draft =
  // 2e-7 / 0.1 m = 2e-6 per vertex, less summed over the hull: 2e-5 of
  // each family's size leaves a factor of ten
  Scene s(steep(1, "gl"));
  ASSERT_TRUE(s.ok()) << s.err;
  ASSERT_STREQ(mjb_info(s.b).backend, "gl");
  double largest = 0;
  const double worst = coldCompare(s, 2e-5, 1e-6, &largest, [](int) {});
  ASSERT_GT(largest, 1000) << "the hulls must float for the comparison to show anything";
  std::printf("gl: worst relative difference from a cold solve %.3g\n", worst);
}

}  // namespace
}  // namespace mjbt
