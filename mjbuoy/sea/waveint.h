// waveint: the dynamic pressure and the water velocity of linear waves
// integrated in closed form over a planar wet piece (docs/physics.md,
// "Pressure", "Cost")
//
// Per component, p = rho g A Re(e^L) and u = A omega (Re e^L D, Im e^L)
// with L = k z' + i theta (deep water; z' Wheeler's stretched height).
// With z' and theta linear over the piece (the cut's own assumption), L is
// linear and (Hermite-Genocchi) the integrals are divided differences of
// exp at the corner values L_c = L_0 + u_c:
//   integral e^L dA = 2 area e^L0 S,  S = exp[0, u1, u2] = sum h_m(u1, u2) / (m + 2)!
//   integral lambda_c e^L dA = 2 area e^L0 T_c,  T_c = exp[u_c, 0, u1, u2]
//                            = sum h_m(u_c, 0, u1, u2) / (m + 3)!
// (h_m the complete homogeneous symmetric polynomials), summed to double
// round-off; for components whose |u| exceeds kRMax the piece is split
// into four half-size triangles until it does not.
#ifndef MJBUOY_WAVEINT_H_
#define MJBUOY_WAVEINT_H_

#include <cstddef>
#include <vector>

#include "sea/sea.h"
#include "sea/waveker.h"

namespace mjb {

// the components of one call in the order the integrals use: wave number
// ascending (so "needs m terms", "below e^-40", "too coarse" are suffixes)
struct WaveTab {
  int n = 0;
  bool finite = false;  // finite depth: a second exponent -k (z' + 2 h)
  double depth = 0;
  std::vector<int> perm;                // sorted index -> WaveNow index
  bool ident = false;                   // perm is the identity (already ascending)
  std::vector<double> k, kdx, kdy, gm;  // k [rad/m], k D, 1 if Gerstner else 0
  // long-crested: two or more components, all of one kind (gm 0 or 1)
  // along one direction D = (dx, dy), so a piece's corner differences are
  // k times one pair for all of them (trivec_kern.h familyShared)
  bool lc = false;
  double ldx = 0, ldy = 0, lgm = 0;
  // weights of Re(I) in the pressure [m], in the horizontal velocity along
  // x and y [m/s] and of Im(I) in the vertical velocity [m/s]; [1]: the
  // finite-depth second exponent
  std::vector<double> wp[2], wux[2], wuy[2], wz[2];
  // room for cap components (no allocation in fill)
  void reserve(size_t cap);
  // from the call's constants (Sea::now)
  void fill(const Sea& sea, const WaveNow* w);
};

// one component by subdivision (any |u|): S and T_c of the triangle with
// corner 0 at exponent L0r + i theta0 (ph = e^(i theta0)) and corners 1, 2
// at u1, u2 from it, split into four half-size triangles (edge midpoints)
// until |u| <= kRMax (at most 8 levels)
void subdivided(double L0r, double phr, double phi, double u1r, double u1i, double u2r,
                double u2i, double S[2], double T[3][2]);

// the integrals over one wet piece of corners q[3] (relative to the COM):
// P += integral p_d dA [N], Pr += integral p_d r dA [N m], V += integral
// (u - current) dA [m^3/s]. Corner 0 is a vertex of the hull, whose e^L
// was computed once per step; E0 holds e^L there per sorted component
// ([0] real, [1] imaginary; [2], [3] the finite-depth second exponent),
// sc0 the sin and cos of its phases (Sea::solve order); zs[c] the
// stretched height of each corner, lab[c] its Gerstner label [m]; area
// the piece's [m^2]; moments false: Pr is not computed (Kerner's pressure
// needs the velocity only)
void pieceIntegrals(const WaveTab& t, const Sea& sea, const double* const E0[4],
                    const double* sc0, const double q[3][3], const double zs[3],
                    const double lab[3][2], double area, bool moments, double* P,
                    double Pr[3], double V[3]);

}  // namespace mjb

#endif  // MJBUOY_WAVEINT_H_
