// diffraction excitation (docs/physics.md section 15): the heave response
// of a freely floating hemisphere in regular waves against the frequency
// domain built from published coefficients (Hulme 1982) and the Haskind
// relation, and the heading interpolation of the table
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "api/buoy.h"
#include "radiation/diffract.h"
#include "hemisphere.h"
#include "testutil.h"

namespace {

using mjbt::kG;
using mjbt::kRho;
using mjbt::Scene;

const double kR = 1;                                   // hemisphere radius [m]
const double kM = kRho * 2.0 / 3.0 * M_PI * kR * kR * kR;  // its displaced mass [kg]
const double kKA = 0.01;                               // wave steepness k A

// Hulme, A. (1982) "The wave forces acting on a floating hemisphere
// undergoing forced periodic oscillations", J. Fluid Mech. 121:443-463,
// Table 1 (heave; as in tests/panel_test.cc): kR, A33 / (rho 2/3 pi R^3),
// B33 / (rho 2/3 pi R^3 omega)
const double kHulme[][3] = {
    {0.3, 0.7157, 0.3254}, {0.6, 0.5381, 0.3271}, {1.0, 0.4284, 0.2484},
    {1.4, 0.3924, 0.1756}, {2.0, 0.3884, 0.1031}};

// the frequency-domain heave RAO |X3 / (C - w^2 (m + A33) - i w B33)| of
// row r: A33, B33 from Hulme, C = rho g pi R^2, and |X3| from the Haskind
// relation for an axisymmetric body in deep water, |X3|^2 = 2 rho g^2 B33 /
// (w k) (Newman 1962, J. Ship Res. 6(3):10-17; Newman 1977, "Marine
// Hydrodynamics", ch. 6; docs/physics.md section 15), so nothing here
// comes from the code under test
double expectedRAO(int r) {
  const double k = kHulme[r][0] / kR, w = std::sqrt(kG * k);
  const double A = kHulme[r][1] * kM, B = kHulme[r][2] * kM * w, C = kRho * kG * M_PI * kR * kR;
  const double X = std::sqrt(2 * kRho * kG * kG * B / (w * k));
  return X / std::abs(std::complex<double>(C - w * w * (kM + A), -w * B));
}

// the floating hemisphere of tests/radattach_test.cc (8 x 24 mesh, collar,
// drag, viscous and slamming terms off, radiation 0.7 to 7 rad/s with the
// lid) in one Airy component of steepness kKA and wave number k0 along +x
std::string raoModel(double k0, bool diffraction) {
  std::ostringstream c;
  c.precision(17);
  c << mjbt::kNoDragEntries << "<numeric name=\"mjbuoy.airy.w\" data=\"" << kKA / k0 << " " << 2 * M_PI / k0 << " 0 0\"/>"
    << "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
    << "<text name=\"mjbuoy.radiation.diffraction\" data=\"" << (diffraction ? "on" : "off") << "\"/>";
  return mjbt::floatingHemisphereXML(kR, kRho, c.str());
}

// measured heave RAO at wave number k: from rest at equilibrium, the wave
// of the model (k = k0) or one set by mjb_setSea (a component of steepness
// Q = 0, whose particles do not move: x = a, the Airy component; docs/physics.md
// section 6), 24 s of transient (the free heave decays by e^-0.59 a 2 s
// cycle: to 1e-3), then z = c0 + c1 cos(w t) + c2 sin(w t) by least squares
// over whole periods covering at least 8 s; sqrt(c1^2 + c2^2) / A
double measuredRAO(Scene& s, double k, double k0) {
  const double w = std::sqrt(kG * k), A = kKA / k, T = 2 * M_PI / w;
  mj_resetData(s.m, s.d);
  if (k != k0) {
    const double wave[5] = {A, 2 * M_PI / k, 0, 0, 0};
    mjbSea sea = {};
    sea.wave = wave;
    sea.nwave = 1;
    char err[256] = "";
    EXPECT_EQ(mjb_setSea(s.b, &sea, err, sizeof err), 1) << err;
  }
  const double dt = s.m->opt.timestep, t0 = 24, t1 = t0 + T * std::ceil(8 / T);
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  const long n = std::lround(t1 / dt);
  for (long i = 0; i < n; i++) {
    mj_step(s.m, s.d);
    if (!std::isfinite(s.d->qpos[2])) return NAN;
    if (s.d->time < t0 - 1e-9) continue;
    Eigen::Vector3d f(1, std::cos(w * s.d->time), std::sin(w * s.d->time));
    N += f * f.transpose();
    r += f * s.d->qpos[2];
  }
  Eigen::Vector3d c = N.ldlt().solve(r);
  return std::hypot(c[1], c[2]) / A;
}

// the heave RAO of rows [r0, r1) of kHulme within 5% of expectedRAO
// (issue 16); one attach, the wave of row r0 the model's own
void checkRAO(int r0, int r1, bool diffraction, double* err) {
  const double k0 = kHulme[r0][0] / kR;
  Scene s(raoModel(k0, diffraction));
  ASSERT_TRUE(s.ok()) << s.err;
  for (int r = r0; r < r1; r++) {
    double e = expectedRAO(r), got = measuredRAO(s, kHulme[r][0] / kR, k0);
    err[r] = got / e - 1;
    std::printf("[rao] kR %.1f diffraction %s: expected %.4f measured %.4f (%+.1f%%)\n",
                kHulme[r][0], diffraction ? "on " : "off", e, got, 100 * err[r]);
  }
}

// the default run: at resonance (kR = 1; without the diffraction force the
// measured RAO is 43% high there, 20 to 34% at kR 0.3 to 1.4)
TEST(Diffraction, HemisphereHeaveRAOAtResonance) {
  double err[5];
  checkRAO(2, 3, true, err);
  EXPECT_LT(std::fabs(err[2]), 0.05);
}

}  // namespace

