// deep-water free-surface Green function of linear potential flow
// (docs/physics.md, "Radiation: panel solver")
#ifndef MJBUOY_GREEN_H_
#define MJBUOY_GREEN_H_

namespace mjb {

// Struve functions H0, H1: power series (Abramowitz & Stegun 12.1.3) up to
// x = 12, the integral form 12.1.7 up to 25, the asymptotic series
// 12.1.31 with Y0, Y1 above
double struveH0(double x);
double struveH1(double x);

// Bessel functions J0, J1, Y0, Y1 together (power series, A&S 9.1.10-11,
// below x = 8; Hankel's asymptotic expansion, A&S 9.2.5-10, above): about
// 1e-9 absolute, several times faster than std::cyl_bessel_j/neumann;
// x > 0
void bessel01(double x, double* j0, double* j1, double* y0, double* y1);

// wave part of the pulsating source, nondimensional: for X = K R >= 0 and
// Y = -K (z + zeta) >= 0 (K = omega^2 / g),
//   F(X, Y) = PV int_0^inf exp(-u Y) J0(u X) / (u - 1) du
// and its derivatives FX = dF/dX, FY = dF/dY; evaluated from
//   F = -(pi/2) e^-Y (H0(X) + Y0(X)) - int_0^Y e^(s-Y) / sqrt(X^2 + s^2) ds
// (F_Z - F = 1/sqrt(X^2 + Z^2), Z = -Y, integrated down from the surface
// value; docs/physics.md section 13); X = 0 uses F = -e^-Y Ei(Y).
// The full source potential (time dependence e^{-i omega t}, outgoing):
//   G = 1/r + 1/r' + 2 K F + 2 pi i K e^-Y J0(X)
struct WaveF {
  double F, FX, FY;
  double J0, J1;  // J0(X), J1(X), for the imaginary part
};
WaveF greenWave(double X, double Y);

}  // namespace mjb

#endif  // MJBUOY_GREEN_H_
