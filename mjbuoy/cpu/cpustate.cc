// cpu backend: per-mjData scratch, and a hull's label guess weights
#include <algorithm>

#include "cpu/cpuhull.h"
#include "sea/seavec.h"
#include "util/zipkern.h"

namespace mjb {

// most points one hull solves at once: its vertices or its triangles
static size_t maxItems(const HullSet& b) {
  size_t n = 1;
  for (const Hull& h : b.hull) n = std::max(n, size_t(std::max(h.nv, h.nt)));
  return n;
}

// most triangles of one hull
static size_t maxTris(const HullSet& b) {
  size_t n = 1;
  for (const Hull& h : b.hull) n = std::max(n, size_t(h.nt));
  return n;
}

// most vertices of one hull
static size_t maxVerts(const HullSet& b) {
  size_t n = 1;
  for (const Hull& h : b.hull) n = std::max(n, size_t(h.nv));
  return n;
}

// per thread: 4 + kLaneTmp per wave for solve() and solveMany() (seavec.h),
// then x, y, a0, a1, z, stretched height z' and 2 per wave (phases) for
// every point of a hull, e^L (eStride per wave), the position relative
// to the COM (3), label (2) and record (kRec, aligned to 8 doubles) for
// every vertex of a hull, 2 per wave per vertex of a chunk of exp
// arguments and the vertex sums (4 per vertex, cpusum.h); the Newton
// scratch, the point arrays, the records and the sums each start on a
// 64-byte line (hullScr: up to 7 doubles to reach one, the
// point count rounded up to 8). A multiple of 8 doubles, so every thread's
// part falls on the lines the same way
static size_t scratchSize(const HullSet& b, const Sea& sea, size_t wcap) {
  size_t nw = std::max(wcap, sea.waves.size());
  const size_t mi8 = (maxItems(b) + 7) & ~size_t(7);
  const size_t n = (4 + kLaneTmp + 2 * kExpChunk) * nw + (6 + 2 * nw) * mi8 +
                   (eStride(sea) * nw + 5 + kRec + 4) * maxVerts(b) + kRec + 4 * 7;
  return (n + 7) & ~size_t(7);
}

size_t cpuStateBytes(const HullSet& b, const Sea& sea, size_t wcap, int nthreads) {
  const size_t nth = std::max(1, nthreads);
  size_t n = scratchSize(b, sea, wcap) * nth * sizeof(double);  // scr
  n += 4 * maxTris(b) * nth * sizeof(int);                       // iscr
  n += 10 * maxTris(b) * nth * sizeof(double);                   // tri: area, c, n, u
  n += hullChunks(int(maxTris(b))) * nth * sizeof(ChunkSum);     // csum
  n += (b.vert.size() / 3 + 1 + 2 * b.face.size()) * sizeof(int);  // adjOff, adj
  return n;
}

// cs->adjOff and cs->adj (cpu.h) from the faces of b: each triangle's
// three edges, both ways (an edge two triangles share listed twice)
static void vertexNeighbours(const HullSet& b, CpuState* cs) {
  const size_t nv = b.vert.size() / 3, nt = b.face.size() / 3;
  cs->adjOff.assign(nv + 1, 0);
  for (size_t k = 0; k < nt; k++) {
    for (int e = 0; e < 3; e++) cs->adjOff[b.face[3 * k + e] + 1] += 2;
  }
  for (size_t i = 0; i < nv; i++) cs->adjOff[i + 1] += cs->adjOff[i];
  cs->adj.assign(cs->adjOff[nv], 0);
  std::vector<int> at(cs->adjOff.begin(), cs->adjOff.end() - 1);
  for (size_t k = 0; k < nt; k++) {
    for (int e = 0; e < 3; e++) {
      const int v = b.face[3 * k + e];
      cs->adj[at[v]++] = b.face[3 * k + (e + 1) % 3];
      cs->adj[at[v]++] = b.face[3 * k + (e + 2) % 3];
    }
  }
}

void makeCpuState(const HullSet& b, const Sea& sea, size_t wcap, const CpuPlan& plan,
                  CpuState* cs) {
  const size_t nth = std::max(1, plan.nthreads);
  cs->tri.per = maxTris(b);
  cs->tri.area.assign(cs->tri.per * nth, 0);
  for (auto* a : {&cs->tri.c, &cs->tri.n, &cs->tri.u}) a->assign(3 * cs->tri.per * nth, 0);
  cs->mi = maxItems(b);
  cs->per = scratchSize(b, sea, wcap);
  cs->scr.assign(cs->per * nth, 0);
  cs->iper = 4 * maxTris(b);
  cs->iscr.assign(cs->iper * nth, 0);
  cs->cper = hullChunks(int(maxTris(b)));
  cs->csum.assign(cs->cper * nth, ChunkSum{});
  cs->nsolve.assign(nth, 0);
  cs->niter.assign(nth, 0);
  cs->vsec.assign(nth, 0);
  vertexNeighbours(b, cs);
}

// the weights L of off, offOld, offOld2 in hull ih's label guesses at time
// t (guessWeights): through the last three steps' offsets (times tgOff,
// tgOld, tgOld2) when all three were solved, the last two, or the last
// alone when fewer were. The offset moves smoothly with the sea and the
// hull, so the quadratic guess is off by O(dt^3) (nanometres at dt = 2 ms)
// where the last step's label was off by O(dt) (millimetres), and Newton,
// converging quadratically, reaches its tolerance in one step instead of
// two; the tolerance is unchanged, so the labels differ only within it
void hullGuess(const HullState& s, int ih, double t, double L[3]) {
  const int n = !s.hv[ih] ? 0 : !s.hvOld[ih] ? 1 : !s.hvOld2[ih] ? 2 : 3;
  const double tk[3] = {s.tgOff, s.tgOld, s.tgOld2};
  guessWeights(t, tk, n, L);
}

}  // namespace mjb
