// mooring lines in a model: MJCF, the step clock under RK4 and
// mj_forward, reset and copy, faults, and a moored body's surge period
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "mjbuoy.h"
#include "api/buoy.h"
#include "mooring/catenary.h"
#include "testutil.h"

namespace {

using mjbt::Scene;

const double kDepth = 100, kLen = 300, kMass = 100, kDiam = 0.12, kEA = 5e8;

std::string chainType() {
  std::ostringstream s;
  s << "<numeric name=\"mjbuoy.linetype.chain.mass\" data=\"" << kMass << "\"/>"
    << "<numeric name=\"mjbuoy.linetype.chain.diameter\" data=\"" << kDiam << "\"/>"
    << "<numeric name=\"mjbuoy.linetype.chain.ea\" data=\"" << kEA << "\"/>";
  return s.str();
}

std::string line(const std::string& name, double ax, double ay, double az,
                 const std::string& site, double len = kLen, int nseg = 20) {
  std::ostringstream s;
  s << "<text name=\"mjbuoy.line." << name << ".type\" data=\"chain\"/>"
    << "<numeric name=\"mjbuoy.line." << name << ".length\" data=\"" << len << "\"/>"
    << "<numeric name=\"mjbuoy.line." << name << ".segments\" data=\"" << nseg << "\"/>"
    << "<numeric name=\"mjbuoy.line." << name << ".anchor\" data=\"" << ax << " " << ay << " "
    << az << "\"/>"
    << "<text name=\"mjbuoy.line." << name << ".fairlead\" data=\"" << site << "\"/>";
  return s.str();
}

// a body of mass M on a surge slide at z = -5, held by three lines at
// 120 degrees: fairleads at radius 10 m, anchors at radius 10 + X on a
// 100 m deep bed
std::string threeLines(double M, double X, const char* integrator = "Euler",
                       double friction = 0.5) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.05\" integrator=\"" << integrator << "\"/><custom>"
    << "<numeric name=\"mjbuoy.sea.depth\" data=\"" << kDepth << "\"/>" << chainType()
    << "<numeric name=\"mjbuoy.seabed.friction\" data=\"" << friction << " " << 2 * friction
    << "\"/>";
  for (int i = 0; i < 3; i++) {
    double a = 2 * M_PI * i / 3, R = 10 + X;
    s << line("l" + std::to_string(i), R * std::cos(a), R * std::sin(a), -kDepth,
              "f" + std::to_string(i));
  }
  s << "</custom><worldbody><body name=\"buoy\" pos=\"0 0 -5\">"
    << "<joint name=\"surge\" type=\"slide\" axis=\"1 0 0\"/>"
    << "<inertial pos=\"0 0 0\" mass=\"" << M << "\" diaginertia=\"1 1 1\"/>";
  for (int i = 0; i < 3; i++) {
    double a = 2 * M_PI * i / 3;
    s << "<site name=\"f" << i << "\" pos=\"" << 10 * std::cos(a) << " " << 10 * std::sin(a)
      << " 0\"/>";
  }
  s << "</body></worldbody></mujoco>";
  return s.str();
}

// surge period of the body released 0.5 m off: upward zero crossings
double surgePeriod(Scene* sc, double T) {
  sc->d->qpos[0] = 0.5;
  std::vector<double> up;
  double prev = 0.5;
  const double dt = sc->m->opt.timestep;
  for (long i = 0; i < std::lround(T / dt); i++) {
    mj_step(sc->m, sc->d);
    double x = sc->d->qpos[0];
    if (!std::isfinite(x)) {
      std::printf("not finite at t = %g: %s\n", sc->d->time, mjb_notices(sc->b, sc->d));
      return NAN;
    }
    if (prev < 0 && x >= 0) up.push_back(sc->d->time - dt * x / (x - prev));
    prev = x;
  }
  if (up.size() < 2) return NAN;
  return (up.back() - up.front()) / (up.size() - 1);
}

