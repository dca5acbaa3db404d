// guard: what every tool does around MuJoCo's simulation. MuJoCo resets a
// state with a NaN, Inf or huge qpos, qvel or qacc to the initial one and
// carries on; a tool must stop there and say so rather than report the
// reset state (or loop on a time that keeps going back). MuJoCo's default
// warning and error output also appends to MUJOCO_LOG.TXT in the working
// directory; the tools print to stderr instead.
#ifndef MJBUOY_TOOLS_GUARD_H_
#define MJBUOY_TOOLS_GUARD_H_

#include <string>

#include <mujoco/mujoco.h>

namespace mjbtool {

// MuJoCo warnings and errors to stderr as "tool: MuJoCo ...", never to
// MUJOCO_LOG.TXT; after 20 warnings the rest are only counted. An error
// is fatal in MuJoCo (it cannot continue): exit status 3
void installMujocoHandlers(const char* tool);

// mjbuoy's progress lines at attach (mjb_setProgress: what the panel
// solver solves and its estimated time, what the radiation cache answers)
// to stderr as "tool: line"; installMujocoHandlers installs it too
void installProgress(const char* tool);

// the last MuJoCo warning text ("" if none since installMujocoHandlers)
std::string lastMujocoWarning();

// did MuJoCo reset the state in the steps so far (bad qpos, qvel or qacc
// counted in d->warning); why: what and MuJoCo's text
bool diverged(const mjData* d, std::string* why);

// the most steps a run may take (a double counts them exactly below 2^53)
constexpr double kMaxSteps = 1e15;

// steps of dt that reach duration (rounded to the nearest step within
// 1e-6 of one; a loop bound independent of d->time); -1 when that is not
// a finite count below kMaxSteps
long stepsFor(double duration, double dt);

// the validated step count of a run (>= 1), or 0 with why naming the
// duration, the time step and the accepted range
long runSteps(double duration, double dt, std::string* why);

}  // namespace mjbtool

#endif  // MJBUOY_TOOLS_GUARD_H_
