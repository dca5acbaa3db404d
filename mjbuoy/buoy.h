// buoy: what mjbuoy keeps per attached model (static) and per mjData (state)
#ifndef MJBUOY_BUOY_H_
#define MJBUOY_BUOY_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "config.h"

namespace mjb {

struct Hull {
  int geom, body;     // MuJoCo ids
  int v0, nv;         // vertex range in Buoy::vert
  int t0, nt;         // triangle range in Buoy::face
  double area;        // total surface area S_total [m^2]
  HullParams par;
};

// static data of one attached model, built once by mjb_attach
struct Buoy {
  const mjModel* m;
  Config cfg;
  std::vector<Hull> hull;      // ordered by body, then geom
  std::vector<double> vert;    // hull vertices in body frame, 3 each [m]
  std::vector<int> face;       // 3 global vertex indices per triangle
  std::vector<int> body;       // bodies carrying hulls, ascending
  std::string warnings;        // newline-separated
  std::string renderer;
};

// per-mjData state; sized at creation, never resized while stepping
struct State {
  std::vector<double> wrench;  // nbody x 6: force, torque about xipos (world)
  std::vector<double> rel;     // vertex positions relative to their body COM [m]
  std::vector<double> h;       // vertex heights above the surface [m]
  std::vector<char> bad;       // per body: state not finite in the last call
};

// allocate s for b
void makeState(const Buoy& b, State* s);

// cpu backend: fill s->wrench from d's current state
void cpuWrench(const Buoy& b, const mjModel* m, const mjData* d, State* s);

}  // namespace mjb

#endif  // MJBUOY_BUOY_H_
