// windload: drag and friction of the air on the dry faces of hulls and
// of superstructure geoms (docs/physics.md, "Irregular seas and wind")
#include "hull/windload.h"

#include <algorithm>
#include <cmath>

#include "hull/hull.h"
#include "sea/sea.h"

namespace mjb {

std::string windMake(const HullSet& hs, const WindParams& par, std::vector<std::string>* warn,
                     Wind* out) {
  Wind& w = *out;
  w.par = par;
  w.gust.reserve(1024);
  windGusts(&w);
  w.part.clear();
  w.body.clear();
  w.extra.clear();
  for (size_t i = 0; i < hs.hull.size(); i++) {
    const Hull& h = hs.hull[i];
    w.part.push_back(Wind::Part{h.body, -1 - h.t0, h.nt, int(i)});
  }
  for (int g : w.par.geom) {
    Mesh mesh = hullMesh(hs.m, g, warn);
    int v0 = w.vert.size() / 3, t0 = w.face.size() / 3;
    w.vert.insert(w.vert.end(), mesh.v.begin(), mesh.v.end());
    for (int i : mesh.f) w.face.push_back(i + v0);
    w.part.push_back(Wind::Part{hs.m->geom_bodyid[g], t0, mesh.nf(), -1});
  }
  for (const Wind::Part& p : w.part) w.body.push_back(p.body);
  std::sort(w.body.begin(), w.body.end());
  w.body.erase(std::unique(w.body.begin(), w.body.end()), w.body.end());
  for (int bd : w.body) {
    if (!std::binary_search(hs.body.begin(), hs.body.end(), bd)) w.extra.push_back(bd);
  }
  return "";
}

// the air's force on one dry triangle (corners p, world frame) of a body
// moving with vel ([angular; linear] at com), added to w about com
static void triForce(const Wind& wd, const double U[2], const double* p0, const double* p1,
                     const double* p2, const double* com, const double vel[6], double* w) {
  double c[3], e1[3], e2[3], n[3];
  for (int j = 0; j < 3; j++) {
    c[j] = (p0[j] + p1[j] + p2[j]) / 3 - com[j];
    e1[j] = p1[j] - p0[j];
    e2[j] = p2[j] - p0[j];
  }
  mju_cross(n, e1, e2);
  double a2 = mju_norm3(n);  // twice the area
  if (!(a2 > 0)) return;
  for (int j = 0; j < 3; j++) n[j] /= a2;
  double a = 0.5 * a2, vt[3], vr[3];
  mju_cross(vt, vel, c);  // omega x r
  for (int j = 0; j < 3; j++) vr[j] = (j < 2 ? U[j] : 0) - (vel[3 + j] + vt[j]);
  double V = mju_norm3(vr);
  if (!(V > 0)) return;
  const double q = 0.5 * wd.par.rho;
  double vn = mju_dot3(vr, n), f[3] = {0, 0, 0};
  // pressure drag on windward faces: 0.5 rho C_d V^2 times the face's
  // area projected across the flow (a cos), along the relative flow
  if (vn < 0) {
    double s = q * wd.par.cd * a * (-vn / V) * V;
    for (int j = 0; j < 3; j++) f[j] += s * vr[j];
  }
  // skin friction on every dry face: 0.5 rho C_f a |v_t| v_t
  double tan[3];
  for (int j = 0; j < 3; j++) tan[j] = vr[j] - vn * n[j];
  double st = q * wd.par.cf * a * mju_norm3(tan);
  for (int j = 0; j < 3; j++) f[j] += st * tan[j];
  double t[3];
  mju_cross(t, c, f);
  for (int j = 0; j < 3; j++) {
    w[j] += f[j];
    w[3 + j] += t[j];
  }
}

void windWrench(const HullSet& hs, const Wind& wd, const Sea& sea, const mjModel* m,
                const mjData* d, const WindIO& io) {
  if (!wd.par.on) return;
  const double t = d->time, sp = windSpeed(wd, t), dr = wd.par.w.dir * M_PI / 180;
  const double U[2] = {sp * std::cos(dr), sp * std::sin(dr)};
  // a centroid above every crest is dry, below every trough wet; between,
  // the exact surface height decides (centroid rule, docs/physics.md)
  double amp = 0;
  for (const Wave& w : sea.waves) amp += std::fabs(w.amp);
  for (const Wind::Part& p : wd.part) {
    const int bd = p.body;
    if (io.bad[bd]) continue;
    mjtNum vel[6];
    mj_objectVelocity(m, d, mjOBJ_BODY, bd, vel, 0);
    const mjtNum* x = d->xpos + 3 * bd;
    const mjtNum* R = d->xmat + 9 * bd;
    const mjtNum* com = d->xipos + 3 * bd;
    bool ok = true;
    for (int j = 0; j < 6; j++) ok = ok && std::isfinite(vel[j]);
    if (!ok) continue;
    double* w = io.part + 6 * bd;
    const bool hull = p.t0 < 0;
    const int t0 = hull ? -1 - p.t0 : p.t0;
    // cpu backend: the vertex heights above the surface its water pass
    // left in io.h (unless it skipped the hull as above every crest: all
    // dry); a centroid is dry when their mean is > 0, the linear surface
    // the pressure cut uses. gl: the exact height at the centroid.
    const bool useH = hull && io.h;
    bool allDry = false;
    if (useH) {
      const Hull& hl = hs.hull[p.hull];
      allDry = x[2] - hl.rad > io.crest + 1e-6 * (1 + std::fabs(x[2]) + hl.rad);
    }
    const int* face = hull ? hs.face.data() : wd.face.data();
    const double* vert = hull ? hs.vert.data() : wd.vert.data();
    for (int k = t0; k < t0 + p.nt; k++) {
      double q[3][3];
      for (int i = 0; i < 3; i++) {
        const double* v = vert + 3 * face[3 * k + i];
        mju_rotVecMat(q[i], v, R);
        for (int j = 0; j < 3; j++) q[i][j] += x[j];
      }
      if (useH && !allDry) {
        const int* f = face + 3 * k;
        if (io.h[f[0]] + io.h[f[1]] + io.h[f[2]] <= 0) continue;
        triForce(wd, U, q[0], q[1], q[2], com, vel, w);
        continue;
      }
      double cz = (q[0][2] + q[1][2] + q[2][2]) / 3;
      if (cz < sea.level - amp && !allDry) continue;
      if (cz <= sea.level + amp && !allDry) {
        double cx = (q[0][0] + q[1][0] + q[2][0]) / 3, cy = (q[0][1] + q[1][1] + q[2][1]) / 3;
        if (cz <= sea.height(cx, cy, t)) continue;
      }
      triForce(wd, U, q[0], q[1], q[2], com, vel, w);
    }
  }
  for (int bd : wd.body) {
    if (io.bad[bd]) continue;
    const double* w = io.part + 6 * bd;
    for (int j = 0; j < 6; j++) io.wrench[6 * bd + j] += w[j];
  }
}

}  // namespace mjb
