// sea: still level plus a sum of Gerstner components (physics.md section 6)
#ifndef MJBUOY_SEA_H_
#define MJBUOY_SEA_H_

#include <cmath>
#include <vector>

#include "sea/wavenow.h"

namespace mjb {

// one wave component, as given in MJCF plus derived constants: Gerstner
// (trochoidal: height by inverting the particle labels) or Airy (linear:
// height a direct sum at the physical point); both have the linear-theory
// kinematics and pressure below the surface (docs/physics.md, "Linear wave
// kinematics and pressure")
struct Wave {
  double amp;      // amplitude A [m]
  double len;      // wavelength lambda [m]
  double dir;      // direction of travel, from +x towards +y [deg]
  double phase;    // phase phi [deg]
  double steep;    // steepness Q [0, 1]
  double k;        // wave number 2 pi / lambda [rad/m]
  double omega;    // angular frequency from the dispersion relation [rad/s]
  double dx, dy;   // unit direction
  double ph;       // phase [rad]
  int kind = 0;      // 0 Gerstner (trochoidal), 1 Airy (linear)
};

// Wheeler (1970) stretching: the height z' in [-h, 0] at which the linear
// profiles of a point z above the level under a surface at eta are taken
// (deep water, depth 0: z' = min(z - eta, 0); depth h:
// (z - eta) h / (h + eta), clamped) [m]
double stretch(double depth, double z, double eta);

// s = sin th and c = cos th of th[0, n) (th padded with zeros, and s and c
// with room, to a multiple of 4): 4 at a time sharing one range reduction (util/sincoskern.h, within
// 3 ulp for |th| < 2^20 pi/2, docs/physics.md "Phases' sine and cosine in
// lanes"), std::sin and std::cos for a group with a phase beyond that
void phaseSinCos(const double* th, int n, double* s, double* c);

// periods of the dominant component in the default start-up ramp: the
// drift a switched-on wave leaves is cut to 1 / (4 N^2 - 1) of that of an
// abrupt start, 1/35 for N = 3 (docs/physics.md section 6)
inline constexpr double kRampPeriods = 3;

// Sea::integration's modes
enum { kIntegrateExact = 0, kIntegrateVertex = 1 };

struct Sea {
  double rho = 1000;        // water density [kg/m^3]
  double level = 0;         // still water level: height of the orbit centres [m]
  double depth = 0;         // water depth [m]; 0 means deep water
  double nu = 1.0e-6;       // kinematic viscosity [m^2/s]
  double current[2] = {0, 0};  // uniform current [m/s]
  double g = 9.81;          // gravity magnitude [m/s^2], from opt.gravity
  bool kerner = false;      // pressure rho g (eta - z) (Kerner) instead of linear theory
  // start-up ramp T [s]: every amplitude is scaled by gain(t), a half
  // cosine from 0 at t = 0 to 1 at t = T (docs/physics.md section 6,
  // "Start-up ramp"); 0 switches the waves on at full amplitude
  double ramp = 0;
  // the cpu lanes' series tolerance: 0 exact (to rounding); else their
  // series stop once the omitted terms' pressure force is at most this
  // fraction of rho g times the hull's volume (docs/physics.md "Series
  // tolerance")
  double seriestol = 0;
  // the cpu lanes' linear wave pressure on a wet piece (mjbuoy.sea.
  // integration): kIntegrateExact, each component's e^L in closed form,
  // or kIntegrateVertex, the components summed at the hull's vertices and
  // the linear interpolant integrated (docs/physics.md "Vertex integration")
  int integration = 0;
  std::vector<Wave> waves;
  // derived: the order of components in now(), Gerstner first, and how
  // many are Gerstner (the rest are Airy)
  std::vector<int> order;
  int ng = 0;

  // fill k, omega, unit direction and phase in radians of every wave, and
  // order, ng
  void derive();

