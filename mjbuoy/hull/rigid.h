// rigid: mass and inertia of the group of bodies a hull moves rigidly with,
// for the slamming bound (docs/physics.md section 10) and the default roll
// damping (section 14)
#ifndef MJBUOY_RIGID_H_
#define MJBUOY_RIGID_H_

#include <mujoco/mujoco.h>

namespace mjb {

struct Rigid {
  double minv;     // 1 / mass of the group [1/kg]; inf when it has no mass
  double iinv[6];  // inverse inertia about the group COM, world frame:
                   // xx yy zz xy xz yz [1/(kg m^2)]
  double com[3];   // group COM, world frame [m]
};

// the group's mass [kg], COM (world) [m] and inertia about it (world
// axes, xx yy zz xy xz yz) [kg m^2] from d->cinert (after mj_comPos);
// false (I 0, com the subtree's) when it has no mass; no allocation
bool groupInertia(const mjModel* m, const mjData* d, int body, double I[6], double com[3],
                  double* mass);

// the bodies welded to body's weld root (body_weldid), from d->cinert
// (valid after mj_comPos, so in mjcb_passive); no allocation
void rigidGroup(const mjModel* m, const mjData* d, int body, Rigid* r);

// effective mass of the group for an impulse at world point p along unit
// u: 1 / (1/m + (r x u) . I^-1 (r x u)), r = p - COM [kg]
double effMass(const Rigid& r, const double p[3], const double u[3]);

}  // namespace mjb

#endif  // MJBUOY_RIGID_H_
