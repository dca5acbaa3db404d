// the radiation memory as a state-space model (docs/physics.md section 14,
// "State-space memory"): the fit of K(t) by damped exponentials and the
// per-step states against the convolution
#include <cmath>
#include <complex>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "hemisphere.h"
#include "radiation/radfit.h"
#include "radiation/radiation.h"
#include "ssconv.h"
#include "testutil.h"

namespace mjbt {
namespace {

using mjb::cplx;

// (a) K(t) = Re(c1 e^{p1 t}) + c2 e^{p2 t}, an oscillating and a plain
// damped mode: the fit finds both poles (the exponentials are the exact
// answer, so any error is the method's), and the state-space force is the
// trapezoid convolution of K with a random velocity to round-off (the
// discretisation of section 14 is exact for sampled K)
TEST(RadFit, TwoDampedModesAreRecoveredAndConvolvedExactly) {
  const cplx p1(-0.8, 4.0), c1(10, -3), p2(-3.0), c2(-4.0);
  const double h = 0.01;
  const int n = 4001;  // 40 s: e^{-0.8 * 40} = 1e-14, the memory is complete
  std::vector<double> K(n);
  for (int k = 0; k < n; k++)
    K[k] = (c1 * std::exp(p1 * (k * h))).real() + (c2 * std::exp(p2 * (k * h))).real();
  std::vector<double> w;
  for (double x = 0.5; x <= 12; x += 0.5) w.push_back(x);
  mjb::KFit f;
  ASSERT_TRUE(mjb::fitKernel(K.data(), n, h, w, 0, 0, &f));
  ASSERT_EQ(f.p.size(), 2u);
  for (cplx p : {p1, p2}) {
    double best = INFINITY;
    for (cplx q : f.p) best = std::min(best, std::abs(q - p) / std::abs(p));
    EXPECT_LT(best, 1e-3) << p;
  }
  EXPECT_LT(f.errT, 1e-6);
  std::printf("[radfit] poles %g%+gi, %g%+gi; errT %.2e errF %.2e\n", f.p[0].real(),
              f.p[0].imag(), f.p[1].real(), f.p[1].imag(), f.errT, f.errF);

  mjb::SsModes sm;
  sm.add(2, 2, f, h);
  std::vector<cplx> X(sm.size()), pw(sm.size());
  double nu6[6] = {0}, first[6], last[6], F[6];
  mjb::SsState st{X.data(), pw.data(), first, last};
  const int ns = 3000;
  std::vector<double> v = randomVelocity(ns, h, 0.2, 7);
  v[0] = 0.7;  // the first sample's half weight matters too
  double e2 = 0, f2 = 0;
  for (int k = 0; k < ns; k++) {
    nu6[2] = v[k];
    if (k == 0) mjb::ssRestart(sm, st, nu6);
    else mjb::ssNew(sm, st, nu6);
    mjb::ssForce(sm, st, h, F);
    const double Fc = convolve(K.data(), K.size(), v, k, h);
    e2 += (F[2] - Fc) * (F[2] - Fc);
    f2 += Fc * Fc;
  }
  std::printf("[radfit] state-space vs convolution: rms difference %.2e of rms force %.3g\n",
              std::sqrt(e2 / f2), std::sqrt(f2 / ns));
  EXPECT_LT(std::sqrt(e2 / f2), 1e-6);
}

// (b) the panel solver's coefficients of the R = 1 m hemisphere (as in
// RadAttach.HemisphereHeaveDecayMatchesHulme): its memory force from the
// fitted state-space model and from the sampled K (the convolution, the
// reference) over 20 s of a random velocity in all six dofs, within 3% of
// the convolution's RMS force (the largest of the dof's kind)
TEST(RadFit, HemisphereStateSpaceMatchesTheConvolution) {
  Scene s(floatingHemisphereXML(1, kRho, std::string(kNoDragEntries) +
                                "<text name=\"mjbuoy.radiation\" data=\"on\"/>"));
  ASSERT_TRUE(s.ok()) << s.err;
  const mjb::Radiation& R = mjb::buoyOf(s.b)->rad;
  ASSERT_EQ(R.rb.size(), 1u);
  const mjb::RadBody& rb = R.rb[0];
  ASSERT_GT(rb.nk, 1);
  ASSERT_GT(rb.ss.size(), 0) << mjb_warnings(s.b);
  const double h = R.dt;
  std::printf("[radfit] hemisphere: %zu pairs, %d samples, %d modes\n", rb.pair.size(), rb.nk,
              rb.ss.size());
  const int ns = int(20 / h);
  double e2[6], f2[6];
  ssAgainstConvolution(rb, h, ns, 11, e2, f2);
  // the scale of dof i: the largest RMS force of its kind (translation or
  // rotation), so that yaw, nothing but panel noise on a body of
  // revolution, is held to the roll and pitch moments' size
  for (int i = 0; i < 6; i++) {
    const double sc = kindScale(f2, i);
    std::printf("[radfit] dof %d: rms difference %.4f of rms force %.4g (scale %.4g)\n", i,
                std::sqrt(e2[i] / f2[i]), std::sqrt(f2[i] / ns), std::sqrt(sc / ns));
    EXPECT_LT(std::sqrt(e2[i] / sc), 0.03) << "dof " << i;
  }
}

// the switch: a value other than statespace or convolution is refused,
// naming the entry, the value and the accepted values
TEST(RadFit, MemoryModelEntryIsValidated) {
  Scene s("<mujoco><custom><text name=\"mjbuoy.radiation.memorymodel\" data=\"prony\"/>"
          "</custom><worldbody/></mujoco>");
  EXPECT_FALSE(s.ok());
  for (const char* w : {"mjbuoy.radiation.memorymodel", "prony", "statespace", "convolution"})
    EXPECT_NE(s.err.find(w), std::string::npos) << s.err;
}

}  // namespace
}  // namespace mjbt