// the linear surge period 2 pi sqrt((m + a11) / k) of a body on three
// catenary lines: k = sum_i (dH/dX cos^2 b_i + H / X sin^2 b_i) = 1.5
// (dH/dX + H / X) for lines at 120 degrees (Faltinsen 1990, Sea Loads,
// sec. 8.2: a line's axial stiffness dH/dX and its transverse stiffness
// H / X, X the horizontal fairlead-anchor distance); dH/dX by central
// differences of the elastic catenary (catenary.h, checked against the
// closed-form equations in mooring_test.cc), for small motion (0.5 m) and
// no bed friction, as the catenary has none. The body has no hull: a11 =
// 0; the lines' own mass (3 x 30 t against 5000 t) and drag stay within 5%
TEST(MooringGlue, SurgeDecayPeriod) {
  const double M = 5e6, X = 270;
  const double W = (kMass - 1000 * M_PI * kDiam * kDiam / 4) * 9.81;
  mjb::Catenary a, b, c;
  ASSERT_TRUE(mjb::catenarySolve(X, kDepth - 5, kLen, kEA, W, true, &c));
  ASSERT_TRUE(mjb::catenarySolve(X + 0.1, kDepth - 5, kLen, kEA, W, true, &a));
  ASSERT_TRUE(mjb::catenarySolve(X - 0.1, kDepth - 5, kLen, kEA, W, true, &b));
  const double k = 1.5 * ((a.hf - b.hf) / 0.2 + c.hf / X);
  const double Tn = 2 * M_PI * std::sqrt(M / k);
  for (const char* integ : {"Euler", "RK4"}) {
    Scene sc(threeLines(M, X, integ, 0));
    ASSERT_TRUE(sc.ok()) << sc.err;
    double T = surgePeriod(&sc, 3.2 * Tn);
    EXPECT_NEAR(T, Tn, 0.05 * Tn) << integ;
    EXPECT_STREQ(mjb_notices(sc.b, sc.d), "");
    std::printf("surge (%s): period %.4g s, linear %.4g s (%+.2f%%), k %.4g N/m\n", integ, T, Tn,
                100 * (T / Tn - 1), k);
  }
}