namespace {

// the five frequencies (label panel): within 5% with the diffraction
// force, and more than 5% off at resonance without it
TEST(DiffractionLong, HemisphereHeaveRAOFiveFrequencies) {
  double on[5], off[5];
  checkRAO(0, 5, true, on);
  for (int r = 0; r < 5; r++) EXPECT_LT(std::fabs(on[r]), 0.05) << "kR " << kHulme[r][0];
  checkRAO(0, 5, false, off);
  EXPECT_GT(std::fabs(off[2]), 0.05);
}

}  // namespace

namespace {

// a 2 m x 1 m x 1 m box at 0.5 m draft, yawed by yaw [deg] in the model,
// one wave (A 0.1 m, lambda 6 m) travelling towards dir [deg]
std::string boxModel(double yaw, double dir) {
  std::ostringstream s;
  s << "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
    << "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
    << "<numeric name=\"mjbuoy.radiation.omega\" data=\"1 9 4\"/>"
    << "<numeric name=\"mjbuoy.airy.w\" data=\"0.1 6 " << dir << " 0\"/>"
    // the full wave from t = 0, as the sea mjb_setSea gives below (ramp 0)
    << "<numeric name=\"mjbuoy.sea.ramp\" data=\"0\"/>"
    << "</custom><worldbody><body name=\"box\" euler=\"0 0 " << yaw << "\"><freejoint/>"
    << "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.5\" mass=\"1000\"/>"
    << "</body></worldbody></mujoco>";
  return s.str();
}

// the diffraction wrench of s's body at time t (world axes, about its COM)
void wrenchAt(Scene& s, double t, double w[6]) {
  mj_kinematics(s.m, s.d);
  s.d->time = t;
  const mjb::Buoy* B = mjb::buoyOf(s.b);
  ASSERT_EQ(B->diff.db.size(), 1u);
  char told = 0;
  std::string notes;
  mjb::diffractionStep(B->diff, B->cfg.sea, s.m, s.d, w, &told, &notes);
}

// the box turned by deg (cs, sn: the turn's cosine and sine) in a wave
// turned by deg, against the unturned box a in its head sea at time t:
// want is a's wrench wa turned by deg about z, which the turned box feels
// within 1e-3 of wa's largest entry big (it is solved again from its
// turned mesh, whose vertices MuJoCo rounds to float: 4e-5 of big
// measured); the unturned box in the turned wave feels another, at least
// 5% of big away (the test can fail)
void expectTurnedWrench(Scene& a, double deg, double cs, double sn, double t, double wa[6],
                        double want[6], double* big) {
  Scene b(boxModel(deg, deg)), c(boxModel(0, deg));
  ASSERT_TRUE(a.ok() && b.ok() && c.ok()) << a.err << b.err << c.err;
  double wb[6], wc[6];
  wrenchAt(a, t, wa);
  wrenchAt(b, t, wb);
  wrenchAt(c, t, wc);
  const double turned[6] = {cs * wa[0] - sn * wa[1], sn * wa[0] + cs * wa[1], wa[2],
                            cs * wa[3] - sn * wa[4], sn * wa[3] + cs * wa[4], wa[5]};
  double diff = 0;
  *big = 0;
  for (int k = 0; k < 6; k++) *big = std::max(*big, std::fabs(wa[k]));
  for (int k = 0; k < 6; k++) {
    want[k] = turned[k];
    EXPECT_NEAR(wb[k], want[k], 1e-3 * *big) << k;
    diff = std::max(diff, std::fabs(wc[k] - want[k]));
  }
  EXPECT_GT(diff, 0.05 * *big);
}

// the force belongs to the body and the wave, not to the world axes: the
// box turned by 90 deg (in the model, or by its free joint while running)
// in a wave turned by 90 deg (the model's, or one set by mjb_setSea) feels
// the wrench of the unturned box in the unturned wave turned by 90 deg;
// a broadside wave on the unturned box gives another (the test can fail)
TEST(Diffraction, WrenchTurnsWithTheBodyAndTheWave) {
  Scene a(boxModel(0, 0));
  const double t = 0.3;
  double wa[6], want[6], big, wt[6];
  // the turn by 90 deg about z: (x, y) -> (-y, x), cosine 0 and sine 1 exactly
  expectTurnedWrench(a, 90, 0, 1, t, wa, want, &big);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_GT(std::fabs(wa[0]), 0.01 * big);  // a surge force in head waves
  // the unturned model, turned by its free joint and given the turned wave
  // by mjb_setSea (steepness 0: the Airy component)
  const double wave[5] = {0.1, 6, 90, 0, 0};
  mjbSea sea = {};
  sea.wave = wave;
  sea.nwave = 1;
  char err[256] = "";
  ASSERT_EQ(mjb_setSea(a.b, &sea, err, sizeof err), 1) << err;
  a.d->qpos[3] = std::cos(M_PI / 4);
  a.d->qpos[6] = std::sin(M_PI / 4);
  wrenchAt(a, t, wt);
  for (int k = 0; k < 6; k++) EXPECT_NEAR(wt[k], want[k], 1e-6 * big) << k;
  std::printf("head-sea wrench %g %g %g %g %g %g\n", wa[0], wa[1], wa[2], wa[3], wa[4], wa[5]);
}

// the same at a turn between the tables' 10 deg headings: the box turned
// by 25 deg in a wave towards 25 deg feels the unturned box's head-sea
// wrench turned by 25 deg (rotational invariance of the potential-flow
// problem about the vertical; docs/physics.md section 13, "Identical
// hulls"): its panels, in axes turned with it, are the unturned box's,
// so no heading is interpolated; an unturned box in the 25 deg wave feels
// another (the test can fail)
TEST(Diffraction, WrenchOfABoxTurnedBetweenTableHeadings) {
  Scene a(boxModel(0, 0));
  double wa[6], want[6], big;
  expectTurnedWrench(a, 25, std::cos(25 * M_PI / 180), std::sin(25 * M_PI / 180), 0.3, wa,
                     want, &big);
}

}  // namespace

