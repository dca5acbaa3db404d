// radinfo: the public radiation queries (mjbuoy.h: mjb_radiationInfo,
// mjb_radiationBodies), so that tools say what radiation does without
// the internal headers
#include <algorithm>
#include <vector>

#include "api/buoy.h"
#include "api/config.h"
#include "mjbuoy.h"

mjbRadInfo mjb_radiationInfo(const mjbBuoy* b) {
  mjbRadInfo i = {0, 0, 0};
  const mjb::Buoy* buoy = mjb::buoyOf(b);
  if (!buoy || buoy->rad.rb.empty()) return i;
  const mjb::Radiation& r = buoy->rad;
  i.nbody = r.rb.size();
  i.nmode = r.nmode;
  i.nsample = r.nmode > 0 ? 0 : r.nh;  // nh: the ring of the longest kernel
  return i;
}

int mjb_radiationBodies(const mjModel* m) {
  if (!m) return -1;
  try {
    mjb::Config c;
    if (!mjb::parseConfig(m, &c).empty()) return -1;  // mjb_attach names the fault
    std::vector<int> bodies;
    for (int g : c.geom) {
      const int bd = m->geom_bodyid[g];
      if (c.rad.radiates(bd) && std::find(bodies.begin(), bodies.end(), bd) == bodies.end()) {
        bodies.push_back(bd);
      }
    }
    return bodies.size();
  } catch (...) {  // out of memory: no C++ exception crosses the C API
    return -1;
  }
}
