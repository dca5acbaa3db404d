// test helper: the floating 1 m cube with radiation on that
// radattach_test.cc (heave decay) and radimmersion_test.cc (immersion
// factor) share, so both read one cached panel solution
#ifndef MJBUOY_TESTS_FLOATBOX_H_
#define MJBUOY_TESTS_FLOATBOX_H_

#include <sstream>
#include <string>

#include "testutil.h"

namespace mjbt {

// 1 m cube of mass rho 0.5 m^3 (draft 0.5 m, centre at the surface when
// floating), COM 0.2 m below the centre; radiation on with refine 1 (384
// wet panels and the lid), 12 frequencies from 0.9 to 9 rad/s
inline std::string floatingCubeXML() {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.005\"/><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
    << "<numeric name=\"mjbuoy.sea.density\" data=\"" << kRho << "\"/>"
    << "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>"
    << "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0.5\"/>"
    << "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0.5\"/>"
    << "<numeric name=\"mjbuoy.hull.slamming\" data=\"0 100 2\"/>"
    << "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
    << "<numeric name=\"mjbuoy.radiation.refine\" data=\"1\"/>"
    << "<numeric name=\"mjbuoy.radiation.omega\" data=\"0.9 9 12\"/>"
    << "</custom><worldbody><body name=\"box\"><freejoint/>"
    << "<inertial pos=\"0 0 -0.2\" mass=\"" << kRho * 0.5 << "\" diaginertia=\"100 100 100\"/>"
    << "<geom name=\"hull\" type=\"box\" size=\"0.5 0.5 0.5\" contype=\"0\" conaffinity=\"0\"/>"
    << "</body></worldbody></mujoco>";
  return s.str();
}

}  // namespace mjbt

#endif  // MJBUOY_TESTS_FLOATBOX_H_