// a floating spar (vertical cylinder, radius 5 m, draft 40 m) on a surge
// slide, held by the three lines of SurgeDecayPeriod: its surge period is
// 2 pi sqrt((m + a11(w)) / k) at w = 2 pi / period, k from the catenary as
// above and a11(w) the hull's surge added mass from mjbuoy's panel solver
// at that frequency, A_inf - (1 / w) int_0^inf K(t) sin(w t) dt from its
// retardation function K (Ogilvie 1964; the simulation uses the fitted
// state-space memory instead), within 5%; strip theory's rho pi R^2 T
// (Newman 1977 sec. 4.13) is printed beside it
TEST(MooringGlue, SurgeDecayFloatingHull) {
  const double R = 5, T = 40, X = 270, rho = 1025;
  const double M = rho * M_PI * R * R * T;  // floats at its draft
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.05\"/><custom>"
    << "<numeric name=\"mjbuoy.sea.depth\" data=\"" << kDepth << "\"/>"
    << "<numeric name=\"mjbuoy.sea.density\" data=\"" << rho << "\"/>"
    << "<text name=\"mjbuoy.hulls\" data=\"spar_hull\"/>" << chainType()
    << "<text name=\"mjbuoy.radiation.body.spar\" data=\"on\"/>"
    << "<numeric name=\"mjbuoy.seabed.friction\" data=\"0 0\"/>";
  for (int i = 0; i < 3; i++) {
    double a = 2 * M_PI * i / 3, Ra = R + X;
    s << line("l" + std::to_string(i), Ra * std::cos(a), Ra * std::sin(a), -kDepth,
              "f" + std::to_string(i));
  }
  s << "</custom><worldbody><body name=\"spar\" pos=\"0 0 0\">"
    << "<joint name=\"surge\" type=\"slide\" axis=\"1 0 0\"/>"
    << "<geom name=\"spar_hull\" type=\"cylinder\" size=\"" << R << " 22\" pos=\"0 0 -18\" mass=\""
    << M << "\"/>";
  for (int i = 0; i < 3; i++) {
    double a = 2 * M_PI * i / 3;
    s << "<site name=\"f" << i << "\" pos=\"" << R * std::cos(a) << " " << R * std::sin(a)
      << " -5\"/>";
  }
  s << "</body></worldbody></mujoco>";
  Scene sc(s.str());
  ASSERT_TRUE(sc.ok()) << sc.err;
  const mjb::Buoy* bb = mjb::buoyOf(sc.b);
  ASSERT_EQ(bb->rad.rb.size(), 1u);
  const mjb::RadBody& rb = bb->rad.rb[0];
  int p = -1;
  for (size_t i = 0; i < rb.pair.size(); i++) if (rb.pair[i] == 0) p = int(i);
  ASSERT_GE(p, 0);
  ASSERT_GT(rb.nk, 0);
  ASSERT_EQ(rb.K.size(), rb.pair.size() * rb.nk);
  // a11 at w (trapezoid rule on the samples K(k dt))
  auto a11at = [&](double w) {
    double in = 0;
    for (int k = 1; k < rb.nk; k++) {
      const double t0 = (k - 1) * bb->rad.dt, t1 = k * bb->rad.dt;
      in += 0.5 * bb->rad.dt * (rb.K[p * rb.nk + k - 1] * std::sin(w * t0) +
                                rb.K[p * rb.nk + k] * std::sin(w * t1));
    }
    return rb.A[0] - in / w;
  };
  const double W = (kMass - 1000 * M_PI * kDiam * kDiam / 4) * 9.81;
  mjb::Catenary a, b, c;
  ASSERT_TRUE(mjb::catenarySolve(X, kDepth - 5, kLen, kEA, W, true, &c));
  ASSERT_TRUE(mjb::catenarySolve(X + 0.1, kDepth - 5, kLen, kEA, W, true, &a));
  ASSERT_TRUE(mjb::catenarySolve(X - 0.1, kDepth - 5, kLen, kEA, W, true, &b));
  const double k = 1.5 * ((a.hf - b.hf) / 0.2 + c.hf / X);
  double Tn = 2 * M_PI * std::sqrt((M + rb.A[0]) / k), a11 = rb.A[0];
  for (int i = 0; i < 20; i++) {  // the period and a11 at its frequency
    a11 = a11at(2 * M_PI / Tn);
    Tn = 2 * M_PI * std::sqrt((M + a11) / k);
  }
  double P = surgePeriod(&sc, 3.2 * Tn);
  EXPECT_NEAR(P, Tn, 0.05 * Tn);
  std::printf("floating spar: a11(w) %.4g kg (A_inf %.4g, strip theory %.4g), m %.4g kg, "
              "period %.4g s, linear %.4g s (%+.2f%%), without a11 %.4g s\n", a11, rb.A[0],
              rho * M_PI * R * R * T, M, P, Tn, 100 * (P / Tn - 1),
              2 * M_PI * std::sqrt(M / k));
}

// the body starts at rest: the lines start on their equilibrium, so it
// moves by far less than the 3 m of the decay test in 20 s
TEST(MooringGlue, StartsAtRest) {
  Scene sc(threeLines(5e6, 250));
  ASSERT_TRUE(sc.ok()) << sc.err;
  for (int i = 0; i < 400; i++) mj_step(sc.m, sc.d);
  EXPECT_LT(std::fabs(sc.d->qpos[0]), 0.01);
}

// a buoy of 20 t on a heave slide, its lines' 20 segments 15 m long,
// held by a constant force: its weight M g plus the lines' pull at t = 0
// (mjb_lineWrench after mj_forward). The lines start on their static
// equilibrium, so their pull stays within 0.5% of 3 V_F (V_F the fairlead's
// vertical tension of the elastic catenary, Irvine 1981; Jonkman 2007 eqs.
// 4-1 to 4-4; MooringLine.StartsOnDiscreteEquilibrium) and in the first
// second the buoy moves at most 0.005 x 3 V_F t^2 / (2 M) (constant
// acceleration; the lines' heave stiffness only holds it closer). Lines
// started on the catenary's points pull 25% short until they settle
TEST(MooringGlue, HeaveStartsAtRest) {
  std::string xml = threeLines(2e4, 250);
  const std::string surge = "axis=\"1 0 0\"";
  xml.replace(xml.find(surge), surge.size(), "axis=\"0 0 1\"");
  Scene sc(xml);
  ASSERT_TRUE(sc.ok()) << sc.err;
  const double W = (kMass - 1000 * M_PI * kDiam * kDiam / 4) * 9.81, M = 2e4, t = 1;
  mjb::Catenary c;
  ASSERT_TRUE(mjb::catenarySolve(250, kDepth - 5, kLen, kEA, W, true, &c));
  const int bd = sc.body("buoy");
  mj_forward(sc.m, sc.d);
  const double f0 = mjb_lineWrench(sc.b, sc.d)[6 * bd + 2];
  EXPECT_NEAR(f0, -3 * c.vf, 0.01 * 3 * c.vf);
  sc.d->xfrc_applied[6 * bd + 2] = M * -sc.m->opt.gravity[2] - f0;
  double worst = 0;
  for (int i = 0; i < std::lround(t / sc.m->opt.timestep); i++) {
    mj_step(sc.m, sc.d);
    worst = std::max(worst, std::fabs(sc.d->qpos[0]));
  }
  const double bound = 0.005 * 3 * c.vf * t * t / (2 * M);
  EXPECT_LT(worst, bound);
  std::printf("heave start: largest |z| in %g s %.4g m, bound %.4g m; pull at t = 0 %.6g N, "
              "-3 V_F %.6g N\n", t, worst, bound, f0, -3 * c.vf);
}

