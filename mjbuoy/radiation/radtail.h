// the high-frequency tail of the radiation damping beyond the table's last
// frequency, for the retardation function (docs/physics.md section 14,
// "High-frequency tail")
#ifndef MJBUOY_RADTAIL_H_
#define MJBUOY_RADTAIL_H_

#include "radiation/hydrocoef.h"

namespace mjb {

// range of the fitted decay exponent p of B ~ omega^-p beyond the table
const double kTailPMin = 2, kTailPMax = 8;

// per dof d the exponent p_d of B_dd(w) = B_dd(w_N) (w_N / w)^p_d for w
// above the last frequency w_N, in [kTailPMin, kTailPMax]: with A(w) in c,
// the one that makes Kramers-Kronig hold best, A_dd(w) - A_inf,dd = (2/pi)
// PV int_0^inf B_dd(v) / (v^2 - w^2) dv in least squares over the
// frequencies up to 0.9 w_N; without A, the least-squares slope of ln B_dd
// against ln w over the last 3 frequencies. 0 (no tail) when c has fewer
// than 3 frequencies or B_dd is not positive at the last 3
void tailExponents(const HydroCoef& c, double p[6]);

// exponent of pair (i, j): (p_i + p_j) / 2, so that B(w) = D B(w_N) D with
// D = diag((w_N / w)^(p_d / 2)) stays positive semi-definite; 0: no tail
double tailExponent(const double p[6], int i, int j);

// (2/pi) int_{wN}^inf bN (wN / w)^p cos(w t) dw, p > 1, t >= 0 [s]: the
// tail's part of K(t) (= (2/pi) bN wN Re E_p(-i wN t), E_p the generalized
// exponential integral)
double tailK(double bN, double wN, double p, double t);

// E_p(-i x) = int_1^inf u^-p e^{i x u} du for p > 1, x >= 0 (re, im)
void expintImag(double p, double x, double* re, double* im);

}  // namespace mjb

#endif  // MJBUOY_RADTAIL_H_
