// the interior lid's damping weight (docs/physics.md section 13, "Irregular
// frequencies and the damped lid"): how far each lid panel lies inside the waterline
#ifndef MJBUOY_PANELLID_H_
#define MJBUOY_PANELLID_H_

#include <vector>

#include "radiation/panel.h"

namespace mjb {

// w per lid face in (0, 1]: the horizontal distance from the point xy
// (2 per face, its collocation point) to the nearest waterline edge (an
// edge of exactly one lid face) over the largest such distance; empty if
// the lid has no faces
std::vector<double> lidWeights(const PanelMesh& lid, const std::vector<double>& xy);

}  // namespace mjb

#endif  // MJBUOY_PANELLID_H_
