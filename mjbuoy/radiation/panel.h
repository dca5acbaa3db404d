// linear potential-flow panel solver, deep or finite depth: added mass,
// radiation damping and exciting force of one rigid body from its wetted
// surface (docs/physics.md section 13)
#ifndef MJBUOY_PANEL_H_
#define MJBUOY_PANEL_H_

#include <complex>
#include <functional>
#include <string>
#include <vector>

#include "radiation/hydrocoef.h"
#include "radiation/rankine.h"

namespace mjb {

// a panel mesh in the body frame [m], z = 0 the mean free surface
struct PanelMesh {
  std::vector<double> vert;  // 3 per vertex
  std::vector<int> face;     // 4 vertex indices per panel; a triangle has face[4 i + 3] = -1
  int nface() const { return (int)face.size() / 4; }
};

// one frequency's solved field, for the mean drift (drift.h): panels (body
// first, then lid; body panel i is body face i), source strengths sig
// (n = nb + nl rows) and the body panels' potentials phi (nb rows), both
// column-major with 6 radiation columns (per unit velocity) then one per
// heading (diffraction, per unit wave amplitude); out holds this
// frequency's A, B and X (row w)
struct PanelField {
  const std::vector<Panel>* pn;
  int nb, nl, w;
  double omega, K;
  const std::complex<double>* sig;
  const std::complex<double>* phi;
  const PanelMesh* body;
  const HydroCoef* out;
};
// called once per frequency, possibly from several threads at once
typedef std::function<void(const PanelField&)> PanelFieldFn;

// body: the mean wetted surface (z <= 0), panels counterclockwise seen from
//   the water (normals out of the body);
// lid: the waterplane inside the waterline (z = 0, normals up), for the
//   removal of irregular frequencies; empty: no removal;
// omega [rad/s] > 0 increasing, heading [rad]; rho, g, depth (0: deep water;
// the body above z = -depth) and ref of out are inputs.
// Fills out's omega, A, B, Ainf, heading, X, FK. Returns false with a message
// naming the bad entry on invalid input or a non-finite result.
// field: when given, called with each frequency's solved field
bool panelSolve(const PanelMesh& body, const PanelMesh& lid, const std::vector<double>& omega,
                const std::vector<double>& heading, HydroCoef* out, std::string* err,
                const PanelFieldFn* field = nullptr);

// hydrodynamic coefficients of a group of N bodies solved together
// (docs/physics.md section 13, "Interaction"): nm = 6 N modes, body k's
// surge..yaw about ref[3 k..3 k + 2] are modes 6 k .. 6 k + 5, forces and
// moments along the group frame's axes; nm x nm matrices row-major per
// frequency, block (i, j) the force on body i per motion of body j; the
// exciting force nm per (omega, heading): ((iw * nh) + ih) * nm + mode, per
// unit wave amplitude at the group frame's origin (hydrocoef.h's phase)
struct PanelGroupCoef {
  std::vector<double> ref;  // input: 3 per body [m], the group frame
  double rho = 1025, g = 9.81, depth = 0;  // input, as in HydroCoef
  std::vector<double> omega, heading;
  std::vector<double> A, B, Ainf;        // nm * nm per frequency; Ainf once
  std::vector<double> Xre, Xim, FKre, FKim;
  int nm() const { return (int)ref.size() / 3 * 6; }
};

// the group's bodies as one boundary-value problem: bodies[k] and lids[k]
// (may be empty) as panelSolve's body and lid, all in the group frame
// (z = 0 the mean free surface); one factorisation per frequency serves the
// 6 N radiation modes and the diffraction headings. Returns false with a
// message naming the bad entry
bool panelSolveGroup(const std::vector<PanelMesh>& bodies, const std::vector<PanelMesh>& lids,
                     const std::vector<double>& omega, const std::vector<double>& heading,
                     PanelGroupCoef* out, std::string* err);

// body k of a solved group as one body's coefficients (hydrocoef.h): its
// own 6x6 blocks of A, B, Ainf (the others held fixed: their scattering
// included, their motion not) and its exciting force with the wave's
// amplitude moved to its ref (times e^{-i k (x cos b + y sin b)}, k the
// wavenumber at the group's depth); ref, rho, g, depth copied. False when
// k is outside 0 .. N - 1
bool panelGroupBody(const PanelGroupCoef& g, int k, HydroCoef* out);

// the block (i, j) of g: A, B and A_inf of the force on body i per motion
// of body j, about each body's ref (rho, g, depth, omega too; ref, heading
// and the exciting force untouched); false for a body g does not hold
bool panelGroupBlock(const PanelGroupCoef& g, int i, int j, HydroCoef* out);

// a panel mesh mirror-symmetric about one vertical plane (within 1e-6 of
// its size) is solved as two half-size systems, about two as four
// quarter-size ones; off (tests): always the full system. Default on
void panelSymmetryUse(bool on);

// the mirror planes panelSolve uses (vertical, through the body's
// wetted-area centroid; normal y and x, or else the horizontal principal
// axes of the wetted surface): 1 (the first) | 2 (the second); 0 none (or
// invalid input)
int panelMirrors(const PanelMesh& body, const PanelMesh& lid);

// panelSolve's cost on body and lid for nw frequencies and nh headings:
// per frequency n rows by n_r columns of Green function integrals (n_r =
// n / |G| the rows of the symmetry-reduced systems, |G| 1, 2 or 4) and
// the dense complex algebra, |G| LU factorisations of 8/3 n_r^3 flops plus
// the 6 + nh solutions and potentials, 16 n n_r (6 + nh) flops
struct PanelCost {
  int n = 0, ng = 1;  // unknowns (body and lid panels), symmetry group order
  double green = 0;   // Green function integrals, all frequencies
  double flops = 0;   // dense algebra, all frequencies
  double seconds = 0;  // estimated wall time on this machine's threads [s]
};
PanelCost panelCost(const PanelMesh& body, const PanelMesh& lid, int nw, int nh);

}  // namespace mjb

#endif  // MJBUOY_PANEL_H_
