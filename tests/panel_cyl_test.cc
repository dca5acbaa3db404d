// the panel solver's second body (issue 16, docs/physics.md section 13,
// "Second body: truncated cylinder"): a floating truncated vertical
// cylinder, radius R = 1, draft T = 0.5, deep water, against an independent
// panel code, and its irregular frequency with and without the lid.
// Panel.Cylinder* run by default on a coarse mesh; PanelConverged.Cylinder*
// (label panel, opt-in) is the converged comparison.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "radiation/panel.h"
#include "radiation/panelmesh.h"

namespace {

using mjb::HydroCoef;
using mjb::PanelMesh;

const double kPi = 3.14159265358979323846;
const double kRho = 1000, kG = 9.81, kR = 1, kT = 0.5;
const double kM = kRho * kPi * kR * kR * kT;  // displaced mass

// ---- reference: an independent panel code ----
// NEMOH v2 (Babarit and Delhommeau 2015, "Theoretical and numerical aspects
// of the open source BEM solver NEMOH", Proc. 11th EWTEC, Nantes; source
// github.com/LHEEA/Nemoh, commit 22ff60c, built and run outside this
// repository): constant-strength source panels with collocation at the
// centroids and Delhommeau's tabulated deep-water Green function. Same
// cylinder, reference point at the origin (centre of the waterplane), no
// lid, meshes nz x nr x na (side rows, bottom rings, around) 6 x 10 x 64
// (1024 panels) and 9 x 15 x 96 (2304), whose differences shrink as O(h)
// (256 -> 1024 -> 2304 panels: A11 at kR = 0.2 moves by -0.0113 then
// -0.0040, B33 at kR = 2 by +0.0035 then +0.0013: ratios 2.8 and 2.7
// against 3.0 for O(h)); the rows are the Richardson extrapolation
// 3 f(2304) - 2 f(1024), which differs from the raw 2304-panel values by at
// most 3.1% (B33 at kR = 2) where asserted (docs/physics.md section 13).
// A / (rho V), B / (rho V omega), pitch / (rho V R^2), surge-pitch / (rho V R),
// V = pi R^2 T; B55 (under 0.002) is not compared.
struct NemohRow {
  double kR, A11, B11, A33, B33, A55, A15;
};
const NemohRow kNemoh[] = {
    {0.2, 0.4623, 0.0058, 1.4516, 0.3651, 0.1317, -0.0137},
    {0.5, 0.5578, 0.0791, 1.1699, 0.4268, 0.1317, -0.0130},
    {1.0, 0.5342, 0.3434, 0.9728, 0.2820, 0.1317, -0.0291},
    {1.5, 0.3241, 0.4366, 0.9403, 0.1562, 0.1319, -0.0379},
    {2.0, 0.1809, 0.3915, 0.9591, 0.0826, 0.1327, -0.0335},
    {2.5, 0.1092, 0.3254, 0.9881, 0.0430, 0.1328, -0.0261},
    {3.5, 0.0621, 0.2216, 1.0162, 0.0143, 0.1322, -0.0148}};

// the first irregular frequency of the surface (interior Dirichlet problem
// J0(j01 r/R) sinh(j01 (z+T)/R), as in panel_test.cc):
// K R = j01 coth(j01 T/R) = 2.882 for T/R = 0.5, j01 = 2.404826. It spoils
// heave (axisymmetric mode); the first surge one (J1, j11 = 3.831706) is at
// K R = j11 coth(j11 T/R) = 4.001, which is why the table stops at 3.5.
const double kJ01 = 2.404826;
const double kKirr = kJ01 / std::tanh(kJ01 * kT / kR);
// at kKirr NEMOH (no lid) is spoiled in heave: the reference is the
// quadratic through the rows kR = 2, 2.5, 3.5 (A33; log B33 for B33). Other
// triples (1.5, 2, 3.5; 1.5, 2, 2.5, 3.5) give A33 0.9925 to 1.0077 and B33
// 0.0269 to 0.0286: the interpolation is good to 1% in A33, 5% in B33.
// Surge is not spoiled there: NEMOH's own value (Richardson as above).
const double kIrrA33 = 1.0035, kIrrB33 = 0.0273, kIrrA11 = 0.0817, kIrrB11 = 0.2802;

// ---- helpers ----
HydroCoef solveCyl(int nz, int nr, int na, const std::vector<double>& kr, bool lid, double* sec = nullptr) {
  PanelMesh body, top;
  mjb::cylinderMesh(kR, kT, nz, nr, na, &body, &top);
  if (!lid) top = PanelMesh();
  HydroCoef h;
  h.rho = kRho;
  h.g = kG;
  std::vector<double> om;
  for (double k : kr) om.push_back(std::sqrt(k / kR * kG));
  std::string err;
  auto t0 = std::chrono::steady_clock::now();
  EXPECT_TRUE(mjb::panelSolve(body, top, om, {0.0}, &h, &err)) << err;
  if (sec) *sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return h;
}
// nondimensional coefficient (i, j) at frequency w, as the table
double coefA(const HydroCoef& h, int w, int i, int j) {
  double s = kM * (i > 2 ? kR : 1) * (j > 2 ? kR : 1);
  return h.A[36 * w + 6 * i + j] / s;
}
double coefB(const HydroCoef& h, int w, int i, int j) {
  double s = kM * (i > 2 ? kR : 1) * (j > 2 ? kR : 1);
  return h.B[36 * w + 6 * i + j] / (s * h.omega[w]);
}
double relErr(double a, double b) { return std::fabs(a - b) / std::fabs(b); }
const NemohRow& nemohAt(double kr) {
  for (const NemohRow& r : kNemoh)
    if (std::fabs(r.kR - kr) < 1e-9) return r;
  ADD_FAILURE() << "no NEMOH row at kR " << kr;
  return kNemoh[0];
}

// surge, heave and pitch at one frequency within tol of NEMOH; the
// surge-pitch coupling within tol of its natural scale sqrt(A11 A55)
void expectNemoh(const HydroCoef& h, int w, double kr, double tol, bool heave = true) {
  const NemohRow& r = nemohAt(kr);
  EXPECT_LT(relErr(coefA(h, w, 0, 0), r.A11), tol) << "kR " << kr << " A11 " << coefA(h, w, 0, 0);
  if (r.B11 > 0.05) {
    EXPECT_LT(relErr(coefB(h, w, 0, 0), r.B11), tol) << "kR " << kr << " B11 " << coefB(h, w, 0, 0);
  }
  EXPECT_LT(relErr(coefA(h, w, 4, 4), r.A55), tol) << "kR " << kr << " A55 " << coefA(h, w, 4, 4);
  EXPECT_LT(std::fabs(coefA(h, w, 0, 4) - r.A15), tol * std::sqrt(r.A11 * r.A55))
      << "kR " << kr << " A15 " << coefA(h, w, 0, 4);
  if (!heave) return;
  EXPECT_LT(relErr(coefA(h, w, 2, 2), r.A33), tol) << "kR " << kr << " A33 " << coefA(h, w, 2, 2);
  EXPECT_LT(relErr(coefB(h, w, 2, 2), r.B33), tol) << "kR " << kr << " B33 " << coefB(h, w, 2, 2);
}

// ---- coarse: default run ----

// 3 x 5 x 32 (256 panels), no lid, kR = 0.5 and 1: surge, heave, pitch and
// the coupling within 4% of NEMOH: measured at this mesh at most 2.3% (B11),
// the discretization error (2304 panels are within 0.8% at these kR, the
// change 256 -> 2304 is 0.7% to 1.7%), plus a margin
TEST(Panel, CylinderCoarse) {
  const std::vector<double> kr = {0.5, 1.0};
  HydroCoef h = solveCyl(3, 5, 32, kr, false);
  for (int w = 0; w < h.nw(); w++) expectNemoh(h, w, kr[w], 0.04);
}

// at the irregular frequency K R = j01 coth(j01 T/R) = 2.882: without the lid
// A33 is spoiled (measured 0.80, -20%; asserted more than 10% off the
// interpolated reference), with the damped lid A33 and B33 are within 3%
// (measured -1.9% and -0.7%; +16% in B33 with the undamped lid this
// replaced, docs/physics.md section 13); 3 x 5 x 32 (+160 lid panels)
TEST(Panel, CylinderIrregularFrequencyLid) {
  HydroCoef bare = solveCyl(3, 5, 32, {kKirr}, false);
  EXPECT_GT(relErr(coefA(bare, 0, 2, 2), kIrrA33), 0.10) << "no irregular frequency at K R " << kKirr;
  HydroCoef lid = solveCyl(3, 5, 32, {kKirr}, true);
  std::printf("K R %.3f: no lid A33 %.4f; lid A33 %.4f B33 %.4f; reference %.4f %.4f\n", kKirr,
              coefA(bare, 0, 2, 2), coefA(lid, 0, 2, 2), coefB(lid, 0, 2, 2), kIrrA33, kIrrB33);
  EXPECT_LT(relErr(coefA(lid, 0, 2, 2), kIrrA33), 0.03) << coefA(lid, 0, 2, 2);
  EXPECT_LT(relErr(coefB(lid, 0, 2, 2), kIrrB33), 0.03) << coefB(lid, 0, 2, 2);
}

// ---- converged validation (label panel) ----

// no lid, meshes 3 x 5 x 32, 6 x 10 x 64, 9 x 15 x 96 (256, 1024, 2304
// panels); prints the convergence table and asserts the finest within 3% of
// NEMOH: surge and pitch to kR = 2.5, heave to kR = 2 (above, heave is in
// the band of the irregular frequency at 2.882 and is printed only; kR = 3.5
// lies between it and surge's at 4.0: printed only). Then the irregular
// frequency at 9 x 15 x 96 without the lid (A33 spoiled, surge not) and
// every kR at 6 x 10 x 64 with the lid (640 lid panels): A33 within 3%, at
// 2.882 of the interpolated reference, and B33 there within 3% (measured
// -1.5%)
TEST(PanelConverged, CylinderNemoh) {
  std::vector<double> kr;
  for (const NemohRow& r : kNemoh) kr.push_back(r.kR);
  const int res[3][3] = {{3, 5, 32}, {6, 10, 64}, {9, 15, 96}};
  std::vector<HydroCoef> hs;
  for (auto& m : res) {
    double sec;
    hs.push_back(solveCyl(m[0], m[1], m[2], kr, false, &sec));
    std::printf("[panel] cylinder %d x %d x %d: %d panels, %.1f s for %d frequencies\n", m[0], m[1], m[2],
                (m[0] + m[1]) * m[2], sec, (int)kr.size());
  }
  std::printf("[panel] kR | A11 256 1024 2304 NEMOH | B11 ... | A33 ... | B33 ... | A55 2304 NEMOH | A15 2304 NEMOH\n");
  for (size_t w = 0; w < kr.size(); w++) {
    const NemohRow& r = kNemoh[w];
    std::printf("[panel] %.1f", kr[w]);
    const int ij[4][2] = {{0, 0}, {0, 0}, {2, 2}, {2, 2}};
    const double ref[4] = {r.A11, r.B11, r.A33, r.B33};
    for (int c = 0; c < 4; c++) {
      std::printf(" |");
      for (const HydroCoef& h : hs)
        std::printf(" %.4f", c % 2 ? coefB(h, w, ij[c][0], ij[c][1]) : coefA(h, w, ij[c][0], ij[c][1]));
      std::printf(" %.4f", ref[c]);
    }
    std::printf(" | %.4f %.4f | %.4f %.4f\n", coefA(hs[2], w, 4, 4), r.A55, coefA(hs[2], w, 0, 4), r.A15);
    if (kr[w] < 2.01)
      expectNemoh(hs[2], w, kr[w], 0.03);
    else if (kr[w] < 2.6)
      expectNemoh(hs[2], w, kr[w], 0.03, false);
  }
  HydroCoef bare = solveCyl(9, 15, 96, {kKirr}, false);
  std::printf("[panel] K R %.3f no lid: A33 %.4f B33 %.4f A11 %.4f B11 %.4f; reference %.4f %.4f %.4f %.4f\n", kKirr,
              coefA(bare, 0, 2, 2), coefB(bare, 0, 2, 2), coefA(bare, 0, 0, 0), coefB(bare, 0, 0, 0), kIrrA33,
              kIrrB33, kIrrA11, kIrrB11);
  EXPECT_GT(relErr(coefA(bare, 0, 2, 2), kIrrA33), 0.10);
  EXPECT_LT(relErr(coefA(bare, 0, 0, 0), kIrrA11), 0.03);
  EXPECT_LT(relErr(coefB(bare, 0, 0, 0), kIrrB11), 0.03);
  // with the lid, every tabulated kR and K R = 2.882: A33 within 3% (the
  // others printed: at kR = 3.5 NEMOH's own, lid-less, heave lies near its
  // irregular frequencies; docs/physics.md section 13)
  std::vector<double> kl = kr;
  kl.insert(kl.end() - 1, kKirr);
  double sec;
  HydroCoef lid = solveCyl(6, 10, 64, kl, true, &sec);
  std::printf("[panel] lid, 1024 + 640 panels, %.1f s: kR | A11 NEMOH | B11 NEMOH | A33 NEMOH | B33 NEMOH\n", sec);
  for (size_t w = 0; w < kl.size(); w++) {
    bool irr = std::fabs(kl[w] - kKirr) < 1e-9;
    double ref[4];
    if (irr) {
      ref[0] = kIrrA11, ref[1] = kIrrB11, ref[2] = kIrrA33, ref[3] = kIrrB33;
    } else {
      const NemohRow& r = nemohAt(kl[w]);
      ref[0] = r.A11, ref[1] = r.B11, ref[2] = r.A33, ref[3] = r.B33;
    }
    std::printf("[panel] lid %.3f | %.4f %.4f | %.4f %.4f | %.4f %.4f | %.4f %.4f\n", kl[w], coefA(lid, w, 0, 0), ref[0],
                coefB(lid, w, 0, 0), ref[1], coefA(lid, w, 2, 2), ref[2], coefB(lid, w, 2, 2), ref[3]);
    EXPECT_LT(relErr(coefA(lid, w, 2, 2), ref[2]), 0.03) << "lid kR " << kl[w];
    if (irr) {
      EXPECT_LT(relErr(coefB(lid, w, 2, 2), ref[3]), 0.03);
    }
  }
}

}  // namespace
