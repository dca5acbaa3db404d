// pressure: wet part of one hull triangle and its hydrostatic integrals
//
// Kerner (2015) cuts each triangle at the waterline and sums
// F = -rho g d_c A n over the wet pieces. Depth d is linear over a planar
// triangle, so we integrate it exactly instead: the force uses the
// centroid depth (exact for linear d), and the torque uses the first
// moment of depth, integral(d r dA), which places the force at the true
// centre of pressure. Kerner part 1 and Cruz (2023) apply the force at the
// centroid, which leaves ghost torques; Cruz also drops the horizontal
// force components. We keep all three.
#ifndef MJBUOY_PRESSURE_H_
#define MJBUOY_PRESSURE_H_

namespace mjb {

// integrals over the wet part (height above water h <= 0) of one triangle,
// with depth d = -h interpolated linearly from the vertices
struct Wet {
  double area;    // wet area [m^2]
  double dA;      // integral of d dA [m^3]
  double drA[3];  // integral of d r dA [m^4]
  double rA[3];   // integral of r dA [m^3] (wet centroid times area)
  double n[3];    // outward unit normal of the triangle (0 if degenerate)
  double q[4][3]; // wet polygon, parent's winding
  int nq;         // its vertex count: 0, 3 or 4
  // where each polygon vertex comes from: p[qa] + qt (p[qb] - p[qa]);
  // qt = 0 for a vertex of the triangle (then qb = qa)
  int qa[4], qb[4];
  double qt[4];
};

// p: the three vertices [m], counter-clockwise seen from outside, relative
// to the point torques are taken about; h: their heights above the water
// surface [m]. Vertices exactly on the surface (h == 0) are handled without
// division by zero; degenerate triangles give all zeros.
// Force on the triangle: -rho g dA n; torque: -rho g drA x n;
// centre of pressure: drA / dA.
void wetTriangle(const double p[3][3], const double h[3], Wet* w);

// wetTriangle's clip alone: w's polygon (q, nq, qa, qb, qt) of a triangle
// with a vertex above and one below the surface; area, integrals and n
// are left as they were
void clipWet(const double p[3][3], const double h[3], Wet* w);

}  // namespace mjb

#endif  // MJBUOY_PRESSURE_H_
