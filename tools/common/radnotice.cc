// radnotice: the tools' radiation lines (see radnotice.h)
#include "radnotice.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "api/buoy.h"  // internal: the attached radiation bodies
#include "api/config.h"

namespace mjbtool {

std::string radiationPlan(const mjModel* m) {
  mjb::Config c;
  if (!mjb::parseConfig(m, &c).empty()) return "";  // mjb_attach names the fault
  std::vector<int> bodies;
  for (int g : c.geom) {
    int bd = m->geom_bodyid[g];
    if (c.rad.radiates(bd) && std::find(bodies.begin(), bodies.end(), bd) == bodies.end()) {
      bodies.push_back(bd);
    }
  }
  if (bodies.empty()) return "";
  char buf[256];
  std::snprintf(buf, sizeof(buf), "radiation is on (mjbuoy.radiation) for %zu hull bod%s: "
                "their panel problems are solved at attach (seconds to minutes, a line per "
                "hull) or read from the cache (at once)", bodies.size(),
                bodies.size() == 1 ? "y" : "ies");
  return buf;
}

std::string radiationState(const mjbBuoy* b) {
  const mjb::Radiation& r = mjb::buoyOf(b)->rad;
  if (r.rb.empty()) return "off";
  char buf[128];
  if (r.nmode > 0) {
    std::snprintf(buf, sizeof(buf), "on, %zu bod%s (state-space memory, %d modes)", r.rb.size(),
                  r.rb.size() == 1 ? "y" : "ies", r.nmode);
  } else {
    std::snprintf(buf, sizeof(buf), "on, %zu bod%s (convolution memory, %d samples)",
                  r.rb.size(), r.rb.size() == 1 ? "y" : "ies", r.nh);
  }
  return buf;
}

}  // namespace mjbtool
