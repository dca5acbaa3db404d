// flat-panel source integrals (docs/physics.md section 13)
#include "radiation/rankine.h"

#include <cmath>

namespace mjb {

namespace {

inline void sub(const double* a, const double* b, double* r) {
  r[0] = a[0] - b[0];
  r[1] = a[1] - b[1];
  r[2] = a[2] - b[2];
}
inline double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline void cross(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
inline double norm(const double* a) { return std::sqrt(dot(a, a)); }

// signed solid angle of triangle (a, b, c) seen from the origin of a, b, c
// (van Oosterom & Strackee 1983): positive when the origin is on the side
// the counterclockwise normal points away from
double solidAngle(const double* a, const double* b, const double* c) {
  double bc[3];
  cross(b, c, bc);
  double num = dot(a, bc);
  double la = norm(a), lb = norm(b), lc = norm(c);
  double den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2 * std::atan2(num, den);
}

}  // namespace

bool makePanel(const double* p0, const double* p1, const double* p2, const double* p3, Panel* pn) {
  const double* p[4] = {p0, p1, p2, p3};
  pn->nv = p3 ? 4 : 3;
  double d1[3], d2[3], n[3];
  if (pn->nv == 4) {
    sub(p2, p0, d1);
    sub(p3, p1, d2);
  } else {
    sub(p1, p0, d1);
    sub(p2, p0, d2);
  }
  cross(d1, d2, n);
  double ln = norm(n);
  pn->area = 0.5 * ln;
  if (!(ln > 0)) return false;
  for (int k = 0; k < 3; k++) pn->n[k] = n[k] / ln;
  double m[3] = {0, 0, 0};
  for (int i = 0; i < pn->nv; i++)
    for (int k = 0; k < 3; k++) m[k] += p[i][k] / pn->nv;
  // project onto the mean plane
  for (int i = 0; i < pn->nv; i++) {
    double d[3];
    sub(p[i], m, d);
    double h = dot(d, pn->n);
    for (int k = 0; k < 3; k++) pn->v[i][k] = p[i][k] - h * pn->n[k];
  }
  // area centroid: fan of triangles from vertex 0
  double c[3] = {0, 0, 0}, at = 0;
  for (int i = 1; i + 1 < pn->nv; i++) {
    double e1[3], e2[3], t[3];
    sub(pn->v[i], pn->v[0], e1);
    sub(pn->v[i + 1], pn->v[0], e2);
    cross(e1, e2, t);
    double a = 0.5 * dot(t, pn->n);
    for (int k = 0; k < 3; k++) c[k] += a * (pn->v[0][k] + pn->v[i][k] + pn->v[i + 1][k]) / 3;
    at += a;
  }
  for (int k = 0; k < 3; k++) pn->c[k] = c[k] / at;
  pn->diam = 0;
  for (int i = 0; i < pn->nv; i++)
    for (int j = i + 1; j < pn->nv; j++) {
      double d[3];
      sub(pn->v[i], pn->v[j], d);
      pn->diam = std::fmax(pn->diam, norm(d));
    }
  return at > 0;
}

void rankinePanel(const Panel& pn, const double x[3], double* phi, double grad[3]) {
  // in-plane part: grad_t phi = -sum_e nu_e L_e (divergence theorem in
  // the plane), L_e = int_e dl / r = ln((ra + rb + s) / (ra + rb - s));
  // normal part: d phi / dn = -Omega, Omega = int z / r^3 dS the signed
  // solid angle; phi = sum_e d_e L_e - z Omega (Newman 1986)
  double r[4][3], rl[4];
  for (int i = 0; i < pn.nv; i++) {
    sub(pn.v[i], x, r[i]);
    rl[i] = norm(r[i]);
  }
  double xc[3];
  sub(x, pn.c, xc);
  double z = dot(xc, pn.n);
  double p = 0, g[3] = {0, 0, 0};
  for (int i = 0; i < pn.nv; i++) {
    int j = (i + 1) % pn.nv;
    double e[3], nu[3];
    sub(pn.v[j], pn.v[i], e);
    double s = norm(e);
    cross(e, pn.n, nu);  // outward in-plane edge normal times s
    for (int k = 0; k < 3; k++) nu[k] /= s;
    double a = rl[i] + rl[j];
    double L = (a - s > 1e-14 * a) ? std::log((a + s) / (a - s)) : 0;
    // (v_i - x) . nu: distance of x's projection inside edge i
    p += dot(r[i], nu) * L;
    // grad_x = -grad_q of 1/r: minus the boundary integral
    for (int k = 0; k < 3; k++) g[k] -= nu[k] * L;
  }
  double om = 0;
  double scale = pn.diam;
  if (std::fabs(z) > 1e-10 * scale) {
    for (int i = 1; i + 1 < pn.nv; i++) om += solidAngle(r[0], r[i], r[i + 1]);
    // van Oosterom's sign is positive for x behind the counterclockwise
    // face; int z / r^3 dS is positive for x in front (z > 0)
    om = -om;
  }
  p -= z * om;
  for (int k = 0; k < 3; k++) g[k] -= om * pn.n[k];
  *phi = p;
  grad[0] = g[0];
  grad[1] = g[1];
  grad[2] = g[2];
}

}  // namespace mjb
