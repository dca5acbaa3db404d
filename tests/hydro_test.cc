// hydrodynamics: tow resistance against the ITTC line by hand, slamming
// bounds, free decay, drift with a current
#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

// 2 x 1 x 0.5 m box of 500 kg (draft 0.25 m); `custom` adds mjbuoy entries,
// `joint` is the body's joint(s)
std::string box(const std::string& custom, const std::string& joint,
                const std::string& extra = "", const char* pos = "0 0 0") {
  return "<mujoco><option timestep=\"0.002\"/><custom>"
         "<text name=\"mjbuoy.hulls\" data=\"hull\"/>" + custom +
         "</custom><worldbody><body name=\"b\" pos=\"" + pos + "\">" + joint +
         "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/></body>"
         "</worldbody>" + extra + "</mujoco>";
}

const char kViscousOnly[] =
    "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0.5\"/>"
    "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0.5\"/>"
    "<numeric name=\"mjbuoy.hull.slamming\" data=\"0 100 2\"/>";

TEST(Hydro, TowResistanceFollowsITTC57) {
  // towed along x at the equilibrium draft by a stiff velocity servo; at
  // steady speed the servo force is the resistance. By hand: wetted area
  // S = bottom + 2 sides = L B + 2 L T = 3 m^2 (the end faces meet the flow
  // head-on and feel no shear), Rn = V L / nu,
  // C_F = 0.075 / (log10 Rn - 2)^2, R = 0.5 rho C_F (1+k) S V^2, 1+k = 1.3.
  // Radiation off: the viscous part alone, at 4 s of tow (with radiation on
  // the memory's fitted modes need longer to pass: the next test)
  Scene s(box(std::string(kViscousOnly) + "<text name=\"mjbuoy.radiation\" data=\"off\"/>",
              "<joint name=\"x\" type=\"slide\" axis=\"1 0 0\"/>",
              "<actuator><velocity joint=\"x\" kv=\"1e5\"/></actuator>"));
  ASSERT_TRUE(s.ok()) << s.err;
  for (double V : {0.5, 1.0, 2.0}) {
    mj_resetData(s.m, s.d);
    s.d->ctrl[0] = V;
    double R = s.settle(4, 1, [&] { return s.d->actuator_force[0]; });
    double v = s.d->qvel[0];
    double rn = v * 2 / 1e-6, cf = 0.075 / std::pow(std::log10(rn) - 2, 2);
    double hand = 0.5 * kRho * cf * 1.3 * 3 * v * v;
    EXPECT_NEAR(R, hand, 0.02 * hand) << "V = " << V << " Rn " << rn << " C_F " << cf;
    RecordProperty("tow_" + std::to_string(V), std::to_string(R) + " vs " + std::to_string(hand));
  }
}

TEST(Hydro, TowResistanceWithRadiationOnIsStillITTC57) {
  // the test above with radiation on (panel solver): once the memory has
  // passed, a steady tow feels no radiation (B(0) = 0; docs/physics.md
  // section 14, "Steady gain"), so the resistance is ITTC 1957's again
  Scene s(box(std::string(kViscousOnly) + "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
              "<numeric name=\"mjbuoy.radiation.omega\" data=\"1 9 6\"/>",
              "<joint name=\"x\" type=\"slide\" axis=\"1 0 0\"/>",
              "<actuator><velocity joint=\"x\" kv=\"1e5\"/></actuator>"));
  ASSERT_TRUE(s.ok()) << s.err;
  mj_forward(s.m, s.d);
  ASSERT_GT(s.d->qM[s.m->dof_Madr[0]], 1.05 * 500);  // surge added mass: radiation is on
  s.d->ctrl[0] = 0.5;
  double R = s.settle(30, 1, [&] { return s.d->actuator_force[0]; });
  double v = s.d->qvel[0];
  double rn = v * 2 / 1e-6, cf = 0.075 / std::pow(std::log10(rn) - 2, 2);
  double hand = 0.5 * kRho * cf * 1.3 * 3 * v * v;
  EXPECT_NEAR(R, hand, 0.02 * hand);
}

