// potential and velocity of a flat polygon of unit source density 1/r
// (Newman 1986, "Distributions of sources and normal dipoles over a
// quadrilateral panel", J. Eng. Math. 20:113-126; docs/physics.md section 13)
#ifndef MJBUOY_RANKINE_H_
#define MJBUOY_RANKINE_H_

namespace mjb {

// flat panel: 3 or 4 vertices (counterclockwise about n), centroid, unit
// normal, area, diameter
struct Panel {
  double v[4][3];
  int nv;
  double c[3], n[3], area, diam;
};

// builds the panel from 3 or 4 points (a non-planar quad is projected onto
// the plane through its vertex mean normal to its diagonals' cross product);
// returns false for a degenerate panel (area <= 0)
bool makePanel(const double* p0, const double* p1, const double* p2, const double* p3, Panel* pn);

// phi = int 1/|x - q| dS_q over the panel and grad = d phi / dx;
// x on the panel's plane inside it gives the principal value (the normal
// component 0: the caller adds the jump -2 pi)
void rankinePanel(const Panel& pn, const double x[3], double* phi, double grad[3]);

}  // namespace mjb

#endif  // MJBUOY_RANKINE_H_
