// hullset: the hulls of an attached model, their meshes in body frames and
// their coefficients; built once by mjb_attach (api/glue.cc), read by the
// backends, the wind and the equilibrium draft
#ifndef MJBUOY_HULLSET_H_
#define MJBUOY_HULLSET_H_

#include <vector>

#include <mujoco/mujoco.h>

namespace mjb {

// per-hull coefficients; defaults in kHullDefault (api/config.cc)
struct HullParams {
  double damp[2];     // simple damping: linear [N s/m], angular [N m s/rad]
  double viscous;     // form factor 1+k of the viscous resistance; 0 = off
  double drag[3];     // pressure drag C_PD1, C_PD2 [N/m^2], exponent f_P
  double suction[3];  // suction drag C_SD1, C_SD2 [N/m^2], exponent f_S
  double vref;        // reference speed of the drag terms [m/s]
  double slam[3];     // slamming gain [0, 1], Gamma_max [m/s^2], power p
};

struct Hull {
  int geom, body;     // MuJoCo ids
  int v0, nv;         // vertex range in HullSet::vert
  int t0, nt;         // triangle range in HullSet::face
  double area;        // total surface area S_total [m^2]
  double vol;         // enclosed volume |V| [m^3] (divergence theorem)
  double mass;        // body mass share of this hull (by area) [kg]
  double share;       // this hull's share (by area) of its rigid group's hulls
  double rad;         // largest vertex distance from the body origin [m]
  HullParams par;
  char radDrag = 0;   // linear drag terms radiation's default zeroed (api/config.h kRadDrag)
};

// every hull of a model, one mesh per hull geom, concatenated
struct HullSet {
  const mjModel* m = nullptr;  // the model whose geoms these are
  std::vector<Hull> hull;      // ordered by body, then geom
  std::vector<double> vert;    // hull vertices in body frame, 3 each [m]
  std::vector<int> face;       // 3 global vertex indices per triangle
  std::vector<double> tarea;   // area of each triangle [m^2]
  std::vector<int> body;       // bodies carrying hulls, ascending
};

}  // namespace mjb

#endif  // MJBUOY_HULLSET_H_