TEST(Hydro, ViscousForceOpposesMotionAtAnyHeading) {
  // a free box moving horizontally in calm water at rest: viscous force is
  // opposite the velocity component along the hull and never drives it
  Scene s(box(kViscousOnly, "<freejoint/>"));
  ASSERT_TRUE(s.ok()) << s.err;
  int b = s.body("b");
  for (double a = 0; a < 2 * M_PI; a += 0.3) {
    mj_resetData(s.m, s.d);
    s.d->qvel[0] = std::cos(a);
    s.d->qvel[1] = std::sin(a);
    mj_forward(s.m, s.d);
    const mjtNum* f = mjb_wrenchPart(s.b, s.d, mjbPART_VISCOUS) + 6 * b;
    EXPECT_LT(f[0] * s.d->qvel[0] + f[1] * s.d->qvel[1], 0) << a;
  }
}

TEST(Hydro, SlammingNeverReversesAndReducesPenetration) {
  // dropped with its bottom 5 m above the water; slamming never does
  // positive work, each step its impulse along the velocity is at most the
  // body's momentum, and the peak depth with slamming is smaller than
  // without. Each triangle's force is against that triangle's own velocity
  // (docs/physics.md eq. 4.6), so the power of the wrench, f.v + tq.w =
  // -sum_j c_j |v_j|^2 with c_j >= 0, is never positive; f.v alone is not
  // bound to be when the body also turns (with radiation on, the box's
  // panel coefficients couple heave to roll and pitch: near rest at 4.5 s
  // it turns at 3e-3 rad/s and moves at 0.7 mm/s, and a 1.9e-4 N slamming
  // force had +1.1e-4 N along v, with negative power)
  auto drop = [&](bool slam, double* worst) {
    std::string c = slam ? "" : "<numeric name=\"mjbuoy.hull.slamming\" data=\"0 100 2\"/>";
    Scene s(box(c, "<freejoint/>", "", "0 0 5.25"));
    EXPECT_TRUE(s.ok()) << s.err;
    int b = s.body("b");
    double lowest = 1e9, dt = s.m->opt.timestep;
    *worst = 0;
    for (long step = 0, nstep = mjbt::stepsTo(s.m, s.d, 6); step < nstep; step++) {
      // the step's forces are computed from the state it starts from;
      // the free joint's angular velocity is in the body frame
      double v[3] = {s.d->qvel[0], s.d->qvel[1], s.d->qvel[2]}, w[3];
      mju_rotVecMat(w, s.d->qvel + 3, s.d->xmat + 9 * b);
      mj_step(s.m, s.d);
      lowest = std::min(lowest, s.d->xipos[3 * b + 2]);
      const mjtNum* f = mjb_wrenchPart(s.b, s.d, mjbPART_SLAM) + 6 * b;
      // round-off of the sum: 1e-12 of its terms' size
      double pw = mju_dot3(f, v) + mju_dot3(f + 3, w);
      double scale = mju_norm3(f) * mju_norm3(v) + mju_norm3(f + 3) * mju_norm3(w);
      EXPECT_LE(pw, 1e-12 * scale) << "slamming does positive work at t " << s.d->time;
      double sp = mju_norm3(v);
      if (sp > 0) *worst = std::max(*worst, -mju_dot3(f, v) / sp * dt / (500 * sp));
    }
    return lowest;
  };
  double wslam, woff;
  double deep = drop(true, &wslam), deepOff = drop(false, &woff);
  EXPECT_LE(wslam, 1.0) << "slamming impulse exceeds the momentum";
  EXPECT_GT(wslam, 0.1) << "slamming barely acted";
  EXPECT_EQ(woff, 0);
  EXPECT_GT(deep, deepOff + 0.05) << "with " << deep << " without " << deepOff;
  RecordProperty("lowest_com", std::to_string(deep) + " vs " + std::to_string(deepOff));
}

