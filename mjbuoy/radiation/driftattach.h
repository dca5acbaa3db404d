// driftattach: at attach, the body dynamics the drift table's motions come
// from, and the table's cache file next to the coefficients' (docs/physics.md
// section 18, "At attach")
#ifndef MJBUOY_DRIFTATTACH_H_
#define MJBUOY_DRIFTATTACH_H_

#include <string>

#include <mujoco/mujoco.h>

#include "radiation/drift.h"

namespace mjb {

// the dynamics of rigid group root for its motion RAOs, in the panel frame
// (world axes, origin o [m, world]; reference point the frame's origin): a
// root on a free joint floats freely (mass matrix from the group's
// inertia, restoring from its wet panels and its weight), a root on slide
// joints along world axes moves in those dofs alone (their springs in C,
// damping in D), any other is restrained (free = false); yaw [rad]: the
// frame's axes turned about the vertical by yaw from the world's (a free
// root only: the panels' frame of identical hulls, radattach.cc)
void driftDynamics(const mjModel* m, const mjData* d, int root, const PanelMesh& body,
                   const double o[3], double rho, double g, DriftBody* b, double yaw = 0);

// the cache key of the drift table for the coefficients' key ckey
std::string driftCacheKey(const std::string& ckey, const DriftBody& b);

// the drift table packed as cache coefficients (X re: far field, X im:
// near field, FK re: Froude-Krylov drift, (Fx, Fy, 0, 0, 0, Mz) per
// frequency and heading) and back;
// unpack: false when c does not fit omega x heading or is not finite
HydroCoef driftPack(const DriftTable& dt, const HydroCoef& like);
bool driftUnpack(const HydroCoef& c, int nw, int nh, DriftTable* dt);

}  // namespace mjb

#endif  // MJBUOY_DRIFTATTACH_H_
