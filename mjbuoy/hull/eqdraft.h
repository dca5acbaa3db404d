// eqdraft: the heave offset that floats a free rigid group on flat water
// (docs/physics.md section 14, "Equilibrium draft")
#ifndef MJBUOY_EQDRAFT_H_
#define MJBUOY_EQDRAFT_H_

#include <string>

#include <mujoco/mujoco.h>

namespace mjb {

struct HullSet;
struct Sea;

// volume [m^3] of the hulls (of hs) of the bodies in root's subtree below
// the flat sea at its mean level (sea.level), with the poses of d shifted up by dz [m]: the
// exact flat-water integral of wetTriangle (pressure.h), V = -sum dA n_z
double displacedVolume(const HullSet& hs, const Sea& sea, const mjData* d, int root, double dz);

// the same for the hulls of root's rigid group (body_weldid == root) only
double groupVolume(const HullSet& hs, const Sea& sea, const mjData* d, int root, double dz);

// heave offset dz [m] at which the subtree of root, a body with a free
// joint, displaces its own mass (body_subtreemass / rho), its orientation
// and x, y kept: bisection between fully submerged and dry to 1e-12 of
// the hull's height (the volume is monotone in dz). false, with the reason
// in why, when it has no hull, no mass, or is heavier than its whole
// displacement (it sinks)
bool equilibriumHeave(const HullSet& hs, const Sea& sea, const mjData* d, int root, double* dz,
                      std::string* why);

}  // namespace mjb

#endif  // MJBUOY_EQDRAFT_H_