TEST(Hydro, FreeHeaveDecayIsMonotonic) {
  // released 0.1 m below equilibrium, default forces (simple damping off)
  Scene s(box("", "<freejoint/>", "", "0 0 -0.1"));
  ASSERT_TRUE(s.ok()) << s.err;
  std::vector<double> peaks;
  double z0 = s.d->qpos[2], z1 = z0;
  int n = 0;
  for (long step = 0, nstep = mjbt::stepsTo(s.m, s.d, 20); step < nstep; step++) {
    mj_step(s.m, s.d);
    double z2 = s.d->qpos[2];
    if (n++ > 1 && z1 > z0 && z1 >= z2) peaks.push_back(z1);
    z0 = z1;
    z1 = z2;
  }
  ASSERT_GE(peaks.size(), 3u);
  for (size_t i = 1; i < peaks.size(); i++) {
    EXPECT_LT(std::fabs(peaks[i]), std::fabs(peaks[i - 1])) << "peak " << i;
  }
  EXPECT_LT(std::fabs(z1), 0.01);  // and it settles
}

TEST(Hydro, DriftsWithTheCurrentOnlyThroughDrag) {
  // radiation off: Kerner's drag alone (with radiation on:
  // DriftsWithTheCurrentWithRadiationOn)
  const char cur[] = "<numeric name=\"mjbuoy.sea.current\" data=\"0.3 0.4\"/>"
                     "<text name=\"mjbuoy.radiation\" data=\"off\"/>";
  Scene s(box(cur, "<freejoint/>"));
  ASSERT_TRUE(s.ok()) << s.err;
  s.settle(90, 1, [] { return 0; });
  EXPECT_NEAR(s.d->qvel[0], 0.3, 0.01 * 0.5);
  EXPECT_NEAR(s.d->qvel[1], 0.4, 0.01 * 0.5);
  Scene off(box(std::string(cur) + "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>"
                "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0.5\"/>"
                "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0.5\"/>", "<freejoint/>"));
  ASSERT_TRUE(off.ok()) << off.err;
  off.settle(90, 1, [] { return 0; });
  EXPECT_LT(std::hypot(off.d->qvel[0], off.d->qvel[1]), 1e-6);
}

TEST(Hydro, DriftsWithTheCurrentWithRadiationOn) {
  // radiation acts on the velocity relative to the water and its memory has
  // no steady gain (B(0) = 0; docs/physics.md section 14): with it on the
  // box still drifts at the current's velocity. The linear drag terms are
  // given (Kerner's 100 N/m^2 at 1 m/s, the default without radiation):
  // with radiation on they default to 0 (docs/physics.md section 16) and
  // the quadratic terms alone close the gap to the current only as 1/t
  Scene s(box("<numeric name=\"mjbuoy.sea.current\" data=\"0.3 0.4\"/>"
              "<numeric name=\"mjbuoy.hull.drag\" data=\"100 400 0.5\"/>"
              "<numeric name=\"mjbuoy.hull.suction\" data=\"100 200 0.5\"/>"
              "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
              "<numeric name=\"mjbuoy.radiation.omega\" data=\"1 9 6\"/>", "<freejoint/>"));
  ASSERT_TRUE(s.ok()) << s.err;
  mj_forward(s.m, s.d);
  ASSERT_GT(s.d->qM[s.m->dof_Madr[2]], 1.2 * 500);  // radiation is on: heave added mass
  s.settle(90, 1, [] { return 0; });
  EXPECT_NEAR(s.d->qvel[0], 0.3, 0.01 * 0.5);
  EXPECT_NEAR(s.d->qvel[1], 0.4, 0.01 * 0.5);
  EXPECT_STREQ(mjb_notices(s.b, s.d), "");
}

}  // namespace
}  // namespace mjbt

