// radnotice: the tools' radiation lines (see radnotice.h)
#include "radnotice.h"

#include <cstdio>

namespace mjbtool {

std::string radiationPlan(const mjModel* m) {
  const int n = mjb_radiationBodies(m);  // -1: mjb_attach names the fault
  if (n <= 0) return "";
  char buf[256];
  std::snprintf(buf, sizeof(buf), "radiation is on (mjbuoy.radiation) for %d hull bod%s: "
                "their panel problems are solved at attach (seconds to minutes, a line per "
                "hull) or read from the cache (at once)", n, n == 1 ? "y" : "ies");
  return buf;
}

std::string radiationState(const mjbBuoy* b) {
  const mjbRadInfo r = mjb_radiationInfo(b);
  if (r.nbody == 0) return "off";
  char buf[128];
  if (r.nmode > 0) {
    std::snprintf(buf, sizeof(buf), "on, %d bod%s (state-space memory, %d modes)", r.nbody,
                  r.nbody == 1 ? "y" : "ies", r.nmode);
  } else {
    std::snprintf(buf, sizeof(buf), "on, %d bod%s (convolution memory, %d samples)", r.nbody,
                  r.nbody == 1 ? "y" : "ies", r.nsample);
  }
  return buf;
}

}  // namespace mjbtool
