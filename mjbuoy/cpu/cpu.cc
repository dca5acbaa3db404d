// cpu backend: the reference implementation every other backend must
// match. This file: hulls in chunks, the threads, the wrench
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "cpu/cpuhull.h"
#include "cpu/cpusum.h"
#include "hull/hydro.h"
#include "util/pool.h"

namespace mjb {

// whole hull above the highest crest the waves can make: all dry, which
// gives exactly what the passes give then (no force, no history)
static void dryHull(const Hull& hl, int ih, bool first, HullState* s) {
  s->hwet[ih] = 0;
  if (!first) return;
  std::memset(&s->curQ[3 * hl.t0], 0, 3 * hl.nt * sizeof(float));
  // the next step's guesses: cold, as after a restart
  std::memset(&s->offNew[2 * hl.v0], 0, 2 * hl.nv * sizeof(float));
  s->hoffNew[2 * ih] = s->hoffNew[2 * ih + 1] = 0;
  s->hvNew[ih] = 0;
}

// a hull's vertices and triangles go in nc chunks of about kChunkTris
// triangles each, fixed by the hull alone: passes 1 and 2 sum per chunk
// and the chunks' sums are added in their order whoever ran them, so the
// results keep their bits for any thread count, and a lone hull can use
// every thread (hullSplit). Chunk starts are multiples of 16, so the
// vector kernels' lanes fall as they would over the whole range
enum { kChunkTris = 2048, kChunkAlign = 16 };

int hullChunks(int nt) { return std::max(1, (nt + kChunkTris - 1) / kChunkTris); }

// start of chunk i of n items in nc chunks (n for i = nc)
static int chunkAt(int n, int nc, int i) {
  return i >= nc ? n : int(long(n) * i / nc) & ~(kChunkAlign - 1);
}

// one hull's call, shared by the chunks of its stages: the owner's call
// and scratch, the body's motion, the flow (hullFlow), the slamming step
// dt [s], and the chunks' sums (the owner's)
struct HullRun {
  HullCall c;
  HullScr hs;
  const double* vel;
  const Rigid* rig;
  double dir[3], speed, dt;
  int nc;
  ChunkSum* cs;
};

static HullCall hullCall(const HullSet& b, const Sea& sea, int ih, const mjData* d, bool first,
                         HullState* s, CpuState* cs, int slot) {
  const Hull& hl = b.hull[ih];
  HullCall c{b, sea, hl, ih, d->xpos + 3 * hl.body, d->xmat + 9 * hl.body,
             d->xipos + 3 * hl.body, {0, 0, 0}, first, s, cs, slot,
             cs->scr.data() + cs->per * slot, nullptr, triScr(cs, slot, hl.t0)};
  c.tmp = laneTmp(c.sc, sea.waves.size());
  return c;
}

// the running thread's view of r: its own Newton and exp scratch (tmp,
// hs->arg) over the hull's shared scratch
static HullCall chunkCall(const HullRun& r, int slot, HullScr* hs) {
  HullCall c = r.c;
  CpuState* cs = c.cs;
  c.slot = slot;
  c.sc = cs->scr.data() + cs->per * slot;
  c.tmp = laneTmp(c.sc, c.sea.waves.size());
  *hs = r.hs;
  hs->arg = c.sc + (r.hs.arg - r.c.sc);
  return c;
}

// stage 1, chunk i: the vertex stage
static void vertexPart(const HullRun& r, int i, int slot) {
  HullScr hs;
  const HullCall c = chunkCall(r, slot, &hs);
  const int nv = c.hl.nv;
  vertexStage(c, hs, chunkAt(nv, r.nc, i), chunkAt(nv, r.nc, i + 1));
}

// stage 1b, chunk i, vertex integration only: the vertex sums (cpusum.h),
// once every vertex of the hull has its height
static void sumPart(const HullRun& r, int i, int slot) {
  HullScr hs;
  const HullCall c = chunkCall(r, slot, &hs);
  const int nv = c.hl.nv;
  vertexSums(c, hs, chunkAt(nv, r.nc, i), chunkAt(nv, r.nc, i + 1));
}

// stage 2, chunk i: passes 1 and 2 into the chunk's sums (and, on a
// step's first call, the slamming history), pass 2 in pass 1's lanes or
// right after it on the same chunk (cpuhull.h passChunk)
static void passPart(const HullRun& r, int i, int slot) {
  HullScr hs;
  const HullCall c = chunkCall(r, slot, &hs);
  const Hull& hl = c.hl;
  ChunkSum& cs = r.cs[i];
  cs = ChunkSum{};
  Pass1 q{c.b, c.sea, c.s, hs, hl, c.com, r.dir, c.ts, cs.wp, 0, 0, INFINITY, -INFINITY};
  int* wl = c.cs->iscr.data() + c.cs->iper * slot;
  const int k0 = hl.t0 + chunkAt(hl.nt, r.nc, i), k1 = hl.t0 + chunkAt(hl.nt, r.nc, i + 1);
  passChunk(q, Pass2{c, r.vel, *r.rig, r.dir, r.dt, &cs}, k0, k1, wl);
  cs.wet = q.wet;
  cs.wdir = q.wdir;
  cs.lo = q.lo;
  cs.hi = q.hi;
}

// before the stages: false when the whole hull is above the highest crest
// (dryHull); else the guesses' weights, the scratch layout and the flow
static bool hullStart(HullRun* r, const mjData* d) {
  const HullCall& c = r->c;
  const Hull& hl = c.hl;
  HullState* s = c.s;
  if (c.x[2] - hl.rad > s->crest + 1e-6 * (1 + std::fabs(c.x[2]) + hl.rad)) {
    dryHull(hl, c.ih, c.first, s);
    return false;
  }
  if (c.first) s->hvNew[c.ih] = 1;
  hullGuess(*s, c.ih, d->time, r->c.L);
  r->hs = hullScr(c.sea, c.sc, c.cs->mi, hl.nv);
  r->speed = hullFlow(c, r->vel, r->dir);
  r->nc = hullChunks(hl.nt);
  r->cs = c.cs->csum.data() + c.cs->cper * c.slot;
  r->dt = s->hasPrev ? d->time - s->tprev : 0;
  return true;
}

// after the passes: the chunks' sums added in order into w; the viscous
// wrench from the wet extent along the flow, ITTC 1957's C_F at the
// hull's Reynolds number over that wetted length and the form factor's
// mean position (formMean); the simple damping (Cruz 2023), scaled by the
// wet fraction r_s = S_wet / S
static void hullEnd(HullRun* r, double* const w[]) {
  double wet = 0, wdir = 0, lo = INFINITY, hi = -INFINITY, v1[6] = {}, vd[6] = {};
  for (int i = 0; i < r->nc; i++) {
    const ChunkSum& cs = r->cs[i];
    for (int j = 0; j < 6; j++) {
      w[mjbPART_PRESSURE][j] += cs.wp[j];
      w[mjbPART_DRAG][j] += cs.wd[j];
      w[mjbPART_SLAM][j] += cs.ws[j];
      v1[j] += cs.wv1[j];
      vd[j] += cs.wvd[j];
    }
    wet += cs.wet;
    wdir += cs.wdir;
    lo = std::min(lo, cs.lo);
    hi = std::max(hi, cs.hi);
  }
  const Hull& hl = r->c.hl;
  const Sea& sea = r->c.sea;
  const double len = hi > lo ? hi - lo : 0;
  const double cf = ittc57(r->speed * len / sea.nu);
  viscousWrench(sea.rho * cf, hl.par.viscous, lo, len, formMean(wet, wdir, lo, hi), v1, vd,
                w[mjbPART_VISCOUS]);
  r->c.s->hwet[r->c.ih] = wet;
  const double rs = wet / hl.area;
  for (int j = 0; j < 3; j++) {
    w[mjbPART_DAMPING][j] -= hl.par.damp[0] * rs * r->vel[3 + j];
    w[mjbPART_DAMPING][3 + j] -= hl.par.damp[1] * rs * r->vel[j];
  }
}

// one stage of a hull over its chunks, on the pool's threads when it has
// more than one chunk and the pool is free, else here
struct StageJob {
  const HullRun* r;
  void (*part)(const HullRun&, int, int);
};

static void runStage(void* arg, int i, int slot) {
  const StageJob& j = *static_cast<const StageJob*>(arg);
  j.part(*j.r, i, slot);
}

static void stage(Pool* pool, const HullRun& r, void (*part)(const HullRun&, int, int)) {
  StageJob j{&r, part};
  if (r.nc > 1 && pool && poolRun(pool, runStage, &j, r.nc)) return;
  for (int i = 0; i < r.nc; i++) part(r, i, r.c.slot);
}

// forces on one hull: pressure (exact), then Kerner's hydrodynamics; w[p]
// is the body's wrench of force family p; slot picks the owner's scratch.
// pool: run each stage's chunks on its threads (a hull split among them),
// or null: all here
static void hullWrench(const HullSet& b, const Sea& sea, int ih, const mjData* d,
                       const double vel[6], const Rigid& rig, bool first, HullState* s,
                       CpuState* cs, int slot, double* const w[], Pool* pool) {
  HullRun r{hullCall(b, sea, ih, d, first, s, cs, slot), {}, vel, &rig, {0, 0, 0}, 0, 0, 0,
            nullptr};
  if (!hullStart(&r, d)) return;
  stage(pool, r, vertexPart);
  if (vertexMode(sea)) stage(pool, r, sumPart);
  // pass 1: cut, pressure force and torque: Kerner's rho g (eta - z), linear
  // in the cut's depth, exactly (-rho g dA n, -rho g drA x n); or linear
  // wave theory (wavepress.h), which flat water reduces to the same; then
  // pass 2, the hydrodynamic forces, chunk by chunk
  stage(pool, r, passPart);
  hullEnd(&r, w);
}

// hulls [h0, h1), which own whole bodies, with scratch slot i; pool: each
// hull split among its threads (cpuWrench)
struct Job {
  const HullSet* b;
  const Sea* sea;
  const CpuPlan* plan;
  const mjModel* m;
  const mjData* d;
  HullState* s;
  CpuState* cs;
  bool first;
};

static void hullRange(const Job& j, int h0, int h1, int slot, Pool* pool) {
  const HullSet& b = *j.b;
  HullState* s = j.s;
  const int nb6 = 6 * j.m->nbody;
  for (int ih = h0; ih < h1; ih++) {
    const int bd = b.hull[ih].body;
    mjtNum vel[6];  // [angular; linear] at the COM, world frame
    mj_objectVelocity(j.m, j.d, mjOBJ_BODY, bd, vel, 0);
    if (!finite(j.d->xpos + 3 * bd, 3) || !finite(j.d->xmat + 9 * bd, 9) ||
        !finite(j.d->xipos + 3 * bd, 3) || !finite(vel, 6)) {
      s->bad[bd] = 1;
      s->hwet[ih] = NAN;
      if (j.first) {  // the next step's guesses: cold
        const Hull& hl = b.hull[ih];
        std::memset(&s->offNew[2 * hl.v0], 0, 2 * hl.nv * sizeof(float));
        s->hoffNew[2 * ih] = s->hoffNew[2 * ih + 1] = 0;
        s->hvNew[ih] = 0;
      }
      continue;
    }
    double* w[mjbNPART];
    for (int p = 0; p < mjbNPART; p++) w[p] = s->part.data() + p * nb6 + 6 * bd;
    Rigid rig;
    rigidGroup(j.m, j.d, bd, &rig);
    hullWrench(b, *j.sea, ih, j.d, vel, rig, j.first, s, j.cs, slot, w, pool);
  }
}

static void runChunk(void* arg, int c, int slot) {
  const Job& j = *static_cast<const Job*>(arg);
  hullRange(j, j.plan->split[c], j.plan->split[c + 1], slot, nullptr);
}

void cpuWrench(const HullSet& b, const Sea& sea, const CpuPlan& plan, const mjModel* m,
               const mjData* d, HullState* s, CpuState* cs) {
  std::memset(s->part.data(), 0, s->part.size() * sizeof(double));
  std::memset(s->bad.data(), 0, s->bad.size());
  int clock = stepClock(m, d, s);
  if (clock == kNewStep) {
    std::swap(s->prevQ, s->curQ);
    // guesses: the last step's become the older, this one's the last
    std::swap(s->offOld2, s->offOld);
    std::swap(s->offOld, s->off);
    std::swap(s->off, s->offNew);
    std::swap(s->hoffOld2, s->hoffOld);
    std::swap(s->hoffOld, s->hoff);
    std::swap(s->hoff, s->hoffNew);
    std::swap(s->hvOld2, s->hvOld);
    std::swap(s->hvOld, s->hv);
    std::swap(s->hv, s->hvNew);
    s->tgOld2 = s->tgOld;
    s->tgOld = s->tgOff;
    s->tgOff = s->tprev;
  }
  if (clock == kRestart) {
    // label guesses start cold so a rerun repeats the first bit for bit
    for (std::vector<float>* v : {&s->off, &s->offNew, &s->offOld, &s->offOld2}) {
      std::fill(v->begin(), v->end(), 0.0f);
    }
    for (std::vector<double>* v : {&s->hoff, &s->hoffNew, &s->hoffOld, &s->hoffOld2}) {
      std::fill(v->begin(), v->end(), 0.0);
    }
    for (std::vector<char>* v : {&s->hv, &s->hvNew, &s->hvOld, &s->hvOld2}) {
      std::fill(v->begin(), v->end(), 0);
    }
    s->tgOff = s->tgOld = s->tgOld2 = 0;
  }
  // per-call wave constants, and the highest crest: level + sum |A|
  sea.now(d->time, s->wn.data());
  if (!sea.waves.empty()) s->tab.fill(sea, s->wn.data());
  s->crest = sea.level;
  for (const Wave& wv : sea.waves) s->crest += std::fabs(wv.amp);
  // many hulls: chunks of hulls shared among the pool's threads; a chunk
  // owns whole bodies and each thread its own scratch. Fewer hulls than
  // the pool balances (glue.cc threads): one hull after the other, each
  // split among the threads. Either way the result does not depend on who
  // runs what. Another mjData holding the pool: serial
  Job job{&b, &sea, &plan, m, d, s, cs, clock != kMidStep};
  if (plan.pool && plan.splitHulls) {
    hullRange(job, 0, b.hull.size(), 0, plan.pool);
  } else if (!plan.pool || !poolRun(plan.pool, runChunk, &job, int(plan.split.size()) - 1)) {
    hullRange(job, 0, b.hull.size(), 0, nullptr);
  }
  finishWrench(b, m, d, s);
}

}  // namespace mjb
