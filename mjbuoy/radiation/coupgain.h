// coupgain: how strongly grouped bodies' explicit added-mass coupling
// feeds one step's error into the next (docs/physics.md section 14,
// "Interaction", stability of the coupling)
#ifndef MJBUOY_COUPGAIN_H_
#define MJBUOY_COUPGAIN_H_

#include <vector>

namespace mjb {

// a gain from this on is warned about at attach: each step keeps at least
// half of the last step's acceleration error, alternating in sign
const double kCoupleGainWarn = 0.5;

// the spectral radius of D^-1 O for n bodies: D[36 k] body k's own inertia
// plus added mass (6 x 6, row-major, kg and kg m^2), O[36 (n i + j)] the
// coupling A_ij(inf) (i != j; the diagonal blocks are not read). The
// coupling acts through the last step's acceleration, so an error e in the
// accelerations becomes -D^-1 O e a step later: below 1 it dies out, at 1
// or more it grows. -1 when D is singular or an entry is not finite
double couplingGain(int n, const std::vector<double>& D, const std::vector<double>& O);

}  // namespace mjb

#endif  // MJBUOY_COUPGAIN_H_
