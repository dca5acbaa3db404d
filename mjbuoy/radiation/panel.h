// linear potential-flow panel solver, deep or finite depth: added mass,
// radiation damping and exciting force of one rigid body from its wetted
// surface (docs/physics.md section 13)
#ifndef MJBUOY_PANEL_H_
#define MJBUOY_PANEL_H_

#include <string>
#include <vector>

#include "radiation/hydrocoef.h"

namespace mjb {

// a panel mesh in the body frame [m], z = 0 the mean free surface
struct PanelMesh {
  std::vector<double> vert;  // 3 per vertex
  std::vector<int> face;     // 4 vertex indices per panel; a triangle has face[4 i + 3] = -1
  int nface() const { return (int)face.size() / 4; }
};

// body: the mean wetted surface (z <= 0), panels counterclockwise seen from
//   the water (normals out of the body);
// lid: the waterplane inside the waterline (z = 0, normals up), for the
//   removal of irregular frequencies; empty: no removal;
// omega [rad/s] > 0 increasing, heading [rad]; rho, g, depth (0: deep water;
// the body above z = -depth) and ref of out are inputs.
// Fills out's omega, A, B, Ainf, heading, X, FK. Returns false with a message
// naming the bad entry on invalid input or a non-finite result.
bool panelSolve(const PanelMesh& body, const PanelMesh& lid, const std::vector<double>& omega,
                const std::vector<double>& heading, HydroCoef* out, std::string* err);

// a panel mesh mirror-symmetric about one vertical plane (within 1e-6 of
// its size) is solved as two half-size systems, about two as four
// quarter-size ones; off (tests): always the full system. Default on
void panelSymmetryUse(bool on);

// the mirror planes panelSolve uses (vertical, through the body's
// wetted-area centroid; normal y and x, or else the horizontal principal
// axes of the wetted surface): 1 (the first) | 2 (the second); 0 none (or
// invalid input)
int panelMirrors(const PanelMesh& body, const PanelMesh& lid);

}  // namespace mjb

#endif  // MJBUOY_PANEL_H_