namespace {

// Kerner's pressure is not the linear Froude-Krylov pressure the
// diffraction force completes: attach warns, naming both entries
TEST(Diffraction, KernerPressureIsWarnedAbout) {
  std::string xml = boxModel(0, 0);
  xml.replace(xml.find("</custom>"), 9,
              "<text name=\"mjbuoy.sea.pressure\" data=\"kerner\"/></custom>");
  Scene s(xml);
  ASSERT_TRUE(s.ok()) << s.err;
  std::string w = mjb_warnings(s.b);
  EXPECT_NE(w.find("mjbuoy.sea.pressure = kerner"), std::string::npos) << w;
  EXPECT_NE(w.find("mjbuoy.radiation.diffraction"), std::string::npos) << w;
  Scene l(boxModel(0, 0));
  ASSERT_TRUE(l.ok()) << l.err;
  EXPECT_EQ(std::string(mjb_warnings(l.b)).find("kerner"), std::string::npos);
}

}  // namespace

namespace {

// the heave diffraction force of the box of boxModel (yaw 0) towed along +x
// at speed u [m/s] from x = 0, in the model's wave (or the one set by
// mjb_setSea), sampled every 1 ms for 20 s
std::vector<double> towedHeave(Scene& s, double u, std::vector<double>* t) {
  std::vector<double> f;
  t->clear();
  for (int i = 0; i <= 20000; i++) {
    const double ti = 1e-3 * i;
    s.d->qpos[0] = u * ti;
    double w[6];
    wrenchAt(s, ti, w);
    t->push_back(ti);
    f.push_back(w[2]);
  }
  return f;
}

// mean period [s] between the first and last upward zero crossing of f(t)
double crossingPeriod(const std::vector<double>& t, const std::vector<double>& f) {
  double t0 = -1, t1 = -1;
  int n = 0;
  for (size_t i = 1; i < f.size(); i++) {
    if (f[i - 1] < 0 && f[i] >= 0) {
      const double tc = t[i - 1] + (t[i] - t[i - 1]) * f[i - 1] / (f[i - 1] - f[i]);
      if (t0 < 0) t0 = tc;
      t1 = tc;
      n++;
    }
  }
  return n > 1 ? (t1 - t0) / (n - 1) : NAN;
}

// amplitude of f(t) at frequency w [rad/s]: c0 + c1 cos(w t) + c2 sin(w t)
// by least squares, sqrt(c1^2 + c2^2)
double amplitudeAt(const std::vector<double>& t, const std::vector<double>& f, double w) {
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < f.size(); i++) {
    Eigen::Vector3d b(1, std::cos(w * t[i]), std::sin(w * t[i]));
    N += b * b.transpose();
    r += b * f[i];
  }
  Eigen::Vector3d c = N.ldlt().solve(r);
  return std::hypot(c[1], c[2]);
}

