// free-surface Green function of water of finite depth h: the deep-water
// wave function of green.h at the propagating wavenumber k0 on four images,
// a closed-form logarithmic part and a sum of exponentials (Prony) for the
// rest of the kernel (docs/physics.md section 13, "Finite depth")
#ifndef MJBUOY_GREENFD_H_
#define MJBUOY_GREENFD_H_

#include <complex>

#include "radiation/greentab.h"

namespace mjb {

const int kProny = 30;  // exponentials of the kernel's remainder

// where the seabed is out of reach (docs/physics.md section 13, "Finite
// depth", measured on a hemisphere and a cylinder): a frequency with
// K h >= kReachKh (tanh(K h) = 1 - 1e-5) is solved with the deep-water
// function when h >= kReachSize r (r the largest distance of a wetted
// vertex from the waterplane centre); there the deep-water coefficients
// and A_inf are within 0.1% of the finite-depth ones
const double kReachKh = 6, kReachSize = 10;

// the kernel of one frequency and depth
struct GreenFd {
  double K = 0, h = 0;  // K = omega^2 / g [1/m], depth [m]
  double k0 = 0;        // propagating wavenumber: k0 tanh(k0 h) = K [1/m]
  double c = 0;         // residue of the kernel at k0 [1/m]
  double a[kProny], b[kProny];  // remainder ~ sum a_j e^{-b_j k h}
};

// the kernel for K > 0, h > 0; false if the fit is not finite
bool greenFdInit(double K, double h, GreenFd* g);

// G - 1/r - 1/r' (r' the image in z = 0) for a unit source at depth zeta
// seen at z (both in [-h, 0], R the horizontal distance) and its
// derivatives by the field point's R and z [1/m, 1/m^2]:
//   G = 1/r + 1/r2 + sum_i [1/r_i + c F(k0 R, -k0 v_i) + i pi c e^{k0 v_i} J0(k0 R) + L(R, v_i)]
// tab: greentab.h's table covering X = k0 R, Y = 4 k0 h (nullptr: direct)
struct WaveFd {
  std::complex<double> G, GR, Gz;
};
WaveFd greenFdWave(const GreenFd& g, const GreenTable* tab, double R, double z, double zeta);

// infinite frequency (phi = 0 on z = 0, dphi/dz = 0 on z = -h): the images
// beyond 1/r - 1/r', sum over m != 0 of (-1)^m (1/|x - s_m| - 1/|x - s'_m|),
// s_m = (xi, eta, zeta + 2 m h), s'_m = (xi, eta, -zeta + 2 m h); d = x - xi
// (horizontal), value and gradient by x
void greenFdInfinite(double h, double dx, double dy, double z, double zeta, double* G,
                     double grad[3]);

// the incident wave's depth factor cosh(k (z + h)) / cosh(k h) and its
// z-derivative / k, sinh(k (z + h)) / cosh(k h); h 0: deep water, e^{kz}
void depthFactor(double k, double h, double z, double* f, double* fz);

}  // namespace mjb

#endif  // MJBUOY_GREENFD_H_