  // the ramp's factor on every amplitude at t [s]: 0.5 (1 - cos(pi t / T))
  // for t < T, 1 after (and always 1 with T = 0)
  double gain(double t) const {
    if (!(ramp > 0) || t >= ramp) return 1;
    return t > 0 ? 0.5 * (1 - std::cos(M_PI * t / ramp)) : 0;
  }
  // the default ramp [s]: kRampPeriods periods 2 pi / omega of the
  // component with the largest amplitude (the peak of a spectrum), 0
  // without waves (docs/physics.md section 6, "Start-up ramp")
  double defaultRamp() const;

  // sum over waves of Q k A; the surface folds (height stops being a
  // function of x, y) when it reaches 1
  double fold() const;

  // exact surface height at a fixed horizontal point [m]: solves for the
  // Gerstner particle label a with x(a) = (x, y) to 1e-9 m, then sums
  // A cos(theta(a)) over the Gerstner components and A cos(theta(x, y))
  // over the Airy ones
  double height(double x, double y, double t) const;

  // water velocity [m/s] and acceleration [m/s^2] (acc may be null) at
  // point p: current plus linear theory of every component, Wheeler
  // stretched to the instantaneous surface; above the surface the surface
  // value is used
  void velocity(const double p[3], double t, double v[3], double acc[3] = nullptr) const;
  // dynamic pressure sum_i p_d,i at p [Pa] (Wheeler stretched; the total
  // pressure below the surface is rho g (level - z) + this)
  double dynamic(const double p[3], double t) const;

  // the same in steps, for callers that keep labels: the Gerstner particle
  // label a whose displaced horizontal position is (x, y), by Newton from
  // the guess in a; the surface height of particle a above x, y
  void label(double x, double y, double t, double a[2]) const;
  double heightOf(const double a[2], double x, double y, double t) const;

  // fast path for the cpu backend: the constants of every component at t
  // (w holds waves.size()), in the order of order[]: Gerstner first
  void now(double t, WaveNow* w) const;
  // label() from the guess in a, to the same tolerance, returning the
  // surface height of the particle found (heightOf); sc gets sin and cos of
  // each component's phase there and tmp is scratch (2 per wave each).
  // Iterates reuse the phase by angle addition, so only the guess costs one
  // sin and cos per component: the result differs from label() by round-off.
  // nit (if given) gets the Newton steps taken added
  double solve(const WaveNow* w, double x, double y, double a[2], double* sc,
               double* tmp, int* nit = nullptr) const;
  // solve() for m points, same bits: positions x, y; guesses in a0, a1
  // become labels; z gets heights and sc 2 per wave per point (point-major,
  // as solve's sc); tmp is scratch of 2 per wave. Returns the Newton steps
  // taken in all. tmp: 2 + kLaneTmp (seavec.h) per wave, the vector path
  // (vmath.h's level: AVX2 or AVX-512) runs the same steps per point in
  // lanes and rounds differently (the lanes' sin and cos, FMA); fast: the
  // vector path's Airy phases within sincoskern.h's kSinCosFastEps instead
  // (vertex integration, docs/physics.md "Vertex integration")
  long solveMany(const WaveNow* w, int m, const double* x, const double* y, double* a0,
                 double* a1, double* z, double* sc, double* tmp, bool fast = false) const;
  // velocity() and acceleration (acc may be null) from the phases solve()
  // left in sc, at height z above the level of a point whose surface is at
  // eta above the level [m]
  void velocitySC(const WaveNow* w, const double* sc, double z, double eta, double v[3],
                  double acc[3] = nullptr) const;
  // dynamic() from the phases solve() left in sc, z and eta as velocitySC
  double dynamicSC(const WaveNow* w, const double* sc, double z, double eta) const;
  // dynamic() at a point whose surface height eta and Gerstner label a are
  // already known (wavepress.cc interpolates them): x, y its position [m],
  // z its height above the level [m]; one cos and one exp per component,
  // none for a component with k z' < -40 (Wheeler z' <= 0), whose
  // e^(k z') < 5e-18 is below double round-off of its amplitude
  double dynamicAt(const WaveNow* w, double x, double y, const double a[2], double z,
                   double eta) const;
};

}  // namespace mjb

#endif  // MJBUOY_SEA_H_
