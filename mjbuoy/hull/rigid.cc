// rigid group mass and inertia (rigid.h)
#include "hull/rigid.h"

#include <cmath>

namespace mjb {

bool groupInertia(const mjModel* m, const mjData* d, int body, double I[6], double com[3],
                  double* mass) {
  // MuJoCo orders bodies depth first: the weld root's subtree is the
  // contiguous run after it whose parents are at or after the root
  const int w = m->body_weldid[body];
  double md[3] = {0, 0, 0};
  *mass = 0;
  for (int j = 0; j < 6; j++) I[j] = 0;
  for (int i = w; i < m->nbody && (i == w || m->body_parentid[i] >= w); i++) {
    if (m->body_weldid[i] != w) continue;
    // cinert: inertia about subtree_com of the root (world axes), m dif, m
    const mjtNum* c = d->cinert + 10 * i;
    for (int j = 0; j < 6; j++) I[j] += c[j];
    for (int j = 0; j < 3; j++) md[j] += c[6 + j];
    *mass += c[9];
  }
  const mjtNum* p = d->subtree_com + 3 * m->body_rootid[w];
  if (!(*mass > 0)) {
    for (int j = 0; j < 3; j++) com[j] = p[j];
    return false;
  }
  // parallel axis theorem back to the group COM c: I_c = I_p - m (|c|^2 E - c c^T)
  const double M = *mass;
  double c[3] = {md[0] / M, md[1] / M, md[2] / M};
  I[0] -= M * (c[1] * c[1] + c[2] * c[2]);
  I[1] -= M * (c[0] * c[0] + c[2] * c[2]);
  I[2] -= M * (c[0] * c[0] + c[1] * c[1]);
  I[3] += M * c[0] * c[1];
  I[4] += M * c[0] * c[2];
  I[5] += M * c[1] * c[2];
  for (int j = 0; j < 3; j++) com[j] = p[j] + c[j];
  return true;
}

void rigidGroup(const mjModel* m, const mjData* d, int body, Rigid* r) {
  double I[6], mass;
  if (!groupInertia(m, d, body, I, r->com, &mass)) {
    r->minv = INFINITY;
    for (int j = 0; j < 6; j++) r->iinv[j] = 0;
    return;
  }
  r->minv = 1 / mass;
  // symmetric 3x3 inverse by cofactors
  const double a = I[0], b = I[1], e = I[2], xy = I[3], xz = I[4], yz = I[5];
  double c00 = b * e - yz * yz, c11 = a * e - xz * xz, c22 = a * b - xy * xy;
  double c01 = xz * yz - xy * e, c02 = xy * yz - b * xz, c12 = xy * xz - a * yz;
  double det = a * c00 + xy * c01 + xz * c02;
  if (!(det > 0) || !std::isfinite(det)) {
    // no rotational inertia: an off-centre impulse cannot be resisted
    r->minv = INFINITY;
    for (int j = 0; j < 6; j++) r->iinv[j] = 0;
    return;
  }
  double s = 1 / det;
  r->iinv[0] = c00 * s;
  r->iinv[1] = c11 * s;
  r->iinv[2] = c22 * s;
  r->iinv[3] = c01 * s;
  r->iinv[4] = c02 * s;
  r->iinv[5] = c12 * s;
}

double effMass(const Rigid& r, const double p[3], const double u[3]) {
  double d[3] = {p[0] - r.com[0], p[1] - r.com[1], p[2] - r.com[2]};
  double w[3] = {d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2], d[0] * u[1] - d[1] * u[0]};
  const double* J = r.iinv;
  double Jw[3] = {J[0] * w[0] + J[3] * w[1] + J[4] * w[2],
                  J[3] * w[0] + J[1] * w[1] + J[5] * w[2],
                  J[4] * w[0] + J[5] * w[1] + J[2] * w[2]};
  return 1 / (r.minv + w[0] * Jw[0] + w[1] * Jw[1] + w[2] * Jw[2]);
}

}  // namespace mjb
