// the immersion factor of the radiation terms (docs/physics.md, "Immersion
// factor"): added mass, Kirchhoff, memory and diffraction act on the wetted
// surface, so a dry hull has none of them
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "floatbox.h"
#include "testutil.h"

namespace {

using mjbt::Scene;
using mjbt::kG;
using mjbt::kRho;

const double kMass = kRho * 0.5;

// heave entry of MuJoCo's inertia matrix after mj_forward at centre height
// z [m] (qpos[2]; the COM is 0.2 m lower), heave velocity w [m/s]
double heaveInertia(Scene& s, double z, double w = 0) {
  mj_resetData(s.m, s.d);
  s.d->qpos[2] = z;
  s.d->qvel[2] = w;
  mj_forward(s.m, s.d);
  return s.d->qM[s.m->dof_Madr[2]];
}

TEST(RadImmersion, DryHullFallsAtG) {
  // above the water nothing touches the hull: Newton gives qacc_z = -g
  // exactly (no added mass, no memory, no Kirchhoff force, no diffraction).
  // Before the immersion factor it fell at -g m / (m + A33)
  Scene s(mjbt::floatingCubeXML());
  ASSERT_TRUE(s.ok()) << s.err;
  const mjb::Buoy& B = *mjb::buoyOf(s.b);
  ASSERT_EQ(B.rad.rb.size(), 1u);
  const double a33 = B.rad.rb[0].A[14];
  // the test can fail: the added mass is a sizeable part of the inertia
  ASSERT_GT(a33, 0.1 * kMass);
  // wet first (memory history of a heaving body), then thrown up: bottom
  // at z - 0.5, dry while the centre is above 0.5 m
  s.d->qpos[2] = -0.1;
  s.d->qvel[2] = 1.0;
  mj_forward(s.m, s.d);
  for (int k = 0; k < 100; k++) mj_step(s.m, s.d);
  s.d->qpos[2] = 2;
  s.d->qvel[2] = -3;
  s.d->qvel[3] = 0.5;  // a roll rate: Kirchhoff terms would act on it
  // lowest corner of the rolling cube [m]
  auto lowest = [&] {
    const mjtNum *c = s.d->geom_xpos, *R = s.d->geom_xmat;
    return c[2] - 0.5 * (std::fabs(R[6]) + std::fabs(R[7]) + std::fabs(R[8]));
  };
  int dry = 0;
  mj_forward(s.m, s.d);
  for (int k = 0; k < 400 && lowest() > 1e-3; k++) {
    // the COM's classical acceleration (the free joint's qacc is the body
    // origin's, 0.2 m off the rolling COM) less gravity, as MuJoCo's cacc
    // counts it (an accelerometer's reading): 0 in free fall, and no
    // angular one (torque free, inertia isotropic about the COM)
    mj_rnePostConstraint(s.m, s.d);
    mjtNum a[6];
    mj_objectAcceleration(s.m, s.d, mjOBJ_BODY, 1, a, 0);
    for (int j = 0; j < 6; j++) {
      EXPECT_NEAR(a[j], 0, 1e-6 * kG) << "step " << k << " z " << s.d->qpos[2] << " component "
                                      << j;
    }
    EXPECT_NEAR(s.d->qM[s.m->dof_Madr[2]], kMass, 1e-9 * kMass);
    dry++;
    mj_step(s.m, s.d);
    mj_forward(s.m, s.d);
  }
  EXPECT_GT(dry, 10);
  std::printf("[radimmersion] dry fall: %d steps at -g (A33 %.1f kg, m %.1f kg: before, "
              "qacc %.4f m/s^2)\n", dry, a33, kMass, -kG * kMass / (kMass + a33));
}

TEST(RadImmersion, FloatingBodyHasItsFullAddedMass) {
  // at its equilibrium (centre at 0) and everywhere it keeps at least half
  // its 0.5 m^3 displacement (centre below 0.25 m), the whole A33 of the
  // panel solution is in the inertia, bit for bit as before the factor:
  // the linear tests (free decay, RAO) run unchanged
  Scene s(mjbt::floatingCubeXML());
  ASSERT_TRUE(s.ok()) << s.err;
  const double a33 = mjb::buoyOf(s.b)->rad.rb[0].A[14];
  for (double z : {0.0, -0.05, 0.05, 0.2, -0.4, -1.0}) {
    EXPECT_EQ(heaveInertia(s, z), kMass + a33) << "centre at " << z << " m";
  }
}

TEST(RadImmersion, EmergingHullLosesItsAddedMassContinuously) {
  // the cube's displaced volume at centre height z is V = 0.5 - z [m^3]
  // (1 m^2 waterplane, bottom at z - 0.5), V_eq = 0.5 m^3: the factor is
  // s = clamp(V / (0.5 V_eq), 0, 1) = clamp((0.5 - z) / 0.25, 0, 1), and
  // the heave inertia m + s A33 is continuous with slope at most A33 / 0.25
  // per metre of heave. The water-entry force (on by default) is off here:
  // it is the inelastic impact -ds/dt A33 w, a deceleration of 16 m/s^2 at
  // this entry that the drop below would count as a jump; what is checked
  // is the added mass switching on alone (the entry force: radentry_test.cc)
  std::string xml = mjbt::floatingCubeXML();
  const std::string on = "<text name=\"mjbuoy.radiation\" data=\"on\"/>";
  xml.insert(xml.find(on) + on.size(), "<text name=\"mjbuoy.radiation.entry\" data=\"off\"/>");
  Scene s(xml);
  ASSERT_TRUE(s.ok()) << s.err;
  const double a33 = mjb::buoyOf(s.b)->rad.rb[0].A[14];
  double last = NAN, worst = 0;
  const double dz = 1e-3;
  for (double z = 0.2; z <= 0.6 + 1e-12; z += dz) {
    const double M = heaveInertia(s, z, -1.0);
    ASSERT_TRUE(std::isfinite(M));
    const double want = kMass + a33 * std::clamp((0.5 - z) / 0.25, 0.0, 1.0);
    EXPECT_NEAR(M, want, 1e-9 * (kMass + a33)) << "centre at " << z << " m";
    for (int i = 0; i < s.m->nv; i++) ASSERT_TRUE(std::isfinite(s.d->qfrc_passive[i]));
    if (std::isfinite(last)) worst = std::max(worst, std::fabs(M - last));
    last = M;
  }
  EXPECT_LE(worst, a33 * dz / 0.25 * (1 + 1e-6));
  // a drop from 1 m through the surface: finite, no MuJoCo reset, and the
  // heave acceleration changes by less than g plus the buoyancy change of
  // one step between steps (no jump from the added mass switching on)
  mj_resetData(s.m, s.d);
  s.d->qpos[2] = 1.0;
  mj_forward(s.m, s.d);
  double a0 = s.d->qacc[2], jump = 0;
  for (int k = 0; k < 600; k++) {
    mj_step(s.m, s.d);
    mj_forward(s.m, s.d);
    ASSERT_TRUE(std::isfinite(s.d->qacc[2])) << "step " << k;
    jump = std::max(jump, std::fabs(s.d->qacc[2] - a0));
    a0 = s.d->qacc[2];
  }
  EXPECT_EQ(s.d->warning[mjWARN_BADQACC].number, 0);
  // per 5 ms step at the entry speed v = sqrt(2 g 0.5 m) = 3.1 m/s: the
  // buoyancy grows by rho g A_wp v dt / m = 0.31 m/s^2 and the factor by
  // v dt / 0.25 m = 0.063, moving g A33 / (m + A33) = 3.8 m/s^2 by 0.24:
  // below g / 10; A33 switched on at once would jump by the 3.8 m/s^2
  EXPECT_LT(jump, 0.1 * kG);
  std::printf("[radimmersion] emerging: largest inertia change per mm %.3f kg (bound %.3f); "
              "drop: largest qacc change per step %.3f m/s^2\n", worst, a33 * dz / 0.25, jump);
}

}  // namespace
