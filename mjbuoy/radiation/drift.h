// mean (second-order) wave drift force and moment in regular waves, from
// the panel solver's first-order solution (docs/physics.md section 17):
// far field (Maruo 1960, Newman 1967) and near field (Pinkster 1980)
#ifndef MJBUOY_DRIFT_H_
#define MJBUOY_DRIFT_H_

#include <complex>
#include <string>
#include <vector>

#include "radiation/panel.h"

namespace mjb {

typedef std::complex<double> dcplx;

// the body's dynamics for its motion RAOs, in the panel frame about the
// solve's reference point out->ref: rigid-body mass M and restoring C
// (hydrostatic plus any spring), 6x6 row-major (hydrocoef.h dofs).
// free false: a restrained (fixed) body, no motion
struct DriftBody {
  bool free = false;
  double M[36] = {0};
  double C[36] = {0};
};

// motion RAOs xi [m/m, rad/m] per heading (6 per heading) at the field's
// frequency: [-omega^2 (M + A) - i omega B + C] xi = X; zero for a fixed
// body. False if the system is singular or the result not finite
bool driftRao(const PanelField& f, const DriftBody& b, std::vector<dcplx>* xi);

// far-field mean drift (Maruo 1960, Newman 1967) per unit wave amplitude
// squared: 3 per heading, (Fx [N/m^2], Fy [N/m^2], Mz about ref's vertical
// [N m/m^2]), from the Kochin function of the total disturbance
void driftFar(const PanelField& f, const std::vector<dcplx>& xi, double* out);

// near-field mean drift (Pinkster 1980, direct pressure integration), same
// layout: waterline, velocity-squared, pressure-gradient and rotation terms
void driftNear(const PanelField& f, const DriftBody& b, const std::vector<dcplx>& xi,
               double* out);

// the drift table of a body: per (omega, heading), 3 numbers (Fx, Fy, Mz)
// [N/m^2, N m/m^2], the far field (near: the near field), same index layout
// as HydroCoef's X ((iw nh + ih) 3 + k)
struct DriftTable {
  std::vector<double> far, near;
};

// panelSolve with the drift table filled alongside out ("" or the error);
// near false: the far field only (near left 0; the time domain uses the far)
std::string panelSolveDrift(const PanelMesh& body, const PanelMesh& lid,
                            const std::vector<double>& omega, const std::vector<double>& heading,
                            const DriftBody& b, HydroCoef* out, DriftTable* dt,
                            bool near = true);

}  // namespace mjb

#endif  // MJBUOY_DRIFT_H_
