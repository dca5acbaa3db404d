// panel meshes for the panel solver (panel.h): analytic test bodies and
// the wetted part of a hull's triangles (docs/physics.md section 13)
#ifndef MJBUOY_PANELMESH_H_
#define MJBUOY_PANELMESH_H_

#include <string>

#include "radiation/panel.h"

namespace mjb {

// floating hemisphere of radius R [m], centre at the origin: nt rings of
// polar angle, na panels around; lid: the waterplane disk (nt/2 rings,
// at least 1)
void hemisphereMesh(double R, int nt, int na, PanelMesh* body, PanelMesh* lid);

// truncated vertical cylinder of radius R and draft T [m]: nz panels down
// the side, nr rings on the bottom, na around; lid: the waterplane disk
void cylinderMesh(double R, double T, int nz, int nr, int na, PanelMesh* body, PanelMesh* lid);

// the wetted surface of a closed triangle mesh: vert (3 per vertex, body
// frame [m]), face (3 vertex indices per triangle, counterclockwise seen
// from outside, as MuJoCo meshes), clipped at the mean free surface for the
// body pose pos [m], quat (w, x, y, z) of the body frame in the world
// (world z = 0 the mean free surface). Output frame: world axes, origin at
// the body origin's horizontal position (x = R v + (0, 0, pos z)): the body
// frame itself, shifted to the waterline, when the body floats upright.
// refine: each panel split in 4 that many times (0..4). lid: the waterplane
// fanned from its centroid and refined as much, when the waterplane is
// star-shaped about its centroid (one convex-ish hull); else lid is left
// empty and *note says why. Returns false with *note naming the bad entry
// when nothing is wetted or the mesh is invalid.
bool hullPanels(const float* vert, int nvert, const int* face, int nface, const double pos[3],
                const double quat[4], int refine, PanelMesh* body, PanelMesh* lid, std::string* note);

}  // namespace mjb

#endif  // MJBUOY_PANELMESH_H_