// two box hulls, each on three 200-segment lines (1206 nodes, past the
// 400 at which lines step on the cpu threads), stepped with one thread
// and with two (the boxes' two hull parts give the second thread a
// worker): each line is independent of the others, so the nodes and the
// bodies follow the same path to the bit
std::string twoHullsOnLines(int threads) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.01\"/><custom>"
    << "<numeric name=\"mjbuoy.sea.depth\" data=\"" << kDepth << "\"/>"
    << "<numeric name=\"mjbuoy.threads\" data=\"" << threads << "\"/>"
    << "<text name=\"mjbuoy.radiation\" data=\"off\"/>"
    << "<text name=\"mjbuoy.hulls\" data=\"h0 h1\"/>" << chainType();
  for (int b = 0; b < 2; b++) {
    for (int i = 0; i < 3; i++) {
      const double a = 2 * M_PI * i / 3, x0 = 100 * b;
      s << line("b" + std::to_string(b) + "l" + std::to_string(i), x0 + 260 * std::cos(a),
                260 * std::sin(a), -kDepth, "f" + std::to_string(b), kLen, 200);
    }
  }
  s << "</custom><worldbody>";
  for (int b = 0; b < 2; b++) {
    s << "<body pos=\"" << 100 * b << " 0 0\"><freejoint/><geom name=\"h" << b
      << "\" type=\"box\" size=\"4 4 2\" mass=\"40000\"/><site name=\"f" << b
      << "\" pos=\"0 0 -2\"/></body>";
  }
  s << "</worldbody></mujoco>";
  return s.str();
}

TEST(MooringGlue, ThreadsGiveSameLines) {
  Scene one(twoHullsOnLines(1)), two(twoHullsOnLines(2));
  ASSERT_TRUE(one.ok()) << one.err;
  ASSERT_TRUE(two.ok()) << two.err;
  for (int i = 0; i < 20; i++) {
    mj_step(one.m, one.d);
    mj_step(two.m, two.d);
  }
  ASSERT_EQ(mjb_lineCount(one.b), 6);
  for (int l = 0; l < 6; l++) {
    int n = mjb_lineNodes(one.b, one.d, l, nullptr, 0);
    ASSERT_EQ(n, 201);
    std::vector<double> p1(3 * n), p2(3 * n);
    mjb_lineNodes(one.b, one.d, l, p1.data(), n);
    mjb_lineNodes(two.b, two.d, l, p2.data(), n);
    EXPECT_EQ(p1, p2) << "line " << l;
  }
  for (int i = 0; i < one.m->nq; i++) EXPECT_EQ(one.d->qpos[i], two.d->qpos[i]) << i;
  EXPECT_STREQ(mjb_notices(one.b, one.d), "");
}

std::vector<double> nodes(const Scene& sc, int line) {
  int n = mjb_lineNodes(sc.b, sc.d, line, nullptr, 0);
  std::vector<double> p(3 * n);
  mjb_lineNodes(sc.b, sc.d, line, p.data(), n);
  return p;
}

