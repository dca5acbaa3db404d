// wind: mean wind at 10 m with optional gusts, as drag and friction on the
// dry faces of hulls and of named superstructure geoms (docs/physics.md,
// "Irregular seas and wind")
#ifndef MJBUOY_WIND_H_
#define MJBUOY_WIND_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "mjbuoy.h"

namespace mjb {

struct Buoy;
struct State;
struct Sea;

// wind entries of a model (docs/mjcf.md section 9)
struct WindParams {
  bool on = false;        // any mjbuoy.wind.* entry: wind forces are computed
  mjbWind w = {0, 0, mjbGUST_NONE, 128, 1};
  double rho = 1.225;     // air density [kg/m^3]
  double cd = 1.0;        // drag coefficient per projected dry area
  double cf = 0.002;      // friction coefficient per dry area
  std::vector<int> geom;  // superstructure geoms
};

struct Gust { double a, f, ph; };  // amplitude [m/s], frequency [Hz], phase [rad]

// wind model of an attached model: gust components and the dry surfaces
struct Wind {
  WindParams par;
  std::vector<Gust> gust;      // capacity reserved at attach
  std::vector<double> vert;    // superstructure vertices, body frame [m]
  std::vector<int> face;       // 3 indices into vert each
  struct Part { int body, t0, nt, hull; };  // triangles of one surface on one body; hull index or -1
  std::vector<Part> part;      // hulls then superstructure; t0 < 0: hull triangles
  std::vector<int> body;       // bodies with a wind surface, ascending
  std::vector<int> extra;      // those of them without a hull
};

// Froya gust spectrum at 10 m [m^2/s^2 per Hz] of mean speed u0 [m/s]
double froya(double u0, double f);

// fill w->gust from w->par.w (no allocation within the 1024 reserved)
void windGusts(Wind* w);

// speed at 10 m along the mean direction at time t [m/s]
double windSpeed(const Wind& w, double t);

// build the superstructure meshes and body list at attach ("" or error)
std::string windMake(Buoy* b);

// add the wind wrench of every wind body to s->part[mjbPART_WIND] and
// s->wrench; bodies with a non-finite state are skipped
void windWrench(const Buoy& b, const mjModel* m, const mjData* d, State* s);

}  // namespace mjb

#endif  // MJBUOY_WIND_H_
