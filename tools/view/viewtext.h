// viewtext: what mjbuoy-view's overlay says about a model (its sea, wind
// and actuators) and how its keys drive the actuators; no window needed
#ifndef MJBUOY_TOOLS_VIEWTEXT_H_
#define MJBUOY_TOOLS_VIEWTEXT_H_

#include <string>

#include <mujoco/mujoco.h>

namespace mjbview {

// one sentence on the sea state of m: calm, or its components by kind
// (Gerstner or linear), their spectra, amplitude and wavelength range
std::string describeSea(const mjModel* m);

// one sentence on the wind of m: mean speed, direction and gusts, or "none"
std::string describeWind(const mjModel* m);

// the control of actuator a of m after one press of its key in direction
// dir (+1 up, -1 down): a twentieth of its ctrlrange per press, clamped
// to the range; kFreeStep per press when the control is not limited
const double kFreeStep = 0.05;
double nudgeCtrl(const mjModel* m, int a, double ctrl, int dir);

// actuator a and its control, e.g. "thrust = 150 in [-300, 300]"
std::string describeCtrl(const mjModel* m, int a, double ctrl);

}  // namespace mjbview

#endif  // MJBUOY_TOOLS_VIEWTEXT_H_
