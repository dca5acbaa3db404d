// tabulated deep-water wave Green function: greenWave (green.h) from tables
// built once per process, interpolated (docs/physics.md section 13,
// "Tabulated wave part")
#ifndef MJBUOY_GREENTAB_H_
#define MJBUOY_GREENTAB_H_

#include <memory>
#include <vector>

#include "radiation/green.h"

namespace mjb {

// F, dF/dX and J0, J1 on nodes; evaluated by greenWaveTab
struct GreenTable {
  // near the origin, rho = sqrt(X^2 + Y^2) in [kRhoMin, kRhoA): a polar grid
  // in s = ln rho and theta = atan2(Y, X) of F and rho dF/dX (smooth there:
  // the log and 1/rho singularities become linear and constant in s)
  int ns = 0, nt = 0;
  double s0 = 0, hs = 0, ht = 0;
  std::vector<double> pF, pFX;  // [it * ns + is]
  // elsewhere: a uniform grid of step h in X in [0, xmax], Y in [0, ymax]
  int nx = 0, ny = 0;
  double h = 0, xmax = 0, ymax = 0;
  std::vector<double> F, FX;  // [iy * nx + ix]
  std::vector<double> J0, J1; // [ix]
};

// a table covering X <= xmax, Y <= ymax (clipped to the largest tabulated
// range; points outside are evaluated directly); shared, built on first
// use or when a larger range is asked for; thread-safe. nullptr when the
// table is switched off (greenTableUse) or could not be allocated
std::shared_ptr<const GreenTable> greenTable(double xmax, double ymax);

// switches the table on (default) or off: off, greenWaveTab evaluates
// greenWave directly (the reference, for tests)
void greenTableUse(bool on);

// greenWave(X, Y) from t (nullptr: direct); within the interpolation bound
// of docs/physics.md section 13 of greenWave for F, FX and FY, and 1e-9
// for J0, J1
WaveF greenWaveTab(const GreenTable* t, double X, double Y);

}  // namespace mjb

#endif  // MJBUOY_GREENTAB_H_
