// water entry with the immersion factor (docs/physics.md section 14,
// "Water entry"): a hull that wets takes up the water's momentum, so the
// added mass it gains does not create energy
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "floatbox.h"
#include "testutil.h"

namespace {

using mjbt::Scene;
using mjbt::kG;
using mjbt::kRho;

const double kMass = kRho * 0.5;

// the floating cube of RadImmersion with mjbuoy.radiation.entry on or off
std::string cubeXML(bool entry) {
  std::string x = mjbt::floatingCubeXML();
  const std::string on = "<text name=\"mjbuoy.radiation\" data=\"on\"/>";
  const size_t at = x.find(on);
  x.insert(at + on.size(), std::string("<text name=\"mjbuoy.radiation.entry\" data=\"") +
                               (entry ? "on" : "off") + "\"/>");
  return x;
}

// mechanical energy of the heaving cube [J]: kinetic energy of body and
// water 1/2 qvel^T M qvel, with M the inertia (M + s A_inf) the step that
// gave qvel solved with (Euler: M_n qvel_{n+1} = M_n qvel_n + h f_n), the
// COM's height in gravity, and the buoyancy's potential of a 1 m^2
// waterplane at bottom depth h = 0.5 - z, rho g h^2 / 2 up to h = 1 (the
// cube under) and rho g (h - 1/2) below (its force rho g min(h, 1) is
// minus its derivative in z)
double energy(const Scene& s, const std::vector<mjtNum>& qM) {
  std::vector<mjtNum> mv(s.m->nv), keep(s.d->qM, s.d->qM + s.m->nM);
  std::copy(qM.begin(), qM.end(), s.d->qM);
  mj_mulM(s.m, s.d, mv.data(), s.d->qvel);
  std::copy(keep.begin(), keep.end(), s.d->qM);
  const double ke = 0.5 * mju_dot(s.d->qvel, mv.data(), s.m->nv);
  const double z = s.d->qpos[2];
  const double h = std::max(0.5 - z, 0.0);
  const double ub = h <= 1 ? h * h / 2 : h - 0.5;
  return ke + kMass * kG * (z - 0.2) + kRho * kG * ub;
}

struct Drop {
  double e0 = 0, emax = 0, eIn = 0, vIn = 0, eOut = 0;
};

// the cube released 0.5 m above the water (bottom at 0.5 m), heave only:
// its energy at release, largest over 2 s, and just before the bottom
// touches (with the speed there) and once the factor is 1 (z < 0.25 m)
Drop drop(bool entry) {
  Scene s(cubeXML(entry));
  EXPECT_TRUE(s.ok()) << s.err;
  Drop r;
  if (!s.ok()) return r;
  s.d->qpos[2] = 1.0;
  mj_forward(s.m, s.d);
  std::vector<mjtNum> qM(s.d->qM, s.d->qM + s.m->nM);
  r.e0 = r.emax = energy(s, qM);
  double e = r.e0;
  for (int k = 0; k < 400; k++) {
    const double z0 = s.d->qpos[2], w = s.d->qvel[2], e0 = e;
    qM.assign(s.d->qM, s.d->qM + s.m->nM);
    mj_step(s.m, s.d);
    mj_forward(s.m, s.d);
    e = energy(s, qM);
    const double z = s.d->qpos[2];
    if (z0 >= 0.5 && z < 0.5 && r.vIn == 0) {
      r.eIn = e0;
      r.vIn = -w;
    }
    if (z0 >= 0.25 && z < 0.25 && r.eOut == 0) r.eOut = e;
    r.emax = std::max(r.emax, e);
    // the cube falls flat: the heave carries its energy
    EXPECT_LT(std::fabs(s.d->qpos[0]) + std::fabs(s.d->qpos[1]), 1e-2) << "step " << k;
  }
  return r;
}

TEST(RadEntry, DroppedCubeLosesTheInelasticEnergyOfTheWaterItPicksUp) {
  // momentum (m + s A33) w is kept while s rises (the entry force
  // -ds/dt A33 w), so the entry is an inelastic collision of the body with
  // the water it wets: for (m + s A) w = m v0 the kinetic energy falls by
  // int_0^1 (1/2) A w^2 ds = (1/2) m v0^2 A / (m + A), whatever the path of
  // s [von Karman 1929; Faltinsen 1990, sec. 9.2]. Gravity and buoyancy are
  // counted in the energy; the memory only dissipates more
  Scene s(cubeXML(true));
  ASSERT_TRUE(s.ok()) << s.err;
  const double a33 = mjb::buoyOf(s.b)->rad.rb[0].A[14];
  ASSERT_GT(a33, 0.1 * kMass);
  const Drop on = drop(true), off = drop(false);
  const double mgh = kMass * kG * 0.5;
  // free fall to the water: the speed of a 0.5 m drop (Euler at 5 ms)
  EXPECT_NEAR(on.vIn, std::sqrt(2 * kG * 0.5), 0.02 * std::sqrt(2 * kG * 0.5));
  const double want = 0.5 * kMass * on.vIn * on.vIn * a33 / (kMass + a33);
  const double lost = on.eIn - on.eOut;
  std::printf("[radentry] A33 %.1f kg; entry at %.3f m/s: energy lost %.1f J, inelastic "
              "%.1f J; largest energy %.1f J over release %.1f J (entry off: %.1f J, "
              "gained %.1f J over the entry)\n", a33, on.vIn, lost, want, on.emax, on.e0,
              off.emax, off.eOut - off.eIn);
  // never more energy than at release (Euler's own error in the fall,
  // m g^2 h^2 / 2 a step, is a loss)
  EXPECT_LE(on.emax, on.e0 + 1e-3 * mgh);
  // at least the inelastic loss; more, as gravity speeds the cube while it
  // wets (m g over the 0.08 s of the entry is a quarter of m v0, so w^2 up
  // to 1.5 times v0^2) and the memory dissipates
  EXPECT_GT(lost, 0.9 * want);
  EXPECT_LT(lost, 1.5 * want);
  // without the entry force the water's kinetic energy (1/2) A33 w^2 comes
  // from nowhere as s rises: the energy grows over the entry
  EXPECT_GT(off.eOut - off.eIn, 0.2 * want);
}

TEST(RadEntry, SmallMotionsAreThoseOfTheLinearModel) {
  // released 5 cm low (RadAttach's decays), the cube keeps more than half
  // its displacement, so s stays 1 and ds/dt 0: the entry term adds
  // nothing, bit for bit, to the linear radiation of the free decay
  Scene a(cubeXML(true)), b(cubeXML(false));
  ASSERT_TRUE(a.ok() && b.ok()) << a.err << b.err;
  for (Scene* s : {&a, &b}) {
    s->d->qpos[2] = -0.05;
    s->d->qvel[4] = 0.2;  // and a pitch rate: the Kirchhoff terms act too
  }
  for (int k = 0; k < 2000; k++) {
    mj_step(a.m, a.d);
    mj_step(b.m, b.d);
  }
  for (int i = 0; i < a.m->nq; i++) EXPECT_EQ(a.d->qpos[i], b.d->qpos[i]) << "qpos " << i;
  EXPECT_GT(std::fabs(a.d->qpos[2] + 0.05), 1e-3) << "it moved";
}

}  // namespace
