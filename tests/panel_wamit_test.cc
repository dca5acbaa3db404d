// the panel solver against published coefficients of further bodies (issue
// 16, docs/physics.md section 13, "Second body, published: WAMIT's test
// runs"): the floating truncated vertical cylinder R = 1, T = 0.5 of WAMIT's
// standard test runs TEST01 and TEST11 and the rectangular barge of TEST16,
// deep water, against the output WAMIT Inc. distributes with the program.
// PanelWamit.* runs under label panel (opt-in; ctest -R panel.wamit).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "radiation/panel.h"
#include "radiation/panelmesh.h"

namespace {

using mjb::HydroCoef;
using mjb::PanelMesh;

const double kPi = 3.14159265358979323846;
const double kRho = 1000, kG = 9.80665;  // WAMIT's GRAV in test01.gdf
const double kR = 1, kT = 0.5;           // radius, draft [m]; length scale L = R = 1

// ---- published reference: WAMIT v7.0 standard test runs ----
// WAMIT User Manual, Version 7.0 (WAMIT Inc., Chestnut Hill MA, 2011-2013),
// section 2.4 and Appendix A.1 (TEST01) and A.11 (TEST11); the output files
// test01.out and test11*.out of WAMIT Version 7.0(x64), release 14 Nov 2011,
// run by WAMIT Inc. on 15 Nov 2011, as distributed with the program (copy:
// github.com/NREL/OpenWARP, commit f142b86, Contest_Output/Test_Case_
// Implementations/Part1/source/automated_test/testruns/out/). Cylinder R = 1,
// T = 0.5, infinite depth, g = 9.80665, origin and reference point at the
// centre of the waterplane, no irregular-frequency removal (IRR = 0).
// Non-dimensional as WAMIT prints them (L = 1): A_ij / (rho L^k),
// B_ij / (rho omega L^k), k = 3 for surge and heave, 4 for surge-pitch, 5 for
// pitch. Periods 8.971402, 2.006403, 1.003033 s: K R = 0.05, 1.0, 4.0.
//
// The reference is TEST11b: WAMIT's higher-order method (B-spline
// potential, exact analytic geometry) with the nonuniform mapping that
// concentrates the panels at the bottom edge, where the flow is singular.
// WAMIT's other runs of the same body (low-order TEST01 on 1024 flat panels;
// higher-order with uniform mapping TEST11a) lie on the same side of it in
// every entry, TEST01 farther, and their distance from it is the published
// data's own discretization spread (TEST01 printed by the test):
// at K R = 1 TEST01 is +1.1% (A11), +1.5% (B11), +1.7% (A33), -2.2% (B33),
// +5.6% (A55) off TEST11b, TEST11a +0.5%, +0.6%, +0.7%, -0.8%, +2.9%.
struct WamitRow {
  double T, A11, B11, A33, B33, A55, A15;
};
// TEST11b (test11b.out; it has the first two periods only)
const WamitRow kTest11b[] = {
    {8.971402, 6.651647e-01, 1.515983e-04, 2.468537e+00, 2.163333e-01, 2.091942e-01, -2.416116e-02},
    {2.006403, 8.405215e-01, 5.380348e-01, 1.530954e+00, 4.452222e-01, 2.083171e-01, -4.569027e-02}};
// TEST01 (test01.out, low-order, 1024 panels): printed for comparison
const WamitRow kTest01[] = {
    {8.971402, 6.733749e-01, 1.528948e-04, 2.488326e+00, 2.154611e-01, 2.205232e-01, -3.523300e-02},
    {2.006403, 8.499342e-01, 5.459198e-01, 1.557561e+00, 4.353419e-01, 2.200614e-01, -5.860385e-02},
    {1.003033, -6.674364e-02, 1.637410e-01, 1.662607e+00, 8.725705e-03, 2.411627e-01, -3.313469e-02}};
// K R = 4.0 (T = 1.003033 s) is at the first surge/pitch irregular frequency
// of the body, j11 coth(j11 T/R) = 4.001 (docs/physics.md section 13): with
// IRR = 0 WAMIT's surge and pitch there are spoiled (TEST01 A11 = -0.067,
// TEST11 B11 = -0.203 < 0) and not compared. Heave is axisymmetric and
// not affected; the reference is TEST11 (test11.out, higher-order, uniform
// mapping, the only higher-order run at this period): A33 = 1.648402,
// B33 = 9.757286e-03. TEST01 gives 1.662607 (+0.9%) and 8.725705e-03
// (-10.6%): the small damping at this K R is uncertain by about 11% in the
// published data itself.
const double kT4 = 1.003033, kA33at4 = 1.648402, kB33at4 = 9.757286e-03, kB33at4lo = 8.725705e-03;

// ---- helpers ----
HydroCoef solve(int nz, int nr, int na, const std::vector<double>& per, double* sec) {
  PanelMesh body, lid;
  mjb::cylinderMesh(kR, kT, nz, nr, na, &body, &lid);
  HydroCoef h;
  h.rho = kRho;
  h.g = kG;
  std::vector<double> om;
  for (double p : per) om.push_back(2 * kPi / p);
  std::string err;
  auto t0 = std::chrono::steady_clock::now();
  EXPECT_TRUE(mjb::panelSolve(body, PanelMesh(), om, {0.0}, &h, &err)) << err;
  *sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return h;
}
// WAMIT's non-dimensional coefficient (L = R = 1): the scale rho L^k
double scale(int i, int j) { return kRho * std::pow(kR, 3 + (i > 2) + (j > 2)); }
double coefA(const HydroCoef& h, int w, int i, int j) { return h.A[36 * w + 6 * i + j] / scale(i, j); }
double coefB(const HydroCoef& h, int w, int i, int j) {
  return h.B[36 * w + 6 * i + j] / (scale(i, j) * h.omega[w]);
}
double relErr(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

// surge, heave, pitch and the surge-pitch coupling at frequency w within
// tol of the row (B11 where it is not negligible, > 0.05 of A11; the
// coupling within tol of its natural scale sqrt(A11 A55))
void expectRow(const HydroCoef& h, int w, const WamitRow& r, double tol) {
  EXPECT_LT(relErr(coefA(h, w, 0, 0), r.A11), tol) << "T " << r.T << " A11 " << coefA(h, w, 0, 0);
  if (r.B11 > 0.05 * r.A11) {
    EXPECT_LT(relErr(coefB(h, w, 0, 0), r.B11), tol) << "T " << r.T << " B11 " << coefB(h, w, 0, 0);
  }
  EXPECT_LT(relErr(coefA(h, w, 2, 2), r.A33), tol) << "T " << r.T << " A33 " << coefA(h, w, 2, 2);
  EXPECT_LT(relErr(coefB(h, w, 2, 2), r.B33), tol) << "T " << r.T << " B33 " << coefB(h, w, 2, 2);
  EXPECT_LT(relErr(coefA(h, w, 4, 4), r.A55), tol) << "T " << r.T << " A55 " << coefA(h, w, 4, 4);
  EXPECT_LT(std::fabs(coefA(h, w, 0, 4) - r.A15), tol * std::sqrt(r.A11 * r.A55))
      << "T " << r.T << " A15 " << coefA(h, w, 0, 4);
}

// every entry expectRow checks is closer to the row on the fine mesh than
// on the coarse one
void expectConverging(const HydroCoef& coarse, const HydroCoef& fine, int w, const WamitRow& r) {
  const int ij[6][2] = {{0, 0}, {0, 0}, {2, 2}, {2, 2}, {4, 4}, {0, 4}};
  const double ref[6] = {r.A11, r.B11, r.A33, r.B33, r.A55, r.A15};
  for (int c = 0; c < 6; c++) {
    if (c == 1 && r.B11 <= 0.05 * r.A11) continue;
    auto get = [&](const HydroCoef& h) {
      return c == 1 || c == 3 ? coefB(h, w, ij[c][0], ij[c][1]) : coefA(h, w, ij[c][0], ij[c][1]);
    };
    EXPECT_LT(std::fabs(get(fine) - ref[c]), std::fabs(get(coarse) - ref[c])) << "T " << r.T << " entry " << c;
  }
}

void printRow(const char* name, const HydroCoef* h, int w, const WamitRow* r) {
  double v[6];
  if (h) {
    const double c[6] = {coefA(*h, w, 0, 0), coefB(*h, w, 0, 0), coefA(*h, w, 2, 2),
                         coefB(*h, w, 2, 2), coefA(*h, w, 4, 4), coefA(*h, w, 0, 4)};
    for (int k = 0; k < 6; k++) v[k] = c[k];
  } else {
    const double c[6] = {r->A11, r->B11, r->A33, r->B33, r->A55, r->A15};
    for (int k = 0; k < 6; k++) v[k] = c[k];
  }
  std::printf("[panel]   %-14s A11 %.5g B11 %.5g A33 %.5g B33 %.5g A55 %.5g A15 %.5g\n", name, v[0], v[1], v[2],
              v[3], v[4], v[5]);
}

// ---- the test (label panel) ----

// meshes 3 x 5 x 32 and 6 x 10 x 64 (256 and 1024 panels, TEST01's count),
// no lid, at WAMIT's three periods (about 4 s in Release). At K R = 0.05 and
// 1 on 1024 panels: surge, heave, pitch and the coupling within 3% of
// TEST11b, and every one of these entries closer to it than on 256 panels
// (convergence toward the published value). At K R = 4 (1024 panels): A33
// within 3% of TEST11, B33 within 14% (the 11% spread of the published runs
// themselves, above, plus 3%); surge and pitch, spoiled here in ours too (no
// lid), are printed only.
TEST(PanelWamit, Cylinder) {
  const std::vector<double> per = {kTest11b[0].T, kTest11b[1].T, kT4};
  const int res[2][3] = {{3, 5, 32}, {6, 10, 64}};
  const char* name[2] = {"ours 256", "ours 1024"};
  std::vector<HydroCoef> hs;
  for (auto& m : res) {
    double sec;
    hs.push_back(solve(m[0], m[1], m[2], per, &sec));
    std::printf("[panel] cylinder %d x %d x %d: %d panels, %.1f s for %d periods\n", m[0], m[1], m[2],
                (m[0] + m[1]) * m[2], sec, (int)per.size());
  }
  for (int w = 0; w < 3; w++) {
    std::printf("[panel] T %.6f s, K R %.4f (WAMIT units: A / (rho L^k), B / (rho omega L^k))\n", per[w],
                hs[0].omega[w] * hs[0].omega[w] / kG * kR);
    for (int m = 0; m < 2; m++) printRow(name[m], &hs[m], w, nullptr);
    if (w < 2) printRow("WAMIT TEST11b", nullptr, 0, &kTest11b[w]);
    printRow("WAMIT TEST01", nullptr, 0, &kTest01[w]);
  }
  std::printf("[panel] K R 4: WAMIT TEST11 A33 %.4f B33 %.4e (TEST01 B33 %.4e)\n", kA33at4, kB33at4, kB33at4lo);
  for (int w = 0; w < 2; w++) {
    expectRow(hs[1], w, kTest11b[w], 0.03);
    expectConverging(hs[0], hs[1], w, kTest11b[w]);
  }
  EXPECT_LT(relErr(coefA(hs[1], 2, 2, 2), kA33at4), 0.03) << coefA(hs[1], 2, 2, 2);
  EXPECT_LT(relErr(coefB(hs[1], 2, 2, 2), kB33at4), 0.14) << coefB(hs[1], 2, 2, 2);
}

// ---- a box: WAMIT's TEST16 barge ----
// WAMIT User Manual v7.0, Appendix A.16 (TEST16, TEST16a), test16.out and
// test16a.out of the same distribution and copy as above: a rectangular
// barge of length 80, beam 10 and draft 5 (half-length 40, half-beam 5),
// infinite depth, g = 9.80665, rho = 1000, reference point at the centre of
// the waterplane, higher-order method on three patches (TEST16: the exact
// geometry of WAMIT's BARGE subroutine; TEST16a: flat patches; 116 unknowns,
// the two agree to 2e-5), IRR = 0, periods 7 and 8 s (K x 40 = 3.29 and
// 2.52). The barge's first irregular frequency, K = k coth(k T) with
// k^2 = (pi/80)^2 + (pi/10)^2, is 0.344 /m, far above K = 0.082 and 0.063.
// Non-dimensional as WAMIT prints them (L = 1 m): A / (rho L^k),
// B / (rho omega L^k). TEST16 also has 8 beam modes, whose coupling does not
// enter the rigid-body coefficients (each radiation problem is solved alone).
const WamitRow kTest16[] = {
    {8.0, 3.791854e+02, 1.156354e+02, 3.470387e+03, 2.582374e+03, 2.187064e+06, 2.071857e+03},
    {7.0, 3.949287e+02, 1.177771e+02, 3.197451e+03, 1.882760e+03, 1.830896e+06, -1.314530e+03}};
const double kBa = 40, kBb = 5, kBt = 5;  // half-length, half-beam, draft [m]

// adds the grid of nu x nv panels spanning o + s u + t v (s, t in [0, 1]),
// each reversed when its normal points against out (normals out of the body)
void addGrid(PanelMesh* m, const double o[3], const double u[3], const double v[3], int nu, int nv,
             const double out[3]) {
  int base = (int)m->vert.size() / 3;
  for (int j = 0; j <= nv; j++)
    for (int i = 0; i <= nu; i++)
      for (int k = 0; k < 3; k++) m->vert.push_back(o[k] + u[k] * i / nu + v[k] * j / nv);
  double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  bool flip = n[0] * out[0] + n[1] * out[1] + n[2] * out[2] < 0;
  for (int j = 0; j < nv; j++)
    for (int i = 0; i < nu; i++) {
      int a = base + j * (nu + 1) + i, b = a + 1, c = b + nu + 1, d = a + nu + 1;
      if (flip) std::swap(b, d);
      for (int q : {a, b, c, d}) m->face.push_back(q);
    }
}

// the wetted box: nx panels along the length, ny across, nz down
PanelMesh boxMesh(int nx, int ny, int nz) {
  PanelMesh m;
  const double a = kBa, b = kBb, t = kBt;
  for (int s : {-1, 1}) {
    const double o1[3] = {-a, s * b, -t}, u1[3] = {2 * a, 0, 0}, v1[3] = {0, 0, t}, n1[3] = {0, (double)s, 0};
    addGrid(&m, o1, u1, v1, nx, nz, n1);  // sides
    const double o2[3] = {s * a, -b, -t}, u2[3] = {0, 2 * b, 0}, v2[3] = {0, 0, t}, n2[3] = {(double)s, 0, 0};
    addGrid(&m, o2, u2, v2, ny, nz, n2);  // ends
  }
  const double o3[3] = {-a, -b, -t}, u3[3] = {2 * a, 0, 0}, v3[3] = {0, 2 * b, 0}, n3[3] = {0, 0, -1};
  addGrid(&m, o3, u3, v3, nx, ny, n3);  // bottom
  return m;
}

// meshes 40 x 5 x 3 (470 panels of 2 m x 2 m x 1.67 m) and 80 x 10 x 6
// (1880), uniform, no lid, at TEST16's two periods (about 8 s in Release).
// On 1880 panels surge, heave, pitch and the coupling within 3% of TEST16,
// and each closer to it than on 470 panels
TEST(PanelWamit, Barge) {
  const int res[2][3] = {{40, 5, 3}, {80, 10, 6}};
  std::vector<HydroCoef> hs;
  for (auto& m : res) {
    HydroCoef h;
    h.rho = kRho;
    h.g = kG;
    std::vector<double> om = {2 * kPi / kTest16[0].T, 2 * kPi / kTest16[1].T};
    std::string err;
    PanelMesh body = boxMesh(m[0], m[1], m[2]);
    auto t0 = std::chrono::steady_clock::now();
    EXPECT_TRUE(mjb::panelSolve(body, PanelMesh(), om, {0.0}, &h, &err)) << err;
    double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("[panel] barge %d x %d x %d: %d panels, %.1f s for 2 periods\n", m[0], m[1], m[2], body.nface(), sec);
    hs.push_back(h);
  }
  for (int w = 0; w < 2; w++) {
    std::printf("[panel] barge T %.1f s (WAMIT units)\n", kTest16[w].T);
    printRow("ours 470", &hs[0], w, nullptr);
    printRow("ours 1880", &hs[1], w, nullptr);
    printRow("WAMIT TEST16", nullptr, 0, &kTest16[w]);
  }
  for (int w = 0; w < 2; w++) {
    expectRow(hs[1], w, kTest16[w], 0.03);
    expectConverging(hs[0], hs[1], w, kTest16[w]);
  }
}

}  // namespace
