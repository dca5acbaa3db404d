// eqdraft: the heave offset that floats a free rigid group (eqdraft.h)
#include "hull/eqdraft.h"

#include <algorithm>
#include <cmath>

#include "hull/hullset.h"
#include "hull/pressure.h"
#include "sea/sea.h"
#include "util/fmt.h"

namespace mjb {

// whether hull body b rides with root (root or below it in the tree)
static bool inSubtree(const mjModel* m, int b, int root) {
  for (; b > 0; b = m->body_parentid[b])
    if (b == root) return true;
  return root == 0;
}

// lowest and highest world z [m] of the subtree's hull vertices at d
static bool zRange(const HullSet& hs, const mjData* d, int root, double* lo, double* hi) {
  *lo = INFINITY, *hi = -INFINITY;
  for (const Hull& h : hs.hull) {
    if (!inSubtree(hs.m, h.body, root)) continue;
    const mjtNum* R = d->xmat + 9 * h.body;
    for (int i = h.v0; i < h.v0 + h.nv; i++) {
      const double* v = &hs.vert[3 * i];
      double z = d->xpos[3 * h.body + 2] + R[6] * v[0] + R[7] * v[1] + R[8] * v[2];
      *lo = std::min(*lo, z), *hi = std::max(*hi, z);
    }
  }
  return *lo <= *hi;
}

// the flat-water volume of the hulls for which pick(body) holds
template <class F>
static double volumeOf(const HullSet& hs, const Sea& sea, const mjData* d, double dz, F pick) {
  double vol = 0, lev = sea.level;
  for (const Hull& h : hs.hull) {
    if (!pick(h.body)) continue;
    const mjtNum* R = d->xmat + 9 * h.body;
    const mjtNum* x = d->xpos + 3 * h.body;
    for (int t = h.t0; t < h.t0 + h.nt; t++) {
      double p[3][3], ht[3];
      for (int k = 0; k < 3; k++) {
        mju_rotVecMat(p[k], &hs.vert[3 * hs.face[3 * t + k]], R);
        ht[k] = x[2] + p[k][2] + dz - lev;
      }
      Wet w;
      wetTriangle(p, ht, &w);
      // the flat-water buoyancy rho g V is -rho g sum dA n_z (pressure.h)
      vol -= w.dA * w.n[2];
    }
  }
  return vol;
}

double displacedVolume(const HullSet& hs, const Sea& sea, const mjData* d, int root, double dz) {
  return volumeOf(hs, sea, d, dz, [&](int b) { return inSubtree(hs.m, b, root); });
}

double groupVolume(const HullSet& hs, const Sea& sea, const mjData* d, int root, double dz) {
  return volumeOf(hs, sea, d, dz, [&](int b) { return hs.m->body_weldid[b] == root; });
}

bool equilibriumHeave(const HullSet& hs, const Sea& sea, const mjData* d, int root, double* dz,
                      std::string* why) {
  const mjModel* m = hs.m;
  double zlo, zhi;
  if (!zRange(hs, d, root, &zlo, &zhi)) return *why = "it carries no hull", false;
  double mass = m->body_subtreemass[root], lev = sea.level;
  if (!(mass > 0)) return *why = "it has no mass", false;
  // dz = lev - zhi: all under; dz = lev - zlo: all dry
  double a = lev - zhi, b = lev - zlo, want = mass / sea.rho;
  double full = displacedVolume(hs, sea, d, root, a);
  if (!(full > want)) {
    *why = "it sinks: its mass " + fmt(mass) + " kg is more than the " + fmt(sea.rho * full) +
           " kg of water its hulls displace fully submerged";
    return false;
  }
  // V(dz) falls from full at a to 0 at b; keep V(a) > want >= V(b)
  double tol = 1e-12 * std::max(zhi - zlo, 1e-6);
  for (int it = 0; it < 200 && b - a > tol; it++) {
    double c = 0.5 * (a + b);
    if (c <= a || c >= b) break;  // far from 0 (a sea level of 1e4 m) doubles run out first
    if (displacedVolume(hs, sea, d, root, c) > want) {
      a = c;
    } else {
      b = c;
    }
  }
  *dz = 0.5 * (a + b);
  return true;
}

}  // namespace mjb
