// the frequency-domain memory length (docs/physics.md section 14, "Memory
// length"): the retardation function cut at that length, tapered and made
// zero-gain, transforms back to the panel solver's B(w)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "api/buoy.h"
#include "radiation/radiation.h"
#include "testutil.h"

namespace mjbt {
namespace {

// worst |B_T(w) - B(w)| / peak |B_dd| of K_dd over tmem s at step h, tapered and zero-gain as the
// memory uses it (steadyZero), over the table's frequencies; B_T = h sum w_k K_k cos(w k h)
double rebuiltError(const mjb::HydroCoef& c, int d, double tmem, double h) {
  const int n = int(std::ceil(tmem / h)) + 1;
  std::vector<double> K(n);
  mjb::retardation(c, d, d, h, n, K.data(), true);
  mjb::steadyZero(K.data(), n);
  double peak = 0, worst = 0;
  for (int f = 0; f < c.nw(); f++) peak = std::max(peak, std::fabs(c.B[36 * f + 7 * d]));
  for (int f = 0; f < c.nw(); f++) {
    double s = 0;
    for (int k = 0; k < n; k++)
      s += (k == 0 || k == n - 1 ? 0.5 : 1) * K[k] * std::cos(c.omega[f] * k * h);
    worst = std::max(worst, std::fabs(h * s - c.B[36 * f + 7 * d]) / peak);
  }
  return worst;
}

TEST(RadMemory, WigleyKernelRebuildsPanelDampingAtItsLength) {
  // the Wigley of models/wigley.xml: its panel table B(w) is the
  // independent reference. At the frequency-domain length the surge and
  // heave kernels, sampled at opt.timestep, cut, tapered and zero-gain,
  // transform back to B within 3% of its peak at every table frequency
  // (kMemoryTol, with 0.5% for the trapezoid sums at the timestep instead
  // of the criterion's grid); at the decay length (|K| < 1% of its peak)
  // surge does not (the window's band, below about 4 pi / T_m, reaches the
  // table's low-frequency side)
  Scene s(shippedModel("wigley.xml", ""));
  ASSERT_TRUE(s.ok()) << s.err;
  ASSERT_FALSE(mjb::buoyOf(s.b)->coef.empty());
  const mjb::HydroCoef& c = mjb::buoyOf(s.b)->coef[0].second;
  const double h = s.m->opt.timestep;
  double worst = 0;
  int pair = -1;
  const double t0 = mjb::memoryLength(c), t = mjb::memoryLengthByTransform(c, &worst, &pair);
  const double surge0 = rebuiltError(c, 0, t0, h), surge = rebuiltError(c, 0, t, h);
  const double heave0 = rebuiltError(c, 2, t0, h), heave = rebuiltError(c, 2, t, h);
  std::printf("[radmemlen] wigley: decay length %.3f s: surge %.2f%%, heave %.2f%%; "
              "frequency-domain length %.3f s: surge %.2f%%, heave %.2f%% (criterion's worst "
              "%.2f%%, pair %d)\n", t0, 100 * surge0, 100 * heave0, t, 100 * surge, 100 * heave,
              100 * worst, pair);
  EXPECT_LE(worst, mjb::kMemoryTol);
  EXPECT_LT(surge, mjb::kMemoryTol + 0.005);
  EXPECT_LT(heave, mjb::kMemoryTol + 0.005);
  EXPECT_GT(surge0, mjb::kMemoryTol);
  EXPECT_GE(t, t0);
  EXPECT_LE(t, mjb::kAutoMemoryMax);
}

TEST(RadMemory, NarrowBandStopsAtTheCap) {
  // B a triangle 0.1 rad/s wide (0 at 1, 1 at 1.05, 0 at 1.1 rad/s): its
  // K(t) = (2/pi) 0.05 cos(1.05 t) (sin(0.025 t) / (0.025 t))^2 rings for
  // about 2 pi / 0.05 = 126 s, longer than any length the criterion may
  // take, so it stops at the cap (or the decay length, if longer) and says
  // by how much the rebuilt B misses (this test's own sums at 1 ms)
  mjb::HydroCoef c;
  c.Ainf[14] = 1;
  c.omega = {1.0, 1.05, 1.1};
  c.B.assign(3 * 36, 0);
  c.B[36 + 14] = 1;
  double worst = 0;
  int pair = -1;
  const double t = mjb::memoryLengthByTransform(c, &worst, &pair);
  EXPECT_GE(t, mjb::kAutoMemoryMax);
  EXPECT_GT(worst, mjb::kMemoryTol);
  EXPECT_EQ(pair, 14);
  EXPECT_NEAR(worst, rebuiltError(c, 2, t, 0.001), 0.005);
}

}  // namespace
}  // namespace mjbt