// forward speed (docs/physics.md section 15, "Forward speed"): a hull
// towed at U through a regular head wave (travelling towards -x) meets
// the crests at the encounter frequency w_e = w + k U (the Doppler shift
// of the phase k D . x - w t at x = U t, D = -x; Salvesen, Tuck and
// Faltinsen 1970, "Ship motions and sea loads", Trans. SNAME 78, eq. 1;
// here w 3.205 rad/s, k 1.047 rad/m, U 1 m/s: w_e 4.252 rad/s, 33% above
// w); its diffraction force oscillates at w_e, with the amplitude of the
// held hull in the same wave (the table read at the wave's own w and k,
// as STF's incident wave keeps them), not that of the held hull in the
// wave of frequency w_e (a wave 1.76 times shorter)
TEST(Diffraction, TowedHullFeelsTheEncounterFrequency) {
  Scene s(boxModel(0, 180));
  ASSERT_TRUE(s.ok()) << s.err;
  const double u = 1, k = 2 * M_PI / 6, w = std::sqrt(kG * k), we = w + k * u;
  std::vector<double> t;
  const std::vector<double> towed = towedHeave(s, u, &t), held = towedHeave(s, 0, &t);
  const double Te = crossingPeriod(t, towed), T0 = crossingPeriod(t, held);
  EXPECT_NEAR(Te / (2 * M_PI / we), 1, 0.005);
  EXPECT_NEAR(T0 / (2 * M_PI / w), 1, 0.005);
  const double at = amplitudeAt(t, towed, we), ah = amplitudeAt(t, held, w);
  EXPECT_NEAR(at / ah, 1, 1e-6);
  // the held box in the wave of frequency w_e (length 2 pi g / w_e^2)
  const double wave[5] = {0.1, 2 * M_PI * kG / (we * we), 180, 0, 0};
  mjbSea sea = {};
  sea.wave = wave;
  sea.nwave = 1;
  char err[256] = "";
  ASSERT_EQ(mjb_setSea(s.b, &sea, err, sizeof err), 1) << err;
  const double ae = amplitudeAt(t, towedHeave(s, 0, &t), we);
  EXPECT_GT(std::fabs(ae / ah - 1), 0.05);
  std::printf("[encounter] T_e %.5f s (2 pi / w_e %.5f), held T %.5f s (2 pi / w %.5f); heave "
              "amplitude towed %.2f N, held %.2f N, held in the w_e wave %.2f N\n",
              Te, 2 * M_PI / we, T0, 2 * M_PI / w, at, ah, ae);
}

}  // namespace

