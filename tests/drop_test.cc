// free drops of a floating sphere with radiation on (docs/physics.md
// section 16, "Energy on water entry"): a drop never dips below rest by
// more than it was dropped, and small drops decay as the linear model of
// Cummins with Hulme's (1982) coefficients predicts
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>
#include <sstream>
#include <string>

#include "testutil.h"

namespace {

using namespace mjbt;

// the sphere's radius [m]: drops of more than kR start dry, so the hull
// enters the water
const double kR = 0.2;

// Kerner's drag terms, skin friction and slamming off: radiation and
// hydrostatics only
const char* kNoKerner =
    "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>"
    "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0.5\"/>"
    "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0.5\"/>"
    "<numeric name=\"mjbuoy.hull.slamming\" data=\"0 100 2\"/>";

// a sphere of radius R [m] and mass rho 2/3 pi R^3 (it floats at its
// equator: the wet half is Hulme's hemisphere), COM at its centre;
// `custom` adds <custom> entries; radiation on (the default), 1.5 to 30 rad/s
// (kR 0.05 to 18 at R = 0.2 m, about the heave frequency 7.2 rad/s)
std::string sphereXML(double R, const std::string& custom) {
  const double m = kRho * 2.0 / 3.0 * M_PI * R * R * R;
  std::ostringstream s;
  s.precision(17);
  s << "<mujoco><option timestep=\"0.005\"/><custom>"
    << "<text name=\"mjbuoy.hulls\" data=\"hull\"/>" << custom
    << "<numeric name=\"mjbuoy.radiation.omega\" data=\"1.5 30 20\"/>"
    << "</custom><worldbody><body name=\"ball\"><freejoint/>"
    << "<inertial pos=\"0 0 0\" mass=\"" << m << "\" diaginertia=\"" << 0.4 * m * R * R << " "
    << 0.4 * m * R * R << " " << 0.4 * m * R * R << "\"/>"
    << "<geom name=\"hull\" type=\"sphere\" size=\"" << R << "\" contype=\"0\" conaffinity=\"0\"/>"
    << "</body></worldbody></mujoco>";
  return s.str();
}

// the rest height [m]: where the sphere settles from its equator (20 s of
// decay from 1 cm low, mean of the last 2 s)
double restHeight(Scene& s) {
  mj_resetData(s.m, s.d);
  s.d->qpos[2] = -0.01 * s.m->geom_size[0];
  return s.settle(20, 2, [&] { return s.d->qpos[2]; });
}

// released at rest h above rest: how far below rest [m] (positive: below)
// the lowest height reached in 6 s is
double dropDip(Scene& s, double rest, double h) {
  mj_resetData(s.m, s.d);
  s.d->qpos[2] = rest + h;
  double low = s.d->qpos[2];
  const long n = stepsTo(s.m, s.d, 6);
  for (long k = 0; k < n; k++) {
    mj_step(s.m, s.d);
    low = std::min(low, s.d->qpos[2]);
  }
  return rest - low;
}

// energy: a sphere floating at its equator dropped from rest h above its
// rest height reaches at most h below it. Its potential about rest is even
// in z: rho g pi (R^2 z^2 / 2 - z^4 / 12) while |z| <= R, and beyond, dry
// above or under water below, the net force is m g towards rest both
// ways (rho g V_sphere = 2 m g), so a lossless motion returns to exactly
// h below and every hydrodynamic term may only take energy out. Drops of
// 0.3 m and more start dry: the hull enters the water, where the added
// mass it takes up must not bring energy (docs/physics.md section 14,
// "Water entry"; with mjbuoy.radiation.entry off, radiation alone dips
// 0.326, 0.565 and 1.144 m below rest after drops of 0.3, 0.5 and 1 m:
// energy made on each entry)
TEST(Drop, FreeDropNeverOvershootsItsDropHeight) {
  for (const char* custom : {"", kNoKerner}) {
    Scene s(sphereXML(kR, custom));
    ASSERT_TRUE(s.ok()) << s.err;
    const double rest = restHeight(s);
    for (double h : {0.03, 0.075, 0.15, 0.3, 0.5, 1.0}) {
      const double dip = dropDip(s, rest, h);
      std::printf("%s: dropped %.3f m above rest %.5f m: dips %.5f m below rest (%.1f%%)\n",
                  *custom ? "radiation only" : "defaults", h, rest, dip, 100 * dip / h);
      EXPECT_LT(dip, h) << (*custom ? "radiation only" : "defaults") << ", drop " << h;
    }
  }
}

// Hulme (1982), J. Fluid Mech. 121:443-463, Table 1 (as tests/panel_test.cc
// and tests/radattach_test.cc): kR, A33 / (rho 2/3 pi R^3), B33 / (rho 2/3
// pi R^3 omega) of the floating hemisphere, the sphere's wet half at rest
const double kHulme[][3] = {
    {0.5, 0.5861, 0.3391}, {0.6, 0.5381, 0.3271}, {0.7, 0.4999, 0.3098}, {0.8, 0.4698, 0.2899},
    {0.9, 0.4464, 0.2691}, {1.0, 0.4284, 0.2484}, {1.2, 0.4047, 0.2096}, {1.4, 0.3924, 0.1756},
    {1.6, 0.3871, 0.1469}, {1.8, 0.3864, 0.1229}, {2.0, 0.3884, 0.1031}};

typedef std::complex<double> cplx;

// -w^2 (m + A(w)) - i w B(w) + C, Hulme's A and B linear in kR between rows
// (continued to complex w), m = rho 2/3 pi R^3, C = rho g pi R^2
cplx heave(cplx w, double R) {
  const double m = kRho * 2.0 / 3.0 * M_PI * R * R * R, C = kRho * kG * M_PI * R * R;
  const cplx kr = w * w * R / kG;
  const int n = sizeof(kHulme) / sizeof(kHulme[0]);
  int i = 0;
  while (i < n - 2 && kHulme[i + 1][0] < kr.real()) i++;
  const cplx u = (kr - kHulme[i][0]) / (kHulme[i + 1][0] - kHulme[i][0]);
  const cplx a = kHulme[i][1] + u * (kHulme[i + 1][1] - kHulme[i][1]);
  const cplx b = kHulme[i][2] + u * (kHulme[i + 1][2] - kHulme[i][2]);
  return -w * w * m * (1.0 + a) - cplx(0, 1) * w * (b * m * w) + C;
}

// small drops decay as the linear model predicts: Cummins' equation with
// Hulme's coefficients, whose free motion is e^{-i w t} at the complex root
// w of heave(w) = 0 (Newton from sqrt(C / m)): period 2 pi / Re w, log
// decrement 2 pi |Im w| / Re w. Measured from the extremes of a 1 cm drop
// (5% of R: the waterplane, pi (R^2 - z^2), within 0.25% of pi R^2), the
// period over cycles 2 to 4 and the decrement from successive
// peak-to-trough heights, with the default settings and radiation only
TEST(Drop, SmallDropDecaysAsCumminsWithHulmesCoefficients) {
  cplx w = std::sqrt(kG * M_PI * kR * kR / (2.0 / 3.0 * M_PI * kR * kR * kR));
  for (int it = 0; it < 50; it++) {
    const cplx dw = 1e-6 * std::abs(w);
    const cplx f = heave(w, kR);
    w -= f / ((heave(w + dw, kR) - f) / dw);
  }
  ASSERT_LT(std::abs(heave(w, kR)), 1e-9 * kRho * kG * kR * kR);
  const double Tp = 2 * M_PI / w.real(), dp = 2 * M_PI * std::fabs(w.imag()) / w.real();
  for (const char* custom : {"", kNoKerner}) {
    Scene s(sphereXML(kR, custom));
    ASSERT_TRUE(s.ok()) << s.err;
    const double rest = restHeight(s);
    mj_resetData(s.m, s.d);
    s.d->qpos[2] = rest + 0.01;
    std::vector<double> t, x;
    double x0 = s.d->qpos[2], x1 = x0;
    const long n = stepsTo(s.m, s.d, 8 * Tp);
    for (long k = 0; k < n; k++) {
      mj_step(s.m, s.d);
      const double x2 = s.d->qpos[2];
      if ((x1 - x0) * (x2 - x1) < 0) {  // vertex of the parabola through 3 samples
        const double h = s.m->opt.timestep, u = 0.5 * (x0 - x2) / (x0 - 2 * x1 + x2);
        t.push_back(s.d->time - h + u * h);
        x.push_back(x1 - 0.25 * (x0 - x2) * u);
      }
      x0 = x1, x1 = x2;
    }
    ASSERT_GE(t.size(), 8u);
    const double T = t[6] - t[4];
    const double dl = 0.5 * std::log(std::fabs(x[2] - x[3]) / std::fabs(x[6] - x[7]));
    std::printf("%s: period %.4f s, log decrement %.4f; Cummins with Hulme %.4f s, %.4f "
                "(%+.1f%%, %+.1f%%)\n", *custom ? "radiation only" : "defaults", T, dl, Tp, dp,
                100 * (T / Tp - 1), 100 * (dl / dp - 1));
    EXPECT_NEAR(T / Tp, 1, 0.05);
    EXPECT_NEAR(dl / dp, 1, 0.05);
  }
}

}  // namespace
