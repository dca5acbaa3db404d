// the drift table at attach (driftattach.h, docs/physics.md section 18)
#include "radiation/driftattach.h"

#include <cmath>
#include <cstring>

#include "hull/rigid.h"
#include "radiation/hydrostatic.h"

namespace mjb {

// a root on slide joints alone, each along a world axis, its parent the
// world: b's dofs the joints' axes, D their damping [N s/m]; else false
// (a restrained body)
static bool slideDofs(const mjModel* m, const mjData* d, int root, DriftBody* b) {
  if (m->body_parentid[root] != 0) return false;
  for (int k = 0; k < 6; k++) b->dof[k] = false;
  for (int j = 0; j < m->body_jntnum[root]; j++) {
    int jj = m->body_jntadr[root] + j, k = -1;
    if (m->jnt_type[jj] != mjJNT_SLIDE) return false;
    for (int a = 0; a < 3; a++)
      if (std::fabs(std::fabs(d->xaxis[3 * jj + a]) - 1) < 1e-9) k = a;
    if (k < 0 || b->dof[k]) return false;
    b->dof[k] = true;
    b->D[7 * k] = m->dof_damping[m->jnt_dofadr[jj]];
  }
  return true;
}

void driftDynamics(const mjModel* m, const mjData* d, int root, const PanelMesh& body,
                   const double o[3], double rho, double g, DriftBody* b, double yaw) {
  *b = DriftBody();
  if (!m->body_jntnum[root]) return;
  bool freej = m->jnt_type[m->body_jntadr[root]] == mjJNT_FREE;
  if (!freej && !slideDofs(m, d, root, b)) return;
  double I[6], G[3], mass;
  if (!groupInertia(m, d, root, I, G, &mass)) return;
  b->free = true;
  double r[3] = {G[0] - o[0], G[1] - o[1], G[2] - o[2]};
  // world axes to the frame's: r' = Z r, I' = Z I Z^T, Z the turn by -yaw
  const double cw = std::cos(yaw), sw = std::sin(yaw);
  const double Z[9] = {cw, sw, 0, -sw, cw, 0, 0, 0, 1};
  const double IW[9] = {I[0], I[3], I[4], I[3], I[1], I[5], I[4], I[5], I[2]};
  double IG[9] = {0}, rw[3] = {r[0], r[1], r[2]};
  for (int i = 0; i < 3; i++) {
    r[i] = Z[3 * i] * rw[0] + Z[3 * i + 1] * rw[1] + Z[3 * i + 2] * rw[2];
    for (int j = 0; j < 3; j++)
      for (int k = 0; k < 3; k++)
        for (int l = 0; l < 3; l++) IG[3 * i + j] += Z[3 * i + k] * IW[3 * k + l] * Z[3 * j + l];
  }
  for (int k = 0; k < 3; k++) b->com[k] = r[k];
  // M about the frame's origin: [m 1, -m [r]x; m [r]x, I_G + m (|r|^2 1 - r r^T)]
  const double X[9] = {0, -r[2], r[1], r[2], 0, -r[0], -r[1], r[0], 0};
  double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  for (int i = 0; i < 3; i++) {
    b->M[6 * i + i] = mass;
    for (int j = 0; j < 3; j++) {
      b->M[6 * i + 3 + j] = -mass * X[3 * i + j];
      b->M[6 * (3 + i) + j] = mass * X[3 * i + j];
      b->M[6 * (3 + i) + 3 + j] = IG[3 * i + j] + mass * ((i == j) * rr - r[i] * r[j]);
    }
  }
  // restoring about the origin: buoyancy from the wet panels (rotStiffness
  // about the origin, the weight's moment left out), plus the weight's
  // -m g z_G (roll, pitch) and m g (x_G, y_G) (roll, pitch from yaw)
  const double zero[3] = {0, 0, 0};
  double C3[9];
  rotStiffness(body, zero, rho * g, C3);
  double awp = 0, sx = 0, sy = 0;
  for (int f = 0; f < body.nface(); f++) {
    const int* fi = &body.face[4 * f];
    int n = fi[3] < 0 ? 3 : 4;
    // projected (signed) area and centroid: the waterplane closes the surface
    double a = 0, cx = 0, cy = 0;
    const double* p0 = &body.vert[3 * fi[0]];
    for (int k = 1; k + 1 < n; k++) {
      const double* p1 = &body.vert[3 * fi[k]];
      const double* p2 = &body.vert[3 * fi[k + 1]];
      double t = 0.5 * ((p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]));
      a += t;
      cx += t * (p0[0] + p1[0] + p2[0]) / 3;
      cy += t * (p0[1] + p1[1] + p2[1]) / 3;
    }
    awp -= a, sx -= cx, sy -= cy;
  }
  double* C = b->C;
  C[6 * 2 + 2] = rho * g * awp;
  C[6 * 2 + 3] = C[6 * 3 + 2] = rho * g * sy;
  C[6 * 2 + 4] = C[6 * 4 + 2] = -rho * g * sx;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) C[6 * (3 + i) + 3 + j] = C3[3 * i + j];
  std::memcpy(b->Cb, b->C, sizeof b->Cb);
  C[6 * 3 + 3] -= mass * g * r[2];
  C[6 * 4 + 4] -= mass * g * r[2];
  C[6 * 3 + 5] += mass * g * r[0];
  C[6 * 4 + 5] += mass * g * r[1];
  // the slide joints' springs (their damping is in D already)
  for (int j = 0; j < m->body_jntnum[root] && !freej; j++) {
    int jj = m->body_jntadr[root] + j;
    for (int k = 0; k < 3; k++)
      if (std::fabs(d->xaxis[3 * jj + k]) > 0.5) C[7 * k] += m->jnt_stiffness[jj];
  }
}

