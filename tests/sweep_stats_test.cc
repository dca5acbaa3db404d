// mjbuoy-sweep statistics (tools/sweep/sweep_stats.cc) on synthetic records whose
// statistics are known in closed form
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sweep.h"

namespace {

using swp::StatKind;
using swp::statValue;

// y = c + A cos(w t + phi) over whole periods, sampled at dt
struct Record {
  std::vector<double> t, y, eta;
  Record(double c, double A, double w, double phi, double T, double dt, double Ae = 0.5) {
    for (long i = 0; i * dt <= T + 1e-12; i++) {
      double s = i * dt;
      t.push_back(s);
      y.push_back(c + A * std::cos(w * s + phi));
      eta.push_back(Ae * std::cos(w * s));
    }
  }
};

TEST(SweepStats, SinusoidMoments) {
  // 10 periods of 2 s, 2000 samples per period: the sums approximate the
  // integrals (1/T) int cos^2 = 1/2 to O(dt / T) from the shared end sample
  const double c = 0.3, A = 0.2, w = M_PI, phi = 0.7, dt = 0.001;
  Record r(c, A, w, phi, 20, dt);
  EXPECT_NEAR(statValue(StatKind::MEAN, r.t, r.y, r.eta, w), c, 1e-4);
  // std of A cos is A / sqrt(2); significant value 4 std
  EXPECT_NEAR(statValue(StatKind::STD, r.t, r.y, r.eta, w), A / std::sqrt(2.0), 1e-4);
  EXPECT_NEAR(statValue(StatKind::SIG, r.t, r.y, r.eta, w), 4 * A / std::sqrt(2.0), 4e-4);
  // rms^2 = c^2 + A^2 / 2
  EXPECT_NEAR(statValue(StatKind::RMS, r.t, r.y, r.eta, w), std::sqrt(c * c + A * A / 2), 1e-4);
  EXPECT_NEAR(statValue(StatKind::MAX, r.t, r.y, r.eta, w), c + A, 1e-6);
  EXPECT_NEAR(statValue(StatKind::MIN, r.t, r.y, r.eta, w), c - A, 1e-6);
  // up-crossings of the mean are one period 2 pi / w apart
  EXPECT_NEAR(statValue(StatKind::TZ, r.t, r.y, r.eta, w), 2.0, 1e-6);
  EXPECT_NEAR(statValue(StatKind::PERIOD, r.t, r.y, r.eta, w), 2.0, 1e-12);
}

TEST(SweepStats, FittedAmplitudePhaseRao) {
  // the fit recovers A and phi exactly (to rounding), also over a window of
  // 2.3 periods that does not start at t = 0, and ignores a second frequency
  const double c = -1.5, A = 0.2, w = 2.0, phi = -2.5, dt = 0.01;
  Record r(c, A, w, phi, 40, dt);
  std::vector<double> t, y, eta;
  for (size_t i = 0; i < r.t.size(); i++) {
    if (r.t[i] < 10 || r.t[i] > 10 + 2.3 * 2 * M_PI / w) continue;
    t.push_back(r.t[i]);
    y.push_back(r.y[i]);
    eta.push_back(r.eta[i]);
  }
  EXPECT_NEAR(statValue(StatKind::AMP, t, y, eta, w), A, 1e-12);
  EXPECT_NEAR(statValue(StatKind::RAO, t, y, eta, w), A / 0.5, 1e-11);
  EXPECT_NEAR(statValue(StatKind::PHASE, t, y, eta, w), phi * 180 / M_PI, 1e-9);
  // over 20 periods, a component at 3 w of amplitude 0.05 changes the fit
  // by its projection only, which vanishes over whole periods
  Record s(c, A, w, phi, 20 * M_PI, 0.001);
  for (size_t i = 0; i < s.t.size(); i++) s.y[i] += 0.05 * std::sin(3 * w * s.t[i]);
  EXPECT_NEAR(statValue(StatKind::AMP, s.t, s.y, s.eta, w), A, 1e-4);
}

TEST(SweepStats, TooFewSamplesIsNan) {
  std::vector<double> t = {0}, y = {1}, eta = {0};
  EXPECT_TRUE(std::isnan(statValue(StatKind::MEAN, t, y, eta, 1)));
  // a record without up-crossings has no zero-crossing period
  std::vector<double> t2 = {0, 1, 2}, y2 = {0, 1, 2};
  EXPECT_TRUE(std::isnan(statValue(StatKind::TZ, t2, y2, y2, 1)));
}

}  // namespace
