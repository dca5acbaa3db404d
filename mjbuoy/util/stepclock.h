// stepclock: which evaluation of a physics step a callback is in, for the
// histories that advance once a step (the radiation memory, the mooring
// lines; docs/physics.md section 7)
#ifndef MJBUOY_UTIL_STEPCLOCK_H_
#define MJBUOY_UTIL_STEPCLOCK_H_

#include <mujoco/mujoco.h>

namespace mjb {

enum StepTick { kTickSame = 0, kTickNew, kTickRestart, kTickMid };

// s holds the clock: key, the mjTIMER_STEP count at the last call (-1:
// none), and tcur, the current step's time [s]. A call at least 3/4 of a
// step after tcur opens a new step, a call at tcur repeats it, one in
// between is an RK4 stage; time going back or the step counter dropping
// (mj_resetData) restarts
template <class S>
int stepTick(const mjModel* m, const mjData* d, S* s) {
  long k = d->timer[mjTIMER_STEP].number;
  int r;
  if (s->key < 0 || k < s->key || d->time < s->tcur) {
    r = kTickRestart;
  } else if (d->time - s->tcur >= 0.75 * m->opt.timestep) {
    r = kTickNew;
  } else {
    s->key = k;
    return d->time == s->tcur ? kTickSame : kTickMid;
  }
  s->key = k;
  s->tcur = d->time;
  return r;
}

}  // namespace mjb

#endif  // MJBUOY_UTIL_STEPCLOCK_H_
