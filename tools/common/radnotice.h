// radnotice: what every tool says on stderr about radiation, so that no
// tool waits silently: before mjb_attach, that the panel solve runs (it
// takes seconds to minutes, docs/mjcf.md section 11); after it, the
// radiation state the run has
#ifndef MJBUOY_TOOLS_RADNOTICE_H_
#define MJBUOY_TOOLS_RADNOTICE_H_

#include <string>

#include <mujoco/mujoco.h>

#include "mjbuoy.h"

namespace mjbtool {

// "" when m's hull bodies get no radiation; else one line (no newline)
// saying how many bodies the panel solve at attach runs for
std::string radiationPlan(const mjModel* m);

// the radiation an attached model has, e.g. "on, 11 bodies (state-space
// memory, 96 modes)", or "off"
std::string radiationState(const mjbBuoy* b);

}  // namespace mjbtool

#endif  // MJBUOY_TOOLS_RADNOTICE_H_
