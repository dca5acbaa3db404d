// finite-difference derivatives: mjd_transitionFD (MuJoCo 2.2.2) steps one
// mjData again and again without putting d->time back, so each perturbed
// step would see the waves later and move mjbuoy's histories on. Frozen
// (mjb_freezeData), every column equals the one a fresh copy gives
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

// a 2 x 1 x 0.5 m box of 500 kg in a 0.2 m, 20 m wave, radiation on (the
// default: memory and added mass), dropped 5 cm so it is moving and slamming
const char kBox[] =
    "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
    "<numeric name=\"mjbuoy.airy.a\" data=\"0.2 20 0 0\"/></custom><worldbody>"
    "<body name=\"box\" pos=\"0 0 0.05\"><freejoint/>"
    "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body>"
    "</worldbody></mujoco>";

// the velocity rows of the velocity columns of A by hand: for each dof j a
// fresh copy of d (mj_copyData + mjb_copyData), qvel[j] += eps, one step;
// dv'_i / dv_j = (v'_i - v_i) / eps against an unperturbed fresh copy
std::vector<double> reference(mjModel* m, mjData* d, mjbBuoy* b, double eps) {
  const int nv = m->nv;
  std::vector<double> out(nv * nv), v0(nv);
  mjData* c = mj_makeData(m);
  for (int j = -1; j < nv; j++) {
    mj_copyData(c, m, d);
    EXPECT_EQ(mjb_copyData(b, c, d), 1);
    if (j >= 0) c->qvel[j] += eps;
    mj_step(m, c);
    for (int i = 0; i < nv; i++) {
      if (j < 0) v0[i] = c->qvel[i];
      else out[i * nv + j] = (c->qvel[i] - v0[i]) / eps;
    }
  }
  mj_deleteData(c);
  return out;
}

// the same block of mjd_transitionFD's A ((2 nv) x (2 nv), row-major:
// A[i][j] = d x'_i / d x_j, x = (dq, v))
std::vector<double> fd(mjModel* m, mjData* d, double eps) {
  const int nv = m->nv, n = 2 * nv;
  std::vector<double> A(n * n), out(nv * nv);
  mjd_transitionFD(m, d, eps, 0, A.data(), nullptr, nullptr, nullptr);
  for (int i = 0; i < nv; i++)
    for (int j = 0; j < nv; j++) out[i * nv + j] = A[(nv + i) * n + nv + j];
  return out;
}

double maxDiff(const std::vector<double>& a, const std::vector<double>& b, double* scale) {
  double e = 0;
  *scale = 0;
  for (size_t i = 0; i < a.size(); i++) {
    e = std::fmax(e, std::fabs(a[i] - b[i]));
    *scale = std::fmax(*scale, std::fabs(b[i]));
  }
  return e;
}

TEST(RobustFd, FrozenDataGivesTheJacobianOfAFreshCopy) {
  Scene s(kBox);
  ASSERT_TRUE(s.ok()) << s.err;
  for (int k = 0; k < 150; k++) mj_step(s.m, s.d);  // 0.3 s: in the water, moving
  const double eps = 1e-6;
  std::vector<double> ref = reference(s.m, s.d, s.b, eps);
  const double t = s.d->time;
  mjData* plain = mj_makeData(s.m);  // the same, not frozen
  mj_copyData(plain, s.m, s.d);
  ASSERT_EQ(mjb_copyData(s.b, plain, s.d), 1);
  ASSERT_EQ(mjb_freezeData(s.b, s.d, 1), 1);
  std::vector<double> got = fd(s.m, s.d, eps);
  ASSERT_EQ(mjb_freezeData(s.b, s.d, 0), 1);
  s.d->time = t;
  double scale, err = maxDiff(got, ref, &scale);
  ASSERT_GT(scale, 0);
  // the same steps from the same state: equal to round-off
  EXPECT_LE(err, 1e-9 * scale) << "frozen FD vs fresh copies";
  // without freezing each of the 7 steps (nominal, 6 dofs) starts 2 ms
  // later than the last, in the wave and with histories moved on
  std::vector<double> drift = fd(s.m, plain, eps);
  double derr = maxDiff(drift, ref, &scale);
  EXPECT_GT(derr, 1e-3 * scale) << "the test must show the drift it guards against";
  // after unfreezing, d continues exactly like a copy that never saw the
  // finite differences
  mjData* c = mj_makeData(s.m);
  mj_copyData(c, s.m, s.d);
  ASSERT_EQ(mjb_copyData(s.b, c, s.d), 1);
  for (int k = 0; k < 20; k++) {
    mj_step(s.m, s.d);
    mj_step(s.m, c);
  }
  for (int i = 0; i < s.m->nq; i++) EXPECT_EQ(s.d->qpos[i], c->qpos[i]) << i;
  mj_deleteData(c);
  mj_deleteData(plain);
}

}  // namespace
}  // namespace mjbt
