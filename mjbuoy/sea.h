// sea: still level plus a sum of Gerstner components (physics.md section 6)
#ifndef MJBUOY_SEA_H_
#define MJBUOY_SEA_H_

#include <vector>

namespace mjb {

// one Gerstner component, as given in MJCF plus derived constants
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

// per-call constants of one component at a fixed time t (Sea::now), so the
// hot loops do no per-wave setup; products keep label()'s association so a
// cold solve gives the same bits as label() + heightOf()
struct WaveNow {
  double k, dx, dy;  // wave number [rad/m], unit direction
  double wt, ph;     // omega t, phase [rad]
  double qx, qy;     // Q A dx, Q A dy [m]
  double qk;         // Q A k [1]
  double amp;        // A [m]
  double qao, ao;    // Q A omega, A omega [m/s]
};

struct Sea {
  double rho = 1000;        // water density [kg/m^3]
  double level = 0;         // still water level: height of the orbit centres [m]
  double depth = 0;         // water depth [m]; 0 means deep water
  double nu = 1.0e-6;       // kinematic viscosity [m^2/s]
  double current[2] = {0, 0};  // uniform current [m/s]
  double g = 9.81;          // gravity magnitude [m/s^2], from opt.gravity
  std::vector<Wave> waves;

  // fill k, omega, unit direction and phase in radians of every wave
  void derive();

  // sum over waves of Q k A; the surface folds (height stops being a
  // function of x, y) when it reaches 1
  double fold() const;

  // exact surface height at a fixed horizontal point [m]: solves for the
  // particle label a with x(a) = (x, y) to 1e-9 m, then sums A cos(theta(a))
  double height(double x, double y, double t) const;

  // water velocity at point p [m/s]: current plus the orbital velocity of
  // every component, decaying below the surface (Airy; exp(k z) in deep
  // water). Above the surface the surface value is used.
  void velocity(const double p[3], double t, double v[3]) const;

  // the same in steps, for callers that keep labels: the particle label a
  // whose displaced horizontal position is (x, y), by Newton from the guess
  // in a; the surface height of particle a; the water velocity at depth
  // zb <= 0 below particle a
  void label(double x, double y, double t, double a[2]) const;
  double heightOf(const double a[2], double t) const;
  void velocityOf(const double a[2], double t, double zb, double v[3]) const;

  // fast path for the cpu backend: the constants of every component at t
  // (w holds waves.size())
  void now(double t, WaveNow* w) const;
  // label() from the guess in a, to the same tolerance, returning the
  // surface height of the particle found (heightOf); sc gets sin and cos of
  // each component's phase there and tmp is scratch (2 per wave each).
  // Iterates reuse the phase by angle addition, so only the guess costs one
  // sin and cos per component: the result differs from label() by round-off
  double solve(const WaveNow* w, double x, double y, double a[2], double* sc,
               double* tmp) const;
  // solve() for m points, same bits: positions x, y; guesses in a0, a1
  // become labels; z gets heights and sc 2 per wave per point (point-major,
  // as solve's sc); tmp is scratch of 2 per wave
  void solveMany(const WaveNow* w, int m, const double* x, const double* y, double* a0,
                 double* a1, double* z, double* sc, double* tmp) const;
  // velocityOf() from the phases solve() left in sc
  void velocitySC(const WaveNow* w, const double* sc, double zb, double v[3]) const;
};

}  // namespace mjb

#endif  // MJBUOY_SEA_H_
