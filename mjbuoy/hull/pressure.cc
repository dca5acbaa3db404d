// exact pressure integrals over the wet part of a triangle
#include "hull/pressure.h"

#include <cmath>

namespace mjb {

void clipWet(const double p[3][3], const double h[3], Wet* w) {
  // clip to h <= 0, walking the edges in the parent's order so the wet
  // polygon keeps its winding (Sutherland-Hodgman); at most 4 vertices
  double (*q)[3] = w->q;
  int& nq = w->nq;
  nq = 0;
  for (int i = 0; i < 3; i++) {
    int k = (i + 1) % 3;
    if (h[i] <= 0) {
      for (int j = 0; j < 3; j++) q[nq][j] = p[i][j];
      w->qa[nq] = w->qb[nq] = i;
      w->qt[nq++] = 0;
    }
    if ((h[i] < 0 && h[k] > 0) || (h[i] > 0 && h[k] < 0)) {
      // cut from the wet end so a shared edge gives the same point in both
      // triangles; t in (0, 1) since the signs differ strictly
      int a = h[i] < 0 ? i : k, b = h[i] < 0 ? k : i;
      double t = h[a] / (h[a] - h[b]);
      for (int j = 0; j < 3; j++) q[nq][j] = p[a][j] + t * (p[b][j] - p[a][j]);
      w->qa[nq] = a;
      w->qb[nq] = b;
      w->qt[nq++] = t;
    }
  }
}

void wetTriangle(const double p[3][3], const double h[3], Wet* w) {
  *w = Wet{};
  double e1[3], e2[3], c[3];
  for (int j = 0; j < 3; j++) {
    e1[j] = p[1][j] - p[0][j];
    e2[j] = p[2][j] - p[0][j];
  }
  c[0] = e1[1] * e2[2] - e1[2] * e2[1];
  c[1] = e1[2] * e2[0] - e1[0] * e2[2];
  c[2] = e1[0] * e2[1] - e1[1] * e2[0];
  double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  if (!(len > 0)) return;
  for (int j = 0; j < 3; j++) w->n[j] = c[j] / len;
  if (h[0] >= 0 && h[1] >= 0 && h[2] >= 0) return;  // dry (or lying on the surface)

  if (h[0] <= 0 && h[1] <= 0 && h[2] <= 0) {
    // all wet: the polygon is the triangle, one piece whose cross product
    // is c; the same arithmetic as the fan below, without the clipping
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) w->q[i][j] = p[i][j];
      w->qa[i] = w->qb[i] = i;
      w->qt[i] = 0;
    }
    w->nq = 3;
    double A = 0.5 * (c[0] * w->n[0] + c[1] * w->n[1] + c[2] * w->n[2]);
    double d0 = -h[0], d1 = -h[1], d2 = -h[2], sd = d0 + d1 + d2;
    w->area = 0 + A;
    w->dA = 0 + A * sd / 3;
    for (int j = 0; j < 3; j++) {
      double sr = p[0][j] + p[1][j] + p[2][j];
      w->drA[j] = 0 + A / 12 * (d0 * p[0][j] + d1 * p[1][j] + d2 * p[2][j] + sd * sr);
      w->rA[j] = 0 + A * sr / 3;
    }
    return;
  }

  clipWet(p, h, w);
  double (*q)[3] = w->q, d[4];
  const int nq = w->nq;
  for (int i = 0; i < nq; i++) d[i] = w->qt[i] == 0 ? -h[w->qa[i]] : 0;

  // fan over the wet polygon; each piece is coplanar with the parent, so
  // its area is (cross . n) / 2 and the integrals of linear d are
  // integral(d dA) = A (d0 + d1 + d2) / 3,
  // integral(d r dA) = A/12 (sum d_i r_i + (sum d_i)(sum r_i))  (physics.md 2)
  for (int t = 1; t + 1 < nq; t++) {
    const double* a = q[0];
    const double* b = q[t];
    const double* cc = q[t + 1];
    double u[3], v[3];
    for (int j = 0; j < 3; j++) {
      u[j] = b[j] - a[j];
      v[j] = cc[j] - a[j];
    }
    double x[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                   u[0] * v[1] - u[1] * v[0]};
    double A = 0.5 * (x[0] * w->n[0] + x[1] * w->n[1] + x[2] * w->n[2]);
    double sd = d[0] + d[t] + d[t + 1];
    w->area += A;
    w->dA += A * sd / 3;
    for (int j = 0; j < 3; j++) {
      double sr = a[j] + b[j] + cc[j];
      w->drA[j] += A / 12 * (d[0] * a[j] + d[t] * b[j] + d[t + 1] * cc[j] + sd * sr);
      w->rA[j] += A * sr / 3;
    }
  }
}

}  // namespace mjb
