// linear-theory wave pressure over a wet triangle: exact hydrostatics plus
// a degree-5 quadrature of the dynamic pressure, the surface height and
// Gerstner label at the quadrature points interpolated linearly from the
// triangle's vertices (as the cut assumes), so no surface solve there
#include "hull/wavepress.h"

#include <cmath>

namespace mjb {

// Radon's 7-point rule, exact for polynomials of degree 5 on a triangle
// (Stroud 1971, "Approximate Calculation of Multiple Integrals", T2:5-1):
// barycentric (1/3, 1/3, 1/3) with weight 9/40, the three permutations of
// (a, a, 1 - 2a), a = (6 - sqrt 15) / 21, weight (155 - sqrt 15) / 1200,
// and of (b, b, 1 - 2b), b = (6 + sqrt 15) / 21, weight (155 + sqrt 15) / 1200
static const double kS15 = 3.872983346207417;
static const double kA = (6 - kS15) / 21, kB = (6 + kS15) / 21;
static const double kWA = (155 - kS15) / 1200, kWB = (155 + kS15) / 1200;
static const double kBary[7][3] = {
    {1.0 / 3, 1.0 / 3, 1.0 / 3}, {kA, kA, 1 - 2 * kA}, {kA, 1 - 2 * kA, kA},
    {1 - 2 * kA, kA, kA},        {kB, kB, 1 - 2 * kB}, {kB, 1 - 2 * kB, kB},
    {1 - 2 * kB, kB, kB}};
static const double kW[7] = {9.0 / 40, kWA, kWA, kWA, kWB, kWB, kWB};

void Surf::at(const double r[3], double* e, double l[2]) const {
  // barycentrics of r's projection on the plane: the 2x2 Gram system of
  // the edges u = p1 - p0, v = p2 - p0
  double u[3], v[3], d[3];
  for (int j = 0; j < 3; j++) {
    u[j] = p[1][j] - p[0][j];
    v[j] = p[2][j] - p[0][j];
    d[j] = r[j] - p[0][j];
  }
  double uu = 0, uv = 0, vv = 0, ud = 0, vd = 0;
  for (int j = 0; j < 3; j++) {
    uu += u[j] * u[j];
    uv += u[j] * v[j];
    vv += v[j] * v[j];
    ud += u[j] * d[j];
    vd += v[j] * d[j];
  }
  double det = uu * vv - uv * uv;
  double b1 = (vv * ud - uv * vd) / det, b2 = (uu * vd - uv * ud) / det;
  *e = eta[0] + b1 * (eta[1] - eta[0]) + b2 * (eta[2] - eta[0]);
  for (int j = 0; j < 2; j++) l[j] = lab[0][j] + b1 * (lab[1][j] - lab[0][j]) + b2 * (lab[2][j] - lab[0][j]);
}

void dynamicPiece(const Sea& sea, const WaveNow* wn, const double* q0, const double* q1,
                  const double* q2, const double n[3], const double com[3], const double e[3],
                  const double l[3][2], double* P, double Pr[3]) {
  double u[3], v[3];
  for (int j = 0; j < 3; j++) {
    u[j] = q1[j] - q0[j];
    v[j] = q2[j] - q0[j];
  }
  double A = 0.5 * ((u[1] * v[2] - u[2] * v[1]) * n[0] + (u[2] * v[0] - u[0] * v[2]) * n[1] +
                    (u[0] * v[1] - u[1] * v[0]) * n[2]);
  if (!(A > 0)) return;
  for (int i = 0; i < 7; i++) {
    const double* b = kBary[i];
    double r[3], a[2];
    for (int j = 0; j < 3; j++) r[j] = b[0] * q0[j] + b[1] * q1[j] + b[2] * q2[j];
    for (int j = 0; j < 2; j++) a[j] = b[0] * l[0][j] + b[1] * l[1][j] + b[2] * l[2][j];
    double eta = b[0] * e[0] + b[1] * e[1] + b[2] * e[2];
    double p = kW[i] * A *
               sea.dynamicAt(wn, r[0] + com[0], r[1] + com[1], a, r[2] + com[2] - sea.level, eta);
    *P += p;
    for (int j = 0; j < 3; j++) Pr[j] += p * r[j];
  }
}

void hydrostaticLevel(const Sea& sea, const Wet& w, const double com[3], double* P,
                      double Pr[3]) {
  *P = 0;
  Pr[0] = Pr[1] = Pr[2] = 0;
  const double rg = sea.rho * sea.g;
  // rho g (level - z), linear: the fan formulas of wetTriangle
  double d[4];
  for (int i = 0; i < w.nq; i++) d[i] = sea.level - (w.q[i][2] + com[2]);
  for (int t = 1; t + 1 < w.nq; t++) {
    const double *a = w.q[0], *b = w.q[t], *c = w.q[t + 1];
    double u[3], v[3];
    for (int j = 0; j < 3; j++) {
      u[j] = b[j] - a[j];
      v[j] = c[j] - a[j];
    }
    double A = 0.5 * ((u[1] * v[2] - u[2] * v[1]) * w.n[0] + (u[2] * v[0] - u[0] * v[2]) * w.n[1] +
                      (u[0] * v[1] - u[1] * v[0]) * w.n[2]);
    double sd = d[0] + d[t] + d[t + 1];
    *P += rg * A * sd / 3;
    for (int j = 0; j < 3; j++) {
      Pr[j] += rg * A / 12 * (d[0] * a[j] + d[t] * b[j] + d[t + 1] * c[j] + sd * (a[j] + b[j] + c[j]));
    }
  }
}

void linearPressure(const Sea& sea, const WaveNow* wn, const Wet& w, const Surf& s,
                    const double com[3], double* P, double Pr[3]) {
  hydrostaticLevel(sea, w, com, P, Pr);
  double e[4], l[4][2];
  for (int i = 0; i < w.nq; i++) s.at(w.q[i], e + i, l[i]);
  for (int t = 1; t + 1 < w.nq; t++) {
    const double pe[3] = {e[0], e[t], e[t + 1]};
    const double pl[3][2] = {{l[0][0], l[0][1]}, {l[t][0], l[t][1]}, {l[t + 1][0], l[t + 1][1]}};
    dynamicPiece(sea, wn, w.q[0], w.q[t], w.q[t + 1], w.n, com, pe, pl, P, Pr);
  }
}

}  // namespace mjb
