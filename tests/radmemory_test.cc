// the radiation memory's convolution in vector lanes, and one memory shared
// by identical hulls (docs/physics.md section 14, "Memory")
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "radiation/radiation.h"
#include "testutil.h"
#include "util/vmath.h"

namespace {

using mjbt::Scene;

// ---- the dot product every level runs, against long double ----

// each level the cpu has: sum a b within n eps sum |a b| of the exact sum
// (Higham 2002, "Accuracy and Stability of Numerical Algorithms", eq. 3.5:
// any summation order, with or without FMA, is within gamma_n sum |a b|),
// and the same bits on a repeat
TEST(VMath, DotWithinRoundOffOnEveryLevel) {
  const int prev = mjb::simdLevel(), best = mjb::simdSet(mjb::kSimdAvx512);
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int level = mjb::kSimdScalar; level <= mjb::kSimdAvx512; level++) {
    if (level > best) {
      std::printf("[vmath] %s: not checked, this cpu does not have it\n", mjb::simdName(level));
      continue;
    }
    mjb::simdSet(level);
    for (int n : {0, 1, 3, 4, 5, 15, 16, 17, 31, 33, 100, 1276, 5001}) {
      std::vector<double> a(n), b(n);
      for (int i = 0; i < n; i++) {
        a[i] = u(g) * std::exp(4 * u(g));
        b[i] = u(g);
      }
      long double ex = 0, ab = 0;
      for (int i = 0; i < n; i++) {
        ex += (long double)a[i] * b[i];
        ab += std::fabs((long double)a[i] * b[i]);
      }
      const double d = mjb::vDot(n, a.data(), b.data());
      EXPECT_LE(std::fabs((long double)d - ex), n * 0x1p-53L * ab * 1.01L)
          << mjb::simdName(level) << " n " << n;
      EXPECT_EQ(d, mjb::vDot(n, a.data(), b.data())) << mjb::simdName(level) << " n " << n;
    }
  }
  mjb::simdSet(prev);
}

// ---- the memory force against its formula, summed in long double ----

// a body with three pairs (heave-heave, surge-pitch and pitch-surge) and
// damped cosine kernels; the history a ring of nh random velocities. The
// memory is -dt sum_k w_k K(k dt) nu(t - k dt) over the n = min(count, nk)
// samples held, w = 1/2 at both ends (docs/physics.md section 14): summed
// here directly over the ring in long double, for heads that put the
// window across the ring's end and not, and counts below and above nk
TEST(RadMemory, ConvolutionIsTheTrapezoidSum) {
  const int prev = mjb::simdLevel(), best = mjb::simdSet(mjb::kSimdAvx512);
  const int nk = 1276, nh = 1300;
  const double dt = 0.002;
  mjb::RadBody rb;
  rb.pair = {6 * 2 + 2, 6 * 0 + 4, 6 * 4 + 0};
  rb.nk = nk;
  auto kr = std::make_shared<std::vector<double>>(3 * nk);
  std::vector<double> K(3 * nk);
  for (int p = 0; p < 3; p++) {
    for (int k = 0; k < nk; k++) {
      const double t = k * dt;
      K[p * nk + k] = (1e4 / (p + 1)) * std::exp(-(0.8 + p) * t) * std::cos((3.1 + p) * t);
      (*kr)[p * nk + nk - 1 - k] = K[p * nk + k];
    }
  }
  rb.Kr = kr;
  std::mt19937_64 g(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> hist(6 * nh);
  for (double& v : hist) v = u(g);
  for (int level = mjb::kSimdScalar; level <= best; level++) {
    mjb::simdSet(level);
    for (int head : {0, 1, 700, nh - 1}) {
      for (int count : {1, 2, 3, 800, nk, nh}) {
        double f[6];
        mjb::radMemory(rb, hist.data(), nh, head, count, dt, f);
        long double ex[6] = {0}, mag[6] = {0};
        const int n = std::min(count, nk);
        for (int p = 0; p < 3 && n >= 2; p++) {
          const int i = rb.pair[p] / 6, j = rb.pair[p] % 6;
          for (int k = 0; k < n; k++) {
            const long double w = (k == 0 || k == n - 1) ? 0.5L : 1.0L;
            const long double t = w * K[p * nk + k] * hist[nh * j + (head - k + nh) % nh];
            ex[i] -= dt * t;
            mag[i] += dt * std::fabs(t);
          }
        }
        for (int i = 0; i < 6; i++) {
          EXPECT_LE(std::fabs((long double)f[i] - ex[i]), (n + 4) * 0x1p-52L * mag[i])
              << mjb::simdName(level) << " head " << head << " count " << count << " dof " << i;
        }
      }
    }
  }
  mjb::simdSet(prev);
}

// ---- identical hulls: one memory ----

// n Wigley hulls (64 triangles), the same mass, at the given x [m], on
// the given cpu threads
std::string fleet(const std::vector<double>& x, int threads = 1) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.002\"/><custom>"
       "<numeric name=\"mjbuoy.threads\" data=\"" << threads << "\"/>"
       "<text name=\"mjbuoy.hulls\" data=\"h*\"/><text name=\"mjbuoy.radiation\" data=\"on\"/>"
       "<text name=\"mjbuoy.radiation.memorymodel\" data=\"convolution\"/>"
       "</custom><asset><mesh name=\"w\" file=\"" MJB_MODELS "/meshes/wigley_64.obj\"/></asset>"
       "<worldbody>";
  for (size_t i = 0; i < x.size(); i++) {
    s << "<body pos=\"" << x[i] << " " << 3 * i << " 0.034\"><freejoint/>"
      << "<inertial pos=\"0 0 -0.08\" mass=\"176.2\" diaginertia=\"6.020 237.28 238.60\"/>"
      << "<geom name=\"h" << i << "\" type=\"mesh\" mesh=\"w\" contype=\"0\" conaffinity=\"0\"/>"
      << "</body>";
  }
  s << "</worldbody></mujoco>";
  return s.str();
}

