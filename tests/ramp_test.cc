// the start-up ramp mjbuoy.sea.ramp (docs/physics.md section 6, "Start-up
// ramp"): the sea during the ramp is the analytic sea with every amplitude
// times 0.5 (1 - cos(pi t / T)) on both backends, in the pressure and the
// diffraction force; and it removes the phase-dependent start-up drift of
// a free hull in regular waves
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "sea/sea.h"
#include "testutil.h"

namespace {

using namespace mjbt;

// the ramp's gain, written out here from docs/physics.md (6.6)
double rampGain(double t, double T) {
  if (t >= T) return 1;
  return t > 0 ? 0.5 * (1 - std::cos(M_PI * t / T)) : 0;
}

// a free 2 x 1 x 0.8 m box floating at draft 0.4 m (mass rho 0.8 m^3) in one
// Airy component of amplitude amp, wavelength 6 m travelling along dir
// [deg] with phase ph [deg]; ramp < 0 leaves mjbuoy.sea.ramp out (default)
std::string boxXML(double amp, double dir, double ph, double ramp, bool rad,
                   const char* pressure = "linear") {
  std::ostringstream s;
  s.precision(17);
  s << "<mujoco><option timestep=\"0.005\"/><custom>"
    << "<text name=\"mjbuoy.hulls\" data=\"hull\"/>"
    << "<text name=\"mjbuoy.sea.pressure\" data=\"" << pressure << "\"/>"
    << "<numeric name=\"mjbuoy.airy.a\" data=\"" << amp << " 6 " << dir << " " << ph << "\"/>";
  if (ramp >= 0) s << "<numeric name=\"mjbuoy.sea.ramp\" data=\"" << ramp << "\"/>";
  if (!rad) s << "<text name=\"mjbuoy.radiation\" data=\"off\"/>";
  s << "</custom><worldbody><body name=\"box\" pos=\"0 0 0\"><freejoint/>"
    << "<inertial pos=\"0 0 0\" mass=\"800\" diaginertia=\"110 310 330\"/>"
    << "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.4\" contype=\"0\" conaffinity=\"0\"/>"
    << "</body></worldbody></mujoco>";
  return s.str();
}

// the wrench on the box held at its rest pose at time t (one mj_forward)
void wrenchAt(const std::string& xml, const char* backend, double t, double out[6]) {
  std::string e;
  mjModel* m = loadXML(xml, &e);
  ASSERT_TRUE(m) << e;
  char err[1024];
  mjbBuoy* b = mjb_attach(m, backend, err, sizeof(err));
  ASSERT_TRUE(b) << err;
  mjData* d = mj_makeData(m);
  d->time = t;
  mj_forward(m, d);
  const mjtNum* w = mjb_wrench(b, d) + 6 * mj_name2id(m, mjOBJ_BODY, "box");
  for (int j = 0; j < 6; j++) out[j] = w[j];
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
}

// the surface during the ramp is the analytic ramped surface: mjb_seaHeight
// against r(t) A cos(k x - omega t + phi) (deep water, omega^2 = g k)
TEST(Ramp, SeaHeightIsTheRampedAnalyticSurface) {
  const double A = 0.2, T = 5, k = 2 * M_PI / 6, om = std::sqrt(kG * k), ph = 30 * M_PI / 180;
  Scene s(boxXML(A, 0, 30, T, false));
  ASSERT_TRUE(s.ok()) << s.err;
  for (double t : {0.0, 0.5, 1.7, 2.5, 4.9, 5.0, 7.3}) {
    for (double x : {-2.0, 0.3, 1.1}) {
      const double want = rampGain(t, T) * A * std::cos(k * x - om * t + ph);
      EXPECT_NEAR(mjb_seaHeight(s.b, x, 0.4, t), want, 1e-12) << "t " << t << " x " << x;
    }
  }
  // ramp 0: full amplitude from t = 0
  Scene s0(boxXML(A, 0, 30, 0, false));
  ASSERT_TRUE(s0.ok()) << s0.err;
  EXPECT_NEAR(mjb_seaHeight(s0.b, 0.3, 0, 0.1), A * std::cos(k * 0.3 - om * 0.1 + ph), 1e-12);
}

// default: kRampPeriods = 3 periods of the largest component, 2 pi / omega
TEST(Ramp, DefaultIsThreePeriodsOfTheLargestComponent) {
  const double A = 0.2, k = 2 * M_PI / 6, Tw = 2 * M_PI / std::sqrt(kG * k);
  Scene s(boxXML(A, 0, 0, -1, false));
  ASSERT_TRUE(s.ok()) << s.err;
  for (double t : {0.3 * Tw, 1.5 * Tw, 2.9 * Tw, 3.2 * Tw}) {
    const double want = rampGain(t, 3 * Tw) * A * std::cos(-std::sqrt(kG * k) * t);
    EXPECT_NEAR(mjb_seaHeight(s.b, 0, 0, t), want, 1e-12) << "t " << t;
  }
}

// the backends' pressure (linear and Kerner's) and the diffraction force
// during the ramp: the wrench of the ramped sea at t is that of the sea
// whose amplitude is r(t) A with no ramp, r from (6.6) above; after the
// ramp it is the full sea's
TEST(Ramp, BackendsSeeTheRampedAmplitude) {
  const double A = 0.15, T = 4;
  struct Case {
    const char* backend;
    const char* pressure;
    bool rad;
  } cases[] = {{"cpu", "linear", false}, {"cpu", "kerner", false}, {"gl", "linear", false},
               {"gl", "kerner", false}, {"cpu", "linear", true}};
  for (const Case& c : cases) {
    for (double t : {0.6, 2.0, 3.1, 4.5}) {
      double wr[6], wa[6], w0[6];
      wrenchAt(boxXML(A, 180, 40, T, c.rad, c.pressure), c.backend, t, wr);
      wrenchAt(boxXML(rampGain(t, T) * A, 180, 40, 0, c.rad, c.pressure), c.backend, t, wa);
      wrenchAt(boxXML(0, 180, 40, 0, c.rad, c.pressure), c.backend, t, w0);
      // the wave part (wrench minus calm water's) must be there to be ramped
      double wave = 0;
      for (int j = 0; j < 6; j++) wave = std::max(wave, std::fabs(wr[j] - w0[j]));
      if (t < T) {
        EXPECT_GT(wave, 10) << c.backend << " " << c.pressure << " t " << t;
      }
      for (int j = 0; j < 6; j++) {
        EXPECT_NEAR(wr[j], wa[j], 1e-9 * 800 * kG)
            << c.backend << " " << c.pressure << (c.rad ? " radiation" : "") << " t " << t
            << " component " << j;
      }
    }
  }
}

// a free upright cylinder, radius 0.3 m, 1.2 m tall, floating at draft
// 0.8 m with its COM 0.5 m down (stable), in an Airy component of
// amplitude amp, wavelength len along dir with phase ph
std::string cylXML(double amp, double len, double dir, double ph, double ramp, bool drag = true) {
  std::ostringstream s;
  s.precision(17);
  const double mass = kRho * M_PI * 0.09 * 0.8;
  s << "<mujoco><option timestep=\"0.005\"/><custom>"
    << "<text name=\"mjbuoy.hulls\" data=\"hull\"/>"
    << "<numeric name=\"mjbuoy.airy.a\" data=\"" << amp << " " << len << " " << dir << " " << ph
    << "\"/>";
  if (ramp >= 0) s << "<numeric name=\"mjbuoy.sea.ramp\" data=\"" << ramp << "\"/>";
  if (!drag) {
    s << "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0.5\"/>"
      << "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0.5\"/>"
      << "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>";
  }
  s << "</custom><worldbody><body name=\"cyl\" pos=\"0 0 0\"><freejoint/>"
    << "<inertial pos=\"0 0 -0.5\" mass=\"" << mass << "\" diaginertia=\"30 30 10\"/>"
    << "<geom name=\"hull\" type=\"cylinder\" size=\"0.3 0.6\" pos=\"0 0 -0.2\" "
    << "contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>";
  return s.str();
}

// the kinematics other parts read (mooring nodes, the Kirchhoff terms, the
// hull's flow: Sea::velocity, dynamic, height) during the ramp are those of
// the sea of amplitude r(t) A, for a Gerstner and an Airy component in
// finite depth
TEST(Ramp, KinematicsOfTheSeaAreRamped) {
  auto make = [](double gain, double ramp) {
    mjb::Sea s;
    s.depth = 12;
    s.ramp = ramp;
    mjb::Wave g{gain * 0.4, 15, 20, 10, 0.6, 0, 0, 0, 0, 0};
    mjb::Wave a{gain * 0.2, 9, -40, 70, 0, 0, 0, 0, 0, 0};
    a.kind = 1;
    s.waves = {g, a};
    s.derive();
    return s;
  };
  const double T = 6;
  const mjb::Sea ramped = make(1, T);
  for (double t : {0.4, 2.2, 4.7}) {
    const mjb::Sea same = make(rampGain(t, T), 0);
    for (double z : {-3.0, -0.5, 0.2}) {
      const double p[3] = {1.3, -0.7, z};
      double v1[3], a1[3], v2[3], a2[3];
      ramped.velocity(p, t, v1, a1);
      same.velocity(p, t, v2, a2);
      for (int j = 0; j < 3; j++) {
        EXPECT_NEAR(v1[j], v2[j], 1e-12) << "t " << t << " z " << z;
        EXPECT_NEAR(a1[j], a2[j], 1e-12) << "t " << t << " z " << z;
      }
      EXPECT_NEAR(ramped.dynamic(p, t), same.dynamic(p, t), 1e-8);
    }
    EXPECT_NEAR(ramped.height(1.3, -0.7, t), same.height(1.3, -0.7, t), 1e-12);
    // and it is not the full sea's
    const mjb::Sea full = make(1, 0);
    const double q[3] = {0, 0, -1};
    EXPECT_GT(std::fabs(ramped.height(1.3, -0.7, t) - full.height(1.3, -0.7, t)) +
              std::fabs(ramped.dynamic(q, t) - full.dynamic(q, t)) / (kRho * kG), 1e-3);
  }
}

// the one validator (sea/seacheck.h rampCheck, kRampRange) refuses a ramp
// outside 0 to 3600 s from the model file and from mjb_setSea alike, naming
// the field and the range; mjb_setSea's ramp replaces the model's, a
// negative one keeps it
TEST(Ramp, OneValidatorForModelAndSetSea) {
  for (const char* bad : {"-1", "3601", "1e308"}) {
    std::string xml = boxXML(0.1, 0, 0, 0, false);
    const std::string at = "<numeric name=\"mjbuoy.sea.ramp\" data=\"0\"/>";
    xml.replace(xml.find(at), at.size(), std::string("<numeric name=\"mjbuoy.sea.ramp\" data=\"") +
                bad + "\"/>");
    Scene s(xml);
    EXPECT_FALSE(s.ok()) << bad;
    EXPECT_NE(s.err.find("mjbuoy.sea.ramp"), std::string::npos) << s.err;
    EXPECT_NE(s.err.find("3600"), std::string::npos) << s.err;
  }
  const double A = 0.2, k = 2 * M_PI / 6, om = std::sqrt(kG * k);
  Scene s(boxXML(A, 0, 0, 4, false));
  ASSERT_TRUE(s.ok()) << s.err;
  double wave[5] = {A, 6, 0, 0, 0};
  mjbSea sea = {};
  sea.wave = wave;
  sea.nwave = 1;
  char e[512] = "";
  for (double bad : {3601.0, double(NAN), double(INFINITY), 1e308}) {
    sea.ramp = bad;
    EXPECT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 0) << bad;
    EXPECT_NE(std::string(e).find("ramp"), std::string::npos) << e;
    EXPECT_NE(std::string(e).find("3600"), std::string::npos) << e;
  }
  sea.ramp = -1;  // keeps the model's 4 s
  ASSERT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 1) << e;
  EXPECT_NEAR(mjb_seaHeight(s.b, 0, 0, 1), rampGain(1, 4) * A * std::cos(-om), 1e-12);
  sea.ramp = 10;
  ASSERT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 1) << e;
  EXPECT_NEAR(mjb_seaHeight(s.b, 0, 0, 5), rampGain(5, 10) * A * std::cos(-5 * om), 1e-12);
  sea.ramp = 0;
  ASSERT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 1) << e;
  EXPECT_NEAR(mjb_seaHeight(s.b, 0, 0, 1), A * std::cos(-om), 1e-12);
}

