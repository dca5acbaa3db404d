// rotational hydrostatic stiffness from wet panels (hydrostatic.h)
#include "radiation/hydrostatic.h"

namespace mjb {

// the surface integrals, each of a polynomial of degree <= 2 times one
// normal component: exact by the edge-midpoint rule on every triangle of a
// panel's fan (a flat panel's integral; a warped quad's fan is its surface)
struct WetSums {
  double vol = 0;               // int z n_z dS = V
  double mb[3] = {0, 0, 0};     // int (x^2 n_x, y^2 n_y, z^2 n_z) / 2 dS = V (x_B, y_B, z_B)
  double wp[3] = {0, 0, 0};     // -int (y'^2, x'^2, x'y') n_z dS: the waterplane's moments
};

static void addTriangle(const double* a, const double* b, const double* c, const double G[3],
                        WetSums* s) {
  double u[3], v[3], S[3];  // S: area vector, out of the body
  for (int k = 0; k < 3; k++) u[k] = b[k] - a[k], v[k] = c[k] - a[k];
  S[0] = 0.5 * (u[1] * v[2] - u[2] * v[1]);
  S[1] = 0.5 * (u[2] * v[0] - u[0] * v[2]);
  S[2] = 0.5 * (u[0] * v[1] - u[1] * v[0]);
  const double* P[3] = {a, b, c};
  for (int e = 0; e < 3; e++) {
    double m[3];
    for (int k = 0; k < 3; k++) m[k] = 0.5 * (P[e][k] + P[(e + 1) % 3][k]);
    const double x = m[0] - G[0], y = m[1] - G[1];
    s->vol += S[2] * m[2] / 3;
    for (int k = 0; k < 3; k++) s->mb[k] += S[k] * m[k] * m[k] / 6;
    s->wp[0] -= S[2] * y * y / 3;
    s->wp[1] -= S[2] * x * x / 3;
    s->wp[2] -= S[2] * x * y / 3;
  }
}

void rotStiffness(const PanelMesh& p, const double G[3], double rhog, double C[9], double* vol) {
  WetSums s;
  for (int f = 0; f < p.nface(); f++) {
    const int* q = &p.face[4 * f];
    const int nv = q[3] < 0 ? 3 : 4;
    for (int k = 1; k + 1 < nv; k++)
      addTriangle(&p.vert[3 * q[0]], &p.vert[3 * q[k]], &p.vert[3 * q[k + 1]], G, &s);
  }
  // the waterplane closes the wet surface at z = 0, where z n_z and
  // z^2 n_z vanish and x^2, y^2 have no normal component: V and V x_B
  // are the wet panels' alone; int f dA_wp = -int_wet f n_z dS for f(x, y)
  const double V = s.vol, zb = V > 0 ? s.mb[2] / V : 0;
  const double mz = V * (zb - G[2]);
  C[0] = rhog * (s.wp[0] + mz);
  C[4] = rhog * (s.wp[1] + mz);
  C[1] = C[3] = -rhog * s.wp[2];
  C[2] = -rhog * (s.mb[0] - V * G[0]);
  C[5] = -rhog * (s.mb[1] - V * G[1]);
  C[6] = C[7] = C[8] = 0;
  if (vol) *vol = V;
}

double axisStiffness(const double C[9], const double e[3]) {
  double r = 0;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) r += e[i] * C[3 * i + j] * e[j];
  return r;
}

}  // namespace mjb
