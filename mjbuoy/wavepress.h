// wavepress: linear-theory wave pressure integrated over a wet triangle
// (docs/physics.md, "Linear wave kinematics and pressure")
//
// p = rho g (level - z) + sum_i p_d,i below the instantaneous surface. The
// hydrostatic part is linear in position and integrated exactly; the
// dynamic part with Radon's 7-point rule of degree 5 on each fan piece of
// the wet polygon.
#ifndef MJBUOY_WAVEPRESS_H_
#define MJBUOY_WAVEPRESS_H_

#include "pressure.h"
#include "sea.h"

namespace mjb {

// adds to P and Pr the dynamic-pressure integrals over the triangle
// q0 q1 q2 (relative to com) with unit normal n: integral(p_d dA) [N] and
// integral(p_d r dA) [N m]. wn: Sea::now constants; off: guess of the
// Gerstner label minus the position (any value converges); sc, tmp:
// scratch of 2 per wave each
void dynamicPiece(const Sea& sea, const WaveNow* wn, const double* q0, const double* q1,
                  const double* q2, const double n[3], const double com[3], const double off[2],
                  double* sc, double* tmp, double* P, double Pr[3]);

// the total linear pressure over the wet polygon of w (from wetTriangle,
// vertices relative to com): P = integral(p dA) [N], Pr = integral(p r dA)
// [N m]; force -P n, torque -Pr x n, centre of pressure Pr / P
void linearPressure(const Sea& sea, const WaveNow* wn, const Wet& w, const double com[3],
                    const double off[2], double* sc, double* tmp, double* P, double Pr[3]);

}  // namespace mjb

#endif  // MJBUOY_WAVEPRESS_H_
