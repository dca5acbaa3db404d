// rigid-body change of frame of hydrodynamic coefficients (coefxform.h)
#include "radiation/coefxform.h"

#include <cmath>

namespace mjb {

// G = T Q, 6x6 row-major: nu_old = G nu_new (T, Q as in coefxform.h)
static void frameMap(const double d[3], const double R[9], double G[36]) {
  // -[d]x: (-[d]x) w = -d x w = w x d
  const double S[9] = {0, d[2], -d[1], -d[2], 0, d[0], d[1], -d[0], 0};
  for (int i = 0; i < 36; i++) G[i] = 0;
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) {
      G[6 * r + c] = R[3 * r + c];
      G[6 * (r + 3) + c + 3] = R[3 * r + c];
      double s = 0;
      for (int k = 0; k < 3; k++) s += S[3 * r + k] * R[3 * k + c];
      G[6 * r + c + 3] = s;
    }
}

// M <- G^T M G
static void congruence(const double G[36], double* M) {
  double t[36];
  for (int i = 0; i < 6; i++)
    for (int j = 0; j < 6; j++) {
      double s = 0;
      for (int k = 0; k < 6; k++) s += M[6 * i + k] * G[6 * k + j];
      t[6 * i + j] = s;
    }
  for (int i = 0; i < 6; i++)
    for (int j = 0; j < 6; j++) {
      double s = 0;
      for (int k = 0; k < 6; k++) s += G[6 * k + i] * t[6 * k + j];
      M[6 * i + j] = s;
    }
}

// complex force vector (re, im) <- G^T f, times e^{i ph}
static void moveForce(const double G[36], double ph, double* re, double* im) {
  double a[6], b[6], c = std::cos(ph), s = std::sin(ph);
  for (int i = 0; i < 6; i++) {
    a[i] = b[i] = 0;
    for (int k = 0; k < 6; k++) a[i] += G[6 * k + i] * re[k], b[i] += G[6 * k + i] * im[k];
  }
  for (int i = 0; i < 6; i++) re[i] = a[i] * c - b[i] * s, im[i] = a[i] * s + b[i] * c;
}

std::string coefTransform(HydroCoef* c, const double p[3], const double R[9], const double pn[3]) {
  double d[3] = {c->ref[0] - p[0], c->ref[1] - p[1], c->ref[2] - p[2]}, G[36];
  frameMap(d, R, G);
  int nw = c->nw(), nh = c->nh();
  if ((int)c->A.size() != 36 * nw || (int)c->B.size() != 36 * nw)
    return "coefficients: A and B must hold 36 values per frequency";
  double turn = 0;
  if (nh) {
    if (std::fabs(R[8] - 1) > 1e-9)
      return "coefficients: the exciting force can only follow a turn about the vertical";
    turn = std::atan2(R[3], R[0]);  // the new x axis's angle in F
    size_t nx = 6 * (size_t)nw * nh;
    if (c->Xre.size() != nx || c->Xim.size() != nx || c->FKre.size() != nx || c->FKim.size() != nx)
      return "coefficients: X and FK must hold 6 values per frequency and heading";
  }
  congruence(G, c->Ainf);
  for (int w = 0; w < nw; w++) {
    congruence(G, &c->A[36 * w]);
    congruence(G, &c->B[36 * w]);
    double k = c->omega[w] * c->omega[w] / c->g;
    for (int h = 0; h < nh; h++) {
      // a at p = a at ref times e^{i k D.(p - ref)}, so X_p = X_ref e^{-i k D.(p - ref)}
      double ph = k * (std::cos(c->heading[h]) * d[0] + std::sin(c->heading[h]) * d[1]);
      size_t o = 6 * ((size_t)w * nh + h);
      moveForce(G, ph, &c->Xre[o], &c->Xim[o]);
      moveForce(G, ph, &c->FKre[o], &c->FKim[o]);
    }
  }
  for (int h = 0; h < nh; h++) c->heading[h] -= turn;
  for (int i = 0; i < 3; i++) c->ref[i] = pn[i];
  return "";
}

}  // namespace mjb
