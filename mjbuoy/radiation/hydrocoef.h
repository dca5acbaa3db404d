// frequency-domain hydrodynamic coefficients of one rigid body:
// what the panel solver produces and the time-domain radiation consumes
// (docs/physics.md, "Radiation")
#ifndef MJBUOY_HYDROCOEF_H_
#define MJBUOY_HYDROCOEF_H_

#include <vector>

namespace mjb {

// conventions
// - dofs: surge, sway, heave, roll, pitch, yaw; forces [N] and moments
//   [N m] about ref, along the axes of the body frame at equilibrium
//   (z up when the body floats upright);
// - 6x6 matrices row-major, mat[6 * i + j] = force i per motion j;
// - time dependence Re(a e^{-i omega t}): a wave of complex amplitude a at
//   the reference point, eta = Re(a e^{i (k D . x - omega t)}), exerts
//   Re(a X e^{-i omega t}) (the sea's phase theta = k D . x - omega t + phi,
//   docs/physics.md section 11, is a = A e^{i phi})
struct HydroCoef {
  double ref[3] = {0, 0, 0};  // reference point in the body frame [m]
  double rho = 1025;          // water density [kg/m^3]
  double g = 9.81;            // gravity [m/s^2]
  double depth = 0;           // water depth [m]; 0: deep water

  std::vector<double> omega;  // frequencies [rad/s], increasing
  std::vector<double> A;      // added mass, 36 per frequency [kg, kg m, kg m^2]
  std::vector<double> B;      // radiation damping, 36 per frequency [kg/s, ...]
  double Ainf[36] = {0};      // added mass at infinite frequency

  std::vector<double> heading;  // wave headings beta [rad]: waves travel to (cos b, sin b)
  std::vector<double> Xre;      // exciting force per unit amplitude [N/m, N m/m],
  std::vector<double> Xim;      //   6 per (omega, heading): ((iw * nh) + ih) * 6 + dof
  std::vector<double> FKre;     // its Froude-Krylov part, same layout
  std::vector<double> FKim;

  int nw() const { return (int)omega.size(); }
  int nh() const { return (int)heading.size(); }
};

}  // namespace mjb

#endif  // MJBUOY_HYDROCOEF_H_
