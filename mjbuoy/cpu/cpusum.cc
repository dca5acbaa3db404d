// cpu backend: the vertex sums of vertex integration (cpusum.h)
#include "cpu/cpusum.h"

#include <cmath>

#include "cpu/cpuhull.h"
#include "sea/waveker.h"
#include "util/vmath.h"

namespace mjb {

// the sums of one vertex's e^L e into out (cpusum.h SumIn)
static void sumVertex(const Sea& sea, const WaveTab& t, const double* e, double* out) {
  SumIn in{e, int(sea.waves.size()), t.n, t.finite ? 2 : 1, {}, {}, {}, {}, out};
  for (int f = 0; f < 2; f++) {
    in.wp[f] = t.wp[f].data();
    in.wux[f] = t.wux[f].data();
    in.wuy[f] = t.wuy[f].data();
    in.wz[f] = t.wz[f].data();
  }
  if (simdLevel() == kSimdAvx512) {
    sumLanesAvx512(in);
  } else {
    sumLanesAvx2(in);
  }
}

// e^L of dry vertex q at height zs above the surface (stretched, not
// clipped at 0 as the vertex stage's z' is) into e, as vertexWaves lays it
// out, by vertex integration's exp (vExpFast, docs/physics.md "Vertex
// integration"); arg: nf n doubles of scratch
static void dryWaves(const Sea& sea, const WaveTab& t, const HullScr& hs, int q, double zs,
                     double* arg, double* e) {
  const size_t nw = sea.waves.size();
  if (const ELanesFn f = eLanesFn()) {  // vertexWaves's fused kernel (cpuexp.h)
    f(eIn(t, nw, true), zs, hs.SC + 2 * nw * q, e);
    return;
  }
  vertexExponents(t, zs, arg);
  vExpFast((t.finite ? 2 : 1) * t.n, arg, arg);
  vertexE(t, sea.waves.size(), arg, hs.SC + 2 * sea.waves.size() * q, e);
}

// whether global vertex i has a neighbour below the surface (cpu.h adj)
static bool wetNeighbour(const CpuState& cs, const double* h, int i) {
  for (int a = cs.adjOff[i]; a < cs.adjOff[i + 1]; a++) {
    if (h[cs.adj[a]] <= 0) return true;
  }
  return false;
}

void vertexSums(const HullCall& c, const HullScr& hs, int q0, int q1) {
  const Sea& sea = c.sea;
  const WaveTab& t = c.s->tab;
  const size_t nw = sea.waves.size(), es = eStride(sea);
  // hs.arg's 2 nw kExpChunk doubles: the exponents, then one vertex's e^L
  double *arg = hs.arg, *e = hs.arg + 2 * nw;
  for (int q = q0; q < q1; q++) {
    const double h = c.s->h[c.hl.v0 + q];
    double* out = hs.VS + 4 * q;
    if (h <= 0) {
      sumVertex(sea, t, hs.E + es * nw * q, out);
      continue;
    }
    // z' linear in the height h at a fixed surface, zero on it (sea.cc
    // stretch without the clip): e^L along a cut edge interpolates to the
    // cut point's z' = 0 (docs/physics.md "Vertex integration")
    const double eta = hs.Z[q] - sea.level;
    double zs = NAN;
    if (!(sea.depth > 0)) {
      zs = h;
    } else if (sea.depth + eta > 0) {
      zs = h * sea.depth / (sea.depth + eta);
    }
    // (e^(k z') grows above the surface: past e^kRMax, the series' own
    // limit, the cut triangles reaching the vertex go to the exact path)
    if (!wetNeighbour(*c.cs, c.s->h.data(), c.hl.v0 + q) || !std::isfinite(zs) ||
        t.k[t.n - 1] * zs > kRMax) {
      for (int j = 0; j < 4; j++) out[j] = NAN;
      continue;
    }
    dryWaves(sea, t, hs, q, zs, arg, e);
    sumVertex(sea, t, e, out);
  }
}

}  // namespace mjb