std::string driftCacheKey(const std::string& ckey, const DriftBody& b) {
  std::string k = ckey + "drift2";
  k.push_back(b.free ? 1 : 0);
  for (bool f : b.dof) k.push_back(f ? 1 : 0);
  for (const double* v : {b.M, b.C, b.D, b.Cb}) k.append((const char*)v, 36 * sizeof(double));
  k.append((const char*)b.com, sizeof b.com);
  return k;
}

HydroCoef driftPack(const DriftTable& dt, const HydroCoef& like) {
  HydroCoef c;
  c.rho = like.rho;
  c.g = like.g;
  c.depth = like.depth;
  std::memcpy(c.ref, like.ref, sizeof c.ref);
  c.omega = like.omega;
  c.heading = like.heading;
  c.A.assign(36 * c.omega.size(), 0);
  c.B.assign(36 * c.omega.size(), 0);
  size_t n = dt.far.size() / 3;
  c.Xre.assign(6 * n, 0);
  c.Xim.assign(6 * n, 0);
  c.FKre.assign(6 * n, 0);
  c.FKim.assign(6 * n, 0);
  for (size_t i = 0; i < n; i++) {
    const int to[3] = {0, 1, 5};
    for (int k = 0; k < 3; k++) {
      c.Xre[6 * i + to[k]] = dt.far[3 * i + k];
      c.Xim[6 * i + to[k]] = dt.near[3 * i + k];
      c.FKre[6 * i + to[k]] = dt.fk[3 * i + k];
    }
  }
  return c;
}

bool driftUnpack(const HydroCoef& c, int nw, int nh, DriftTable* dt) {
  size_t n = (size_t)nw * nh;
  if (c.nw() != nw || c.nh() != nh || c.Xre.size() != 6 * n || c.Xim.size() != 6 * n ||
      c.FKre.size() != 6 * n)
    return false;
  dt->far.assign(3 * n, 0);
  dt->near.assign(3 * n, 0);
  dt->fk.assign(3 * n, 0);
  for (size_t i = 0; i < n; i++) {
    const int to[3] = {0, 1, 5};
    for (int k = 0; k < 3; k++) {
      dt->far[3 * i + k] = c.Xre[6 * i + to[k]];
      dt->near[3 * i + k] = c.Xim[6 * i + to[k]];
      dt->fk[3 * i + k] = c.FKre[6 * i + to[k]];
      if (!std::isfinite(dt->far[3 * i + k]) || !std::isfinite(dt->near[3 * i + k]) ||
          !std::isfinite(dt->fk[3 * i + k]))
        return false;
    }
  }
  return true;
}

}  // namespace mjb
