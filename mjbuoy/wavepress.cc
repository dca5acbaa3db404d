// linear-theory wave pressure over a wet triangle: exact hydrostatics plus
// a degree-5 quadrature of the dynamic pressure
#include "wavepress.h"

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

void dynamicPiece(const Sea& sea, const WaveNow* wn, const double* q0, const double* q1,
                  const double* q2, const double n[3], const double com[3], const double off[2],
                  double* sc, double* tmp, double* P, double Pr[3]) {
  double u[3], v[3];
  for (int j = 0; j < 3; j++) {
    u[j] = q1[j] - q0[j];
    v[j] = q2[j] - q0[j];
  }
  double A = 0.5 * ((u[1] * v[2] - u[2] * v[1]) * n[0] + (u[2] * v[0] - u[0] * v[2]) * n[1] +
                    (u[0] * v[1] - u[1] * v[0]) * n[2]);
  if (!(A > 0)) return;
  for (int i = 0; i < 7; i++) {
    double r[3];
    for (int j = 0; j < 3; j++) r[j] = kBary[i][0] * q0[j] + kBary[i][1] * q1[j] + kBary[i][2] * q2[j];
    double x = r[0] + com[0], y = r[1] + com[1], a[2] = {x + off[0], y + off[1]};
    double eta = sea.solve(wn, x, y, a, sc, tmp) - sea.level;
    double p = kW[i] * A * sea.dynamicSC(wn, sc, r[2] + com[2] - sea.level, eta);
    *P += p;
    for (int j = 0; j < 3; j++) Pr[j] += p * r[j];
  }
}

void linearPressure(const Sea& sea, const WaveNow* wn, const Wet& w, const double com[3],
                    const double off[2], double* sc, double* tmp, double* P, double Pr[3]) {
  *P = 0;
  Pr[0] = Pr[1] = Pr[2] = 0;
  const double rg = sea.rho * sea.g;
  // hydrostatic rho g (level - z), linear: the fan formulas of wetTriangle
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
    dynamicPiece(sea, wn, a, b, c, w.n, com, off, sc, tmp, P, Pr);
  }
}

}  // namespace mjb