// mj_forward alone does not step the lines; mj_resetData puts them back
// on their rest shape; mjb_copyData carries them so a copy continues the
// same to the bit
TEST(MooringGlue, ClockResetCopy) {
  Scene sc(threeLines(5e6, 250));
  ASSERT_TRUE(sc.ok()) << sc.err;
  EXPECT_EQ(mjb_lineCount(sc.b), 3);
  sc.d->qpos[0] = 2;
  mj_forward(sc.m, sc.d);
  std::vector<double> rest = nodes(sc, 0);
  ASSERT_EQ(rest.size(), 63u);
  for (int i = 0; i < 5; i++) mj_forward(sc.m, sc.d);
  EXPECT_EQ(nodes(sc, 0), rest);
  for (int i = 0; i < 50; i++) mj_step(sc.m, sc.d);
  EXPECT_NE(nodes(sc, 0), rest);
  mjData* d2 = mj_makeData(sc.m);
  mj_copyData(d2, sc.m, sc.d);
  ASSERT_EQ(mjb_copyData(sc.b, d2, sc.d), 1);
  for (int i = 0; i < 50; i++) {
    mj_step(sc.m, sc.d);
    mj_step(sc.m, d2);
  }
  int n = mjb_lineNodes(sc.b, d2, 0, nullptr, 0);
  std::vector<double> p2(3 * n);
  mjb_lineNodes(sc.b, d2, 0, p2.data(), n);
  EXPECT_EQ(p2, nodes(sc, 0));
  EXPECT_EQ(d2->qpos[0], sc.d->qpos[0]);
  mj_deleteData(d2);
  mj_resetData(sc.m, sc.d);
  sc.d->qpos[0] = 2;
  mj_forward(sc.m, sc.d);
  EXPECT_EQ(nodes(sc, 0), rest);
}

// mjb_lineWrench gives the lines' pull on the body at rest: by symmetry no
// horizontal force, and down three times the fairlead's vertical tension
// V_F of the elastic catenary (Irvine 1981; Jonkman 2007 eqs. 4-1 to 4-4,
// span 250 m, fairlead 95 m above the anchors), within 1% once the
// 20-segment lines have settled (100 s); mjb_wrench (the hull wrench) does
// not hold it. mjb_seabed is at level - depth
TEST(MooringGlue, LineWrenchAndSeabed) {
  Scene sc(threeLines(5e6, 250));
  ASSERT_TRUE(sc.ok()) << sc.err;
  for (int i = 0; i < 2000; i++) mj_step(sc.m, sc.d);
  const mjtNum* w = mjb_lineWrench(sc.b, sc.d);
  ASSERT_TRUE(w);
  const int bd = sc.body("buoy");
  const double W = (kMass - 1000 * M_PI * kDiam * kDiam / 4) * 9.81;
  mjb::Catenary c;
  ASSERT_TRUE(mjb::catenarySolve(250, kDepth - 5, kLen, kEA, W, true, &c));
  EXPECT_NEAR(w[6 * bd + 2], -3 * c.vf, 0.01 * 3 * c.vf);
  EXPECT_NEAR(w[6 * bd], 0, 0.01 * c.hf);
  EXPECT_NEAR(w[6 * bd + 1], 0, 0.01 * c.hf);
  std::printf("line wrench: Fz %.6g N, catenary -3 V_F %.6g N (%+.3f%%)\n", w[6 * bd + 2],
              -3 * c.vf, 100 * (w[6 * bd + 2] / (-3 * c.vf) - 1));
  const mjtNum* h = mjb_wrench(sc.b, sc.d);
  ASSERT_TRUE(h);
  EXPECT_EQ(h[6 * bd + 2], 0);  // no hull: the lines are not in the hull wrench
  mjtNum z = 0;
  EXPECT_EQ(mjb_seabed(sc.b, &z), 1);
  EXPECT_EQ(z, -kDepth);
  // no lines and a deep sea: no bed, and no line wrench
  Scene free("<mujoco><worldbody><body><freejoint/><geom type=\"box\" size=\"1 1 1\"/>"
             "</body></worldbody></mujoco>");
  ASSERT_TRUE(free.ok()) << free.err;
  EXPECT_EQ(mjb_seabed(free.b, &z), 0);
  mj_forward(free.m, free.d);
  EXPECT_EQ(mjb_lineWrench(free.b, free.d), nullptr);
}

