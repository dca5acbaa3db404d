// radattach: at mjb_attach, the panel solver's coefficients for every hull
// body with radiation on, fed to the time-domain radiation
// (docs/physics.md section 14, "From the panel solver"; docs/mjcf.md)
#ifndef MJBUOY_RADATTACH_H_
#define MJBUOY_RADATTACH_H_

#include <string>
#include <vector>

#include "radiation/panel.h"

namespace mjb {

struct Buoy;

// default frequencies of a hull whose waterplane has radius R [m] (of the
// disk of equal area) and whose wet panels have the 90th-percentile edge
// length h [m] (panelEdge90): n = 20 omegas uniform from kR = 0.05 to
// defaultTopKR(R, h), omega = sqrt(g k) (deep water; docs/physics.md
// section 14, "Default frequencies")
std::vector<double> defaultOmega(double R, double h, double g);

// highest k R of the default range: where the panels still resolve the
// radiated wave, 6 panels per wavelength, k_h = 2 pi / (6 h), within
// [kTopKRMin, kTopKRMax]: min(5, max(1.5, k_h R))
double defaultTopKR(double R, double h);
const double kTopKRMin = 1.5, kTopKRMax = 5;

// the 90th-percentile edge length [m] of a panel mesh (every edge of
// every panel, nearest rank; 0 for no panels)
double panelEdge90(const PanelMesh& p);

// waterplane radius [m] of a wet panel mesh: sqrt(A_wp / pi), A_wp = |sum
// of the panels' vertical area| (the wetted surface closes on the
// waterplane); the largest horizontal vertex distance if that is 0
double waterplaneRadius(const PanelMesh& p);

// the default wet-panel budget (mjbuoy.radiation.panels, RadConfig::panels):
// a rigid group with more wet panels (hull and lid) is solved on a
// coarsened copy of its hull within it (panelcoarse.h); radiation on
// without an entry asking for it skips, with a warning, a group that
// cannot be coarsened to it, or is not wet at qpos0, or whose panel
// solution fails: the panel solution's O(N^3) cost (a 408-panel
// hemisphere at 12 frequencies: 2.7 s on 2 cores) stays within seconds
// and a default never makes an attach fail
const int kDefaultPanels = 400;

// Miche's (1944) deep-water breaking limit of a wave's height to length,
// H / lambda; 0.142 tanh(k h) at depth h. A steeper component is beyond
// linear theory: the radiation default leaves such a sea alone
const double kBreakHL = 0.142;

// for each rigid group of hull bodies with radiation on (all its hulls'
// panels together, at the flat-water equilibrium of a free body, else at
// the model's qpos0 (radattach.cc, poseHeave), clipped at the mean sea level):
// panelSolve, coefficients moved to the root body's COM in its axes,
// setRadiation. Warnings go to B->cfg.warn. "" or the error, naming the body
std::string attachRadiation(Buoy* B);

}  // namespace mjb

#endif  // MJBUOY_RADATTACH_H_
