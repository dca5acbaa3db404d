// rigid-body change of frame of hydrodynamic coefficients: new reference
// point and new axes (docs/physics.md section 14, "From the panel solver")
#ifndef MJBUOY_COEFXFORM_H_
#define MJBUOY_COEFXFORM_H_

#include <string>

#include "radiation/hydrocoef.h"

namespace mjb {

// c is about c->ref in frame F (axes e_F). Re-express it about the point p
// (given in F [m]) in axes e_N, with R (row-major 3x3) the rotation whose
// columns are e_N in F (a vector's F components x_F = R x_N). Sets
// c->ref = pn (p in the new frame, the caller's choice of origin).
// With d = ref - p: motion at ref v_ref = v_p + w x d, moment about p
// M_p = M_ref + d x F, i.e. nu_ref = T nu_p, f_p = T^T f_ref,
// T = [[I, -[d]x], [0, I]]; then Q = diag(R, R): A_N = Q^T T^T A T Q, the
// same for B and A_inf; X, FK (force vectors) f_N = Q^T T^T f and their
// phase moves to p: times e^{-i k D.(p - ref)}, k = omega^2 / g (deep
// water). The headings stay those of F's axes: with X present R must keep
// z (a turn about the vertical) and the headings turn by its angle.
// "" or why not.
std::string coefTransform(HydroCoef* c, const double p[3], const double R[9], const double pn[3]);

}  // namespace mjb

#endif  // MJBUOY_COEFXFORM_H_
