// cpu backend: the vertex stage (positions, the surface search, heights,
// e^L at wet vertices) and the flow at a hull's COM
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "cpu/cpuhull.h"
#include "sea/seavec.h"
#include "util/vmath.h"
#include "util/zipkern.h"

namespace mjb {

// e^L of every component at the wet vertices wq[0, nq) of a hull (waveint.h):
// L = k z' + i theta, and at finite depth also -k (z' + 2 h) + i theta; one
// exp per component and exponent (vectorised, all the chunk's at once), the
// phases' sin and cos from the label search; arg: 2 n kExpChunk scratch;
// fast (vertex integration): the exp within vmath.h's vExpFast's 1e-10.
// On a vector level the three fused per vertex (cpuexp.h), the same bits
static void vertexWaves(const WaveTab& t, size_t nw, size_t stride, const HullScr& hs,
                        const int* wq, int nq, double* arg, bool fast) {
  if (const ELanesFn f = eLanesFn()) {  // fused per vertex, lanes over components
    const EIn in = eIn(t, nw, fast);
    for (int c = 0; c < nq; c++) {
      f(in, hs.ZS[wq[c]], hs.SC + 2 * nw * wq[c], hs.E + stride * nw * wq[c]);
    }
    return;
  }
  const int nf = t.finite ? 2 : 1;
  for (int c = 0; c < nq; c++) vertexExponents(t, hs.ZS[wq[c]], arg + nf * t.n * c);
  (fast ? vExpFast : vExp)(nf * t.n * nq, arg, arg);
  for (int c = 0; c < nq; c++) {
    vertexE(t, nw, arg + nf * t.n * c, hs.SC + 2 * nw * wq[c], hs.E + stride * nw * wq[c]);
  }
}

// the vertex stage's scratch layout in sc (scratchSize)
HullScr hullScr(const Sea& sea, double* sc, size_t mi, int nv) {
  const size_t nw = sea.waves.size();
  HullScr hs;
  // the point arrays each on a line (mi rounded up to 8 doubles)
  mi = (mi + 7) & ~size_t(7);
  hs.X = lineUp(laneTmp(sc, nw) + (2 + kLaneTmp) * nw);
  hs.Y = hs.X + mi;
  hs.A0 = hs.Y + mi;
  hs.A1 = hs.A0 + mi;
  hs.Z = hs.A1 + mi;
  hs.ZS = hs.Z + mi;
  hs.SC = hs.ZS + mi;
  hs.E = hs.SC + 2 * nw * mi;
  hs.rel = hs.E + eStride(sea) * nw * nv;
  hs.lab = hs.rel + 3 * nv;
  hs.rec = lineUp(hs.lab + 2 * nv);  // (a record is one load)
  hs.arg = hs.rec + kRec * nv;
  hs.VS = lineUp(hs.arg + 2 * kExpChunk * nw);
  return hs;
}

// vertices [q0, q1) of the hull: body frame -> relative to COM (rel),
// world x, y and the label search's start: the vertex's label offset of
// the last steps (zero after a restart), which moves by mm per step
static void placeVertices(const HullCall& c, const HullScr& hs, int q0, int q1) {
  const Hull& hl = c.hl;
  HullState* s = c.s;
  const mjtNum *x = c.x, *R = c.R, *com = c.com;
  const double* L = c.L;
  const int v = hl.v0 + q0;
  int qs = q0;  // whole chunks in lanes (seavec.h), the rest here
  if (simdLevel() != kSimdScalar) {
    PlaceIn in{c.b.vert.data() + 3 * v, q1 - q0, {}, {}, {}, {L[0], L[1], L[2]},
               {&s->off[2 * v], &s->offOld[2 * v], &s->offOld2[2 * v]},
               hs.rel + 3 * q0, hs.X + q0, hs.Y + q0, hs.A0 + q0, hs.A1 + q0};
    for (int j = 0; j < 9; j++) in.R[j] = R[j];
    for (int j = 0; j < 3; j++) in.t[j] = x[j] - com[j], in.com[j] = com[j];
    qs += simdLevel() == kSimdAvx512 ? placeLanesAvx512(in) : placeLanesAvx2(in);
  }
  for (int q = qs; q < q1; q++) {
    const int i = hl.v0 + q;
    const double* p = c.b.vert.data() + 3 * i;
    double* r = hs.rel + 3 * q;
    for (int j = 0; j < 3; j++) {
      r[j] = R[3 * j] * p[0] + R[3 * j + 1] * p[1] + R[3 * j + 2] * p[2] + x[j] - com[j];
    }
    hs.X[q] = r[0] + com[0];
    hs.Y[q] = r[1] + com[1];
    const float *o = &s->off[2 * i], *o1 = &s->offOld[2 * i], *o2 = &s->offOld2[2 * i];
    hs.A0[q] = hs.X[q] + (L[0] * o[0] + L[1] * o1[0] + L[2] * o2[0]);
    hs.A1[q] = hs.Y[q] + (L[0] * o[1] + L[1] * o1[1] + L[2] * o2[1]);
  }
}

// after the label search, vertices [q0, q1): labels, the next step's
// guesses and heights above the surface, whole chunks in lanes
// (seavec.h), the rest here
static void vertexOut(const HullCall& c, const HullScr& hs, int q0, int q1) {
  const Hull& hl = c.hl;
  HullState* s = c.s;
  const double zc = c.com[2];
  const int v = hl.v0 + q0;
  int qs = q0;
  if (simdLevel() != kSimdScalar) {
    HeightIn in{q1 - q0, hs.rel + 3 * q0, zc, hs.X + q0, hs.Y + q0, hs.A0 + q0,
                hs.A1 + q0, hs.Z + q0, c.first, hs.lab + 2 * q0, s->offNew.data() + 2 * v,
                s->h.data() + v};
    qs += simdLevel() == kSimdAvx512 ? heightLanesAvx512(in) : heightLanesAvx2(in);
  }
  for (int q = qs; q < q1; q++) {
    const int i = hl.v0 + q;
    hs.lab[2 * q] = hs.A0[q];
    hs.lab[2 * q + 1] = hs.A1[q];
    if (c.first) {
      // (a label not finite, which the height reports, guesses nothing)
      const double o0 = hs.A0[q] - hs.X[q], o1 = hs.A1[q] - hs.Y[q];
      const bool ok = std::isfinite(o0) && std::isfinite(o1);
      s->offNew[2 * i] = ok ? float(o0) : 0;
      s->offNew[2 * i + 1] = ok ? float(o1) : 0;
    }
    s->h[i] = hs.rel[3 * q + 2] + zc - hs.Z[q];
  }
}

// at the wet vertices of [q0, q1) (h <= 0, a wet piece's corner 0) the
// stretched height and e^L, kExpChunk vertices per vertexWaves call; for
// a sea of at most kWetLanesMax components whole lane groups of every
// vertex at once instead (seavec.h WetIn: no branch on wet or dry, whose
// pattern along the mesh mispredicts; the dry ones' values are not read),
// with the same operations and exp, so the same bits per vertex. More
// components: the list, which spends the exps on wet vertices only
enum { kWetLanesMax = 8 };
static void wetVertices(const HullCall& c, const HullScr& hs, int q0, int q1) {
  const Hull& hl = c.hl;
  const Sea& sea = c.sea;
  HullState* s = c.s;
  const size_t nw = sea.waves.size();
  if (nw == 0) return;
  const double zc = c.com[2];
  // vertex integration: e^(k z') by vExpFast / expFast (1e-10 relative)
  const bool fast = sea.integration == kIntegrateVertex;
  int qs = q0;
  if (simdLevel() != kSimdScalar && int(nw) <= kWetLanesMax) {
    const WaveTab& t = s->tab;
    const int es = int(eStride(sea));
    WetIn in{q1 - q0, hs.rel + 3 * q0, hs.Z + q0, hs.SC + 2 * nw * q0, zc, sea.level, t.depth,
             t.n, int(nw), t.finite, es, t.k.data(), t.ident ? nullptr : t.perm.data(),
             hs.ZS + q0, hs.E + es * nw * q0, fast};
    qs += simdLevel() == kSimdAvx512 ? wetLanesAvx512(in) : wetLanesAvx2(in);
  }
  int wq[kExpChunk], nq = 0;
  for (int q = qs; q < q1; q++) {
    const int i = hl.v0 + q;
    if (!(s->h[i] <= 0)) continue;
    hs.ZS[q] = stretch(sea.depth, hs.rel[3 * q + 2] + zc - sea.level, hs.Z[q] - sea.level);
    wq[nq++] = q;
    if (nq == kExpChunk) {
      vertexWaves(s->tab, nw, eStride(sea), hs, wq, nq, hs.arg, fast);
      nq = 0;
    }
  }
  if (nq > 0) vertexWaves(s->tab, nw, eStride(sea), hs, wq, nq, hs.arg, fast);
}

// the records of vertices [q0, q1) (HullScr rec), whole chunks in lanes
// (seavec.h), the rest here
static void packVertices(const HullCall& c, const HullScr& hs, int q0, int q1) {
  const double* h = c.s->h.data() + c.hl.v0;
  int qs = q0;
  if (simdLevel() != kSimdScalar) {
    PackIn in{q1 - q0, hs.rel + 3 * q0, h + q0, hs.ZS + q0, hs.A0 + q0, hs.A1 + q0,
              hs.rec + kRec * q0};
    qs += simdLevel() == kSimdAvx512 ? packLanesAvx512(in) : packLanesAvx2(in);
  }
  for (int q = qs; q < q1; q++) {
    double* r = hs.rec + kRec * q;
    const double f[kRec] = {hs.rel[3 * q], hs.rel[3 * q + 1], hs.rel[3 * q + 2], h[q],
                            hs.ZS[q],      hs.A0[q],          hs.A1[q],          0};
    std::memcpy(r, f, sizeof f);
  }
}

// the vertex stage of vertices [q0, q1), timed into vsec: positions, the
// label search for all at once (structure of arrays), heights and e^L.
// The hull's scratch hs is shared by the threads of a split hull; tmp and
// hs.arg are the running thread's
void vertexStage(const HullCall& c, const HullScr& hs, int q0, int q1) {
  const auto tv0 = std::chrono::steady_clock::now();
  HullState* s = c.s;
  const size_t nw = c.sea.waves.size();
  placeVertices(c, hs, q0, q1);
  // vertex integration: the phases' reduced-cost sin and cos (sincoskern.h
  // sinCosFast; docs/physics.md "Vertex integration")
  const bool fast = c.sea.integration == kIntegrateVertex;
  c.cs->niter[c.slot] += c.sea.solveMany(s->wn.data(), q1 - q0, hs.X + q0, hs.Y + q0,
                                            hs.A0 + q0, hs.A1 + q0, hs.Z + q0,
                                            hs.SC + 2 * nw * q0, c.tmp, fast);
  c.cs->nsolve[c.slot] += q1 - q0;
  vertexOut(c, hs, q0, q1);
  wetVertices(c, hs, q0, q1);
  packVertices(c, hs, q0, q1);
  c.cs->vsec[c.slot] +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - tv0).count();
}