namespace mjbt {
namespace {

// a fit that misses its tolerance falls back to the exact convolution; by
// default quietly (only the cost differs), with a warning naming the body
// when the state-space model was asked for. The floating sphere of
// models/fleet.xml's buoys (r 0.5 m, 157.08 kg) with the table below is
// such a body
TEST(RadFit, FallbackWarnsOnlyWhenTheStateSpaceModelWasAskedFor) {
  auto xml = [](const char* extra) {
    return std::string("<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h\"/>"
                       "<text name=\"mjbuoy.radiation\" data=\"on\"/>") + extra +
           "</custom><worldbody><body name=\"buoy\" pos=\"0 0 0.137\"><freejoint/>"
           "<inertial pos=\"0 0 -0.2\" mass=\"157.080\" diaginertia=\"15.708 15.708 15.708\"/>"
           "<geom name=\"h\" type=\"sphere\" size=\"0.5\"/></body></worldbody></mujoco>";
  };
  // a kernel the exponentials do not follow: the lid off and 80
  // frequencies to 20 rad/s (kR about 10) put the sphere's irregular
  // frequencies in the table, where B swings through zero, and K rings.
  // (With the default range and the tail of B, docs/physics.md section
  // 14, the sphere's kernels fit; 40 frequencies to 9.9 rad/s, one
  // irregular frequency, fit too since the poles are refined against B
  // and A)
  const char* om = "<numeric name=\"mjbuoy.radiation.omega\" data=\"1 20 80\"/><text name=\"mjbuoy.radiation.lid\" data=\"off\"/>";
  Scene quiet(xml(om)), asked(xml((std::string(om) + "<text name=\"mjbuoy.radiation.memorymodel\" data=\"statespace\"/>").c_str()));
  ASSERT_TRUE(quiet.ok()) << quiet.err;
  ASSERT_TRUE(asked.ok()) << asked.err;
  const std::string wq = mjb_warnings(quiet.b), wa = mjb_warnings(asked.b);
  // the same fit in both: the asked one says it fell back, so both did
  ASSERT_NE(wa.find("radiation: body \"buoy\": no fit of K_"), std::string::npos) << wa;
  EXPECT_EQ(wq.find("no fit of"), std::string::npos) << wq;
  EXPECT_EQ(mjb::buoyOf(quiet.b)->rad.rb.at(0).ss.size(), 0u);
  EXPECT_EQ(mjb::buoyOf(asked.b)->rad.rb.at(0).ss.size(), 0u);
}

}  // namespace
}  // namespace mjbt

