// hydrostatic: the rotational hydrostatic stiffness of a floating body from
// its wet panels, for the default roll damping (docs/physics.md section 14,
// "Viscous roll damping")
#ifndef MJBUOY_HYDROSTATIC_H_
#define MJBUOY_HYDROSTATIC_H_

#include "radiation/panel.h"

namespace mjb {

// the rotational block of the hydrostatic stiffness [N m/rad] about the
// body's COM G [m] (panel frame: world axes, z = 0 the mean free surface),
// world axes, row-major: for small rotations a about G the restoring
// moment is -C a. From the wet panels p (z <= 0, closed by the waterplane,
// normals out of the body) by the divergence theorem:
//   C = rho g [ W + V (z_B - G_z) diag(1, 1, 0) ]
//       + rho g V ( -(x_B - G_x) e_1 e_3^T - (y_B - G_y) e_2 e_3^T ),
//   W = int over the waterplane of (y'^2, -x'y', 0; -x'y', x'^2, 0; 0, 0, 0) dA,
// x' = x - G_x, y' = y - G_y, V and (x_B, y_B, z_B) the displaced volume
// and its centre; the weight's moment about its own point of action, - m g
// (z_G - G_z), is 0. vol: V [m^3] (nullptr: not wanted)
void rotStiffness(const PanelMesh& p, const double G[3], double rhog, double C[9],
                  double* vol = nullptr);

// e^T C e: the stiffness about the unit axis e through G [N m/rad]
double axisStiffness(const double C[9], const double e[3]);

}  // namespace mjb

#endif  // MJBUOY_HYDROSTATIC_H_
