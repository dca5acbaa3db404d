// radattach: at mjb_attach, the panel solver's coefficients for every hull
// body with radiation on, fed to the time-domain radiation
// (docs/physics.md section 14, "From the panel solver"; docs/mjcf.md)
#ifndef MJBUOY_RADATTACH_H_
#define MJBUOY_RADATTACH_H_

#include <string>
#include <vector>

#include "panel.h"

namespace mjb {

struct Buoy;

// default frequencies of a hull whose waterplane has radius R [m] (of the
// disk of equal area): n = 20 omegas uniform from kR = 0.05 to 5,
// omega = sqrt(g k) (deep water)
std::vector<double> defaultOmega(double R, double g);

// waterplane radius [m] of a wet panel mesh: sqrt(A_wp / pi), A_wp = |sum
// of the panels' vertical area| (the wetted surface closes on the
// waterplane); the largest horizontal vertex distance if that is 0
double waterplaneRadius(const PanelMesh& p);

// for each rigid group of hull bodies with radiation on (all its hulls'
// panels together, at the model's qpos0, clipped at the mean sea level):
// panelSolve, coefficients moved to the root body's COM in its axes,
// setRadiation. Warnings go to B->cfg.warn. "" or the error, naming the body
std::string attachRadiation(Buoy* B);

}  // namespace mjb

#endif  // MJBUOY_RADATTACH_H_
