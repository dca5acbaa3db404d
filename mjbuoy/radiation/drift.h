// mean (second-order) wave drift force and moment in regular waves, from
// the panel solver's first-order solution (docs/physics.md section 18):
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
// solve's reference point out->ref: rigid-body mass M, restoring C
// (hydrostatic plus any spring), extra linear damping D (joints'), 6x6
// row-major (hydrocoef.h dofs); Cb: the part of C from the water pressure
// (buoyancy), for the Froude-Krylov drift's rotation term.
// free false: a restrained (fixed) body, no motion; dof: the dofs it moves
// in (a body on slide joints), the others held
struct DriftBody {
  bool free = false;
  bool dof[6] = {true, true, true, true, true, true};
  double M[36] = {0};
  double C[36] = {0};
  double D[36] = {0};
  double Cb[36] = {0};
  double com[3] = {0, 0, 0};  // the COM [m, panel frame]
};

// motion RAOs xi [m/m, rad/m] per heading (6 per heading) at the field's
// frequency: [-omega^2 (M + A) - i omega (B + D) + C] xi = X over the
// body's dofs (the others 0); zero for a fixed body. False if the system
// is singular or the result not finite
bool driftRao(const PanelField& f, const DriftBody& b, std::vector<dcplx>* xi);

// far-field mean drift (Maruo 1960, Newman 1967) per unit wave amplitude
// squared: 3 per heading, (Fx [N/m^2], Fy [N/m^2], Mz about ref's vertical
// [N m/m^2]), from the Kochin function of the total disturbance
void driftFar(const PanelField& f, const std::vector<dcplx>& xi, double* out);

// near-field mean drift (Pinkster 1980, direct pressure integration), same
// layout: waterline, velocity-squared, pressure-gradient and rotation terms
void driftNear(const PanelField& f, const DriftBody& b, const std::vector<dcplx>& xi,
               double* out);

// the Froude-Krylov drift: Pinkster's near field with the incident wave
// alone (waterline, velocity-squared, pressure-gradient and rotation terms
// of phi_I and the body's motion xi), same layout: the mean force that
// integrating the incident pressure and hydrostatics over the moving
// wetted surface gives (docs/physics.md section 18, "Time domain")
void driftFK(const PanelField& f, const DriftBody& b, const std::vector<dcplx>& xi, double* out);

// the mean force of the time domain's diffraction force applied at the
// wave's phase at the moving COM (docs/physics.md section 15), added to
// out: (1/2) Re(i K X_D conj(U)), U the COM's motion along the wave
void driftPhase(const PanelField& f, const DriftBody& b, const std::vector<dcplx>& xi,
                double* out);

// the drift table of a body: per (omega, heading), 3 numbers (Fx, Fy, Mz)
// [N/m^2, N m/m^2], the far field (near: the near field; fk: the drift the
// time-domain step gives by itself, driftFK + driftPhase), same index
// layout as HydroCoef's X
// ((iw nh + ih) 3 + k)
struct DriftTable {
  std::vector<double> far, near, fk;
};

// panelSolve with the drift table filled alongside out ("" or the error);
// near false: the far and Froude-Krylov drift only (near left 0; the time
// domain applies far - fk)
std::string panelSolveDrift(const PanelMesh& body, const PanelMesh& lid,
                            const std::vector<double>& omega, const std::vector<double>& heading,
                            const DriftBody& b, HydroCoef* out, DriftTable* dt,
                            bool near = true);

}  // namespace mjb

#endif  // MJBUOY_DRIFT_H_
