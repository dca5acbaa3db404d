// mean and slowly varying wave drift in the time domain (docs/physics.md
// section 18, "Time domain"): the drift table of a body next to its
// diffraction table, summed over the sea's components by Newman's (1974)
// approximation
#ifndef MJBUOY_DRIFTSTEP_H_
#define MJBUOY_DRIFTSTEP_H_

#include <complex>
#include <string>

#include "radiation/diffract.h"
#include "radiation/drift.h"
#include "sea/sea.h"

namespace mjb {

// the drift table T of body's diffraction entry: the far-field drift less
// the part the step gives by itself (dt.fk: Froude-Krylov drift and the
// diffraction force's phase), per unit amplitude squared (Tfar: the far
// field alone), (Fx, Fy, Mz) per (omega, heading) of its diffraction
// table, computed about ref (panel frame, the table's axes), the moment
// moved to com [m] (same frame). "" or the error
std::string setDrift(int body, const DriftTable& dt, const double ref[3], const double com[3],
                     Diffraction* df);

// T of b at row (iw, tw) (diffRow) and heading beta [rad] (table axes):
// Fx, Fy, Mz
void driftAt(const DiffBody& b, int iw, double tw, double beta, double T[3]);

// Newman's (1974) approximation of the difference-frequency force, summed
// one component at a time in the diffraction step (diffractionWrench):
//   F(t) = sum_ij A_i A_j (T_i + T_j) / 2 cos(theta_i - theta_j)
//        = Re[(sum_i a_i T_i) conj(sum_j a_j)],  a_j = A_j e^{i theta_j},
// O(N) per step; one component gives the steady mean drift A^2 T.
// P = sum_i a_i T_i (Fx, Fy, Mz), Q = sum_j a_j
struct DriftSum {
  std::complex<double> P[3] = {0, 0, 0};
  std::complex<double> Q = 0;
};

// T of b (non-empty) at the weights tw (tableWeights): Fx, Fy, Mz
inline void driftBlend(const DiffBody& b, const TableWeights& tw, double T[3]) {
  T[0] = T[1] = T[2] = 0;
  for (int i = 0; i < tw.n; i++) {
    const double* p = b.T.data() + 3 * (size_t)tw.off[i];
    for (int d = 0; d < 3; d++) T[d] += tw.f[i] * p[d];
  }
}

// add the component of amplitude a = (re, im) at the COM, T at weights tw
// (tableWeights); none when b has no drift table
inline void driftAdd(const DiffBody& b, const TableWeights& tw, double are, double aim,
                     DriftSum* s) {
  if (b.T.empty()) return;
  double T[3];
  driftBlend(b, tw, T);
  const std::complex<double> a(are, aim);
  for (int k = 0; k < 3; k++) s->P[k] += T[k] * a;
  s->Q += a;
}

// add Re(P conj(Q)) times the start-up ramp r squared to F (surge, sway, yaw)
void driftFinish(const DiffBody& b, const DriftSum& s, double r, double F[6]);

}  // namespace mjb

#endif  // MJBUOY_DRIFTSTEP_H_