std::string attachError(const std::string& custom, const std::string& body) {
  std::string xml = "<mujoco><custom><numeric name=\"mjbuoy.sea.depth\" data=\"100\"/>" +
                    chainType() + custom + "</custom><worldbody>" + body +
                    "</worldbody></mujoco>";
  Scene sc(xml);
  return sc.ok() ? "" : sc.err;
}

// bad lines are refused with the line, the field and the range named
TEST(MooringGlue, RefusesBadLines) {
  const std::string site = "<site name=\"s\" pos=\"50 0 -5\"/>";
  std::string e = attachError(line("a", 0, 0, -100, "s", 0), site);
  EXPECT_NE(e.find("line \"a\""), std::string::npos) << e;
  EXPECT_NE(e.find("length"), std::string::npos) << e;
  EXPECT_NE(e.find("> 0"), std::string::npos) << e;
  e = attachError("<numeric name=\"mjbuoy.linetype.soft.ea\" data=\"0\"/>", site);
  EXPECT_NE(e.find("line type \"soft\""), std::string::npos) << e;
  EXPECT_NE(e.find("ea"), std::string::npos) << e;
  e = attachError(line("a", 0, 0, -100, "nosuch"), site);
  EXPECT_NE(e.find("site \"nosuch\""), std::string::npos) << e;
  e = attachError(line("a", 0, 0, -150, "s"), site);
  EXPECT_NE(e.find("below the seabed"), std::string::npos) << e;
  e = attachError(line("a", 0, 0, -100, "s", 300, 0), site);
  EXPECT_NE(e.find("segments"), std::string::npos) << e;
  e = attachError(line("a", 0, 0, -100, "s") +
                      "<numeric name=\"mjbuoy.line.a.colour\" data=\"1\"/>", site);
  EXPECT_NE(e.find("length, segments, anchor"), std::string::npos) << e;
}

// a line pulled past its length reports its overload once and stays finite
TEST(MooringGlue, TautOverloadNotice) {
  Scene sc(threeLines(5e6, 250));
  ASSERT_TRUE(sc.ok()) << sc.err;
  sc.d->xfrc_applied[6 * sc.body("buoy")] = -2e9;  // away from line 0's anchor
  for (int i = 0; i < 400; i++) mj_step(sc.m, sc.d);
  std::string n = mjb_notices(sc.b, sc.d);
  EXPECT_NE(n.find("line \"l0\""), std::string::npos) << n;
  EXPECT_NE(n.find("overloaded"), std::string::npos) << n;
  EXPECT_TRUE(std::isfinite(sc.d->qpos[0]));
  for (double x : nodes(sc, 0)) ASSERT_TRUE(std::isfinite(x));
}

// a line lying wholly on the bed (both ends on it, closer than its
// length) stays there, slack: the fairlead feels only its half segment
TEST(MooringGlue, LineOnSeabed) {
  std::string xml = "<mujoco><option timestep=\"0.05\"/><custom>"
                    "<numeric name=\"mjbuoy.sea.depth\" data=\"100\"/>" + chainType() +
                    line("a", 0, 0, -100, "s") + "</custom><worldbody>"
                    "<site name=\"s\" pos=\"100 0 -100\"/></worldbody></mujoco>";
  Scene sc(xml);
  ASSERT_TRUE(sc.ok()) << sc.err;
  for (int i = 0; i < 400; i++) mj_step(sc.m, sc.d);
  for (size_t i = 2; i < 63; i += 3) {
    std::vector<double> p = nodes(sc, 0);
    ASSERT_TRUE(std::isfinite(p[i]));
    EXPECT_NEAR(p[i], -100, 0.05);
  }
}

