// the demo scene (models/jonswap.xml) at its own time step against a step
// five times finer: the motions have converged in the step
// (docs/benchmarks.md "The demo")
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "mjbuoy.h"

namespace {

// simulated time [s] and the window [s] over which the RMS are taken: the
// sea's start-up ramp (3 periods of the longest swell component, 8.9 s:
// 26.6 s) is at 0.35 of full amplitude at 10 s and 0.79 at 20 s
const double kSeconds = 20, kFrom = 10;
// the finer step's ratio: the independent reference
const int kFine = 5;

// heave [m], roll and pitch [rad] of every free body, one sample per step of
// the coarser run: q[3 b + 0..2][sample]
struct Motion {
  std::vector<std::string> name;
  std::vector<std::vector<double>> q;
};

// models/jonswap.xml run at step h for kSeconds, sampled every `every` steps;
// every body checked finite, within 1 m of the surface and tilted under 60
// degrees at every step
void runDemo(double h, int every, Motion* out) {
  char e[1024] = "";
  mjModel* m = mj_loadXML(MJB_MODELS "/jonswap.xml", nullptr, e, sizeof(e));
  ASSERT_TRUE(m) << e;
  // the step before mjb_attach: the radiation memory is made at it
  m->opt.timestep = h;
  mjbBuoy* b = mjb_attach(m, nullptr, e, sizeof(e));
  if (!b) mj_deleteModel(m);
  ASSERT_TRUE(b) << e;
  mjData* d = mj_makeData(m);
  std::vector<int> body;
  for (int j = 0; j < m->njnt; j++) {
    if (m->jnt_type[j] != mjJNT_FREE) continue;
    body.push_back(m->jnt_bodyid[j]);
    out->name.push_back(m->names + m->name_bodyadr[m->jnt_bodyid[j]]);
  }
  out->q.assign(3 * body.size(), {});
  const long nstep = std::lround(kSeconds / h);
  bool ok = true;
  for (long step = 1; step <= nstep && ok; step++) {
    mj_step(m, d);
    for (size_t k = 0; k < body.size() && ok; k++) {
      const mjtNum* x = d->xipos + 3 * body[k];
      const mjtNum* R = d->xmat + 9 * body[k];
      const double eta = mjb_seaHeight(b, x[0], x[1], d->time);
      ok = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) &&
           std::fabs(x[2] - eta) < 1 && R[8] > std::cos(60 * M_PI / 180);
      EXPECT_TRUE(ok) << out->name[k] << " at t = " << d->time << " s, step " << h
                      << " s: pos " << x[0] << " " << x[1] << " " << x[2] << ", surface " << eta
                      << ", cos(tilt) " << R[8];
      if (step % every) continue;
      // z-y-x Euler angles of the body's rotation R (world from body)
      out->q[3 * k].push_back(x[2]);
      out->q[3 * k + 1].push_back(std::atan2(R[7], R[8]));
      out->q[3 * k + 2].push_back(std::asin(std::fmax(-1.0, std::fmin(1.0, -R[6]))));
    }
  }
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
}

// RMS of the difference of a's and b's samples from index i0
double rmsDiffFrom(const std::vector<double>& a, const std::vector<double>& b, size_t i0) {
  double sq = 0;
  for (size_t i = i0; i < a.size(); i++) sq += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sq / double(a.size() - i0));
}

// RMS about the mean of v's samples from index i0
double rmsFrom(const std::vector<double>& v, size_t i0) {
  double mean = 0, sq = 0;
  for (size_t i = i0; i < v.size(); i++) mean += v[i];
  mean /= double(v.size() - i0);
  for (size_t i = i0; i < v.size(); i++) sq += (v[i] - mean) * (v[i] - mean);
  return std::sqrt(sq / double(v.size() - i0));
}

TEST(Demo, MotionsConvergeInTheTimeStep) {
  // MuJoCo's default integrator, semi-implicit Euler, is first order in
  // the step h: the error e(h) = C h + O(h^2), so the run at h / 5 is
  // within e(h) / 5 of the exact motion and the difference of the two runs
  // bounds e(h) within 25% [Hairer, Lubich and Wanner 2006, sec. I.1;
  // the convergence check of docs/benchmarks.md "The demo"]. Slamming's
  // force over one step (docs/physics.md 4.4) is not of this kind, but its
  // share of the difference is small in this sea (the same page)
  char e[1024] = "";
  mjModel* m = mj_loadXML(MJB_MODELS "/jonswap.xml", nullptr, e, sizeof(e));
  ASSERT_TRUE(m) << e;
  const double h = m->opt.timestep;
  ASSERT_EQ(m->opt.integrator, mjINT_EULER);
  mj_deleteModel(m);

  Motion coarse, fine;
  runDemo(h, 1, &coarse);
  runDemo(h / kFine, kFine, &fine);
  ASSERT_FALSE(HasFailure());
  ASSERT_EQ(coarse.q.size(), fine.q.size());
  const char* what[3] = {"heave", "roll", "pitch"};
  for (size_t k = 0; k < coarse.q.size(); k++) {
    ASSERT_EQ(coarse.q[k].size(), fine.q[k].size());
    const size_t i0 = std::lround(kFrom / h);
    const double rc = rmsFrom(coarse.q[k], i0), rf = rmsFrom(fine.q[k], i0);
    const double dq = rmsDiffFrom(coarse.q[k], fine.q[k], i0);
    std::printf("[demo] %s %s: RMS %.5g at %g s, %.5g at %g s (%+.2f%%); series %.2f%%\n",
                coarse.name[k / 3].c_str(), what[k % 3], rc, h, rf, h / kFine,
                100 * (rc - rf) / rf, 100 * dq / rf);
    // the heave series within 5% of its RMS: the runs follow the same motion
    if (k % 3 == 0) {
      EXPECT_LT(dq, 0.05 * rf) << coarse.name[k / 3] << " heave: RMS difference of the series";
    }
    // the RMS motions within 2% of the finer step's
    EXPECT_NEAR(rc, rf, 0.02 * rf) << coarse.name[k / 3] << " " << what[k % 3] << ": RMS at step "
                                   << h << " s against " << h / kFine << " s";
  }
}

}  // namespace
