// windload: the wind's drag and friction on the dry faces of hulls and of
// named superstructure geoms (docs/physics.md, "Irregular seas and wind")
#ifndef MJBUOY_WINDLOAD_H_
#define MJBUOY_WINDLOAD_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "hull/hullset.h"
#include "sea/wind.h"

namespace mjb {

struct Sea;

// wind model of an attached model: the field and the dry surfaces
struct Wind : WindField {
  std::vector<double> vert;    // superstructure vertices, body frame [m]
  std::vector<int> face;       // 3 indices into vert each
  // triangles of one surface on one body; hull index or -1
  struct Part { int body, t0, nt, hull; };
  std::vector<Part> part;      // hulls then superstructure; t0 < 0: hull triangles
  std::vector<int> body;       // bodies with a wind surface, ascending
  std::vector<int> extra;      // those of them without a hull
};

// build w's field from par, its superstructure meshes and body list at
// attach, for the hulls hs; load warnings go to warn ("" or error)
std::string windMake(const HullSet& hs, const WindParams& par, std::vector<std::string>* warn,
                     Wind* w);

// what windWrench reads and writes for one mjData: the cpu backend's
// vertex heights above the surface h [m] and the highest crest [m] (h null
// on the gl backend: the exact height at each centroid decides), per body
// whether its state is not finite (bad), the wind family's wrenches (part,
// nbody x 6) and the total wrenches (wrench, nbody x 6) it adds to
struct WindIO {
  const double* h;
  double crest;
  const char* bad;
  double* part;
  double* wrench;
};

// add the wind wrench of every wind body to io.part and io.wrench; bodies
// with a non-finite state are skipped
void windWrench(const HullSet& hs, const Wind& wd, const Sea& sea, const mjModel* m,
                const mjData* d, const WindIO& io);

}  // namespace mjb

#endif  // MJBUOY_WINDLOAD_H_
