// the default frequency range from the panel resolution and the
// high-frequency tail of B in K(t) (docs/physics.md section 14, "Default
// frequencies" and "High-frequency tail")
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "floatbox.h"
#include "api/radattach.h"
#include "radiation/radiation.h"
#include "radiation/radtail.h"
#include "testutil.h"

namespace mjbt {
namespace {

// a box hull of half sizes hx hy hz and mass rho * wet volume (so it floats
// at draft T), free, radiation on, extra custom entries
std::string boxXML(double hx, double hy, double hz, double T, const std::string& extra) {
  char x[1024];
  std::snprintf(x, sizeof x, "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h\"/>"
                "<numeric name=\"mjbuoy.sea.density\" data=\"%g\"/>"
                "<text name=\"mjbuoy.radiation\" data=\"on\"/>%s</custom><worldbody>"
                "<body name=\"box\"><freejoint/><geom name=\"h\" type=\"box\" size=\"%g %g %g\" "
                "mass=\"%.17g\" contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>",
                kRho, extra.c_str(), hx, hy, hz, kRho * 4 * hx * hy * T);
  return x;
}

// A_ii(w) rebuilt from K_ii by Kramers-Kronig (Ogilvie 1964), A(w) = A_inf
// - (1/w) int_0^inf K(t) sin(w t) dt, trapezoid over 60 s at 2 ms;
// the largest |A_kk - A| / |A| over the table's frequencies
double kkError(const mjb::HydroCoef& c, int i, bool tail, std::string* rows) {
  const double dt = 0.002;
  const int n = 30001;
  std::vector<double> K(n);
  mjb::retardation(c, i, i, dt, n, K.data(), tail);
  double worst = 0;
  for (int f = 0; f < c.nw(); f++) {
    const double w = c.omega[f];
    double s = 0;
    for (int k = 0; k < n; k++) s += (k == 0 || k == n - 1 ? 0.5 : 1) * K[k] * std::sin(w * k * dt);
    const double A = c.Ainf[7 * i] - s * dt / w, a = c.A[36 * f + 7 * i];
    worst = std::max(worst, std::fabs(A - a) / std::fabs(a));
    char b[128];
    std::snprintf(b, sizeof b, " %.2f:%+.1f%%", w, 100 * (A - a) / a);
    *rows += b;
  }
  return worst;
}

TEST(RadAttach, DefaultRangeEndsWhereThePanelsResolveTheWave) {
  // the rule (docs/physics.md section 14, "Default frequencies"): k_max R
  // = min(5, max(1.5, k_h R)), k_h = 2 pi / (6 h), h the 90th-percentile
  // edge of the wet panels, R = sqrt(A_wp / pi); the range starts at kR =
  // 0.05. The box tessellation (hull.h kBoxDiv) splits each face in 4 x 4
  // rectangles of two triangles each, so the edges are known by hand:
  //
  // 1 m cube at draft 0.5: 0.25 m squares, 16 wet on the bottom and 8 on
  // each side: 96 triangles, 288 edges, of which 96 (a third) are the
  // diagonals 0.25 sqrt 2 = 0.35355 m: h = 0.35355, R = 1 / sqrt(pi) =
  // 0.56419 m, k_h R = 2 pi / (6 h) R = 1.6711, inside [1.5, 5].
  //
  // 1 x 1 x 2 m box at draft 1.5: sides 0.25 x 0.5 rectangles, 3 of 4 rows
  // wet: 96 side triangles (edges 0.5590, 0.5, 0.25, 96 each) and 32 bottom
  // triangles (32 diagonals 0.35355, 64 of 0.25): 384 edges, the longest
  // 96 (25%) are 0.5590 = h: k_h R = 1.0569, so the floor 1.5.
  struct Case { double hx, hy, hz, T, topkR; };
  const Case cases[] = {{0.5, 0.5, 0.5, 0.5, 2 * M_PI / (6 * 0.25 * std::sqrt(2.0)) / std::sqrt(M_PI)},
                        {0.5, 0.5, 1.0, 1.5, 1.5}};
  const double R = 1 / std::sqrt(M_PI);
  EXPECT_NEAR(cases[0].topkR, 1.6711, 1e-4);
  // refine 0 given: the edges above are the unrefined tessellation's (by
  // default the 1 x 1 x 2 m box's 0.56 m edges, above 2 pi R / 1.5 / 6 =
  // 0.39 m, would be refined once: docs/physics.md section 13, "Panel size")
  for (const Case& k : cases) {
    Scene s(boxXML(k.hx, k.hy, k.hz, k.T, "<numeric name=\"mjbuoy.radiation.refine\" data=\"0\"/>"));
    ASSERT_TRUE(s.ok()) << s.err;
    const mjb::Buoy* B = mjb::buoyOf(s.b);
    ASSERT_EQ(B->coef.size(), 1u);
    const mjb::HydroCoef& c = B->coef[0].second;
    ASSERT_EQ(c.nw(), 20);
    EXPECT_NEAR(c.omega[0], std::sqrt(kG * 0.05 / R), 1e-9 * c.omega[0]);
    EXPECT_NEAR(c.omega.back(), std::sqrt(kG * k.topkR / R), 1e-9 * c.omega.back()) << k.hz;
    // a physics consequence: potential flow radiates energy (B_ii >= 0),
    // and within the resolved range the coarse box's damping is positive
    // (no warning)
    EXPECT_EQ(std::string(mjb_warnings(s.b)), "") << k.hz;
  }
  char old[160];
  std::snprintf(old, sizeof old, "<numeric name=\"mjbuoy.radiation.omega\" data=\"%.17g %.17g 20\"/>",
                std::sqrt(kG * 0.05 / R), std::sqrt(kG * 5 / R));
  Scene s(boxXML(0.5, 0.5, 0.5, 0.5, old));
  ASSERT_TRUE(s.ok()) << s.err;
  const mjb::HydroCoef& c = mjb::buoyOf(s.b)->coef[0].second;
  double bmin = 1e300, bmax = 0;
  for (int w = 0; w < c.nw(); w++) {
    bmin = std::min(bmin, c.B[36 * w + 14]);
    bmax = std::max(bmax, c.B[36 * w + 14]);
  }
  // the old default range to kR = 5 runs into what the 0.25 m panels do not
  // resolve; with the rigid lid the cube's heave damping went negative
  // there (-7.5 N s/m at 8 rad/s, a warning), with the damped lid it stays
  // positive, as a body radiating energy must (measured 0.0073 to
  // 249 N s/m; docs/physics.md section 13)
  std::printf("cube, old range to kR = 5: heave B33 from %g to %g N s/m\n", bmin, bmax);
  EXPECT_GT(bmin, 0);
  EXPECT_EQ(std::string(mjb_warnings(s.b)).find("heave damping is -"), std::string::npos)
      << mjb_warnings(s.b);
  // the ceiling: panels fine enough for k_h R > 5 keep the range to kR = 5
  EXPECT_EQ(mjb::defaultTopKR(1.0, 0.1), 5.0);  // k_h R = 10.5
}

TEST(RadTail, ExponentialIntegralMatchesQuadrature) {
  // E_p(-i x) = int_1^inf u^-p e^{i x u} du (the tail's part of K, radtail.h)
  // against Simpson's rule on [1, 200] (200000 intervals) plus the
  // the remainder beyond, int_U^inf u^-p e^{ixu} du = e^{ixU} (i U^-p / x +
  // p U^-p-1 / x^2) + O(p^2 U^-p-2 / x^3) (by parts)
  for (double p : {2.0, 3.3, 8.0}) {
    for (double x : {0.3, 1.0, 5.0, 40.0}) {
      const double U = 200;
      const int n = 200000;
      const double h = (U - 1) / n;
      double sc = 0, ss = 0;
      for (int k = 0; k <= n; k++) {
        const double u = 1 + k * h, w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
        sc += w * std::pow(u, -p) * std::cos(x * u);
        ss += w * std::pow(u, -p) * std::sin(x * u);
      }
      const double a = std::pow(U, -p) / x, b = p * std::pow(U, -p - 1) / (x * x);
      sc = sc * h / 3 - a * std::sin(x * U) + b * std::cos(x * U);
      ss = ss * h / 3 + a * std::cos(x * U) + b * std::sin(x * U);
      double re, im;
      mjb::expintImag(p, x, &re, &im);
      EXPECT_NEAR(re, sc, 2e-6) << p << " " << x;
      EXPECT_NEAR(im, ss, 2e-6) << p << " " << x;
    }
    // x = 0: int_1^inf u^-p du
    double re, im;
    mjb::expintImag(p, 0, &re, &im);
    EXPECT_NEAR(re, 1 / (p - 1), 1e-15);
    EXPECT_EQ(im, 0);
  }
}

TEST(RadTail, KramersKronigHoldsWithTheDefaultRange) {
  // A(w) is the Hilbert transform of B(w) (Kramers-Kronig; Ogilvie 1964),
  // so the panel solver's own A(w) checks the retardation function built
  // from its B(w): A_inf - (1/w) int K sin(w t) dt must give A(w) back at
  // the table's frequencies. With the default range ending where the
  // panels resolve the wave (kR = 1.5 for both), the damping beyond it is
  // the power-law tail; without it the rebuilt A33 fell 4-54% short on the
  // barge and 10-150% on the cylinder (the log singularity at w_N). The
  // tail's exponent is fitted to this A (one number per dof, radtail.h), so
  // this checks that one exponent makes the relation hold at all 20
  // frequencies; the next test checks the tail against damping the panel
  // solver computed above w_N
  struct Case { const char* file; double tol33; };
  for (const Case& k : {Case{"barge.xml", 0.03}, Case{"cylinder.xml", 0.10}}) {
    Scene s(mjbt::shippedModel(k.file, ""));
    ASSERT_TRUE(s.ok()) << s.err;
    const mjb::HydroCoef& c = mjb::buoyOf(s.b)->coef[0].second;
    std::string r0, r1;
    const double e0 = kkError(c, 2, false, &r0), e1 = kkError(c, 2, true, &r1);
    double p[6];
    mjb::tailExponents(c, p);
    std::printf("[radtail] %s A33 by Kramers-Kronig, no tail (largest %.1f%%):%s\n"
                "[radtail] %s with the tail, p33 = %.2f (largest %.1f%%):%s\n", k.file, 100 * e0,
                r0.c_str(), k.file, p[2], 100 * e1, r1.c_str());
    EXPECT_LT(e1, k.tol33) << k.file;
    EXPECT_GT(e0, 0.2) << k.file;
  }
}

TEST(RadTail, TruncatedTableWithTheTailGivesTheFullTablesAddedMass) {
  // the 1 m cube of RadAttach's box decay (refine 1, 12 frequencies 0.9 to
  // 9 rad/s; tests/floatbox.h): the time-domain model built from its first
  // 6 frequencies (to 4.58 rad/s, kR = 1.2) with the tail against the one
  // built from all 12. In the time domain the added mass at frequency w is
  // A_inf - (1/w) int K sin(w t) dt (Cummins' equation in the frequency
  // domain; Ogilvie 1964): the truncated table's must be the full table's
  // at the truncated table's frequencies, which without the tail it is not
  // near its top (the missing damping's Hilbert transform)
  Scene s(floatingCubeXML());
  ASSERT_TRUE(s.ok()) << s.err;
  const mjb::HydroCoef& full = mjb::buoyOf(s.b)->coef[0].second;
  ASSERT_EQ(full.nw(), 12);
  mjb::HydroCoef cut = full;
  cut.omega.resize(6);
  cut.A.resize(36 * 6);
  cut.B.resize(36 * 6);
  const double dt = 0.002;
  const int n = 30001;
  std::vector<double> K(n), K0(n), K1(n);
  mjb::retardation(full, 2, 2, dt, n, K.data());
  mjb::retardation(cut, 2, 2, dt, n, K0.data(), false);
  mjb::retardation(cut, 2, 2, dt, n, K1.data());
  auto added = [&](const std::vector<double>& k, double w) {
    double sum = 0;
    for (int i = 0; i < n; i++) sum += (i == 0 || i == n - 1 ? 0.5 : 1) * k[i] * std::sin(w * i * dt);
    return full.Ainf[14] - sum * dt / w;
  };
  double e0 = 0, e1 = 0;
  for (int f = 0; f < cut.nw(); f++) {
    const double w = cut.omega[f], a = added(K, w), a0 = added(K0, w), a1 = added(K1, w);
    std::printf("[radtail] cube A33 at %.2f rad/s: full table %.2f, truncated %.2f (%+.1f%%), with the "
                "tail %.2f (%+.1f%%); panel %.2f\n", w, a, a0, 100 * (a0 - a) / a, a1,
                100 * (a1 - a) / a, full.A[36 * f + 14]);
    e0 = std::max(e0, std::fabs(a0 - a) / a);
    e1 = std::max(e1, std::fabs(a1 - a) / a);
  }
  EXPECT_LT(e1, 0.02);
  EXPECT_GT(e0, 0.1);
  // K itself: the tail puts back damping above 4.58 rad/s, but as a power
  // law, while the box's heave damping falls faster (exponentially with the
  // draft, section 14): K's early part is not the full table's, its L2
  // error still falls
  double l = 0, l0 = 0, l1 = 0;
  for (int i = 0; i < n; i++)
    l += K[i] * K[i], l0 += std::pow(K0[i] - K[i], 2), l1 += std::pow(K1[i] - K[i], 2);
  std::printf("[radtail] cube K33 from 6 of 12 frequencies: L2 error %.1f%% with the tail, %.1f%% "
              "without; K(0) %.1f, %.1f, full %.1f\n", 100 * std::sqrt(l1 / l), 100 * std::sqrt(l0 / l),
              K1[0], K0[0], K[0]);
  EXPECT_LT(l1, l0);
}

}  // namespace
}  // namespace mjbt