// the free cylinder's COM surge x [m] after 60 s from rest (mean over the
// last 2 periods), in head waves of amplitude 0.1 m and wavelength len
// travelling along -x (positive: upwave), phase ph [deg]
double drift60(double len, double ph, double ramp, bool drag) {
  Scene s(cylXML(0.1, len, 180, ph, ramp, drag));
  EXPECT_TRUE(s.ok()) << s.err;
  if (!s.ok()) return NAN;
  const double Tw = 2 * M_PI / std::sqrt(kG * 2 * M_PI / len);
  return s.settle(60, 2 * Tw, [&] { return s.d->xipos[3]; });
}

// spread max - min of 4 values
double spread(const double v[4]) {
  return *std::max_element(v, v + 4) - *std::min_element(v, v + 4);
}

const double kPhases[4] = {0, 90, 180, 270};

// docs/physics.md (6.5), with only the linear forces (Kerner's drag terms
// and skin friction off): a wave switched on at full amplitude leaves the
// surge velocity F cos(phi) / (m_s omega) (the wave along -x: the surge
// force F sin(omega t - phi)). The cylinder is slender (k a = 0.16):
// Morison's long-wave force, C_M = 2, F = 2 rho g pi a^2 A (1 - e^(-k d)),
// and m_s = m + A_11 = 2 rho pi a^2 d (C_a = 1, 2D strip value; the 3D
// flow round the bottom lowers it, hence 15%). The half-cosine ramp over
// N = 3 periods leaves at most 1 / (4 N^2 - 1) = 1/35 of that velocity
// for any phase, so the phases' spread of the drift is at most 1/35 of
// the abrupt start's
TEST(Ramp, StartUpDriftIsTheLinearTransientAndTheRampRemovesIt) {
  const double len = 12, A = 0.1, a = 0.3, dr = 0.8, k = 2 * M_PI / len, om = std::sqrt(kG * k);
  const double Tw = 2 * M_PI / om;
  const double F = 2 * kRho * kG * M_PI * a * a * A * (1 - std::exp(-k * dr));
  const double u0 = F / (2 * kRho * M_PI * a * a * dr * om);
  double off[4], on[4];
  for (int i = 0; i < 4; i++) {
    off[i] = drift60(len, kPhases[i], 0, false);
    on[i] = drift60(len, kPhases[i], -1, false);  // the default ramp, 3 periods
    std::printf("no drag terms, phase %3.0f deg: drift over 60 s without ramp %+.4f m, "
                "with %+.4f m\n", kPhases[i], off[i], on[i]);
  }
  // abrupt: phase 0 drifts upwave, 180 downwave, by u0 times the mean time
  // of the window (60 - Tw) each; their difference removes the mean drift
  const double want = 2 * u0 * (60 - Tw);
  std::printf("phase 0 minus 180: %.3f m, Morison predicts %.3f m\n", off[0] - off[2], want);
  EXPECT_GT(off[0], 0);
  EXPECT_LT(off[2], 0);
  EXPECT_NEAR(off[0] - off[2], want, 0.15 * want);
  EXPECT_LE(spread(on), (off[0] - off[2]) / 35);
}

// with the default settings (Kerner's quadratic drag and skin friction
// on), in waves long enough that the abrupt start carries the hull upwave
// (12 m), and in 8 m waves, whose reflection drives the mean drift
// downwave (Maruo 1960): with the ramp every phase drifts downwave. Drag
// quadratic in the velocity makes the displacement of a velocity offset u0
// concave in it, x = (m / c) ln(1 + c u0 t / m), so the phases' spread
// shrinks by less than the velocity's 1/35 (between 1/35 and 1): at
// least 10 times is asserted
TEST(Ramp, DefaultRampLeavesADownwaveDrift) {
  EXPECT_GT(drift60(12, 0, 0, true), 0.4);  // abrupt, phase 0: upwave
  double off[4], on[4];
  for (int i = 0; i < 4; i++) {
    off[i] = drift60(8, kPhases[i], 0, true);
    on[i] = drift60(8, kPhases[i], -1, true);
    std::printf("defaults, phase %3.0f deg: drift over 60 s without ramp %+.4f m, with %+.4f m\n",
                kPhases[i], off[i], on[i]);
    EXPECT_LT(on[i], 0) << "phase " << kPhases[i];
  }
  EXPECT_LE(spread(on), spread(off) / 10);
}

}  // namespace