// hulls far apart get their panel meshes from world positions, so their B
// differ in the last bits; the memory of each is then the first one's
// (shared, computed once), and within round-off of what the last hull gets
// alone, where it is computed from its own coefficients
TEST(RadMemory, IdenticalHullsShareOneMemory) {
  Scene all(fleet({0, 37.3, -81.7}));
  ASSERT_TRUE(all.ok()) << all.err;
  Scene one(fleet({-81.7}));
  ASSERT_TRUE(one.ok()) << one.err;
  const mjb::Radiation& ra = mjb::buoyOf(all.b)->rad;
  const mjb::Radiation& r1 = mjb::buoyOf(one.b)->rad;
  ASSERT_EQ(ra.rb.size(), 3u);
  ASSERT_EQ(r1.rb.size(), 1u);
  const mjb::RadBody &a = ra.rb[2], &o = r1.rb[0];
  ASSERT_GT(o.nk, 100);
  EXPECT_EQ(ra.rb[1].Kr.get(), ra.rb[0].Kr.get());
  EXPECT_EQ(a.Kr.get(), ra.rb[0].Kr.get());
  ASSERT_EQ(a.nk, o.nk);
  ASSERT_EQ(a.pair, o.pair);
  double kmax = 0, dmax = 0;
  for (size_t q = 0; q < o.Kr->size(); q++) {
    kmax = std::max(kmax, std::fabs((*o.Kr)[q]));
    dmax = std::max(dmax, std::fabs((*o.Kr)[q] - (*a.Kr)[q]));
  }
  // the keys (memory length, step, frequencies, B) of the hulls differ
  double bmax = 0, bd = 0;
  for (size_t q = 0; q < a.key.size(); q++) {
    bmax = std::max(bmax, std::fabs(a.key[q]));
    bd = std::max(bd, std::fabs(a.key[q] - ra.rb[0].key[q]));
  }
  std::printf("[radmemory] %zu pairs x %d samples: B of the third and first hulls differ by "
              "%.2g of the largest; shared K within %.2g of the third's own\n",
              o.pair.size(), o.nk, bd / bmax, dmax / kmax);
  EXPECT_LE(dmax, 1e-9 * kmax);
  // and the two runs agree: the same motion under the same forces
  for (int k = 0; k < 300; k++) {
    mj_step(all.m, all.d);
    mj_step(one.m, one.d);
  }
  for (int j = 0; j < 7; j++) {
    const double qa = all.d->qpos[14 + j], q1 = one.d->qpos[j];
    EXPECT_NEAR(qa - (j == 0 ? -81.7 : j == 1 ? 6 : 0), q1 - (j == 0 ? -81.7 : 0), 1e-9) << j;
  }
}

// the convolutions' pairs are shared among the cpu backend's threads once
// a step holds enough of them (radstep.cc preParts: 16384 multiply-adds);
// each pair's sum is the same function of the same history whoever
// computes it, so 1 and 2 threads give the same bits, step after step
// (docs/mjcf.md, mjbuoy.threads: the result does not depend on them)
TEST(RadMemory, ThreadsShareTheConvolutionsWithTheSameBits) {
  std::vector<double> x;
  for (int i = 0; i < 12; i++) x.push_back(7.0 * (i % 4));
  Scene one(fleet(x, 1)), two(fleet(x, 2));
  ASSERT_TRUE(one.ok() && two.ok()) << one.err << two.err;
  // the work of the last steps: every pair over min(steps, nk) samples
  const int steps = 400;
  const mjb::Radiation& r = mjb::buoyOf(two.b)->rad;
  long work = 0;
  for (const mjb::RadBody& rb : r.rb) work += long(rb.pair.size()) * std::min(steps, rb.nk);
  ASSERT_GT(work, 2 * 16384) << "too little memory to reach the threads";
  for (int k = 0; k < steps; k++) {
    mj_step(one.m, one.d);
    mj_step(two.m, two.d);
  }
  for (int i = 0; i < one.m->nq; i++) EXPECT_EQ(one.d->qpos[i], two.d->qpos[i]) << i;
  for (int i = 0; i < one.m->nv; i++) {
    EXPECT_EQ(one.d->qvel[i], two.d->qvel[i]) << i;
    EXPECT_EQ(one.d->qfrc_passive[i], two.d->qfrc_passive[i]) << i;
  }
  // the boats moved, so the memory had something to sum
  EXPECT_GT(std::fabs(one.d->qvel[2]), 1e-4);
}

}  // namespace
