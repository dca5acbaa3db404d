// wavepress: linear-theory wave pressure integrated over a wet triangle
// (docs/physics.md, "Linear wave kinematics and pressure")
//
// p = rho g (level - z) + sum_i p_d,i below the instantaneous surface. The
// hydrostatic part is linear in position and integrated exactly; the
// dynamic part with Radon's 7-point rule of degree 5 on each fan piece of
// the wet polygon. The cpu backend integrates the dynamic part in closed
// form instead (waveint.h); this rule stays as an independent reference
// for the tests.
#ifndef MJBUOY_WAVEPRESS_H_
#define MJBUOY_WAVEPRESS_H_

#include "hull/pressure.h"
#include "sea/sea.h"

namespace mjb {

// the surface over one hull triangle, as the cut assumes it: height eta
// above the level [m] and Gerstner label (absolute [m]) linear between the
// triangle's vertices, p[3] (relative to com), where they were solved
struct Surf {
  double p[3][3];
  double eta[3];
  double lab[3][2];
  // eta and label at point r (relative to com) of the triangle's plane
  void at(const double r[3], double* eta, double lab[2]) const;
};

// adds to P and Pr the dynamic-pressure integrals over the triangle
// q0 q1 q2 (relative to com) with unit normal n: integral(p_d dA) [N] and
// integral(p_d r dA) [N m]; e, l: eta and label at q0 q1 q2, interpolated
// linearly to the quadrature points (no surface solve there)
void dynamicPiece(const Sea& sea, const WaveNow* wn, const double* q0, const double* q1,
                  const double* q2, const double n[3], const double com[3], const double e[3],
                  const double l[3][2], double* P, double Pr[3]);

// the hydrostatic part rho g (level - z) of the linear pressure over the
// wet polygon of w (vertices relative to com), exactly (fan formulas of
// wetTriangle): P = integral(p dA) [N], Pr = integral(p r dA) [N m]
void hydrostaticLevel(const Sea& sea, const Wet& w, const double com[3], double* P,
                      double Pr[3]);

// the total linear pressure over the wet polygon of w (from wetTriangle,
// vertices relative to com) of the triangle whose surface is s:
// P = integral(p dA) [N], Pr = integral(p r dA) [N m]; force -P n, torque
// -Pr x n, centre of pressure Pr / P
void linearPressure(const Sea& sea, const WaveNow* wn, const Wet& w, const Surf& s,
                    const double com[3], double* P, double Pr[3]);

}  // namespace mjb

#endif  // MJBUOY_WAVEPRESS_H_
