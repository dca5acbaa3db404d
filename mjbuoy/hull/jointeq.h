// jointeq: the pose on flat water at which a hull's slide and hinge joints
// are in equilibrium (docs/physics.md section 14, "Equilibrium along joints")
#ifndef MJBUOY_JOINTEQ_H_
#define MJBUOY_JOINTEQ_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

namespace mjb {

// the hull triangles t0 .. t0 + nt - 1 of body `body` (EqWater::face)
struct EqHull {
  int body, t0, nt;
};

// the hulls and the flat sea they float in
struct EqWater {
  const double* vert = nullptr;  // hull vertices in their body frames, 3 each [m]
  const int* face = nullptr;     // 3 vertex indices per triangle
  std::vector<EqHull> hull;
  double level = 0, rho = 1025, g = 9.81;  // mean sea level [m], density, gravity
};

// generalized force [N or N m] on the dofs of joints jnt (slide or hinge) at
// d's qpos, qvel 0: gravity (mj_rne), the joints' springs and the
// flat-water buoyancy of w's hulls (wetTriangle: -rho g dA n). Runs
// mj_kinematics and mj_comPos on d
void jointForce(const mjModel* m, mjData* d, const EqWater& w, const std::vector<int>& jnt,
                double* q);

// moves d's qpos of joints jnt (slide or hinge; the others stay) to a
// stable zero of jointForce, started from d's qpos: damped Newton steps
// on a finite-difference Jacobian, each at most a quarter of the hulls'
// height (slides) or 0.25 rad (hinges). "" when found (d then holds the
// pose's kinematics), else why (d's qpos is then restored)
std::string jointEquilibrium(const mjModel* m, mjData* d, const EqWater& w,
                             const std::vector<int>& jnt);

}  // namespace mjb

#endif  // MJBUOY_JOINTEQ_H_