namespace {

// D = X - FK of row iw, heading ih, dof (table axes, about the COM)
std::complex<double> tableD(const mjb::HydroCoef& c, int iw, int ih, int dof) {
  const size_t o = ((size_t)iw * c.nh() + ih) * 6 + dof;
  return {c.Xre[o] - c.FKre[o], c.Xim[o] - c.FKim[o]};
}

// the documented interpolation (docs/physics.md section 15, "The table"),
// written out independently of the step: periodic Catmull-Rom in heading
// in its polynomial form, P(s) = (2 P1 + (P2 - P0) s + (2 P0 - 5 P1 +
// 4 P2 - P3) s^2 + (3 P1 - P0 - 3 P2 + P3) s^3) / 2, then linear in
// frequency, linear from 0 below the first row, none above the last;
// at(row, heading) gives the table value
template <class T, class At>
T interpolated(const std::vector<double>& om, int nh, double omega, double beta, At at) {
  const int nw = om.size();
  if (omega > om[nw - 1]) return T(0);
  double u = std::fmod(beta / (2 * M_PI / nh), nh);
  if (u < 0) u += nh;
  const int i = std::min((int)std::floor(u), nh - 1);
  const double s = u - i;
  auto heading = [&](int r) {
    const T p0 = at(r, (i - 1 + nh) % nh), p1 = at(r, i), p2 = at(r, (i + 1) % nh),
            p3 = at(r, (i + 2) % nh);
    return 0.5 * (2.0 * p1 + (p2 - p0) * s + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * s * s +
                  (3.0 * p1 - p0 - 3.0 * p2 + p3) * s * s * s);
  };
  if (omega < om[0]) return (omega / om[0]) * heading(0);
  int r = 0;
  while (r < nw - 2 && om[r + 1] <= omega) r++;
  const double f = (omega - om[r]) / (om[r + 1] - om[r]);
  return (1 - f) * heading(r) + f * heading(r + 1);
}

// the diffraction step's wrench w of the free box of s at (px, py) [m],
// yawed by psi [rad], at time t [s]
void stepAt(Scene& s, const mjb::Diffraction& df, const mjb::Sea& sea, double px, double py,
            double psi, double t, double w[6]) {
  s.d->qpos[0] = px, s.d->qpos[1] = py;
  s.d->qpos[3] = std::cos(psi / 2), s.d->qpos[4] = s.d->qpos[5] = 0;
  s.d->qpos[6] = std::sin(psi / 2);
  mj_kinematics(s.m, s.d);
  s.d->time = t;
  char told = 0;
  std::string notes;
  mjb::diffractionStep(df, sea, s.m, s.d, w, &told, &notes);
}

// the diffraction and drift wrench of the step (one pass over the
// components) against the sums written out directly at random headings,
// positions and times in a ramped five-component sea: D by the documented
// interpolation of X - FK, the diffraction force sum_j Re(r A_j D_j
// e^{i theta_j}), Newman's drift as the double sum
// r^2 sum_ij A_i A_j (T_i + T_j) / 2 cos(theta_i - theta_j) over the
// components within the table's frequencies (section 18, "Time domain":
// those beyond add nothing), turned by the body's yaw; to 1e-12 of the
// largest entry
TEST(Diffraction, StepIsTheDocumentedInterpolationSummed) {
  Scene s(boxModel(0, 0));
  ASSERT_TRUE(s.ok()) << s.err;
  const mjb::Buoy* B = mjb::buoyOf(s.b);
  ASSERT_EQ(B->diff.db.size(), 1u);
  mjb::Diffraction df = B->diff;
  const mjb::DiffBody& b = df.db[0];
  ASSERT_FALSE(b.T.empty());  // the drift table (mjbuoy.radiation.drift defaults on)
  const std::vector<double>& om = b.c.omega;
  const int nh = b.c.nh();
  mjb::Sea sea = B->cfg.sea;
  sea.ramp = 20;  // the start-up ramp: 0.5 (1 - cos(pi t / T)) up to T, then 1 (sea.h)
  sea.waves.clear();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(0, 1);
  // below the first frequency, within the table (three), above the last
  const double omegas[5] = {0.6 * om[0], 0.3 * om[0] + 0.7 * om[1], 0.5 * (om[1] + om[2]),
                            om[2] + 0.9 * (om.back() - om[2]), 1.1 * om.back()};
  for (double w1 : omegas) {
    mjb::Wave w{};
    w.kind = 1;
    w.amp = 0.05 + 0.1 * uni(rng);
    w.omega = w1;
    w.k = w1 * w1 / kG;
    w.dir = 360 * uni(rng) - 180;
    w.dx = std::cos(w.dir * M_PI / 180), w.dy = std::sin(w.dir * M_PI / 180);
    w.ph = 2 * M_PI * uni(rng);
    sea.waves.push_back(w);
  }
  mjb::diffSea(sea, &df);
  for (int trial = 0; trial < 4; trial++) {
    const double psi = 2 * M_PI * uni(rng) - M_PI, t = 25 * uni(rng);
    const double px = 4 * uni(rng) - 2, py = 4 * uni(rng) - 2;
    double w[6];
    stepAt(s, df, sea, px, py, psi, t, w);
    const double* x = s.d->xipos + 3 * b.body;
    const double r = t < sea.ramp ? 0.5 * (1 - std::cos(M_PI * t / sea.ramp)) : 1;
    double F[6] = {0, 0, 0, 0, 0, 0}, T[5][3], th[5], A[5];
    for (int j = 0; j < 5; j++) {
      const mjb::Wave& wv = sea.waves[j];
      const double beta = wv.dir * M_PI / 180 - psi;
      th[j] = wv.k * (wv.dx * x[0] + wv.dy * x[1]) + wv.ph - wv.omega * t;
      A[j] = wv.amp;
      for (int dof = 0; dof < 6; dof++) {
        const std::complex<double> D = interpolated<std::complex<double>>(
            om, nh, wv.omega, beta, [&](int iw, int ih) { return tableD(b.c, iw, ih, dof); });
        F[dof] += (r * A[j] * D * std::polar(1.0, th[j])).real();
      }
      for (int k = 0; k < 3; k++)
        T[j][k] = interpolated<double>(om, nh, wv.omega, beta, [&](int iw, int ih) {
          return b.T[3 * ((size_t)iw * nh + ih) + k];
        });
    }
    const int dofOf[3] = {0, 1, 5};
    for (int i = 0; i < 4; i++)  // the fifth is above the table
      for (int j = 0; j < 4; j++)
        for (int k = 0; k < 3; k++)
          F[dofOf[k]] += r * r * A[i] * A[j] * 0.5 * (T[i][k] + T[j][k]) * std::cos(th[i] - th[j]);
    const double c = std::cos(psi), sn = std::sin(psi);
    const double want[6] = {c * F[0] - sn * F[1], sn * F[0] + c * F[1], F[2],
                            c * F[3] - sn * F[4], sn * F[3] + c * F[4], F[5]};
    double big = 0;
    for (double v : want) big = std::max(big, std::fabs(v));
    ASSERT_GT(big, 0);
    for (int k = 0; k < 6; k++) EXPECT_NEAR(w[k], want[k], 1e-12 * big) << "dof " << k;
  }
}

// the same sums in a sea of 70 components (the step takes the phases' sine
// and cosine 64 at a time, 4 in lanes: docs/physics.md "Phases' sine and
// cosine in lanes"), directions over the spectra's +-360 deg (headings more
// than a turn from the table's first), at times up to 2e6 s (phases beyond
// the lanes' 2^20 pi/2, where std::sin and std::cos take over) and within
// the lanes' range: to 1e-12 of the largest entry, as above
TEST(Diffraction, StepSumsManyComponentsAtLongTimes) {
  Scene s(boxModel(0, 0));
  ASSERT_TRUE(s.ok()) << s.err;
  const mjb::Buoy* B = mjb::buoyOf(s.b);
  ASSERT_EQ(B->diff.db.size(), 1u);
  mjb::Diffraction df = B->diff;
  const mjb::DiffBody& b = df.db[0];
  ASSERT_FALSE(b.T.empty());
  const std::vector<double>& om = b.c.omega;
  const int nh = b.c.nh(), nc = 70;
  mjb::Sea sea = B->cfg.sea;
  sea.ramp = 0;
  sea.waves.clear();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uni(0, 1);
  for (int j = 0; j < nc; j++) {
    mjb::Wave w{};
    w.kind = 1;
    w.amp = 0.01 + 0.02 * uni(rng);
    w.omega = 1.05 * om.back() * uni(rng) + 1e-3;  // a few beyond the table
    w.k = w.omega * w.omega / kG;
    w.dir = 720 * uni(rng) - 360;
    w.dx = std::cos(w.dir * M_PI / 180), w.dy = std::sin(w.dir * M_PI / 180);
    w.ph = 2 * M_PI * uni(rng);
    sea.waves.push_back(w);
  }
  mjb::diffSea(sea, &df);
  ASSERT_EQ(b.iw.size(), (size_t)nc);
  for (double t : {3.7, 1234.5, 2.0e6 + 0.3}) {
    const double psi = 2 * M_PI * uni(rng) - M_PI;
    const double px = 4 * uni(rng) - 2, py = 4 * uni(rng) - 2;
    double w[6];
    stepAt(s, df, sea, px, py, psi, t, w);
    const double* x = s.d->xipos + 3 * b.body;
    double F[6] = {0, 0, 0, 0, 0, 0}, T[nc][3], th[nc], A[nc];
    double big_phase = 0;
    for (int j = 0; j < nc; j++) {
      const mjb::Wave& wv = sea.waves[j];
      const double beta = wv.dir * M_PI / 180 - psi;
      th[j] = wv.k * (wv.dx * x[0] + wv.dy * x[1]) + wv.ph - wv.omega * t;
      big_phase = std::max(big_phase, std::fabs(th[j]));
      A[j] = wv.omega > om.back() ? 0 : wv.amp;  // beyond the table: none
      for (int dof = 0; dof < 6; dof++) {
        const std::complex<double> D = interpolated<std::complex<double>>(
            om, nh, wv.omega, beta, [&](int iw, int ih) { return tableD(b.c, iw, ih, dof); });
        F[dof] += (A[j] * D * std::polar(1.0, th[j])).real();
      }
      for (int k = 0; k < 3; k++)
        T[j][k] = interpolated<double>(om, nh, wv.omega, beta, [&](int iw, int ih) {
          return b.T[3 * ((size_t)iw * nh + ih) + k];
        });
    }
    if (t > 1e6) {
      EXPECT_GT(big_phase, std::ldexp(M_PI / 2, 20));  // the fallback's range
    }
    const int dofOf[3] = {0, 1, 5};
    // cos(th_i - th_j) of the phases as rounded: th_i - th_j in double would
    // lose ulp(th) ~ 1e-9 rad at t = 2e6 s, so the difference's cosine in
    // long double as cos th_i cos th_j + sin th_i sin th_j
    for (int i = 0; i < nc; i++)
      for (int j = 0; j < nc; j++)
        for (int k = 0; k < 3; k++) {
          const long double a = th[i], b2 = th[j];
          const double cij = (double)(cosl(a) * cosl(b2) + sinl(a) * sinl(b2));
          F[dofOf[k]] += A[i] * A[j] * 0.5 * (T[i][k] + T[j][k]) * cij;
        }
    const double c = std::cos(psi), sn = std::sin(psi);
    const double want[6] = {c * F[0] - sn * F[1], sn * F[0] + c * F[1], F[2],
                            c * F[3] - sn * F[4], sn * F[3] + c * F[4], F[5]};
    double big = 0;
    for (double v : want) big = std::max(big, std::fabs(v));
    ASSERT_GT(big, 0);
    for (int k = 0; k < 6; k++)
      EXPECT_NEAR(w[k], want[k], 1e-12 * big) << "t " << t << " dof " << k;
  }
}

}  // namespace

