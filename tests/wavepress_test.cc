// linear wave kinematics and pressure (docs/physics.md, "Linear wave
// kinematics and pressure") against closed forms of linear theory
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sea/sea.h"
#include "testutil.h"
#include "hull/wavepress.h"

namespace mjbt {
namespace {

mjb::Sea airySea(double amp, double len, double depth) {
  mjb::Sea s;
  s.depth = depth;
  mjb::Wave w{amp, len, 0, 0, 0, 0, 0, 0, 0, 0};
  w.kind = 1;
  s.waves.push_back(w);
  s.derive();
  return s;
}

// Airy velocity, acceleration and dynamic pressure under crest, trough and
// node against Dean & Dalrymple (1991) eqs. 4.31-4.35 (finite depth; deep:
// Newman 1977 sec. 6.2), Wheeler (1970) stretched to the local surface eta:
// s = k (z' + h), z' + h = (z + h) h / (h + eta) (deep: z' = z - eta);
// u = A w cosh s / sinh kh cos th, w = A w sinh s / sinh kh sin th,
// du/dt = A w^2 cosh s / sinh kh sin th, dw/dt = -A w^2 sinh s / sinh kh cos th,
// p_d = rho g A cosh s / cosh kh cos th, with w^2 = g k tanh kh
TEST(WaveKinematics, AiryUnderCrestTroughAndNode) {
  const double A = 0.1, L = 10, k = 2 * M_PI / L, z = -1;
  for (double h : {0.0, 4.0}) {
    mjb::Sea s = airySea(A, L, h);
    const double om = std::sqrt(kG * k * (h > 0 ? std::tanh(k * h) : 1));
    for (double x : {0.0, L / 4, L / 2}) {  // crest, node, trough at t = 0
      const double th = k * x, eta = A * std::cos(th);
      double fch, fsh, fcc;
      if (h > 0) {
        double sg = k * (z + h) * h / (h + eta);
        fch = std::cosh(sg) / std::sinh(k * h);
        fsh = std::sinh(sg) / std::sinh(k * h);
        fcc = std::cosh(sg) / std::cosh(k * h);
      } else {
        fch = fsh = fcc = std::exp(k * (z - eta));
      }
      double p[3] = {x, 0, z}, v[3], a[3];
      s.velocity(p, 0, v, a);
      const double tol = 1e-12;
      EXPECT_NEAR(v[0], A * om * fch * std::cos(th), tol) << h << " " << x;
      EXPECT_NEAR(v[1], 0, tol);
      EXPECT_NEAR(v[2], A * om * fsh * std::sin(th), tol) << h << " " << x;
      EXPECT_NEAR(a[0], A * om * om * fch * std::sin(th), tol) << h << " " << x;
      EXPECT_NEAR(a[2], -A * om * om * fsh * std::cos(th), tol) << h << " " << x;
      EXPECT_NEAR(s.dynamic(p, 0), kRho * kG * A * fcc * std::cos(th), 1e-9) << h << " " << x;
      EXPECT_NEAR(mjb::Sea(s).height(x, 0, 0), eta, 1e-15);
    }
    // p = 0 at the instantaneous surface: rho g (level - eta) + p_d(eta) = 0
    for (double x : {0.0, 1.3, L / 2}) {
      double p[3] = {x, 0, s.height(x, 0, 0)};
      EXPECT_NEAR(kRho * kG * (0 - p[2]) + s.dynamic(p, 0), 0, 1e-9) << h << " " << x;
    }
  }
}

// overflow: cosh(k h) is inf past k h = 710; at k h = 1e4 and 1e6 the
// finite-depth profiles must be finite and (under a node, eta = 0, where
// Wheeler does not stretch) equal the deep-water ones (tanh(kh) = 1)
TEST(WaveKinematics, FiniteDepthSafeAtAnyDepth) {
  const double L = 1, k = 2 * M_PI / L;
  mjb::Sea deep = airySea(0.05, L, 0);
  for (double kh : {1e4, 1e6}) {
    mjb::Sea fin = airySea(0.05, L, kh / k);
    for (double z : {0.0, -0.1, -1.0, -50.0}) {
      double p[3] = {L / 4, 0, z}, vd[3], ad[3], vf[3], af[3];
      deep.velocity(p, 0, vd, ad);
      fin.velocity(p, 0, vf, af);
      for (int j = 0; j < 3; j++) {
        ASSERT_TRUE(std::isfinite(vf[j]) && std::isfinite(af[j]));
        EXPECT_NEAR(vf[j], vd[j], 1e-12 * (1 + std::fabs(vd[j])));
        EXPECT_NEAR(af[j], ad[j], 1e-12 * (1 + std::fabs(ad[j])));
      }
      EXPECT_NEAR(fin.dynamic(p, 0), deep.dynamic(p, 0), 1e-9);
    }
  }
}

// Gerstner steepness shapes the crest but not how fast the water moves:
// under the crest (label 0, at x = 0 for any Q) the horizontal velocity is
// A w e^{k (z - A)} for Q = 0 and Q = 0.8 alike (linear theory, Newman
// 1977 sec. 6.2, Wheeler stretched); before this, Q = 0 gave u = 0
TEST(WaveKinematics, SteepnessDoesNotChangeTheVelocity) {
  const double A = 0.1, L = 10, k = 2 * M_PI / L, om = std::sqrt(kG * k), z = -0.5;
  for (double q : {0.0, 0.8}) {
    mjb::Sea s;
    s.waves.push_back(mjb::Wave{A, L, 0, 0, q, 0, 0, 0, 0, 0});
    s.derive();
    double p[3] = {0, 0, z}, v[3];
    s.velocity(p, 0, v);
    EXPECT_NEAR(v[0], A * om * std::exp(k * (z - A)), 1e-12) << q;
    EXPECT_NEAR(v[2], 0, 1e-12) << q;
  }
}

// mixed sea: a Gerstner component (its label a lands at x = a - Q A sin th)
// plus an Airy one summed at the physical point: mjb_seaHeight returns
// A1 cos th1(a) + A2 cos th2(x), the surface the physics cuts hulls with
TEST(WaveKinematics, SeaHeightOfAMixedSea) {
  Scene s("<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h\"/>"
          "<numeric name=\"mjbuoy.wave.g\" data=\"0.3 12 0 20 0.7\"/>"
          "<numeric name=\"mjbuoy.airy.a\" data=\"0.2 7 30 -40\"/>"
          "<numeric name=\"mjbuoy.sea.ramp\" data=\"0\"/></custom>"
          "<worldbody><body><freejoint/><geom name=\"h\" type=\"box\" size=\"1 1 1\"/>"
          "</body></worldbody></mujoco>");
  ASSERT_TRUE(s.ok()) << s.err;
  const double k1 = 2 * M_PI / 12, k2 = 2 * M_PI / 7, t = 3.3;
  const double w1 = std::sqrt(kG * k1), w2 = std::sqrt(kG * k2), d = M_PI / 180;
  for (double a : {-4.0, 0.0, 1.7, 5.2}) {
    double th1 = k1 * a - w1 * t + 20 * d;
    double x = a - 0.7 * 0.3 * std::sin(th1), y = 0.9;
    double th2 = k2 * (std::cos(30 * d) * x + std::sin(30 * d) * y) - w2 * t - 40 * d;
    EXPECT_NEAR(mjb_seaHeight(s.b, x, y, t), 0.3 * std::cos(th1) + 0.2 * std::cos(th2), 1e-9);
  }
}

// vertical pressure force on body b at time t (mj_forward runs the callback)
double heave(Scene& s, int b, double t) {
  s.d->time = t;
  mj_forward(s.m, s.d);
  return mjb_wrenchPart(s.b, s.d, mjbPART_PRESSURE)[6 * b + 2];
}

std::string boxScene(double hx, double hy, double hz, double zc, const std::string& sea) {
  std::ostringstream o;
  o.precision(17);
  // no start-up ramp: the analytic Froude-Krylov force of the full wave at any t
  o << "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h\"/>" << sea
    << "<numeric name=\"mjbuoy.sea.ramp\" data=\"0\"/></custom>"
    << "<worldbody><body name=\"b\" pos=\"0 0 " << zc << "\"><freejoint/>"
    << "<geom name=\"h\" type=\"box\" size=\"" << hx << " " << hy << " " << hz
    << "\" contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>";
  return o.str();
}

// Froude-Krylov force on a small submerged body (Newman 1977 sec. 4.16;
// Faltinsen 1990 sec. 3.2): F = -integral(p n dS) = -integral(grad p dV)
// = rho V (g + a_z) vertically, a_z the undisturbed water acceleration at
// its centre: heave amplitude rho V g k A e^{-kd} (deep) and
// rho V g k A sinh(k (h - d)) / cosh(k h) (depth h; Dean & Dalrymple 1991).
// A 0.2 m cube at d = 1 m under a 10 m wave (k a = 0.13: finite-size
// corrections (k a)^2 / 24 < 0.1%), A = 2 mm (Wheeler's e^{-k eta} < 0.2%).
// backend: custom entries that pick it; A: wave amplitude [m]; checkMean:
// also the mean force, rho g V
void cubeFroudeKrylov(const std::string& backend, double A, bool checkMean) {
  const double L = 10, k = 2 * M_PI / L, d = 1, V = 0.2 * 0.2 * 0.2;
  for (double h : {0.0, 3.0}) {
    std::ostringstream sea;
    sea << backend << "<numeric name=\"mjbuoy.airy.a\" data=\"" << A << " " << L << " 0 0\"/>";
    if (h > 0) sea << "<numeric name=\"mjbuoy.sea.depth\" data=\"" << h << "\"/>";
    Scene s(boxScene(0.1, 0.1, 0.1, -d, sea.str()));
    ASSERT_TRUE(s.ok()) << s.err;
    const int b = s.body("b");
    const double om = std::sqrt(kG * k * (h > 0 ? std::tanh(k * h) : 1));
    // crest above the centre at t = 0, trough at half a period
    double fc = heave(s, b, 0), ft = heave(s, b, M_PI / om);
    double amp = 0.5 * (ft - fc), mean = 0.5 * (ft + fc);
    double want = kRho * V * kG * k * A *
                  (h > 0 ? std::sinh(k * (h - d)) / std::cosh(k * h) : std::exp(-k * d));
    std::printf("[fk] cube %sdepth %g: amplitude %.6g N, closed form %.6g N\n",
                backend.empty() ? "" : "gl ", h, amp, want);
    EXPECT_NEAR(amp, want, 0.01 * want) << h;
    if (checkMean) {
      EXPECT_NEAR(mean, kRho * kG * V, 1e-6 * kRho * kG * V) << h;
    }
  }
}

TEST(WavePressure, FroudeKrylovOnASmallSubmergedCube) { cubeFroudeKrylov("", 0.002, true); }

// the same on the gl backend (float; its closed-form integrals per piece,
// finite depth with both exponentials): A = 2 cm, so the 0.5 N amplitude
// stands well above float round-off of the 80 N buoyancy (Wheeler's
// e^{-k eta} change < 1.3%: k A = 0.013, first order but averaging out
// between crest and trough to (k A)^2 / 2 < 1e-4)
TEST(WavePressure, FroudeKrylovOnASmallSubmergedCubeOnGl) {
  cubeFroudeKrylov("<text name=\"mjbuoy.backend\" data=\"gl\"/>", 0.02, false);
}

// wall-sided box L x B, draft T, in head waves, crest at midships: heave
// Froude-Krylov amplitude F3 = rho g A B L e^{-kT} sin(kL/2) / (kL/2)
// (integral of the dynamic pressure rho g A e^{-kT} cos kx over the
// bottom; Faltinsen 1990 sec. 3.2), within 1% for kL from 0.5 to 6.
// Kerner's pressure rho g (eta - z) has no decay: F3 e^{kT}; its surface
// is interpolated linearly between hull vertices (0.5 m apart on this box),
// which holds 1% only for kL <= 1 (k * 0.5 m <= 0.25)
TEST(WavePressure, FroudeKrylovHeaveOfAWallSidedBox) {
  const double Lb = 2, B = 1, T = 0.3, H = 1, A = 0.001;
  for (bool kerner : {false, true}) {
    for (double kL : {0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0}) {
      if (kerner && kL > 1) continue;
      const double k = kL / Lb, len = 2 * M_PI / k;
      std::ostringstream sea;
      sea << "<numeric name=\"mjbuoy.airy.a\" data=\"" << A << " " << len << " 0 0\"/>";
      if (kerner) sea << "<text name=\"mjbuoy.sea.pressure\" data=\"kerner\"/>";
      Scene s(boxScene(Lb / 2, B / 2, H / 2, H / 2 - T, sea.str()));
      ASSERT_TRUE(s.ok()) << s.err;
      const int b = s.body("b");
      const double om = std::sqrt(kG * k);
      double fc = heave(s, b, 0), ft = heave(s, b, M_PI / om);
      double amp = 0.5 * (fc - ft);
      double want = kRho * kG * A * B * Lb * std::sin(kL / 2) / (kL / 2) *
                    (kerner ? 1 : std::exp(-k * T));
      std::printf("[fk] box %s kL %.1f: F3 %.6g N, closed form %.6g N\n",
                  kerner ? "kerner" : "linear", kL, amp, want);
      EXPECT_NEAR(amp, want, 0.01 * std::fabs(want)) << "kL " << kL << " kerner " << kerner;
    }
  }
}

// the same on the gl backend (float), kL 0.5 to 6; A = 1 cm so F3 (3.8 N at
// kL = 6) stands well above float round-off of the 5900 N buoyancy
TEST(WavePressure, FroudeKrylovHeaveOfAWallSidedBoxOnGl) {
  const double Lb = 2, B = 1, T = 0.3, H = 1, A = 0.01;
  for (double kL : {0.5, 2.0, 4.0, 6.0}) {
    const double k = kL / Lb, len = 2 * M_PI / k;
    std::ostringstream sea;
    sea << "<text name=\"mjbuoy.backend\" data=\"gl\"/>"
        << "<numeric name=\"mjbuoy.airy.a\" data=\"" << A << " " << len << " 0 0\"/>";
    Scene s(boxScene(Lb / 2, B / 2, H / 2, H / 2 - T, sea.str()));
    ASSERT_TRUE(s.ok()) << s.err;
    const int b = s.body("b");
    const double om = std::sqrt(kG * k);
    double amp = 0.5 * (heave(s, b, 0) - heave(s, b, M_PI / om));
    // A = 1 cm: k A <= 0.02, Wheeler's second-order change cosh(k A) - 1 < 2e-4
    double want = kRho * kG * A * B * Lb * std::sin(kL / 2) / (kL / 2) * std::exp(-k * T);
    std::printf("[fk] box gl kL %.1f: F3 %.6g N, closed form %.6g N\n", kL, amp, want);
    EXPECT_NEAR(amp, want, 0.01 * std::fabs(want)) << "kL " << kL;
  }
}

// flat water (an Airy component of zero amplitude, which runs the linear
// pressure path): the same exact hydrostatics as the Kerner path and as no
// waves at all (which hydrostatics_test checks against tetrahedral
// clipping) at a tilted pose, to 1e-9
TEST(WavePressure, FlatWaterIsExactHydrostaticsInBothModels) {
  const double q[7] = {0.1, -0.2, 0.05, 0.96, 0.2, -0.15, 0.1};
  std::vector<double> ref;
  for (const char* sea : {"", "<numeric name=\"mjbuoy.airy.a\" data=\"0 10 0 0\"/>",
                          "<numeric name=\"mjbuoy.airy.a\" data=\"0 10 0 0\"/>"
                          "<text name=\"mjbuoy.sea.pressure\" data=\"kerner\"/>"}) {
    Scene s(boxScene(1, 0.5, 0.4, 0, sea));
    ASSERT_TRUE(s.ok()) << s.err;
    for (int j = 0; j < 7; j++) s.d->qpos[j] = q[j];
    mju_normalize4(s.d->qpos + 3);
    mj_forward(s.m, s.d);
    const mjtNum* w = mjb_wrenchPart(s.b, s.d, mjbPART_PRESSURE) + 6 * s.body("b");
    if (ref.empty()) {
      ref.assign(w, w + 6);
      EXPECT_GT(ref[2], 1000.0);
    }
    for (int j = 0; j < 6; j++) EXPECT_NEAR(w[j], ref[j], 1e-9 * std::fabs(ref[2])) << sea;
  }
}

// the surface over triangle a b c solved exactly at its corners (height
// above the level and Gerstner label), as the cpu backend does at vertices
mjb::Surf cornerSurf(const mjb::Sea& sea, const double* a, const double* b, const double* c,
                     double t) {
  mjb::Surf sf;
  const double* q[3] = {a, b, c};
  for (int e = 0; e < 3; e++) {
    for (int j = 0; j < 3; j++) sf.p[e][j] = q[e][j];
    double l[2] = {q[e][0], q[e][1]};
    if (sea.ng > 0) sea.label(q[e][0], q[e][1], t, l);
    sf.eta[e] = sea.heightOf(l, q[e][0], q[e][1], t) - sea.level;
    sf.lab[e][0] = l[0];
    sf.lab[e][1] = l[1];
  }
  return sf;
}

// the degree-5 rule on one triangle of side s against the same rule on
// 4^lev sub-triangles: exact=false keeps the parent's linear surface at
// the sub-vertices (the same integrand: the rule's own error), exact=true
// solves the surface at each sub-vertex (converges to the integral under
// the exact surface)
void subdivide(const mjb::Sea& sea, const mjb::WaveNow* wn, const mjb::Surf& par, bool exact,
               double t, const double* a, const double* b, const double* c, const double n[3],
               int lev, double* P, double Pr[3]) {
  const double com[3] = {0, 0, 0};
  if (lev == 0) {
    double e[3], l[3][2];
    mjb::Surf sf = exact ? cornerSurf(sea, a, b, c, t) : par;
    const double* q[3] = {a, b, c};
    for (int i = 0; i < 3; i++) sf.at(q[i], e + i, l[i]);
    mjb::dynamicPiece(sea, wn, a, b, c, n, com, e, l, P, Pr);
    return;
  }
  double ab[3], bc[3], ca[3];
  for (int j = 0; j < 3; j++) {
    ab[j] = 0.5 * (a[j] + b[j]);
    bc[j] = 0.5 * (b[j] + c[j]);
    ca[j] = 0.5 * (c[j] + a[j]);
  }
  subdivide(sea, wn, par, exact, t, a, ab, ca, n, lev - 1, P, Pr);
  subdivide(sea, wn, par, exact, t, ab, b, bc, n, lev - 1, P, Pr);
  subdivide(sea, wn, par, exact, t, ca, bc, c, n, lev - 1, P, Pr);
  subdivide(sea, wn, par, exact, t, ab, bc, ca, n, lev - 1, P, Pr);
}

// a tilted triangle 0.4 m below the level, sides about sd [m]
struct Tri {
  double a[3], b[3], c[3], n[3], area;
  explicit Tri(double sd)
      : a{0.3, -0.2, -0.4}, b{0.3 + sd, 0.1 * sd, -0.4 - 0.3 * sd},
        c{0.3 + 0.4 * sd, 0.9 * sd - 0.2, -0.4 - 0.5 * sd} {
    double u[3], v[3];
    for (int j = 0; j < 3; j++) {
      u[j] = b[j] - a[j];
      v[j] = c[j] - a[j];
    }
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    area = 0.5 * nl;
    for (double& x : n) x /= nl;
  }
};

// the rule's own error under the surface the cut assumes (linear between
// the corners): against 4^6 sub-triangles (converged to 1e-14 relative),
// for a deep Airy wave and a finite-depth mixed sea; the error of a
// degree-5 rule scales as (k s)^6: measured below 2e-6 (k s)^6 of the
// integral's scale rho g A area, both force and moment
TEST(WavePressure, QuadratureErrorAgainstFineSubdivision) {
  const double t = 1.7;
  for (int seaKind = 0; seaKind < 2; seaKind++) {
    mjb::Sea sea = airySea(0.2, 6, 0);
    if (seaKind == 1) {
      sea.depth = 5;
      sea.waves.push_back(mjb::Wave{0.15, 9, 40, 30, 0.6, 0, 0, 0, 0, 0});
      sea.derive();
    }
    std::vector<mjb::WaveNow> wn(sea.waves.size());
    sea.now(t, wn.data());
    const double k = 2 * M_PI / 6;
    for (double ks : {0.25, 0.5, 1.0}) {
      const double sd = ks / k;  // side [m]
      Tri tr(sd);
      mjb::Surf sf = cornerSurf(sea, tr.a, tr.b, tr.c, t);
      double P1 = 0, R1[3] = {0, 0, 0}, P6 = 0, R6[3] = {0, 0, 0};
      subdivide(sea, wn.data(), sf, false, t, tr.a, tr.b, tr.c, tr.n, 0, &P1, R1);
      subdivide(sea, wn.data(), sf, false, t, tr.a, tr.b, tr.c, tr.n, 6, &P6, R6);
      const double scale = kRho * kG * 0.2 * tr.area, bound = 2e-6 * std::pow(ks, 6);
      std::printf("[quadrature] sea %d k s %.2f: force error %.2e, moment error %.2e (x rho g A area)\n",
                  seaKind, ks, std::fabs(P1 - P6) / scale,
                  std::fabs(R1[0] - R6[0]) / (scale * (1 + sd)));
      EXPECT_LT(std::fabs(P1 - P6), bound * scale) << ks;
      for (int j = 0; j < 3; j++) EXPECT_LT(std::fabs(R1[j] - R6[j]), bound * scale * (1 + sd));
    }
  }
}

// the surface interpolated linearly from the corners instead of solved at
// each quadrature point (docs/physics.md, "Cost"): deep Airy wave, p_d =
// rho g A e^{k (z - eta)} cos th depends on eta only through the stretch,
// |dp_d / d eta| <= rho g k A; linear interpolation of eta on a triangle
// errs by at most R^2 / 2 max|D^2 eta| (Waldron 1998, R the radius of the
// smallest enclosing circle, <= s / sqrt 3 for longest side s) with
// |D^2 eta| <= k^2 A: |error| <= rho g A area (k A) (k s)^2 / 6, force and
// moment (times the largest |r|), against the exact surface at 4^6
// sub-triangles (its own interpolation error (k s)^2 / 4^12 smaller)
TEST(WavePressure, SurfaceInterpolationErrorIsSecondOrder) {
  const double t = 0.9, A = 0.2, L = 6, k = 2 * M_PI / L;
  mjb::Sea sea = airySea(A, L, 0);
  std::vector<mjb::WaveNow> wn(sea.waves.size());
  sea.now(t, wn.data());
  for (double ks : {0.25, 0.5, 1.0}) {
    const double sd = ks / k;
    Tri tr(sd);
    // longest side
    double s2 = 0;
    const double* q[3] = {tr.a, tr.b, tr.c};
    for (int i = 0; i < 3; i++) {
      double d2 = 0;
      for (int j = 0; j < 3; j++) d2 += std::pow(q[(i + 1) % 3][j] - q[i][j], 2);
      s2 = std::fmax(s2, d2);
    }
    mjb::Surf sf = cornerSurf(sea, tr.a, tr.b, tr.c, t);
    double P1 = 0, R1[3] = {0, 0, 0}, Pe = 0, Re[3] = {0, 0, 0};
    subdivide(sea, wn.data(), sf, false, t, tr.a, tr.b, tr.c, tr.n, 0, &P1, R1);
    subdivide(sea, wn.data(), sf, true, t, tr.a, tr.b, tr.c, tr.n, 6, &Pe, Re);
    const double scale = kRho * kG * A * tr.area, bound = k * A * k * k * s2 / 6;
    double rmax = 0;
    for (int i = 0; i < 3; i++) rmax = std::fmax(rmax, std::sqrt(q[i][0] * q[i][0] + q[i][1] * q[i][1] + q[i][2] * q[i][2]));
    std::printf("[interpolation] k s %.2f: force error %.2e of bound %.2e (x rho g A area)\n", ks,
                std::fabs(P1 - Pe) / scale, bound);
    EXPECT_LT(std::fabs(P1 - Pe), bound * scale) << ks;
    // and it is not zero: the exact surface does differ
    EXPECT_GT(std::fabs(P1 - Pe), 1e-12 * scale) << ks;
    for (int j = 0; j < 3; j++) EXPECT_LT(std::fabs(R1[j] - Re[j]), bound * scale * rmax) << ks;
  }
}

}  // namespace
}  // namespace mjbt
