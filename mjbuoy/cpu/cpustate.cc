// cpu backend: per-mjData state and scratch, the step clock of the slamming
// history, and the label guesses' weights
#include <algorithm>
#include <cstring>

#include "cpu/cpuhull.h"
#include "sea/seavec.h"
#include "util/zipkern.h"

namespace mjb {

// most points one hull solves at once: its vertices or its triangles
static size_t maxItems(const Buoy& b) {
  size_t n = 1;
  for (const Hull& h : b.hull) n = std::max(n, size_t(std::max(h.nv, h.nt)));
  return n;
}

// most triangles of one hull
static size_t maxTris(const Buoy& b) {
  size_t n = 1;
  for (const Hull& h : b.hull) n = std::max(n, size_t(h.nt));
  return n;
}

// most vertices of one hull
static size_t maxVerts(const Buoy& b) {
  size_t n = 1;
  for (const Hull& h : b.hull) n = std::max(n, size_t(h.nv));
  return n;
}

// per thread: 4 + kLaneTmp per wave for solve() and solveMany() (seavec.h),
// then x, y, a0, a1, z, stretched height z' and 2 per wave (phases) for
// every point of a hull, e^L (eStride per wave), the position relative
// to the COM (3), label (2) and record (kRec, aligned to 8 doubles) for
// every vertex of a hull, and 2 per wave per vertex of a chunk of exp
// arguments; the Newton scratch, the point arrays and the records each
// start on a 64-byte line (hullScr: up to 7 doubles to reach one, the
// point count rounded up to 8). A multiple of 8 doubles, so every thread's
// part falls on the lines the same way
static size_t scratchSize(const Buoy& b) {
  size_t nw = std::max(b.wcap, b.cfg.sea.waves.size());
  const size_t mi8 = (maxItems(b) + 7) & ~size_t(7);
  const size_t n = (4 + kLaneTmp + 2 * kExpChunk) * nw + (6 + 2 * nw) * mi8 +
                   (eStride(b.cfg.sea) * nw + 5 + kRec) * maxVerts(b) + kRec + 3 * 7;
  return (n + 7) & ~size_t(7);
}

size_t stateBytes(const Buoy& b, int nthreads) {
  const size_t nth = std::max(1, nthreads), nt = b.face.size() / 3, nv = b.vert.size() / 3;
  const size_t nw = std::max(b.wcap, b.cfg.sea.waves.size());
  size_t n = scratchSize(b) * nth * sizeof(double);     // scr
  n += 4 * maxTris(b) * nth * sizeof(int);               // iscr
  n += 10 * maxTris(b) * nth * sizeof(double);           // tri: area, c, n, u
  n += hullChunks(int(maxTris(b))) * nth * sizeof(ChunkSum);
  n += 2 * 3 * nt * sizeof(float);                       // curQ, prevQ
  n += 4 * 2 * nv * sizeof(float) + nv * sizeof(double);  // label offsets, h
  n += nw * (sizeof(WaveNow) + 16 * sizeof(double));     // wn, tab
  return n;
}

void makeState(const Buoy& b, State* s) {
  size_t nt = b.face.size() / 3;
  s->wrench.assign(6 * b.m->nbody, 0);
  s->part.assign(mjbNPART * 6 * b.m->nbody, 0);
  s->h.assign(b.vert.size() / 3, 0);
  s->bad.assign(b.m->nbody, 0);
  s->told.assign(b.m->nbody, 0);
  s->badPart.assign(b.m->nbody * mjbNPART, 0);
  s->toldPart.assign(b.m->nbody * mjbNPART, 0);
  s->dwrench.assign(6 * b.diff.db.size(), 0);
  s->dtold.assign(b.diff.db.size(), 0);
  s->notices.clear();
  s->notices.reserve(4096);
  s->tri.per = maxTris(b);
  const size_t nth = std::max(1, b.nthreads);
  s->tri.area.assign(s->tri.per * nth, 0);
  for (auto* a : {&s->tri.c, &s->tri.n, &s->tri.u}) a->assign(3 * s->tri.per * nth, 0);
  s->hwet.assign(b.hull.size(), 0);
  s->curQ.assign(3 * nt, 0);
  s->prevQ.assign(3 * nt, 0);
  s->off.assign(b.vert.size() / 3 * 2, 0);
  s->offNew.assign(b.vert.size() / 3 * 2, 0);
  s->hoff.assign(2 * b.hull.size(), 0);
  s->hoffNew.assign(2 * b.hull.size(), 0);
  s->offOld.assign(b.vert.size() / 3 * 2, 0);
  s->offOld2.assign(b.vert.size() / 3 * 2, 0);
  s->hoffOld.assign(2 * b.hull.size(), 0);
  s->hoffOld2.assign(2 * b.hull.size(), 0);
  s->hv.assign(b.hull.size(), 0);
  s->hvNew.assign(b.hull.size(), 0);
  s->hvOld.assign(b.hull.size(), 0);
  s->hvOld2.assign(b.hull.size(), 0);
  s->wn.assign(std::max(b.wcap, b.cfg.sea.waves.size()), WaveNow{});
  s->tab.reserve(std::max(b.wcap, b.cfg.sea.waves.size()));
  s->mi = maxItems(b);
  s->per = scratchSize(b);
  s->scr.assign(s->per * std::max(1, b.nthreads), 0);
  s->iper = 4 * maxTris(b);
  s->iscr.assign(s->iper * std::max(1, b.nthreads), 0);
  s->cper = hullChunks(int(maxTris(b)));
  s->csum.assign(s->cper * std::max(1, b.nthreads), ChunkSum{});
  s->nsolve.assign(std::max(1, b.nthreads), 0);
  s->niter.assign(std::max(1, b.nthreads), 0);
  s->vsec.assign(std::max(1, b.nthreads), 0);
  s->key = -1;
  s->hasPrev = false;
}

// advance the slamming history when time has moved on by a step, whatever
// loop moved it (mj_step, mj_forward + mj_Euler, ...): a call at a time at
// least 3/4 of opt.timestep past the current step's opens a new step; a
// call at the current step's time records (the last evaluation at that time
// is the step's history); a call in between is an RK4 stage (t + h/2) and
// records nothing. Time going backwards, or the step counter
// timer[mjTIMER_STEP] dropping (mj_resetData zeroes it), restarts
int stepClock(const mjModel* m, const mjData* d, State* s) {
  long k = d->timer[mjTIMER_STEP].number;
  int r;
  if (s->key < 0 || k < s->key || d->time < s->tcur) {
    s->hasPrev = false;
    r = kRestart;
  } else if (d->time - s->tcur >= 0.75 * m->opt.timestep) {
    s->tprev = s->tcur;
    s->hasPrev = true;
    r = kNewStep;
  } else {
    s->key = k;
    return d->time == s->tcur ? kSameStep : kMidStep;
  }
  s->key = k;
  s->tcur = d->time;
  return r;
}

void guessWeights(double t, const double tk[3], int n, double L[3]) {
  const double t0 = tk[0], t1 = tk[1], t2 = tk[2];
  L[0] = n >= 1 ? 1 : 0;
  L[1] = L[2] = 0;
  if (n < 2 || !(t0 > t1) || !(t - t0 <= 2 * (t0 - t1)) || !(t >= t0)) return;
  if (n >= 3 && t1 > t2) {
    L[0] = (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2));
    L[1] = (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2));
    L[2] = (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
  } else {
    L[0] = (t - t1) / (t0 - t1);
    L[1] = (t - t0) / (t1 - t0);
  }
}

// the weights L of off, offOld, offOld2 in hull ih's label guesses at time
// t (guessWeights): through the last three steps' offsets (times tgOff,
// tgOld, tgOld2) when all three were solved, the last two, or the last
// alone when fewer were. The offset moves smoothly with the sea and the
// hull, so the quadratic guess is off by O(dt^3) (nanometres at dt = 2 ms)
// where the last step's label was off by O(dt) (millimetres), and Newton,
// converging quadratically, reaches its tolerance in one step instead of
// two; the tolerance is unchanged, so the labels differ only within it
void hullGuess(const State& s, int ih, double t, double L[3]) {
  const int n = !s.hv[ih] ? 0 : !s.hvOld[ih] ? 1 : !s.hvOld2[ih] ? 2 : 3;
  const double tk[3] = {s.tgOff, s.tgOld, s.tgOld2};
  guessWeights(t, tk, n, L);
}

}  // namespace mjb
