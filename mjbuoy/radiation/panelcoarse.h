// panelcoarse: a coarsened copy of a hull's triangles for the panel solver
// when its wet panels exceed a budget (docs/physics.md section 13,
// "Coarsened hulls")
#ifndef MJBUOY_PANELCOARSE_H_
#define MJBUOY_PANELCOARSE_H_

#include <string>

#include "radiation/panel.h"

namespace mjb {

// what coarsenPanels did: wet panels (body, plus lid when counted),
// hull triangles, displaced volume [m^3] and waterplane area [m^2] of the wet
// panels before (0) and after; err: the simplifier's error, relative to
// the mesh's extent
struct CoarseInfo {
  int panels0 = 0, panels = 0, tri0 = 0, tri = 0;
  double vol0 = 0, vol = 0, awp0 = 0, awp = 0;
  double err = 0;
};

// displaced volume [m^3] of a wet panel mesh (hullPanels' body, z <= 0,
// normals out of the body): the divergence theorem with the field (0, 0, z),
// whose flux through the waterplane z = 0 is 0, so no lid is needed
double panelVolume(const PanelMesh& body);

// waterplane area [m^2] of a wet panel mesh: minus the sum of its panels'
// vertical area vectors (the wet surface closes on the waterplane)
double panelWaterplane(const PanelMesh& body);

// the hull's triangles (vert: 3 floats per vertex, face: 3 indices per
// triangle, counterclockwise outside) welded (vertices within 1e-6 of the
// extent become one), simplified by quadric edge collapse (Garland and
// Heckbert 1997; meshoptimizer's meshopt_simplify) to 70% of a target
// count and brought to it by bisecting the longest edges, then cut and
// paneled by hullPanels (same pos, quat, refine); the target is adjusted
// until the wet panels (body, plus the lid when countLid) are at most
// budget and, if it can be had in 10 tries, at least 97% of it. *body,
// *lid, *note become hullPanels' on the coarse hull (same panel frame).
// body and lid come in as the uncoarsened panels (for the counts in
// *info). false (with *note; body, lid unchanged) when no try is within
// the budget
bool coarsenPanels(const float* vert, int nvert, const int* face, int nface, const double pos[3],
                   const double quat[4], int refine, bool countLid, int budget, PanelMesh* body,
                   PanelMesh* lid, std::string* note, CoarseInfo* info);

}  // namespace mjb

#endif  // MJBUOY_PANELCOARSE_H_
