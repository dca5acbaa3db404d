// forward-speed terms of the radiation memory (docs/physics.md section 14,
// "Forward speed"): the part of Salvesen, Tuck and Faltinsen's (1970)
// speed corrections that body-axis velocities and the Kirchhoff terms do
// not already give, a pitch moment U (L33 * w) and a yaw moment
// -U (L22 * v), L_jj(t) = int_0^t K_jj(s) ds
#ifndef MJBUOY_RADSPEED_H_
#define MJBUOY_RADSPEED_H_

#include <vector>

#include "radiation/hydrocoef.h"
#include "radiation/radfit.h"

namespace mjb {

// L_22 and L_33 at step dt over the memory length tmem [s] (> 0), 2 n
// values (sway, then heave) into L; n = 0 (L empty) when c has neither
// sway nor heave damping. K as the memory's: tapered, steady gain removed
void speedKernels(const HydroCoef& c, double tmem, double dt, std::vector<double>* L, int* n);

// (L_j * nu)(t) = dt sum_k w_k L_j(k dt) nu(t - k dt), trapezoid weights
// over the count samples held of ring (nh long, newest at head) [m or m/s
// times N s/m: N s]; j 0 sway, 1 heave
double speedConv(const std::vector<double>& L, int n, int j, const double* ring, int nh,
                 int head, int count, double dt);

// the same from a state-space memory's own per-mode states (radfit.h), in
// O(modes): the trapezoid integral of the fitted K_jj = Re sum c lam^k,
// less its limit (the fit's steady gain, 0), is L_k = Re sum d lam^k with
// d = c (h/2) (1 + lam) / (lam - 1) (-> c/p as h -> 0), convolved as ssForce
// does; out[0] sway, out[1] heave [N s]; a pair without modes gives 0, as
// its memory does (docs/physics.md section 14, "Forward speed").
// lam: the modes' exp(p h) at the step h in force (nullptr: sm.lam)
void speedSs(const SsModes& sm, SsState s, double h, double out[2], const cplx* lam = nullptr);

}  // namespace mjb

#endif  // MJBUOY_RADSPEED_H_
