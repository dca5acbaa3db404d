// panel meshes for the panel solver (panel.h): analytic test bodies and
// the wetted part of a hull's triangles (docs/physics.md section 13)
#ifndef MJBUOY_PANELMESH_H_
#define MJBUOY_PANELMESH_H_

#include "panel.h"

namespace mjb {

// floating hemisphere of radius R [m], centre at the origin: nt rings of
// polar angle, na panels around; lid: the waterplane disk (nt/2 rings,
// at least 1)
void hemisphereMesh(double R, int nt, int na, PanelMesh* body, PanelMesh* lid);

// truncated vertical cylinder of radius R and draft T [m]: nz panels down
// the side, nr rings on the bottom, na around; lid: the waterplane disk
void cylinderMesh(double R, double T, int nz, int nr, int na, PanelMesh* body, PanelMesh* lid);

}  // namespace mjb

#endif  // MJBUOY_PANELMESH_H_
