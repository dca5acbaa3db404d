// test helper: a floating hemisphere as a MuJoCo mesh (radattach_test.cc,
// diffract_test.cc)
#ifndef MJBUOY_TESTS_HEMISPHERE_H_
#define MJBUOY_TESTS_HEMISPHERE_H_

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace mjbt {

// hemisphere of radius R [m] under z = 0 (nt polar rings, na around), a
// vertical collar up to z = hc so the waterplane stays a disk while it
// heaves, and a flat top: a closed MuJoCo mesh, counterclockwise outside
inline std::string hemisphereMeshXML(double R, int nt, int na, double hc) {
  std::vector<double> v = {0, 0, -R};
  for (int i = 1; i <= nt + 1; i++) {
    double th = M_PI / 2 * std::min(i, nt) / nt, r = R * std::sin(th);
    double z = i <= nt ? -R * std::cos(th) : hc;
    for (int a = 0; a < na; a++) {
      double ph = 2 * M_PI * a / na;
      v.insert(v.end(), {r * std::cos(ph), r * std::sin(ph), std::fabs(z) < 1e-12 ? 0.0 : z});
    }
  }
  v.insert(v.end(), {0, 0, hc});
  int top = v.size() / 3 - 1;
  auto ring = [&](int i, int a) { return 1 + (i - 1) * na + (a % na); };
  std::vector<int> f;
  for (int a = 0; a < na; a++) f.insert(f.end(), {0, ring(1, a + 1), ring(1, a)});
  for (int i = 1; i <= nt; i++)
    for (int a = 0; a < na; a++) {
      int l0 = ring(i, a), l1 = ring(i, a + 1), u0 = ring(i + 1, a), u1 = ring(i + 1, a + 1);
      f.insert(f.end(), {l0, l1, u1, l0, u1, u0});
    }
  for (int a = 0; a < na; a++) f.insert(f.end(), {top, ring(nt + 1, a), ring(nt + 1, a + 1)});
  std::ostringstream s;
  s.precision(17);
  s << "<mesh name=\"hemi\" vertex=\"";
  for (double x : v) s << x << " ";
  s << "\" face=\"";
  for (int i : f) s << i << " ";
  s << "\"/>";
  return s.str();
}

// radius scale f of that mesh, f^2 = (2 pi / na) / sin(2 pi / na): vertices
// on a sphere of radius R f make the na-gon waterline enclose pi R^2, the
// hemisphere's waterplane (the inscribed na-gon's is 1.1% less at na = 24),
// and the displaced volume 0.5% short of 2 pi R^3 / 3 at nt = 8, na = 24
// (2.1% short without the scale), so the body floats within millimetres of
// its rim
inline double hemisphereAreaScale(int na) {
  return std::sqrt((2 * M_PI / na) / std::sin(2 * M_PI / na));
}

// mjbuoy's drag, viscous and slamming terms off, so that only hydrostatics
// (and radiation, where on) act on the floating hemisphere below
inline const char* kNoDragEntries =
    "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>"
    "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 0.5\"/>"
    "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 0.5\"/>"
    "<numeric name=\"mjbuoy.hull.slamming\" data=\"0 100 2\"/>";

// a freely floating hemisphere of radius R [m] in water of density rho
// [kg/m^3]: the mesh above with vertices at R f (hemisphereAreaScale), an
// 8 x 24 mesh with a 0.3 m collar, mass rho 2/3 pi R^3 (it floats at its
// rim), COM 0.3 m down; `custom` holds the test's own <custom> entries
// (drag terms, sea, radiation switches); radiation 0.7 to 7 rad/s
inline std::string floatingHemisphereXML(double R, double rho, const std::string& custom) {
  const double m = rho * 2.0 / 3.0 * M_PI * R * R * R;
  std::ostringstream s;
  s.precision(17);
  s << "<mujoco><option timestep=\"0.005\"/><asset>"
    << hemisphereMeshXML(R * hemisphereAreaScale(24), 8, 24, 0.3)
    << "</asset><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
    << "<numeric name=\"mjbuoy.sea.density\" data=\"" << rho << "\"/>" << custom
    << "<numeric name=\"mjbuoy.radiation.omega\" data=\"0.7 7 12\"/>"
    << "</custom><worldbody><body name=\"hemi\"><freejoint/>"
    << "<inertial pos=\"0 0 -0.3\" mass=\"" << m << "\" diaginertia=\"" << 0.4 * m << " "
    << 0.4 * m << " " << 0.4 * m << "\"/>"
    << "<geom name=\"hull\" type=\"mesh\" mesh=\"hemi\" contype=\"0\" conaffinity=\"0\"/>"
    << "</body></worldbody></mujoco>";
  return s.str();
}

}  // namespace mjbt

#endif  // MJBUOY_TESTS_HEMISPHERE_H_