namespace mjbt {
namespace {

// roll peaks of a calm-water decay of the 64-triangle Wigley of
// models/wigley.xml, released at 5 deg of heel: mean period and log
// decrement over the peaks after the first
void wigleyRollDecay(const char* model, double* T, double* delta) {
  std::string xml =
      "<mujoco><option timestep=\"0.002\"/><custom>"
      "<numeric name=\"mjbuoy.sea.density\" data=\"1000\"/>"
      "<text name=\"mjbuoy.hulls\" data=\"h\"/><text name=\"mjbuoy.sea.pressure\" data=\"linear\"/>"
      "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
      "<text name=\"mjbuoy.radiation.memorymodel\" data=\"" + std::string(model) + "\"/>"
      "</custom><asset><mesh name=\"w\" file=\"" MJB_MODELS "/meshes/wigley_64.obj\"/></asset>"
      "<worldbody><body name=\"wigley\" pos=\"0 0 0.034\" quat=\"0.99904822 0.04361939 0 0\">"
      "<freejoint/><inertial pos=\"0 0 -0.08\" mass=\"176.2\" diaginertia=\"6.020 237.28 238.60\"/>"
      "<geom name=\"h\" type=\"mesh\" mesh=\"w\" contype=\"0\" conaffinity=\"0\"/>"
      "</body></worldbody></mujoco>";
  Scene s(xml);
  ASSERT_TRUE(s.ok()) << s.err;
  std::vector<double> tp, xp;
  double x0 = 0, x1 = 0;
  for (int k = 0; k < 10000; k++) {
    mj_step(s.m, s.d);
    // roll of the body's y axis out of the horizontal
    const double x = std::asin(s.d->xmat[9 + 7]);
    if (k > 1 && x1 > x0 && x1 >= x && x1 > 0) {
      tp.push_back(s.d->time - s.m->opt.timestep);
      xp.push_back(x1);
    }
    x0 = x1;
    x1 = x;
  }
  ASSERT_GE(tp.size(), 9u);
  *T = (tp[8] - tp[1]) / 7;
  *delta = std::log(xp[1] / xp[8]) / 7;
}

// the state-space memory of a slender hull, whose roll damping B44 is
// about 1e-3 of its yaw damping B66 (the 64-triangle Wigley: peaks 2.3 and
// 1900 kg m^2/s), decays in roll as the exact convolution does (the
// reference, docs/physics.md section 14, "Scale of each pair"). When every
// rotational K was held to the largest one's size, the roll kernel was
// fitted to 3% of the yaw's: the state-space roll decrement was 0.018
// against the convolution's 0.074, period 1.404 s against 1.436 s (the
// 576- and 2800-triangle hulls: -0.018 and -0.027, roll growing in calm
// water)
TEST(RadFit, SlenderHullRollDecaysAsWithTheConvolution) {
  double Tc, dc, Ts, ds;
  wigleyRollDecay("convolution", &Tc, &dc);
  wigleyRollDecay("statespace", &Ts, &ds);
  std::printf("[radfit] wigley 64 roll decay: convolution T %.4f s delta %.4f, statespace "
              "T %.4f s delta %.4f\n", Tc, dc, Ts, ds);
  // B44 >= 0 (passive) gives a decay
  EXPECT_GT(dc, 0.02);
  EXPECT_NEAR(Ts, Tc, 0.01 * Tc);
  EXPECT_NEAR(ds, dc, 0.05 * dc);
}

}  // namespace
}  // namespace mjbt