namespace {

// two free boxes 5 m apart in the wave of boxModel, the second hx2 long
// (1: identical hulls, which share one solution and so one table)
std::string twoBoxModel(double hx2) {
  std::ostringstream s;
  s << "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull hull2\"/>"
    << "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
    << "<numeric name=\"mjbuoy.radiation.omega\" data=\"1 9 4\"/>"
    << "<numeric name=\"mjbuoy.airy.w\" data=\"0.1 6 30 0\"/>"
    << "<numeric name=\"mjbuoy.sea.ramp\" data=\"0\"/>"
    << "</custom><worldbody><body name=\"box\"><freejoint/>"
    << "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.5\" mass=\"1000\"/></body>"
    << "<body name=\"box2\" pos=\"0 5 0\"><freejoint/>"
    << "<geom name=\"hull2\" type=\"box\" size=\"" << hx2 << " 0.5 0.5\" mass=\"" << 1000 * hx2
    << "\"/></body></worldbody></mujoco>";
  return s.str();
}

// identical hulls hold one diffraction and drift table; their wrenches
// are those of the same bodies each with its own copy (what setDiffraction
// built before sharing: the reference), to the bit, at poses that differ;
// a longer second box keeps its own tables (the test can fail)
TEST(Diffraction, IdenticalHullsShareOneTable) {
  Scene s(twoBoxModel(1)), c(twoBoxModel(1.2));
  ASSERT_TRUE(s.ok() && c.ok()) << s.err << c.err;
  const mjb::Buoy* B = mjb::buoyOf(s.b);
  ASSERT_EQ(B->diff.db.size(), 2u);
  const mjb::DiffBody &a = B->diff.db[0], &b = B->diff.db[1];
  ASSERT_FALSE(a.D.empty());
  ASSERT_FALSE(a.T.empty());  // the drift table (mjbuoy.radiation.drift defaults on)
  EXPECT_EQ(a.D.data(), b.D.data());
  EXPECT_EQ(a.T.data(), b.T.data());
  const std::vector<mjb::DiffBody>& dc = mjb::buoyOf(c.b)->diff.db;
  ASSERT_EQ(dc.size(), 2u);
  EXPECT_NE(dc[0].D.data(), dc[1].D.data());
  EXPECT_NE(dc[0].T.data(), dc[1].T.data());
  mjb::Diffraction own = B->diff;
  for (mjb::DiffBody& x : own.db) {
    x.D = std::vector<double>(x.D);  // a copy of its own
    x.T = std::vector<double>(x.T);
  }
  ASSERT_NE(own.db[0].D.data(), own.db[1].D.data());
  // the second box turned by 40 deg and moved: another wrench than the first's
  s.d->qpos[7 + 3] = std::cos(M_PI / 9), s.d->qpos[7 + 6] = std::sin(M_PI / 9);
  s.d->qpos[7 + 0] = 1.5;
  mj_kinematics(s.m, s.d);
  s.d->time = 0.7;
  double ws[12], wo[12];
  char told[2] = {0, 0};
  std::string notes;
  mjb::diffractionStep(B->diff, B->cfg.sea, s.m, s.d, ws, told, &notes);
  mjb::diffractionStep(own, B->cfg.sea, s.m, s.d, wo, told, &notes);
  double big = 0, diff = 0;
  for (int k = 0; k < 12; k++) {
    EXPECT_EQ(ws[k], wo[k]) << k;
    big = std::max(big, std::fabs(ws[k]));
  }
  for (int k = 0; k < 6; k++) diff = std::max(diff, std::fabs(ws[k] - ws[6 + k]));
  EXPECT_GT(big, 0);
  EXPECT_GT(diff, 0.01 * big);  // the bodies' wrenches differ: each reads at its own pose
}

}  // namespace
