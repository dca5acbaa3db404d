// moorstep: the mooring lines inside mjcb_passive (docs/mooring.md
// "Integration"): their step clock, the end kinematics from mjData, and
// the wrench they put on each body
#ifndef MJBUOY_MOORSTEP_H_
#define MJBUOY_MOORSTEP_H_

#include <string>

#include <mujoco/mujoco.h>

#include "mooring/mooring.h"
#include "sea/sea.h"
#include "util/pool.h"

namespace mjb {

// size s for mo's lines in a model of nbody bodies
void moorMakeState(const Mooring& mo, int nbody, MoorState* s);

// forget the lines' history: the next call puts them on their static
// equilibrium (mj_resetData, a new mjData)
void moorRestart(MoorState* s);

// one evaluation: on the first call of a new step move the lines from the
// last step's time to d->time (their ends interpolated between the two),
// after a restart put them at rest; then fill s->wrench (bodies of
// mo.body) with the end forces at d's current state. Faults go to notices.
// The lines are independent: with pool (may be NULL) and enough nodes
// they step on its threads, with the same results
void moorStep(const Mooring& mo, const Sea& sea, const mjModel* m, const mjData* d,
              MoorState* s, std::string* notices, Pool* pool);

}  // namespace mjb

#endif  // MJBUOY_MOORSTEP_H_