namespace mjbt {
namespace {

// the motorboat of models/motorboat.xml with its thruster yawed `deg` off
// the centreline and drag exponents f_P = f_S = f (drag off when f < 0)
std::string motorboat(double deg, double f) {
  std::string drag = f < 0 ? "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0.5\"/>"
                             "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0.5\"/>"
                           : "<numeric name=\"mjbuoy.hull.drag\" data=\"100 400 " +
                                 std::to_string(f) + "\"/><numeric name=\"mjbuoy.hull.suction\""
                                 " data=\"100 200 " + std::to_string(f) + "\"/>";
  return "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
         "/meshes/wigley_576.obj\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>" +
         drag + "</custom><worldbody><body name=\"boat\" pos=\"0 0 0.034\"><freejoint/>"
         "<inertial pos=\"0 0 -0.08\" mass=\"176.2\" diaginertia=\"6.020 237.28 238.60\"/>"
         "<geom name=\"hull\" type=\"mesh\" mesh=\"w\"/>"
         "<site name=\"thruster\" pos=\"-1.9 0 -0.15\" euler=\"0 0 " + std::to_string(deg) +
         "\"/></body></worldbody><actuator><motor site=\"thruster\" gear=\"1 0 0 0 0 0\"/>"
         "</actuator></mujoco>";
}

// steady turn: speed over yaw rate after the transient [m]
struct Turn { double radius, speed, sway[mjbNPART]; };
Turn turn(double deg, double f) {
  Scene s(motorboat(deg, f));
  EXPECT_TRUE(s.ok()) << s.err;
  s.d->ctrl[0] = 60;
  Turn r = {0, 0, {0}};
  double yaw = 0, dist = 0, T0 = 80, T1 = 100;
  for (long step = 0, nstep = mjbt::stepsTo(s.m, s.d, T1); step < nstep; step++) {
    mj_step(s.m, s.d);
    if (s.d->time <= T0) continue;
    const mjtNum* v = s.d->qvel;
    double dt = s.m->opt.timestep;
    yaw += v[5] * dt;  // world z angular velocity
    dist += std::hypot(v[0], v[1]) * dt;
    // sideways force on the hull in its own frame, by force family
    const mjtNum* R = s.d->xmat + 9;
    for (int p = 0; p < mjbNPART; p++) {
      const mjtNum* w = mjb_wrenchPart(s.b, s.d, p) + 6;
      r.sway[p] += (R[1] * w[0] + R[4] * w[1] + R[7] * w[2]) * dt / (T1 - T0);
    }
  }
  r.speed = dist / (T1 - T0);
  r.radius = dist / std::fabs(yaw);
  return r;
}

TEST(Hydro, SelfPropelledBoatReachesSteadySpeed) {
  // 60 N of thrust: the speed levels off, where the hydrodynamic resistance
  // along the track balances the thrust
  Scene s(motorboat(0, 0.5));
  ASSERT_TRUE(s.ok()) << s.err;
  s.d->ctrl[0] = 60;
  s.settle(40, 1, [] { return 0; });
  double v40 = s.d->qvel[0];
  double drag = s.settle(60, 5, [&] { return s.wrench(1)[0]; });
  double v60 = s.d->qvel[0];
  EXPECT_GT(v40, 0.5);
  EXPECT_NEAR(v60, v40, 0.01 * v40);
  EXPECT_NEAR(drag, -60, 0.02 * 60);
  RecordProperty("steady_speed", std::to_string(v60));
}

TEST(Hydro, TurningRadiusShrinksWithLowerDragExponents) {
  // thruster yawed 10 deg: a steady turn. Lower f_P, f_S give faces that
  // meet the flow obliquely more pressure drag (cos^f), hence more sideways
  // resistance and a tighter turn (Kerner part 2)
  Turn a = turn(10, 0.5), b = turn(10, 0.25), c = turn(10, 0.1);
  EXPECT_LT(b.radius, 0.95 * a.radius) << a.radius << " " << b.radius;
  EXPECT_LT(c.radius, 0.95 * b.radius) << b.radius << " " << c.radius;
  // the sideways force resisting the drift is pressure/suction drag
  EXPECT_GT(std::fabs(a.sway[mjbPART_DRAG]), 3 * std::fabs(a.sway[mjbPART_VISCOUS]));
  // without pressure drag nothing resists the drift: the boat spins in place
  Turn off = turn(10, -1);
  EXPECT_LT(off.radius, 0.1 * a.radius);
  RecordProperty("radius", std::to_string(a.radius) + " " + std::to_string(b.radius) + " " +
                               std::to_string(c.radius) + " off " + std::to_string(off.radius));
}

}  // namespace
}  // namespace mjbt
