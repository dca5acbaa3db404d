// hydrodynamic interaction: a group of bodies solved as one panel problem
// (panelSolveGroup, docs/physics.md section 13, "Interaction"), against
// Green's-theorem reciprocity, energy conservation (Haskind's relation for
// the whole group), the wide-spacing limit of two heaving bodies and the
// single-body solve at growing separation
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "radiation/panel.h"
#include "radiation/panelmesh.h"

namespace {

using mjb::HydroCoef;
using mjb::PanelGroupCoef;
using mjb::PanelMesh;

const double kPi = 3.14159265358979323846;
const double kRho = 1000, kG = 9.81;

// mesh m moved horizontally by (dx, dy) [m]
PanelMesh moved(PanelMesh m, double dx, double dy) {
  for (size_t i = 0; i < m.vert.size(); i += 3) m.vert[i] += dx, m.vert[i + 1] += dy;
  return m;
}

// truncated cylinders (radius 1 m, draft 1 m, 4 x 3 x 16 panels, lids) at
// horizontal positions xy (2 per body), refs on their axes at the waterline
PanelGroupCoef solveCylinders(const std::vector<double>& xy, const std::vector<double>& om,
                              const std::vector<double>& head) {
  PanelMesh b, l;
  mjb::cylinderMesh(1, 1, 4, 3, 16, &b, &l);
  PanelGroupCoef g;
  g.rho = kRho;
  g.g = kG;
  std::vector<PanelMesh> bs, ls;
  for (size_t k = 0; k < xy.size() / 2; k++) {
    bs.push_back(moved(b, xy[2 * k], xy[2 * k + 1]));
    ls.push_back(moved(l, xy[2 * k], xy[2 * k + 1]));
    g.ref.insert(g.ref.end(), {xy[2 * k], xy[2 * k + 1], 0.0});
  }
  std::string err;
  EXPECT_TRUE(mjb::panelSolveGroup(bs, ls, om, head, &g, &err)) << err;
  return g;
}

// one such cylinder alone (panelSolve), ref at the origin, into one; ""
// or the solver's error
std::string solveCylinder(const std::vector<double>& om, const std::vector<double>& head,
                          HydroCoef* one) {
  PanelMesh b, l;
  mjb::cylinderMesh(1, 1, 4, 3, 16, &b, &l);
  one->rho = kRho;
  one->g = kG;
  std::string err;
  if (mjb::panelSolve(b, l, om, head, one, &err)) return "";
  return err.empty() ? "panelSolve failed without a message" : err;
}

typedef Eigen::MatrixXd Mat;

Mat block(const std::vector<double>& v, int nm, int w) {
  return Eigen::Map<const Eigen::Matrix<double, -1, -1, Eigen::RowMajor>>(&v[nm * nm * w], nm, nm);
}

// reciprocity (Green's second identity on the radiation potentials of two
// modes, e.g. Newman 1977 "Marine Hydrodynamics" section 6.13; Falnes 2002
// "Ocean Waves and Oscillating Systems" section 5.2): A_ij = A_ji^T and
// B_ij = B_ji^T between the bodies' 6x6 blocks, so A and B are symmetric;
// energy (radiated power >= 0): B positive semi-definite. Two cylinders at
// a general placement (no mirror plane through both), 1.5 m gap; the
// collocation method satisfies reciprocity to the discretisation error
// (Panel.AsymmetricHullSymmetricAndDissipative: 2%)
TEST(PanelGroup, TwoCylindersReciprocalAndDissipative) {
  PanelGroupCoef g = solveCylinders({0, 0, 3.0, 1.2}, {0.8, 1.5, 3.0}, {});
  int nm = g.nm();
  ASSERT_EQ(nm, 12);
  for (int w = 0; w < (int)g.omega.size(); w++) {
    for (const std::vector<double>* m : {&g.A, &g.B}) {
      Mat a = block(*m, nm, w);
      Mat a12 = a.block(0, 6, 6, 6), a21 = a.block(6, 0, 6, 6);
      double e = (a12 - a21.transpose()).norm() / a12.norm();
      std::printf("[group] omega %.2f |%s12 - %s21^T| / |%s12| = %.4f, |%s12| / |%s11| = %.3f\n",
                  g.omega[w], m == &g.A ? "A" : "B", m == &g.A ? "A" : "B", m == &g.A ? "A" : "B",
                  e, m == &g.A ? "A" : "B", m == &g.A ? "A" : "B",
                  a12.norm() / a.block(0, 0, 6, 6).norm());
      EXPECT_LT(e, 0.03) << "omega " << g.omega[w];
      EXPECT_LT((a - a.transpose()).norm() / a.norm(), 0.02) << "omega " << g.omega[w];
    }
    Mat bm = block(g.B, nm, w);
    Eigen::SelfAdjointEigenSolver<Mat> es(0.5 * (bm + bm.transpose()));
    EXPECT_GT(es.eigenvalues().minCoeff(), -1e-3 * es.eigenvalues().maxCoeff()) << g.omega[w];
  }
  Mat ai = Eigen::Map<const Eigen::Matrix<double, -1, -1, Eigen::RowMajor>>(g.Ainf.data(), nm, nm);
  EXPECT_LT((ai.block(0, 6, 6, 6) - ai.block(6, 0, 6, 6).transpose()).norm() /
                ai.block(0, 6, 6, 6).norm(), 0.03);
}

// Haskind's relation for the whole group (energy: the power radiated by
// any combination of modes equals the flux of its far field, which the
// exciting forces give; Newman 1962, J. Ship Res. 6(3):10-17; Falnes 2002
// section 5.6 for arrays): B_ij = omega k / (4 pi rho g^2) Re int_0^2pi
// X_i X_j^* dbeta for every mode pair of both bodies, X from the
// diffraction solves, B from the radiation solves; trapezoid rule on 72
// headings; within 3% of sqrt(B_ii B_jj) (the coarse mesh's error)
TEST(PanelGroup, TwoCylindersHaskind) {
  const int nh = 72;
  std::vector<double> head;
  for (int i = 0; i < nh; i++) head.push_back(2 * kPi * i / nh);
  PanelGroupCoef g = solveCylinders({0, 0, 3.0, 1.2}, {3.0}, head);
  int nm = g.nm();
  double om = g.omega[0], k = om * om / kG, c = om * k / (4 * kPi * kRho * kG * kG);
  Mat b = block(g.B, nm, 0);
  std::printf("[group] B diagonal:");
  for (int i = 0; i < nm; i++) std::printf(" %.4g", b(i, i));
  std::printf("\n");
  double worst = 0;
  for (int i = 0; i < nm; i++)
    for (int j = 0; j < nm; j++) {
      double scale = std::sqrt(b(i, i) * b(j, j));
      // yaw of a cylinder radiates no waves (B_ii 1e-30)
      if (!(scale > 1e-3 * b.diagonal().maxCoeff())) continue;
      double s = 0;
      for (int h = 0; h < nh; h++) {
        int o = nm * h;
        s += g.Xre[o + i] * g.Xre[o + j] + g.Xim[o + i] * g.Xim[o + j];
      }
      s *= c * 2 * kPi / nh;
      double e = std::fabs(s - b(i, j)) / scale;
      worst = std::fmax(worst, e);
      EXPECT_LT(e, 0.03) << "mode " << i << ", " << j << ": B " << b(i, j) << " Haskind " << s;
    }
  std::printf("[group] Haskind worst |B_ij - Haskind| / sqrt(B_ii B_jj) %.4f\n", worst);
}

// growing separation d along x (omega 1.5 rad/s, k = 0.229 /m): body 1's
// own block returns to the single cylinder's (panelSolve), within 1% of
// the block's largest entry at d = 160 m (kd = 37; the wave scattered back
// by body 2 decays like 1/(kd)), the exciting force within 1% of its heave
// at d = 640 m (body 2's scattered wave reaches body 1 once: 1/sqrt(kd)); and the heave coupling approaches the
// wide-spacing (point-absorber) limit B_{3,9} = B_33 J0(kd) (Budal 1977,
// J. Ship Res. 21(4):248-253; Evans 1979 in "Power from Sea Waves";
// Falnes 2002 section 5.6: two bodies that radiate as if alone) within
// 0.03 B_33 (the scattering correction, O(kR / sqrt(kd)))
TEST(PanelGroup, SeparationReturnsToSingleBody) {
  const double om = 1.5, k = om * om / kG;
  HydroCoef one;
  ASSERT_EQ(solveCylinder({om}, {0.0}, &one), "");
  Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>> a1(one.A.data()), b1(one.B.data());
  double prev = 1e300;
  for (double d : {10.0, 40.0, 160.0, 640.0}) {
    PanelGroupCoef g = solveCylinders({0, 0, d, 0}, {om}, {0.0});
    Mat a = block(g.A, 12, 0), bb = block(g.B, 12, 0);
    double ea = (a.block(0, 0, 6, 6) - a1).cwiseAbs().maxCoeff() / a1.cwiseAbs().maxCoeff();
    double eb = (bb.block(0, 0, 6, 6) - b1).cwiseAbs().maxCoeff() / b1.cwiseAbs().maxCoeff();
    double x = 0;
    for (int i = 0; i < 6; i++)
      x = std::fmax(x, std::hypot(g.Xre[i] - one.Xre[i], g.Xim[i] - one.Xim[i]));
    double ex = x / std::hypot(one.Xre[2], one.Xim[2]);
    double j0 = std::cyl_bessel_j(0.0, k * d), r = bb(2, 8) / b1(2, 2);
    std::printf("[group] d %5.0f m kd %5.1f: A11 %.4f B11 %.4f X1 %.4f off single; "
                "B39 / B33 %.4f, J0(kd) %.4f\n", d, k * d, ea, eb, ex, r, j0);
    if (d > 100) {
      EXPECT_LT(ea, 0.01);
      EXPECT_LT(eb, 0.01);
    }
    if (d > 500) {
      EXPECT_LT(ex, 0.01);
    }
    if (d > 30) {
      EXPECT_NEAR(r, j0, 0.03);
    }
    EXPECT_LT(std::fmax(ea, eb), prev * 1.5);  // decays (within the 1/kd oscillation)
    prev = std::fmax(ea, eb);
  }
}

// bad input names the body and the entry
TEST(PanelGroup, BadInputIsNamed) {
  PanelMesh b, l;
  mjb::cylinderMesh(1, 1, 2, 1, 8, &b, &l);
  PanelGroupCoef g;
  g.ref = {0, 0, 0};
  std::string err;
  EXPECT_FALSE(mjb::panelSolveGroup({b, moved(b, 4, 0)}, {l, l}, {1.0}, {}, &g, &err));
  EXPECT_NE(err.find("3 ref coordinates per body"), std::string::npos) << err;
  g.ref = {0, 0, 0, 4, 0, 0};
  PanelMesh bad = moved(b, 4, 0);
  bad.face[1] = 100000;
  EXPECT_FALSE(mjb::panelSolveGroup({b, bad}, {l, moved(l, 4, 0)}, {1.0}, {}, &g, &err));
  EXPECT_NE(err.find("group body 1: panel body face 0"), std::string::npos) << err;
  EXPECT_FALSE(mjb::panelSolveGroup({b, moved(b, 4, 0)}, {l, moved(l, 4, 0)}, {}, {}, &g, &err));
  EXPECT_NE(err.find("no frequencies"), std::string::npos) << err;
}

// two equal cylinders on the x axis: the union is mirror-symmetric about
// y = 0 and about the plane between them, which swaps the bodies; the
// reduced solve (panel.cc groupSolve) must give the full system's
// coefficients (the reduction is exact: M(g i, g j) = M(i, j)), and the
// swap maps body 1's block to body 2's with x and the moments about z and
// y mirrored (surge, roll, yaw change sign with x -> -x: for modes a, b,
// A_2a2b = s_a s_b A_1a1b, s = (-1, 1, 1, 1, -1, -1))
TEST(PanelGroup, MirrorPairMatchesFullSolve) {
  auto run = [](bool sym) {
    mjb::panelSymmetryUse(sym);
    PanelGroupCoef g = solveCylinders({0, 0, 3.5, 0}, {1.0, 2.5}, {0.4});
    mjb::panelSymmetryUse(true);
    return g;
  };
  // the union has both mirrors (else the comparison below compares the
  // full solve with itself)
  PanelMesh b, l, u;
  mjb::cylinderMesh(1, 1, 4, 3, 16, &b, &l);
  for (const PanelMesh& m : {b, moved(b, 3.5, 0)}) {
    int v0 = (int)u.vert.size() / 3;
    u.vert.insert(u.vert.end(), m.vert.begin(), m.vert.end());
    for (int i : m.face) u.face.push_back(i < 0 ? i : i + v0);
  }
  EXPECT_EQ(mjb::panelMirrors(u, PanelMesh()), 3);
  PanelGroupCoef r = run(true), f = run(false);
  double amax = 0, bmax = 0;
  for (double a : f.A) amax = std::fmax(amax, std::fabs(a));
  for (double b : f.B) bmax = std::fmax(bmax, std::fabs(b));
  for (size_t i = 0; i < f.A.size(); i++) {
    EXPECT_NEAR(r.A[i], f.A[i], 1e-8 * amax) << i;
    EXPECT_NEAR(r.B[i], f.B[i], 1e-8 * bmax) << i;
  }
  for (size_t i = 0; i < f.Xre.size(); i++) EXPECT_NEAR(r.Xre[i], f.Xre[i], 1e-6 * amax) << i;
  const double sg[6] = {-1, 1, 1, 1, -1, -1};
  for (int w = 0; w < 2; w++) {
    Mat a = block(f.A, 12, w);
    for (int i = 0; i < 6; i++)
      for (int j = 0; j < 6; j++)
        EXPECT_NEAR(a(6 + i, 6 + j), sg[i] * sg[j] * a(i, j), 0.01 * a.cwiseAbs().maxCoeff());
  }
}

// panelGroupBody: a body far from the other (640 m at 30 degrees, kd = 147
// at omega 1.5 rad/s) has the single body's coefficients, its exciting
// force referred to its own position (amplitude at its ref: the phase
// factor e^{-i k D . r}), within 1% of the largest entry at two headings
TEST(PanelGroup, FarBodyIsTheSingleBody) {
  const double om = 1.5, d = 640, c = std::cos(kPi / 6), s = std::sin(kPi / 6);
  HydroCoef one;
  ASSERT_EQ(solveCylinder({om}, {0.0, 0.7}, &one), "");
  PanelGroupCoef g = solveCylinders({0, 0, d * c, d * s}, {om}, {0.0, 0.7});
  HydroCoef two;
  ASSERT_TRUE(mjb::panelGroupBody(g, 1, &two));
  EXPECT_FALSE(mjb::panelGroupBody(g, 2, &two));
  ASSERT_TRUE(mjb::panelGroupBody(g, 1, &two));
  EXPECT_DOUBLE_EQ(two.ref[0], d * c);
  auto maxAbs = [](const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::fmax(m, std::fabs(x));
    return m;
  };
  for (int i = 0; i < 36; i++) {
    EXPECT_NEAR(two.A[i], one.A[i], 0.01 * maxAbs(one.A)) << i;
    EXPECT_NEAR(two.B[i], one.B[i], 0.01 * maxAbs(one.B)) << i;
    EXPECT_NEAR(two.Ainf[i], one.Ainf[i], 0.01 * maxAbs(one.A)) << i;
  }
  double xm = std::fmax(maxAbs(one.Xre), maxAbs(one.Xim)), worst = 0;
  for (size_t i = 0; i < one.Xre.size(); i++) {
    double e = std::hypot(two.Xre[i] - one.Xre[i], two.Xim[i] - one.Xim[i]) / xm;
    worst = std::fmax(worst, e);
    EXPECT_LT(e, 0.01) << i;
    EXPECT_LT(std::hypot(two.FKre[i] - one.FKre[i], two.FKim[i] - one.FKim[i]), 1e-6 * xm) << i;
  }
  std::printf("[group] far body: worst |X - X_single| / max |X| %.4f\n", worst);
}

}  // namespace