// the hull's flow: its COM velocity relative to the water there, its speed
// (returned) and direction dir (body x when at rest)
double hullFlow(const HullCall& c, const double vel[6], double dir[3]) {
  const Sea& sea = c.sea;
  HullState* s = c.s;
  const int ih = c.ih;
  const mjtNum* com = c.com;
  const double* L = c.L;
  double uw[3], vr[3];
  const double *o = &s->hoff[2 * ih], *o1 = &s->hoffOld[2 * ih], *o2 = &s->hoffOld2[2 * ih];
  double a[2] = {com[0] + (L[0] * o[0] + L[1] * o1[0] + L[2] * o2[0]),
                 com[1] + (L[0] * o[1] + L[1] * o1[1] + L[2] * o2[1])};
  int nit = 0;
  double hz = sea.solve(s->wn.data(), com[0], com[1], a, c.sc, c.tmp, &nit);
  c.cs->niter[c.slot] += nit;
  c.cs->nsolve[c.slot]++;
  if (c.first) {
    const double o0 = a[0] - com[0], o1 = a[1] - com[1];
    const bool ok = std::isfinite(o0) && std::isfinite(o1);
    s->hoffNew[2 * ih] = ok ? o0 : 0;
    s->hoffNew[2 * ih + 1] = ok ? o1 : 0;
  }
  sea.velocitySC(s->wn.data(), c.sc, com[2] - sea.level, hz - sea.level, uw);
  for (int j = 0; j < 3; j++) vr[j] = vel[3 + j] - uw[j];
  double speed = std::sqrt(dot(vr, vr));
  for (int j = 0; j < 3; j++) dir[j] = speed > 1e-9 ? vr[j] / speed : c.R[3 * j];
  return speed;
}

}  // namespace mjb
