// radgroup: bodies named in mjbuoy.radiation.group solved together by the
// panel solver at attach (docs/physics.md section 14, "Interaction";
// docs/mjcf.md, "Radiation")
#ifndef MJBUOY_RADGROUP_H_
#define MJBUOY_RADGROUP_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "radiation/hydrocoef.h"
#include "radiation/panel.h"

namespace mjb {

struct Buoy;

// mjbuoy.radiation.group's names as groups of weld roots (one per named
// body's rigid group), each group of 2 or more, no root in two groups, each
// root radiating (RadConfig::groupRadiates) from the panel solver (no
// coefficient file). "" or the error naming the field, the body and the fix
std::string groupBodies(const Buoy& B, std::vector<std::vector<int>>* roots);

// the panels of one body of a group: body and lid in its own panel frame
// (world axes, origin at its root's horizontal position on the mean sea
// level, hullPanels) and that origin's horizontal position xy [m]
struct GroupMember {
  std::string who;
  PanelMesh body, lid;
  double xy[2] = {0, 0};
  int root = 0;                          // its weld root (MuJoCo body id)
  double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // its body axes in the world at the panel pose
  double com[3] = {0, 0, 0};             // its COM in its panel frame [m]
};

// the members solved together (panelSolveGroup in a group frame at the
// first member's origin) at omega and head; c[k]: member k's own
// coefficients in its panel frame (panelGroupBody: its 6x6 blocks with the
// others held fixed, its exciting force with their diffraction), ref 0;
// in: rho, g, depth; cpl[n i + j] (i != j): the coupling block (i, j),
// the force on member i per motion of member j (A, B, Ainf; no exciting
// force), about member i's and j's panel-frame origins, world axes.
// Through the cache (radcache.h), keyed by every member's panels at their
// relative placement. false with *err
bool groupSolve(Buoy* B, const std::vector<GroupMember>& mem, const std::vector<double>& omega,
                const std::vector<double>& head, const HydroCoef& in, std::vector<HydroCoef>* c,
                std::vector<HydroCoef>* cpl, std::string* err);

// the coupling blocks cpl (groupSolve) moved to each member's COM in its
// body axes (as its own coefficients are), their memory kernels and
// A_ij(inf) added to B->rad (setCouple), after every member's
// setRadiation; then warns when the explicit coupling's gain
// (couplingGain, with each member's weld group's inertia from d, after
// mj_comPos) reaches kCoupleGainWarn. "" or the error
// the explicit coupling's gain (couplingGain) of the grouped bodies roots
// (MuJoCo body ids, each with radiation): each one's weld group's rigid
// inertia from d (after mj_comPos) plus its A_ii(inf), and the couplings'
// A_ij(inf), all about the bodies' refs in body axes; -1 when a body has
// no radiation or no mass
double groupGain(const Buoy& B, const mjData* d, const std::vector<int>& roots);

std::string coupleGroup(Buoy* B, const mjData* d, const std::vector<GroupMember>& mem,
                        const std::vector<HydroCoef>& cpl);

}  // namespace mjb

#endif  // MJBUOY_RADGROUP_H_
