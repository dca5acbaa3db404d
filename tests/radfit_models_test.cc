// the state-space radiation memory of every shipped hull (docs/physics.md
// section 14, "State-space memory"): the fit meets its tolerances, its B
// rebuilt in closed form follows the panel solution's, and its memory
// force follows the exact convolution of the sampled K
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "radiation/radfit.h"
#include "radiation/radiation.h"
#include "ssconv.h"
#include "testutil.h"

namespace mjbt {
namespace {

using mjb::cplx;

// the panel solution's B_ij at table frequency f, from the body's memory
// key (radiation.cc, memoryKey: memory, step, count, omega, then B)
double keyB(const mjb::RadBody& rb, int f, int i, int j) {
  const int nw = int(rb.key[2]);
  return rb.key[3 + nw + 36 * f + 6 * i + j];
}

// the largest |B_ii| over the table of each dof, floored at kFitNoise of
// the largest of its kind (radiation.cc, pairScales)
void diagScales(const mjb::RadBody& rb, double E[6]) {
  const int nw = int(rb.key[2]);
  double S[2] = {0, 0};
  for (int d = 0; d < 6; d++) {
    E[d] = 0;
    for (int f = 0; f < nw; f++) E[d] = std::max(E[d], std::fabs(keyB(rb, f, d, d)));
    S[d / 3] = std::max(S[d / 3], E[d]);
  }
  for (int d = 0; d < 6; d++) E[d] = std::max(E[d], mjb::kFitNoise * S[d / 3]);
}

// one body's check: every pair's modes (fitted or copied) rebuilt into a
// KFit; B and A - A_inf of the fit (fitTransform, closed form) against
// the trapezoid transform of the sampled K at the table's frequencies
// (but the last) where B is at least 10% of the pair's scale (fitKernel's
// errF, within kFitTolF); then the memory force over 10 s of a random
// velocity in all six dofs against the convolution
void checkBody(const std::string& what, const mjb::Radiation& R, const mjb::RadBody& rb) {
  SCOPED_TRACE(what);
  ASSERT_GT(rb.ss.size(), 0) << "the memory fell back to the convolution";
  const double h = R.dt;
  const int nk = rb.nk, nw = int(rb.key[2]);
  ASSERT_EQ(rb.K.size(), rb.pair.size() * size_t(nk));
  double E[6];
  diagScales(rb, E);
  double worstF = 0, worstP = 0;
  for (size_t q = 0; q < rb.pair.size(); q++) {
    const int i = rb.pair[q] / 6, j = rb.pair[q] % 6;
    mjb::KFit f;
    for (int r = 0; r < rb.ss.size(); r++)
      if (rb.ss.i[r] == i && rb.ss.j[r] == j) f.p.push_back(rb.ss.p[r]), f.c.push_back(rb.ss.c[r]);
    ASSERT_FALSE(f.p.empty()) << "pair " << i << j;
    for (cplx p : f.p) EXPECT_LT(p.real(), 0) << "unstable pole of pair " << i << j;
    const double* K = rb.K.data() + q * nk;
    std::vector<double> Bk(nw), Ak(nw);
    double bmax = std::sqrt(E[i] * E[j]);
    for (int w = 0; w < nw; w++) {
      const double om = rb.key[3 + w];
      double sc = 0, ss = 0;
      for (int k = 0; k < nk; k++) {
        const double wk = k == 0 || k == nk - 1 ? 0.5 : 1;
        sc += wk * K[k] * std::cos(om * k * h);
        ss += wk * K[k] * std::sin(om * k * h);
      }
      Bk[w] = h * sc;
      Ak[w] = -h * ss / om;
      bmax = std::max(bmax, std::fabs(Bk[w]));
    }
    for (int w = 0; w + 1 < nw; w++) {
      if (std::fabs(Bk[w]) < 0.1 * bmax) continue;
      double B, dA;
      mjb::fitTransform(f, rb.key[3 + w], &B, &dA);
      const double sc = std::max(std::fabs(Bk[w]), std::fabs(Ak[w]));
      worstF = std::max(worstF, std::max(std::fabs(B - Bk[w]), std::fabs(dA - Ak[w])) / sc);
      worstP = std::max(worstP, std::fabs(B - keyB(rb, w, i, j)) / sc);
    }
  }
  // (B against the panel table is printed, not held: the sampled K, cut
  // at the memory length, is the fit's reference, and its transform
  // departs from the table by more than kFitTolF at some frequencies)
  std::printf("[radfit] %s: %zu pairs, %d modes; worst errF %.4f, B against the panel %.4f\n",
              what.c_str(), rb.pair.size(), rb.ss.size(), worstF, worstP);
  EXPECT_LE(worstF, mjb::kFitTolF);
  // the memory force: state-space (radss.cc) against the trapezoid
  // convolution of the sampled K (radstep.cc), RMS difference per dof
  // within 5% of the largest RMS force of its kind: each pair's K is held
  // to 2% (L2, kFitTolT) and a dof sums up to six pairs' errors
  double e2[6], f2[6];
  ssAgainstConvolution(rb, h, int(10 / h), 5, e2, f2);
  for (int i = 0; i < 6; i++) {
    const double sc = kindScale(f2, i);
    if (sc == 0) continue;
    std::printf("[radfit] %s dof %d: rms difference %.4f of the kind's rms force\n",
                what.c_str(), i, std::sqrt(e2[i] / sc));
    EXPECT_LT(std::sqrt(e2[i] / sc), 0.05) << "dof " << i;
  }
}

// every body of an attached model with a memory of its own (twins share
// their first's, radiation.cc copyMemory)
void checkModel(const std::string& name, mjModel* m, mjbBuoy* b) {
  const mjb::Radiation& R = mjb::buoyOf(b)->rad;
  int n = 0;
  for (const mjb::RadBody& rb : R.rb) {
    if (rb.nk == 0 || rb.K.empty()) continue;
    checkBody(name + " body " + (m->names + m->name_bodyadr[rb.body]), R, rb);
    n++;
  }
  EXPECT_GT(n, 0) << name << ": no body with a radiation memory";
}

// the shipped models with radiation on (all but examples/rao/column.xml,
// which turns it off): tolerances of docs/physics.md section 14
TEST(RadFitModels, EveryShippedHullFits) {
  for (const char* file : {"barge.xml", "buoy.xml", "cylinder.xml", "fleet.xml", "jonswap.xml",
                           "moored_buoy.xml", "motorboat.xml", "wec_taut.xml", "wigley.xml"}) {
    char e[1024] = "";
    mjModel* m = mj_loadXML((std::string(MJB_MODELS "/") + file).c_str(), nullptr, e, sizeof(e));
    ASSERT_TRUE(m) << file << ": " << e;
    mjbBuoy* b = mjb_attach(m, nullptr, e, sizeof(e));
    EXPECT_TRUE(b) << file << ": " << e;
    if (b) checkModel(file, m, b);
    if (b) mjb_detach(b);
    mj_deleteModel(m);
  }
}

// the Wigleys of mjbuoy-bench (tools/bench/bench.cc, scene()): one boat
// at each resolution, radiation on by default
TEST(RadFitModels, BenchWigleysFit) {
  for (int tris : {64, 256, 576, 2800}) {
    const std::string xml =
        "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
        "/meshes/wigley_" + std::to_string(tris) + ".obj\"/></asset><custom>"
        "<text name=\"mjbuoy.hulls\" data=\"h*\"/></custom><worldbody>"
        "<body name=\"w\" pos=\"0 0 0.03\"><freejoint/>"
        "<inertial pos=\"0 0 -0.08\" mass=\"176.2\" diaginertia=\"6.02 237.28 238.6\"/>"
        "<geom name=\"h0\" type=\"mesh\" mesh=\"w\" contype=\"0\" conaffinity=\"0\"/>"
        "</body></worldbody></mujoco>";
    Scene s(xml);
    ASSERT_TRUE(s.ok()) << s.err;
    checkModel("wigley_" + std::to_string(tris), s.m, s.b);
  }
}

}  // namespace
}  // namespace mjbt