// a seabed deeper than the line reaches: the line hangs free from an
// anchor above the bed, touching nothing
TEST(MooringGlue, BedBeyondReach) {
  std::string xml = "<mujoco><option timestep=\"0.05\"/><custom>"
                    "<numeric name=\"mjbuoy.sea.depth\" data=\"1000\"/>" + chainType() +
                    line("a", 0, 0, -100, "s", 150) + "</custom><worldbody>"
                    "<site name=\"s\" pos=\"100 0 -5\"/></worldbody></mujoco>";
  Scene sc(xml);
  ASSERT_TRUE(sc.ok()) << sc.err;
  for (int i = 0; i < 400; i++) mj_step(sc.m, sc.d);
  std::vector<double> p = nodes(sc, 0);
  for (size_t i = 2; i < p.size(); i += 3) {
    ASSERT_TRUE(std::isfinite(p[i]));
    EXPECT_GT(p[i], -400);
  }
  EXPECT_STREQ(mjb_notices(sc.b, sc.d), "");
}

}  // namespace

namespace {

// the shipped moored buoy (models/moored_buoy.xml) in its JONSWAP sea
// (Hs 2 m) stays finite, held near its anchors' centre, its lines taut
// but far from overload: 20 s by default, MJBUOY_SOAK_SECONDS under the
// soak label (600 s, tests/CMakeLists.txt)
TEST(MooredBuoy, JonswapStaysBounded) {
  double T = 20;
  if (const char* e = std::getenv("MJBUOY_SOAK_SECONDS")) T = std::atof(e);
  ASSERT_GT(T, 0);
  mjModel* m = mj_loadXML(MJB_MODELS "/moored_buoy.xml", nullptr, nullptr, 0);
  ASSERT_TRUE(m);
  char err[1024];
  mjbBuoy* b = mjb_attach(m, nullptr, err, sizeof(err));
  ASSERT_TRUE(b) << err;
  mjData* d = mj_makeData(m);
  const int ten = m->sensor_adr[mj_name2id(m, mjOBJ_SENSOR, "tension_a")];
  double tmax = 0;
  for (long i = 0; i < std::lround(T / m->opt.timestep); i++) {
    mj_step(m, d);
    ASSERT_TRUE(std::isfinite(d->qpos[0]) && std::isfinite(d->sensordata[ten])) << d->time;
    tmax = std::max(tmax, d->sensordata[ten]);
    // a chain of 130 m on anchors 100 m out lets the buoy drift a few metres
    ASSERT_LT(std::hypot(d->qpos[0], d->qpos[1]), 15) << d->time;
  }
  // the fairlead carries at least its hanging chain (about 45 m of 256 N/m)
  // and stays far below the 10% strain overload, EA / 10 = 1.2e7 N
  EXPECT_GT(d->sensordata[ten], 5e3);
  EXPECT_LT(tmax, 1.2e7);
  EXPECT_STREQ(mjb_notices(b, d), "");
  std::printf("moored buoy %g s: max fairlead tension %.4g N\n", T, tmax);
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
}

}  // namespace

namespace {

// the shipped taut-moored wave-energy float (models/wec_taut.xml): its
// tether starts at the design pretension EA (26.45 / 26.406 - 1) = 50 kN
// (Hooke, the rope's weight, 18 N/m, aside) and stays taut and finite in
// 20 s of its JONSWAP sea, the power take-off moving
TEST(MooredBuoy, TautWecFloat) {
  mjModel* m = mj_loadXML(MJB_MODELS "/wec_taut.xml", nullptr, nullptr, 0);
  ASSERT_TRUE(m);
  char err[1024];
  mjbBuoy* b = mjb_attach(m, nullptr, err, sizeof(err));
  ASSERT_TRUE(b) << err;
  mjData* d = mj_makeData(m);
  const int ten = m->sensor_adr[mj_name2id(m, mjOBJ_SENSOR, "tether_tension")];
  mj_forward(m, d);
  const double T0 = 3e7 * (26.45 / 26.406 - 1);
  EXPECT_NEAR(d->sensordata[ten], T0, 0.01 * T0);
  double qmin = 0, qmax = 0;
  for (int i = 0; i < 4000; i++) {
    mj_step(m, d);
    ASSERT_TRUE(std::isfinite(d->qpos[0]) && std::isfinite(d->sensordata[ten])) << d->time;
    ASSERT_GT(d->sensordata[ten], 0) << d->time;  // taut
    qmin = std::min(qmin, d->qpos[7]);
    qmax = std::max(qmax, d->qpos[7]);
  }
  EXPECT_GT(qmax - qmin, 0.05);  // the take-off strokes
  EXPECT_STREQ(mjb_notices(b, d), "");
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
}

}  // namespace
