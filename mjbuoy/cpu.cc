// cpu backend: the reference implementation every other backend must match
#include <cmath>
#include <cstring>

#include "buoy.h"
#include "pressure.h"

namespace mjb {

void makeState(const Buoy& b, State* s) {
  s->wrench.assign(6 * b.m->nbody, 0);
  s->rel.assign(b.vert.size(), 0);
  s->h.assign(b.vert.size() / 3, 0);
  s->bad.assign(b.m->nbody, 0);
}

static bool finite(const mjtNum* x, int n) {
  for (int i = 0; i < n; i++) if (!std::isfinite(x[i])) return false;
  return true;
}

void cpuWrench(const Buoy& b, const mjModel* m, const mjData* d, State* s) {
  const Sea& sea = b.cfg.sea;
  const double rg = sea.rho * sea.g, t = d->time;
  std::memset(s->wrench.data(), 0, s->wrench.size() * sizeof(double));
  std::memset(s->bad.data(), 0, s->bad.size());

  for (const Hull& hl : b.hull) {
    const int bd = hl.body;
    const mjtNum* x = d->xpos + 3 * bd;
    const mjtNum* R = d->xmat + 9 * bd;
    const mjtNum* c = d->xipos + 3 * bd;
    mjtNum vel[6];  // [angular; linear] at the COM, world frame
    mj_objectVelocity(m, d, mjOBJ_BODY, bd, vel, 0);
    if (!finite(x, 3) || !finite(R, 9) || !finite(c, 3) || !finite(vel, 6)) {
      s->bad[bd] = 1;
      continue;
    }
    double* w = s->wrench.data() + 6 * bd;

    // vertices: body frame -> relative to COM, and height above the surface
    for (int i = hl.v0; i < hl.v0 + hl.nv; i++) {
      const double* p = b.vert.data() + 3 * i;
      double* r = s->rel.data() + 3 * i;
      for (int j = 0; j < 3; j++) {
        r[j] = R[3 * j] * p[0] + R[3 * j + 1] * p[1] + R[3 * j + 2] * p[2] + x[j] - c[j];
      }
      double z = r[2] + c[2];
      s->h[i] = sea.waves.empty() ? z - sea.level : z - sea.height(r[0] + c[0], r[1] + c[1], t);
    }

    // triangles: pressure force -rho g dA n, torque -rho g drA x n
    double f[3] = {0, 0, 0}, tq[3] = {0, 0, 0}, wet = 0;
    for (int k = hl.t0; k < hl.t0 + hl.nt; k++) {
      const int* fc = b.face.data() + 3 * k;
      double p[3][3], h[3];
      for (int e = 0; e < 3; e++) {
        std::memcpy(p[e], s->rel.data() + 3 * fc[e], 3 * sizeof(double));
        h[e] = s->h[fc[e]];
      }
      Wet wt;
      wetTriangle(p, h, &wt);
      if (wt.area <= 0) continue;
      const double* n = wt.n;
      for (int j = 0; j < 3; j++) f[j] -= rg * wt.dA * n[j];
      tq[0] -= rg * (wt.drA[1] * n[2] - wt.drA[2] * n[1]);
      tq[1] -= rg * (wt.drA[2] * n[0] - wt.drA[0] * n[2]);
      tq[2] -= rg * (wt.drA[0] * n[1] - wt.drA[1] * n[0]);
      wet += wt.area;
    }

    // simple damping (Cruz 2023): scaled by the wet fraction r_s = S_wet / S
    double rs = wet / hl.area;
    for (int j = 0; j < 3; j++) {
      w[j] += f[j] - hl.par.damp[0] * rs * vel[3 + j];
      w[3 + j] += tq[j] - hl.par.damp[1] * rs * vel[j];
    }
  }

  // a body with a non-finite state gets no force (other hulls of it included)
  for (int bd : b.body) {
    if (s->bad[bd]) std::memset(s->wrench.data() + 6 * bd, 0, 6 * sizeof(double));
  }
}

}  // namespace mjb
