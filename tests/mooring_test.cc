// mooring lines: the lumped-mass line against the elastic catenary, string
// and drag formulas, energy conservation, and a moored body's surge period
// (docs/mooring.md)
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "mjbuoy.h"
#include "mooring/catenary.h"
#include "mooring/line.h"
#include "testutil.h"

namespace {

using mjb::Catenary;
using mjb::Line;
using mjb::LineState;
using mjb::LineWater;
using mjb::Sea;
using mjb::Seabed;

// a line alone in a sea, stepped by hand with fixed ends
struct Rig {
  Sea sea;
  Seabed bed;
  Line l;
  LineState s;
  LineWater w;
  double e0[6] = {0}, e1[6] = {0};
  double t = 0;
  Rig(const mjb::LineType& type, double len, int nseg, double bedz, double crest) {
    bed.z = bedz;
    l.name = "test";
    l.t = type;
    l.len = len;
    l.nseg = nseg;
    w = {&sea, &bed, crest, 0};
    EXPECT_EQ(mjb::lineDerive(w, &l), "");
    mjb::lineMake(l, &s);
  }
  void ends(const double a[3], const double b[3]) {
    for (int k = 0; k < 3; k++) e0[k] = a[k], e1[k] = b[k];
  }
  void run(double T, double dt) {
    long n = std::lround(T / dt);
    for (long i = 0; i < n; i++, t += dt) mjb::lineStep(w, l, t, dt, e0, e1, &s);
  }
  // force on the end (0 anchor, 1 fairlead) [N]
  void force(int end, double f[3]) { mjb::lineEndForce(w, l, s, end, end ? e1 : e0, t, 0, f); }
};

// studless chain, about 100 kg/m: d is the volume-equivalent diameter
mjb::LineType chain() {
  mjb::LineType t;
  t.mass = 100;
  t.diam = 0.12;
  t.ea = 5e8;
  return t;
}

// the elastic catenary with seabed contact and no bed friction, written
// out here from Jonkman 2007 (NREL/TP-500-41958) eqs. 4-1 to 4-4 (C_B = 0),
// which are Irvine 1981 sec. 2.2 with an elastic line: the fairlead span
// and height for fairlead tension H, V
void irvine(double H, double V, double L, double EA, double W, bool bed, double* x, double* z) {
  if (bed && V < W * L) {
    *x = L - V / W + H / W * std::asinh(V / H) + H * L / EA;
    *z = H / W * (std::sqrt(1 + V * V / (H * H)) - 1) + V * V / (2 * EA * W);
  } else {
    double Va = V - W * L;
    *x = H / W * (std::asinh(V / H) - std::asinh(Va / H)) + H * L / EA;
    *z = H / W * (std::sqrt(1 + V * V / (H * H)) - std::sqrt(1 + Va * Va / (H * H))) +
         (V * L - W * L * L / 2) / EA;
  }
}

// the solver returns H, V that put the fairlead where asked, by the
// closed-form equations above (residual far below the tests' 0.5%)
TEST(Catenary, SolverMeetsIrvineEquations) {
  const double L = 300, EA = 5e8, W = 850;
  for (double X : {220.0, 250.0, 283.0, 290.0}) {
    Catenary c;
    ASSERT_TRUE(mjb::catenarySolve(X, 95, L, EA, W, true, &c)) << X;
    double x, z;
    irvine(c.hf, c.vf, L, EA, W, true, &x, &z);
    EXPECT_NEAR(x, X, 1e-6 * L) << X;
    EXPECT_NEAR(z, 95, 1e-6 * L) << X;
  }
  // the grounded and suspended regimes both appear
  Catenary a, b;
  mjb::catenarySolve(220, 95, L, EA, W, true, &a);
  mjb::catenarySolve(290, 95, L, EA, W, true, &b);
  EXPECT_GT(a.lb, 50);
  EXPECT_EQ(b.lb, 0);
  EXPECT_GT(b.vf, W * L);  // the anchor pulls up: taut
}

// a settled lumped-mass line matches the continuous elastic catenary: the
// fairlead tension within 0.5% (Irvine 1981; Jonkman 2007 eqs. 4-1 to
// 4-4, checked above), and the length on the bed, L_B (the touchdown
// point's distance from the anchor, L_B (1 + H / EA)), within 0.5%, at
// spans from mostly grounded to taut (a span below L - depth = 205 m has
// no catenary: the line would have to fold on the bed; near it the
// radius H / w at touchdown falls below the 7.5 m segments)
TEST(MooringLine, StaticCatenary) {
  const double depth = 100, L = 300;
  for (double X : {235.0, 250.0, 280.0, 287.0}) {
    Rig r(chain(), L, 40, -depth, 0);
    double a[3] = {0, 0, -depth}, b[3] = {X, 0, -5};
    r.ends(a, b);
    mjb::lineRest(r.w, r.l, a, b, &r.s);
    // shake it off its start: every inner node 2 m sideways
    for (int j = 1; j < r.l.nseg; j++) r.s.r[3 * j + 1] += 2;
    r.run(150, 0.05);
    const double W = mjb::lineWetWeight(r.sea, r.l.t);
    Catenary c;
    ASSERT_TRUE(mjb::catenarySolve(X, depth - 5, L, r.l.t.ea, W, true, &c));
    double f[3];
    r.force(1, f);
    const double T = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    const double Ta = std::hypot(c.hf, c.vf);
    EXPECT_NEAR(T, Ta, 0.005 * Ta) << "span " << X;
    EXPECT_NEAR(-f[0], c.hf, 0.005 * Ta) << "span " << X;
    EXPECT_NEAR(-f[2], c.vf, 0.005 * Ta) << "span " << X;
    EXPECT_NEAR(r.s.bedlen, c.lb, 0.005 * c.lb + 1e-9) << "span " << X;
    std::printf("span %g m: T %.6g N (catenary %.6g, %+.3f%%), on bed %.5g m (catenary %.5g, "
                "%+.3f%%)\n", X, T, Ta, 100 * (T / Ta - 1), r.s.bedlen, c.lb,
                c.lb > 0 ? 100 * (r.s.bedlen / c.lb - 1) : 0.0);
  }
}

// the line starts on the lumped-mass line's own static equilibrium
// (lineRest), not on the continuous catenary's points (whose chords fall
// short of the stretched arc, so 15 m segments start slack near the
// fairlead): with the ends held, its fairlead force at t = 0 equals the
// one after 60 s of stepping with its internal damping and drag (an
// independent method: dynamic relaxation of the same line) within 0.5%,
// for 15 m and 3 m segments, with part of the line on the bed and fully
// suspended (the anchor 95 m below the fairlead, the bed 900 m below it)
TEST(MooringLine, StartsOnDiscreteEquilibrium) {
  const double L = 300, X = 250;
  for (int nseg : {20, 100}) {
    for (double bedz : {-100.0, -1000.0}) {
      Rig r(chain(), L, nseg, bedz, 0);
      double a[3] = {0, 0, -100}, b[3] = {X, 0, -5};
      r.ends(a, b);
      ASSERT_TRUE(mjb::lineRest(r.w, r.l, a, b, &r.s)) << nseg << " " << bedz;
      double f0[3], f1[3];
      r.force(1, f0);
      r.run(60, 0.05);
      r.force(1, f1);
      const double T0 = std::sqrt(f0[0] * f0[0] + f0[1] * f0[1] + f0[2] * f0[2]);
      const double T1 = std::sqrt(f1[0] * f1[0] + f1[1] * f1[1] + f1[2] * f1[2]);
      EXPECT_NEAR(T0, T1, 0.005 * T1) << nseg << " segments, bed " << bedz;
      EXPECT_NEAR(f0[2], f1[2], 0.005 * T1) << nseg << " segments, bed " << bedz;
      EXPECT_NEAR(f0[0], f1[0], 0.005 * T1) << nseg << " segments, bed " << bedz;
      std::printf("%d segments, bed %g m: fairlead T(0) %.6g N, T(60 s) %.6g N (%+.4f%%), "
                  "V(0) %.6g N, V(60 s) %.6g N\n", nseg, bedz, T0, T1, 100 * (T0 / T1 - 1),
                  -f0[2], -f1[2]);
    }
  }
}

// an end that is not finite has no equilibrium: lineRest says so (the
// caller names the line) instead of reporting a converged start
TEST(MooringLine, RestRefusesNonFiniteEnd) {
  Rig r(chain(), 300, 20, -100, 0);
  double a[3] = {0, 0, -100}, b[3] = {NAN, 0, -5};
  EXPECT_FALSE(mjb::lineRest(r.w, r.l, a, b, &r.s));
}

// the horizontal restoring force of three lines at 120 degrees on a
// fairlead ring offset by dx: the sum over lines of the catenary's H along
// each line's horizontal direction (Irvine 1981; Faltinsen 1990, Sea Loads,
// sec. 8.2), within 0.5% of the largest line's tension; the settled
// lumped-mass lines in 3-D directions
TEST(MooringLine, ThreeLineRestoringForce) {
  const double depth = 100, L = 300, R = 10, X = 260;
  for (double dx : {2.0, 8.0}) {
    double F[2] = {0, 0}, Fa[2] = {0, 0}, Tmax = 0;
    for (int i = 0; i < 3; i++) {
      const double a = 2 * M_PI * i / 3;
      Rig r(chain(), L, 40, -depth, 0);
      double an[3] = {(R + X) * std::cos(a), (R + X) * std::sin(a), -depth};
      double fl[3] = {R * std::cos(a) + dx, R * std::sin(a), -5};
      r.ends(an, fl);
      mjb::lineRest(r.w, r.l, an, fl, &r.s);
      r.run(100, 0.05);
      double f[3];
      r.force(1, f);
      F[0] += f[0];
      F[1] += f[1];
      const double hx = an[0] - fl[0], hy = an[1] - fl[1], span = std::hypot(hx, hy);
      Catenary c;
      ASSERT_TRUE(mjb::catenarySolve(span, depth - 5, L, r.l.t.ea,
                                     mjb::lineWetWeight(r.sea, r.l.t), true, &c));
      Fa[0] += c.hf * hx / span;
      Fa[1] += c.hf * hy / span;
      Tmax = std::max(Tmax, std::hypot(c.hf, c.vf));
    }
    EXPECT_NEAR(F[0], Fa[0], 0.005 * Tmax) << dx;
    EXPECT_NEAR(F[1], Fa[1], 0.005 * Tmax) << dx;
    EXPECT_LT(Fa[0], 0);  // it pulls back
    std::printf("offset %g m: restoring %.6g N, catenary %.6g N (%+.3f%%)\n", dx, F[0], Fa[0],
                100 * (F[0] / Fa[0] - 1));
  }
}

// energy of a line in air with both ends fixed: kinetic, gravity and
// spring (1/2 EA / l0 e^2 l0^2 per stretched segment)
double energy(const Rig& r, double* power) {
  const Line& l = r.l;
  const double m = l.mnode, g = r.sea.g, k = l.t.ea / l.l0;
  double E = 0;
  std::vector<double> F(r.s.r.size(), 0.0);
  for (int j = 1; j < l.nseg; j++) {
    const double* v = &r.s.v[3 * j];
    E += 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + m * g * r.s.r[3 * j + 2];
    F[3 * j + 2] -= m * g;
  }
  for (int i = 0; i < l.nseg; i++) {
    double d[3], n = 0;
    for (int q = 0; q < 3; q++) d[q] = r.s.r[3 * i + 3 + q] - r.s.r[3 * i + q], n += d[q] * d[q];
    n = std::sqrt(n);
    double e = std::max(n - l.l0, 0.0);
    E += 0.5 * k * e * e;
    for (int q = 0; q < 3; q++) F[3 * i + q] += k * e * d[q] / n, F[3 * i + 3 + q] -= k * e * d[q] / n;
  }
  *power = 0;
  for (int j = 1; j < l.nseg; j++) {
    for (int q = 0; q < 3; q++) *power += F[3 * j + q] * r.s.v[3 * j + q];
  }
  return E;
}

// an undamped line released from a straight, non-equilibrium shape in air
// never gains energy. Bound: the transverse elastic forces are semi-implicit
// (symplectic) Euler, which keeps a mode of frequency w on the invariant v^2
// + w^2 x^2 - h w^2 x v (Hairer, Lubich & Wanner 2006, Geometric Numerical
// Integration, sec. I.1), so its energy stays within a factor 1 +- (h w /
// 2) / (1 - h w / 2) of its start; the axial stiffness is backward Euler,
// whose energy change per step is -(h^2 / 2) (v'^T K v' + |M^-1/2 K x'|^2)
// <= 0 for a linear spring K (docs/mooring.md "Integration"): it only
// dissipates (AxialModeDamping checks by how much). Summed over the modes,
// with w at most the highest, 2 sqrt(k / m), and the energy in motion at
// most E(0) - E(rest), E(t) - E(0) is at most (h w / 2) / (1 - h w / 2)
// (E(0) - E(rest)) over 20 s, 10^5 steps
TEST(MooringLine, EnergyNeverGainedInAir) {
  mjb::LineType t;
  t.mass = 10;
  t.diam = 0.03;
  t.ea = 2e6;
  t.ba = 0;
  Rig r(t, 50, 20, -1e9, 0);  // 100 m above a calm sea: dry
  double a[3] = {0, 0, 100}, b[3] = {45, 0, 100};
  r.ends(a, b);
  double P, Erest;
  mjb::lineRest(r.w, r.l, a, b, &r.s);
  Erest = energy(r, &P);
  for (int j = 0; j <= 20; j++) {
    for (int k = 0; k < 3; k++) r.s.r[3 * j + k] = a[k] + (b[k] - a[k]) * j / 20.0;
  }
  std::fill(r.s.v.begin(), r.s.v.end(), 0.0);
  double E0 = energy(r, &P), worst = 0;
  const double h = 2e-4, om = 2 * std::sqrt(t.ea / r.l.l0 / r.l.mnode);
  ASSERT_LT(h, r.l.hmax);
  const double bound = (h * om / 2) / (1 - h * om / 2) * (E0 - Erest);
  ASSERT_GT(E0 - Erest, 0);
  for (int i = 0; i < 100000; i++) {
    r.run(h, h);
    double E = energy(r, &P);
    worst = std::max(worst, E - E0);
    ASSERT_LE(E - E0, bound) << "t = " << r.t;
  }
  std::printf("energy: max gain %.3g J, bound %.3g J, E(0) - E(rest) %.6g J, lost by 20 s %.4g J\n",
              worst, bound, E0 - Erest, E0 - energy(r, &P));
}

// the numerical damping of the implicit axial stiffness: a taut, undamped,
// weightless line in air started in its first axial mode (a beaded bar
// fixed at both ends, mode shape sin(pi j / N), w = 2 sqrt(k / m) sin(pi /
// 2N): Rao 2007 sec. 8.5's string of beads, axially) is a single linear
// oscillator, and backward Euler multiplies its energy by exactly 1 / (1 +
// (h w)^2) per step (the amplification 1 / (1 - i h w): Hairer & Wanner
// 1996, Solving ODEs II, sec. IV.3): a damping ratio of about h w / 2
// (docs/mooring.md "Integration"). The energy above rest after n steps
// matches (1 + (h w)^2)^-n within 1%
TEST(MooringLine, AxialModeDamping) {
  mjb::LineType t;
  t.mass = 2;
  t.diam = 0.02;
  t.ea = 1e6;
  t.ba = 0;
  const int n = 10;
  Rig r(t, 10, n, -1e9, 0);
  r.sea.g = 0;
  double a[3] = {0, 0, 10}, b[3] = {10.2, 0, 10};  // 2% stretch: taut throughout
  r.ends(a, b);
  for (int j = 0; j <= n; j++) {
    r.s.r[3 * j] = 10.2 * j / n + 0.01 * std::sin(M_PI * j / n);
    r.s.r[3 * j + 2] = 10;
  }
  std::copy(a, a + 3, r.s.end0);
  std::copy(b, b + 3, r.s.end1);
  const double k = t.ea / r.l.l0, m = r.l.mnode;
  const double om = 2 * std::sqrt(k / m) * std::sin(M_PI / (2 * n));
  // the energy above the evenly stretched rest state
  auto excess = [&]() {
    double E = 0;
    for (int i = 0; i < n; i++) {
      const double e = r.s.r[3 * i + 3] - r.s.r[3 * i] - r.l.l0, e0 = 0.2 / n;
      E += 0.5 * k * (e * e - e0 * e0);
    }
    for (int j = 1; j < n; j++) E += 0.5 * m * r.s.v[3 * j] * r.s.v[3 * j];
    return E;
  };
  const double h = 0.1 / om, E0 = excess();
  const long steps = 70;  // (1 + 0.01)^-70 = 0.50
  r.run(steps * h, h);
  const double want = E0 * std::pow(1 + h * om * h * om, -double(steps));
  EXPECT_NEAR(excess(), want, 0.01 * want);
  std::printf("axial mode: E(n) / E(0) %.5f, backward Euler %.5f\n", excess() / E0, want / E0);
}

// steel chain (0.1 m studless: 200 kg/m, EA 0.85e9 N, volume-equivalent
// diameter 0.18 m; DNV-OS-E302 grade R3) and polyester (0.16 m rope: 17
// kg/m, EA 1.5e8 N, volume-equivalent diameter 0.125 m at 1380 kg/m^3)
// catenaries in current, their fairlead heaving and surging 2 m at 8 s, at
// the model's 2 ms and at a 10 ms step: stable at the step the model takes,
// with no sub-step criterion on the axial stiffness. Bounds: every node
// finite and slower than 5 times the fairlead's peak speed (a line swinging
// with its fairlead), no segment past kOverStrain; and the fairlead tension
// (RMS difference over the last period) against the same line at 0.5 ms:
// backward Euler's error is first order in h, within 5% at 2 ms and 15%
// at 10 ms (its damping of the lines' axial modes, ratio h w / 2:
// AxialModeDamping)
TEST(MooringLine, StiffLinesStableAtModelStep) {
  struct Kind { const char* name; double mass, diam, ea; };
  const Kind kinds[] = {{"chain", 200, 0.18, 0.85e9}, {"polyester", 17, 0.125, 1.5e8}};
  for (const Kind& kd : kinds) {
    std::vector<double> tens[3];
    int run = 0;
    for (double dt : {0.0005, 0.002, 0.01}) {
      mjb::LineType t;
      t.mass = kd.mass;
      t.diam = kd.diam;
      t.ea = kd.ea;
      Rig r(t, 300, 30, -100, 0);
      r.sea.current[0] = 0.5;
      double a[3] = {-250, 0, -100}, b[3] = {0, 0, -5};
      r.ends(a, b);
      mjb::lineRest(r.w, r.l, a, b, &r.s);
      const double A = 2, w = 2 * M_PI / 8, vpeak = A * w * std::sqrt(2.0);
      double vmax = 0;
      const long steps = std::lround(40 / dt);
      for (long i = 0; i < steps; i++) {
        const double tn = r.t + dt;
        r.e1[0] = A * std::sin(w * tn);
        r.e1[2] = -5 + A * std::sin(w * tn);
        r.e1[3] = r.e1[5] = A * w * std::cos(w * tn);
        mjb::lineStep(r.w, r.l, r.t, dt, r.e0, r.e1, &r.s);
        r.t = tn;
        for (double x : r.s.r) ASSERT_TRUE(std::isfinite(x)) << kd.name << " dt " << dt;
        for (double x : r.s.v) vmax = std::max(vmax, std::fabs(x));
        ASSERT_EQ(r.s.over, 0) << kd.name << " dt " << dt << " t " << r.t;
        if (i + 1 > std::lround(32 / dt) && (i + 1) % std::lround(0.01 / dt) == 0) {
          double f[3];
          r.force(1, f);
          tens[run].push_back(std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
        }
      }
      EXPECT_LT(vmax, 5 * vpeak) << kd.name << " dt " << dt;
      std::printf("%s dt %g: max node speed %.3g m/s (fairlead %.3g)\n", kd.name, dt, vmax,
                  vpeak);
      run++;
    }
    for (int k = 1; k < 3; k++) {
      ASSERT_EQ(tens[0].size(), tens[k].size());
      double d2 = 0, t2 = 0;
      for (size_t i = 0; i < tens[0].size(); i++) {
        d2 += std::pow(tens[k][i] - tens[0][i], 2);
        t2 += tens[0][i] * tens[0][i];
      }
      EXPECT_LT(std::sqrt(d2 / t2), k == 1 ? 0.05 : 0.15) << kd.name;
      std::printf("%s: fairlead tension at %s ms, RMS off 0.5 ms's %.3g%% of %.4g N\n", kd.name,
                  k == 1 ? "2" : "10", 100 * std::sqrt(d2 / t2), std::sqrt(t2 / tens[0].size()));
    }
  }
}

// first transverse mode of a taut weightless line: the string frequency
// f1 = (1 / 2S) sqrt(T / mu), S the stretched span, mu the mass per
// stretched length, T = EA (S / L - 1) (Rao 2007, Vibration of Continuous
// Systems, sec. 8.5), within 0.5% (the 40-node chain is off by
// (pi / 2N)^2 / 6 = 1e-4, Rayleigh's beaded string)
TEST(MooringLine, TautStringFrequency) {
  mjb::LineType t;
  t.mass = 2;
  t.diam = 0.02;
  t.ea = 1e6;
  t.ba = 0;
  Rig r(t, 50, 40, -1e9, 0);
  r.sea.g = 0;  // weightless: no sag
  double a[3] = {0, 0, 10}, b[3] = {50.5, 0, 10};
  r.ends(a, b);
  const int n = 40;
  for (int j = 0; j <= n; j++) {
    r.s.r[3 * j] = 50.5 * j / n;
    r.s.r[3 * j + 1] = 0.01 * std::sin(M_PI * j / n);
    r.s.r[3 * j + 2] = 10;
  }
  std::copy(a, a + 3, r.s.end0);
  std::copy(b, b + 3, r.s.end1);
  const double T = t.ea * (50.5 / 50 - 1), mu = t.mass * 50 / 50.5;
  const double f1 = 1 / (2 * 50.5) * std::sqrt(T / mu);
  // upward zero crossings of the middle node over 20 periods
  std::vector<double> up;
  double prev = r.s.r[3 * (n / 2) + 1];
  const double dt = 1e-3;
  for (int i = 0; i < std::lround(21 / f1 / dt); i++) {
    r.run(dt, dt);
    double y = r.s.r[3 * (n / 2) + 1];
    if (prev < 0 && y >= 0) up.push_back(r.t - dt * y / (y - prev));
    prev = y;
  }
  ASSERT_GE(up.size(), 10u);
  double f = (up.size() - 1) / (up.back() - up.front());
  EXPECT_NEAR(f, f1, 0.005 * f1);
  std::printf("string: f %.6g Hz, analytic %.6g Hz (%+.3f%%)\n", f, f1, 100 * (f / f1 - 1));
}

// a taut, neutrally buoyant line across a uniform current carries the
// normal drag 0.5 rho C_dn d S U^2 (Morison; DNV-RP-C205 sec. 6.2), S its
// stretched length: the two ends together take it, within 1% (the line
// bows by 2 cm on 50 m, so the flow meets it square)
TEST(MooringLine, DragInCurrent) {
  mjb::LineType t;
  t.diam = 0.1;
  t.mass = 1000 * M_PI * 0.01 / 4;  // displaced water: no net weight
  t.ea = 1e8;
  t.cdn = 1.2;
  Rig r(t, 49.5, 20, -1e9, 0);
  r.sea.current[0] = 1.0;
  double a[3] = {0, -25, -50}, b[3] = {0, 25, -50};
  r.ends(a, b);
  mjb::lineRest(r.w, r.l, a, b, &r.s);
  r.run(60, 0.01);
  double fa[3], fb[3];
  r.force(0, fa);
  r.force(1, fb);
  double S = 0;
  for (int i = 0; i < r.l.nseg; i++) {
    double d2 = 0;
    for (int k = 0; k < 3; k++) d2 += std::pow(r.s.r[3 * i + 3 + k] - r.s.r[3 * i + k], 2);
    S += std::sqrt(d2);
  }
  const double D = 0.5 * 1000 * 1.2 * 0.1 * S * 1.0;
  EXPECT_NEAR(fa[0] + fb[0], D, 0.01 * D);
  EXPECT_NEAR(fa[2] + fb[2], 0, 0.01 * D);  // no net weight
  std::printf("drag: %.6g N, formula %.6g N (%+.3f%%)\n", fa[0] + fb[0], D,
              100 * ((fa[0] + fb[0]) / D - 1));
}

}  // namespace

namespace {

// the OC3-Hywind spar's mooring (Jonkman 2010, "Definition of the Floating
// System for Phase IV of OC3", NREL/TP-500-47535, table "Mooring System
// Properties"): three lines at 120 degrees, 320 m deep, fairleads 70 m
// below the surface at radius 5.2 m, anchors at radius 853.87 m, 902.2 m
// of line of 77.7066 kg/m (698.094 N/m in water, with d = 0.09 m), EA
// 384,243,000 N. The same report gives its linearised surge stiffness at
// zero offset, K11 = 41,180 N/m (the "additional yaw spring" aside). The
// settled lumped-mass lines (40 segments of 22.6 m, g 9.80665 as there) at
// offsets of +-1 m give the slope within 1%, and so does the catenary
TEST(MooringLine, Oc3HywindSurgeStiffness) {
  mjb::LineType t;
  t.mass = 77.7066;
  t.diam = 0.09;
  t.ea = 384243000;
  const double depth = 320, zf = -70, rf = 5.2, ra = 853.87, L = 902.2, K11 = 41180;
  double F[2] = {0, 0}, Fc[2] = {0, 0};
  for (int side = 0; side < 2; side++) {
    const double dx = side ? 1 : -1;
    for (int i = 0; i < 3; i++) {
      const double a = 2 * M_PI * i / 3;
      Rig r(t, L, 40, -depth, 0);
      r.sea.g = 9.80665;
      r.sea.rho = 1025;
      r.bed.mu[0] = r.bed.mu[1] = 0;  // the catenary's frictionless bed
      double an[3] = {ra * std::cos(a), ra * std::sin(a), -depth};
      double fl[3] = {rf * std::cos(a) + dx, rf * std::sin(a), zf};
      r.ends(an, fl);
      mjb::lineRest(r.w, r.l, an, fl, &r.s);
      r.run(60, 0.05);
      double f[3];
      r.force(1, f);
      F[side] += f[0];
      const double hx = an[0] - fl[0], hy = an[1] - fl[1], span = std::hypot(hx, hy);
      const double W = mjb::lineWetWeight(r.sea, t);
      EXPECT_NEAR(W, 698.094, 0.01);  // the report's weight in water
      Catenary c;
      ASSERT_TRUE(mjb::catenarySolve(span, depth + zf, L, t.ea, W, true, &c));
      Fc[side] += c.hf * hx / span;
    }
  }
  const double k = -(F[1] - F[0]) / 2, kc = -(Fc[1] - Fc[0]) / 2;
  EXPECT_NEAR(k, K11, 0.01 * K11);
  EXPECT_NEAR(kc, K11, 0.01 * K11);
  std::printf("OC3-Hywind surge stiffness: lines %.6g N/m, catenary %.6g N/m, published %g N/m "
              "(%+.2f%%, %+.2f%%)\n", k, kc, K11, 100 * (k / K11 - 1), 100 * (kc / K11 - 1));
}

}  // namespace
