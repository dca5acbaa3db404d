// cpu backend: the reference implementation every other backend must match
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "buoy.h"
#include "hydro.h"
#include "pool.h"
#include "pressure.h"
#include "rigid.h"
#include "seavec.h"
#include "trisort.h"
#include "trivec.h"
#include "vmath.h"
#include "waveint.h"
#include "wavepress.h"

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

// doubles per wave of e^L at a vertex: real and imaginary part of one
// exponent, two at finite depth (waveint.h; depth does not change after attach)
static size_t eStride(const Sea& sea) { return sea.depth > 0 ? 4 : 2; }

// wet vertices whose e^L one vExp call computes (vertexWaves): a call per
// vertex cost more than the exp itself on a one-component sea
enum { kExpChunk = 32 };

// per thread: 4 + kLaneTmp per wave for solve() and solveMany() (seavec.h),
// then x, y, a0, a1, z, stretched height z' and 2 per wave (phases) for
// every point of a hull, e^L (eStride per wave) for every vertex of a
// hull, and 2 per wave per vertex of a chunk of exp arguments
static size_t scratchSize(const Buoy& b) {
  size_t nw = std::max(b.wcap, b.cfg.sea.waves.size());
  return (4 + kLaneTmp + 2 * kExpChunk) * nw + (6 + 2 * nw) * maxItems(b) +
         eStride(b.cfg.sea) * nw * maxVerts(b);
}

void makeState(const Buoy& b, State* s) {
  size_t nt = b.face.size() / 3;
  s->wrench.assign(6 * b.m->nbody, 0);
  s->part.assign(mjbNPART * 6 * b.m->nbody, 0);
  s->rel.assign(b.vert.size(), 0);
  s->h.assign(b.vert.size() / 3, 0);
  s->lab.assign(2 * (b.vert.size() / 3), 0);
  s->bad.assign(b.m->nbody, 0);
  s->told.assign(b.m->nbody, 0);
  s->badPart.assign(b.m->nbody * mjbNPART, 0);
  s->toldPart.assign(b.m->nbody * mjbNPART, 0);
  s->dwrench.assign(6 * b.diff.db.size(), 0);
  s->dtold.assign(b.diff.db.size(), 0);
  s->notices.clear();
  s->notices.reserve(4096);
  s->tri.area.assign(nt, 0);
  s->tri.per = 3 * maxTris(b);
  for (auto* a : {&s->tri.c, &s->tri.n, &s->tri.v, &s->tri.u}) {
    a->assign(s->tri.per * std::max(1, b.nthreads), 0);
  }
  s->curA.assign(nt, 0);
  s->prevA.assign(nt, 0);
  s->curV.assign(3 * nt, 0);
  s->prevV.assign(3 * nt, 0);
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

static bool finite(const mjtNum* x, int n) {
  for (int i = 0; i < n; i++) if (!std::isfinite(x[i])) return false;
  return true;
}

static double dot(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross(const double* a, const double* b, double* c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
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

// add force f at c (relative to the COM) to the wrench w
static void add(double* w, const double* f, const double* c) {
  double t[3];
  cross(c, f, t);
  for (int j = 0; j < 3; j++) {
    w[j] += f[j];
    w[3 + j] += t[j];
  }
}

// per-hull structure-of-arrays scratch of hullWrench (scratchSize): label
// search points, then per vertex the stretched height, phases and e^L
struct HullScr {
  double *X, *Y, *A0, *A1, *Z, *ZS, *SC, *E, *arg;
};

// e^L of every component at the wet vertices wq[0, nq) of a hull (waveint.h):
// L = k z' + i theta, and at finite depth also -k (z' + 2 h) + i theta; one
// exp per component and exponent (vectorised, all the chunk's at once), the
// phases' sin and cos from the label search; arg: 2 n kExpChunk scratch
static void vertexWaves(const WaveTab& t, size_t nw, size_t stride, const HullScr& hs,
                        const int* wq, int nq, double* arg) {
  const int n = t.n, nf = t.finite ? 2 : 1;
  for (int c = 0; c < nq; c++) {
    const double zs = hs.ZS[wq[c]];
    double* a = arg + nf * n * c;
    for (int j = 0; j < n; j++) a[j] = t.k[j] * zs;
    if (t.finite) {
      for (int j = 0; j < n; j++) a[n + j] = -t.k[j] * (zs + 2 * t.depth);
    }
  }
  vExp(nf * n * nq, arg, arg);
  for (int c = 0; c < nq; c++) {
    const double* sc = hs.SC + 2 * nw * wq[c];
    const double* a = arg + nf * n * c;
    for (int f = 0; f < nf; f++) {
      double* er = hs.E + stride * nw * wq[c] + 2 * f * nw;
      double* ei = er + nw;
      const double* af = a + f * n;
      if (t.ident) {  // no gather: a loop the compiler vectorises
        for (int j = 0; j < n; j++) {
          er[j] = af[j] * sc[2 * j + 1];
          ei[j] = af[j] * sc[2 * j];
        }
        continue;
      }
      for (int j = 0; j < n; j++) {
        const int i = t.perm[j];
        er[j] = af[j] * sc[2 * i + 1];
        ei[j] = af[j] * sc[2 * i];
      }
    }
  }
}

// the dynamic pressure integrals Pd, Pr (docs/physics.md, "Pressure") and
// the integral of the water's wave velocity V over the wet polygon of wt,
// in closed form on the fan from one of its hull vertices (waveint.h);
// fc the triangle's global vertex indices, v0 the hull's first; Pr only
// with moments
static void wetWaves(const Sea& sea, const WaveTab& t, size_t nw, const Wet& wt, const int* fc,
                     int v0, const double* lab, const HullScr& hs, bool moments, double* Pd,
                     double Pr[3], double V[3]) {
  *Pd = 0;
  for (int j = 0; j < 3; j++) Pr[j] = V[j] = 0;
  double zq[4], lq[4][2];
  int s0 = -1;
  for (int i = 0; i < wt.nq; i++) {
    const int a = fc[wt.qa[i]], b = fc[wt.qb[i]];
    const double u = wt.qt[i];
    if (u == 0 && s0 < 0) s0 = i;
    // a cut point lies on the surface: z' = 0; labels linear along the edge
    zq[i] = u == 0 ? hs.ZS[a - v0] : 0;
    for (int j = 0; j < 2; j++) lq[i][j] = lab[2 * a + j] + u * (lab[2 * b + j] - lab[2 * a + j]);
  }
  if (s0 < 0) return;  // no hull vertex is wet: cannot happen for nq > 0
  const int v = fc[wt.qa[s0]] - v0;
  const double* Ev = hs.E + eStride(sea) * nw * v;
  const double* const E0[4] = {Ev, Ev + nw, t.finite ? Ev + 2 * nw : nullptr,
                               t.finite ? Ev + 3 * nw : nullptr};
  for (int m = 1; m + 1 < wt.nq; m++) {
    const int i1 = (s0 + m) % wt.nq, i2 = (s0 + m + 1) % wt.nq;
    const double q[3][3] = {{wt.q[s0][0], wt.q[s0][1], wt.q[s0][2]},
                            {wt.q[i1][0], wt.q[i1][1], wt.q[i1][2]},
                            {wt.q[i2][0], wt.q[i2][1], wt.q[i2][2]}};
    double u[3], w[3], c[3];
    for (int j = 0; j < 3; j++) {
      u[j] = q[1][j] - q[0][j];
      w[j] = q[2][j] - q[0][j];
    }
    cross(u, w, c);
    const double area = 0.5 * dot(c, wt.n);
    if (!(area > 0)) continue;
    const double zs[3] = {zq[s0], zq[i1], zq[i2]};
    const double l3[3][2] = {{lq[s0][0], lq[s0][1]}, {lq[i1][0], lq[i1][1]},
                             {lq[i2][0], lq[i2][1]}};
    pieceIntegrals(t, sea, E0, hs.SC + 2 * nw * v, q, zs, l3, area, moments, Pd, Pr, V);
  }
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
static void hullGuess(const State& s, int ih, double t, double L[3]) {
  const int n = !s.hv[ih] ? 0 : !s.hvOld[ih] ? 1 : !s.hvOld2[ih] ? 2 : 3;
  const double tk[3] = {s.tgOff, s.tgOld, s.tgOld2};
  guessWeights(t, tk, n, L);
}

// one hull's per-triangle results in the thread's scratch (TriState):
// triangle k's at 3 (k - t0); v is the slamming history curV itself on a
// step's first call (hullWrench)
struct TriScr {
  double *c, *n, *u, *v;
  int t0;
  double* at(double* a, int k) const { return a + 3 * (k - t0); }
};

static TriScr triScr(State* s, int slot, int t0) {
  const size_t o = s->tri.per * slot;
  return {s->tri.c.data() + o, s->tri.n.data() + o, s->tri.u.data() + o, s->tri.v.data() + o,
          t0};
}

// pass 1's data for one hull (hullWrench): what the triangles read and the
// sums they add to (pressure wrench wp, wet area, its first moment along
// the flow wdir, the extent along the flow)
struct Pass1 {
  const Buoy& b;
  const Sea& sea;
  State* s;
  const HullScr& hs;
  const Hull& hl;
  const double* com;
  const double* dir;
  TriScr ts;
  double* wp;
  double wet, wdir, lo, hi;
};

// cut, pressure force and torque of triangle k, the water's mean wave
// velocity over its wet part; the scalar reference of pass1Lanes
static void pass1Tri(Pass1& q, int k) {
  const Buoy& b = q.b;
  const Sea& sea = q.sea;
  State* s = q.s;
  const size_t nw = sea.waves.size();
  const bool linear = !sea.kerner && nw > 0;
  const double rg = sea.rho * sea.g;
  double* wp = q.wp;
  const int* fc = b.face.data() + 3 * k;
  double p[3][3], h[3] = {s->h[fc[0]], s->h[fc[1]], s->h[fc[2]]};
  for (int e = 0; e < 3; e++) std::memcpy(p[e], s->rel.data() + 3 * fc[e], 3 * sizeof(double));
  Wet wt;
  wetTriangle(p, h, &wt);
  if (!std::isfinite(wt.area) || !std::isfinite(wt.dA)) {
    wp[0] += NAN;  // reported by finishWrench, never a silent zero
    s->tri.area[k] = 0;
    return;
  }
  s->tri.area[k] = wt.area > 0 ? wt.area : 0;
  if (!(wt.area > 0)) return;
  const double* n = wt.n;
  double mo[3], P = rg * wt.dA, Pr[3] = {rg * wt.drA[0], rg * wt.drA[1], rg * wt.drA[2]};
  // the water's mean wave velocity over the wet part, and with linear
  // pressure the dynamic part, both in closed form (waveint.h)
  double* uq = q.ts.at(q.ts.u, k);
  for (int j = 0; j < 3; j++) uq[j] = j < 2 ? sea.current[j] : 0;
  if (nw > 0) {
    double Pd, Prd[3], V[3];
    wetWaves(sea, s->tab, nw, wt, fc, q.hl.v0, s->lab.data(), q.hs, linear, &Pd, Prd, V);
    for (int j = 0; j < 3; j++) uq[j] += V[j] / wt.area;
    if (linear) {
      hydrostaticLevel(sea, wt, q.com, &P, Pr);
      P += Pd;
      for (int j = 0; j < 3; j++) Pr[j] += Prd[j];
    }
  }
  cross(Pr, n, mo);
  for (int j = 0; j < 3; j++) {
    wp[j] -= P * n[j];
    wp[3 + j] -= mo[j];
    q.ts.at(q.ts.c, k)[j] = wt.rA[j] / wt.area;
    q.ts.at(q.ts.n, k)[j] = n[j];
  }
  q.wet += wt.area;
  q.wdir += dot(wt.rA, q.dir);
  for (int i = 0; i < wt.nq; i++) {
    double e = dot(wt.q[i], q.dir);
    q.lo = std::min(q.lo, e);
    q.hi = std::max(q.hi, e);
  }
}

// the lane kernels' view of hull q (trivec.h): its vertices, the wave
// table, the pressure model, where per-triangle results go
static TriIn triIn(const Pass1& q) {
  const Sea& sea = q.sea;
  State* s = q.s;
  const WaveTab& t = s->tab;
  TriIn in;
  in.face = q.b.face.data();
  in.v0 = q.hl.v0;
  in.rel = s->rel.data();
  in.h = s->h.data();
  in.lab = s->lab.data();
  in.zs = q.hs.ZS;
  in.E = q.hs.E;
  in.nw = int(sea.waves.size());
  in.es = int(eStride(sea));
  in.n = in.nw > 0 ? t.n : 0;
  in.finite = t.finite;
  in.depth = t.depth;
  in.k = t.k.data();
  in.kdx = t.kdx.data();
  in.kdy = t.kdy.data();
  in.gm = t.gm.data();
  for (int f = 0; f < 2; f++) {
    in.wp[f] = t.wp[f].data();
    in.wux[f] = t.wux[f].data();
    in.wuy[f] = t.wuy[f].data();
    in.wz[f] = t.wz[f].data();
  }
  in.linear = !sea.kerner && in.nw > 0;
  in.rg = sea.rho * sea.g;
  in.level = sea.level;
  in.comz = q.com[2];
  in.cur[0] = sea.current[0];
  in.cur[1] = sea.current[1];
  for (int j = 0; j < 3; j++) in.dir[j] = q.dir[j];
  in.area = s->tri.area.data();
  in.c = q.ts.c;
  in.nrm = q.ts.n;
  in.u = q.ts.u;
  in.t0 = q.ts.t0;
  return in;
}

// the triangles wl[0, nl) of one kind (trivec.h triLanes) in vector
// lanes; those the lanes leave (a piece too coarse for the series, not
// finite) through pass1Tri; rest: nl ints of scratch
static void pass1Lanes(Pass1& q, TriIn& in, int kind, const int* wl, int nl, int* rest) {
  in.idx = wl;
  in.m = nl;
  in.rest = rest;
  if (simdLevel() == kSimdAvx512) {
    triLanesAvx512(&in, kind);
  } else {
    triLanesAvx2(&in, kind);
  }
  for (int j = 0; j < 3; j++) {
    q.wp[j] += in.f[j];
    q.wp[3 + j] += in.t[j];
  }
  q.wet += in.wet;
  q.wdir += in.wdir;
  q.lo = std::min(q.lo, in.lo);
  q.hi = std::max(q.hi, in.hi);
  for (int i = 0; i < in.nrest; i++) pass1Tri(q, rest[i]);
}

// whether pass 2 can run in lanes: every exponent it raises to is 0.5, 1
// or 2 (hydro.cc's powp without the general pow)
static bool flowExponents(const HullParams& par, bool slam) {
  auto ok = [](double p) { return p == 0.5 || p == 1 || p == 2; };
  return ok(par.drag[2]) && ok(par.suction[2]) && (!slam || ok(par.slam[2]));
}

// pass 1's results pass 2 reads: the wet extent along the flow and its
// length, the mean position along it, ITTC's C_F, the slamming dt
struct Flow2 {
  double lo, len, sbar, cf, dt;
};

// pass 2 for the wet triangles wl[0, nf) in vector lanes (trivec.h)
static void pass2Lanes(const Buoy& b, const Hull& hl, State* s, const TriScr& ts,
                       const double vel[6], const double* com, const Rigid& rig,
                       const double dir[3], const Flow2& f2, const int* wl, int nf,
                       double* const w[]) {
  const HullParams& par = hl.par;
  const Sea& sea = b.cfg.sea;
  FlowIn in;
  in.idx = wl;
  in.m = nf;
  in.area = s->tri.area.data();
  in.c = ts.c;
  in.nrm = ts.n;
  in.u = ts.u;
  in.v = ts.v;
  in.t0 = ts.t0;
  in.tarea = b.tarea.data();
  in.prevA = s->prevA.data();
  in.prevV = s->prevV.data();
  for (int j = 0; j < 6; j++) in.vel[j] = vel[j];
  for (int j = 0; j < 3; j++) {
    in.com[j] = com[j];
    in.dir[j] = dir[j];
    in.drag[j] = par.drag[j];
    in.suction[j] = par.suction[j];
    in.gcom[j] = rig.com[j];
  }
  in.visc = par.viscous > 0;
  in.rcf = sea.rho * f2.cf;
  in.kv = par.viscous;
  in.lo = f2.lo;
  in.len = f2.len;
  in.sbar = f2.sbar;
  in.vref = par.vref;
  in.slam = s->hasPrev && par.slam[0] > 0 && f2.dt > 0;
  in.gain = par.slam[0];
  in.gmax = par.slam[1];
  in.pw = par.slam[2];
  in.share = hl.share;
  in.shull = hl.area;
  in.dt = f2.dt;
  in.minv = rig.minv;
  for (int j = 0; j < 6; j++) in.iinv[j] = rig.iinv[j];
  if (simdLevel() == kSimdAvx512) {
    flowLanesAvx512(&in);
  } else {
    flowLanesAvx2(&in);
  }
  for (int j = 0; j < 6; j++) {
    w[mjbPART_VISCOUS][j] += in.wv[j];
    w[mjbPART_DRAG][j] += in.wd[j];
    w[mjbPART_SLAM][j] += in.ws[j];
  }
}

// whole hull above the highest crest the waves can make: all dry, which
// gives exactly what the passes give then (no force, no history)
static void dryHull(const Hull& hl, int ih, bool first, State* s) {
  std::memset(&s->tri.area[hl.t0], 0, hl.nt * sizeof(double));
  if (!first) return;
  std::memset(&s->curA[hl.t0], 0, hl.nt * sizeof(double));
  std::memset(&s->curV[3 * hl.t0], 0, 3 * hl.nt * sizeof(double));
  // the next step's guesses: cold, as after a restart
  std::memset(&s->offNew[2 * hl.v0], 0, 2 * hl.nv * sizeof(float));
  s->hoffNew[2 * ih] = s->hoffNew[2 * ih + 1] = 0;
  s->hvNew[ih] = 0;
}

// hullWrench's per-call data: the body's pose, the thread's scratch and the
// label guesses' weights L (guessWeights)
struct HullCall {
  const Buoy& b;
  const Hull& hl;
  int ih;
  const mjtNum *x, *R, *com;
  double L[3];
  bool first;
  State* s;
  int slot;
  double *sc, *tmp;
  TriScr ts;
};

// the vertex stage's scratch layout in sc (scratchSize)
static HullScr hullScr(const Sea& sea, double* sc, size_t mi, int nv) {
  const size_t nw = sea.waves.size();
  HullScr hs;
  hs.X = sc + (4 + kLaneTmp) * nw;
  hs.Y = hs.X + mi;
  hs.A0 = hs.Y + mi;
  hs.A1 = hs.A0 + mi;
  hs.Z = hs.A1 + mi;
  hs.ZS = hs.Z + mi;
  hs.SC = hs.ZS + mi;
  hs.E = hs.SC + 2 * nw * mi;
  hs.arg = hs.E + eStride(sea) * nw * nv;
  return hs;
}

// vertices [q0, q1) of the hull: body frame -> relative to COM (rel),
// world x, y and the label search's start: the vertex's label offset of
// the last steps (zero after a restart), which moves by mm per step
static void placeVertices(const HullCall& c, const HullScr& hs, int q0, int q1) {
  const Hull& hl = c.hl;
  State* s = c.s;
  const mjtNum *x = c.x, *R = c.R, *com = c.com;
  const double* L = c.L;
  const int v = hl.v0 + q0;
  int qs = q0;  // whole chunks in lanes (seavec.h), the rest here
  if (simdLevel() != kSimdScalar) {
    PlaceIn in{c.b.vert.data() + 3 * v, q1 - q0, {}, {}, {}, {L[0], L[1], L[2]},
               {&s->off[2 * v], &s->offOld[2 * v], &s->offOld2[2 * v]},
               s->rel.data() + 3 * v, hs.X + q0, hs.Y + q0, hs.A0 + q0, hs.A1 + q0};
    for (int j = 0; j < 9; j++) in.R[j] = R[j];
    for (int j = 0; j < 3; j++) in.t[j] = x[j] - com[j], in.com[j] = com[j];
    qs += simdLevel() == kSimdAvx512 ? placeLanesAvx512(in) : placeLanesAvx2(in);
  }
  for (int q = qs; q < q1; q++) {
    const int i = hl.v0 + q;
    const double* p = c.b.vert.data() + 3 * i;
    double* r = s->rel.data() + 3 * i;
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
  State* s = c.s;
  const double zc = c.com[2];
  const int v = hl.v0 + q0;
  int qs = q0;
  if (simdLevel() != kSimdScalar) {
    HeightIn in{q1 - q0, s->rel.data() + 3 * v, zc, hs.X + q0, hs.Y + q0, hs.A0 + q0,
                hs.A1 + q0, hs.Z + q0, c.first, s->lab.data() + 2 * v, s->offNew.data() + 2 * v,
                s->h.data() + v};
    qs += simdLevel() == kSimdAvx512 ? heightLanesAvx512(in) : heightLanesAvx2(in);
  }
  for (int q = qs; q < q1; q++) {
    const int i = hl.v0 + q;
    s->lab[2 * i] = hs.A0[q];
    s->lab[2 * i + 1] = hs.A1[q];
    if (c.first) {
      // (a label not finite, which the height reports, guesses nothing)
      const double o0 = hs.A0[q] - hs.X[q], o1 = hs.A1[q] - hs.Y[q];
      const bool ok = std::isfinite(o0) && std::isfinite(o1);
      s->offNew[2 * i] = ok ? float(o0) : 0;
      s->offNew[2 * i + 1] = ok ? float(o1) : 0;
    }
    s->h[i] = s->rel[3 * i + 2] + zc - hs.Z[q];
  }
}

// at the wet vertices of [q0, q1) (h <= 0, a wet piece's corner 0) the
// stretched height and e^L, kExpChunk vertices per vertexWaves call
static void wetVertices(const HullCall& c, const HullScr& hs, int q0, int q1) {
  const Hull& hl = c.hl;
  const Sea& sea = c.b.cfg.sea;
  State* s = c.s;
  const size_t nw = sea.waves.size();
  if (nw == 0) return;
  const double zc = c.com[2];
  int wq[kExpChunk], nq = 0;
  for (int q = q0; q < q1; q++) {
    const int i = hl.v0 + q;
    if (!(s->h[i] <= 0)) continue;
    hs.ZS[q] = stretch(sea.depth, s->rel[3 * i + 2] + zc - sea.level, hs.Z[q] - sea.level);
    wq[nq++] = q;
    if (nq == kExpChunk) {
      vertexWaves(s->tab, nw, eStride(sea), hs, wq, nq, hs.arg);
      nq = 0;
    }
  }
  if (nq > 0) vertexWaves(s->tab, nw, eStride(sea), hs, wq, nq, hs.arg);
}

// the vertex stage of vertices [q0, q1), timed into vsec: positions, the
// label search for all at once (structure of arrays), heights and e^L.
// The hull's scratch hs is shared by the threads of a split hull; tmp and
// hs.arg are the running thread's
static void vertexStage(const HullCall& c, const HullScr& hs, int q0, int q1) {
  const auto tv0 = std::chrono::steady_clock::now();
  State* s = c.s;
  const size_t nw = c.b.cfg.sea.waves.size();
  placeVertices(c, hs, q0, q1);
  s->niter[c.slot] += c.b.cfg.sea.solveMany(s->wn.data(), q1 - q0, hs.X + q0, hs.Y + q0,
                                            hs.A0 + q0, hs.A1 + q0, hs.Z + q0,
                                            hs.SC + 2 * nw * q0, c.tmp);
  s->nsolve[c.slot] += q1 - q0;
  vertexOut(c, hs, q0, q1);
  wetVertices(c, hs, q0, q1);
  s->vsec[c.slot] += std::chrono::duration<double>(std::chrono::steady_clock::now() - tv0).count();
}

// the hull's flow: its COM velocity relative to the water there, its speed
// (returned) and direction dir (body x when at rest)
static double hullFlow(const HullCall& c, const double vel[6], double dir[3]) {
  const Sea& sea = c.b.cfg.sea;
  State* s = c.s;
  const int ih = c.ih;
  const mjtNum* com = c.com;
  const double* L = c.L;
  double uw[3], vr[3];
  const double *o = &s->hoff[2 * ih], *o1 = &s->hoffOld[2 * ih], *o2 = &s->hoffOld2[2 * ih];
  double a[2] = {com[0] + (L[0] * o[0] + L[1] * o1[0] + L[2] * o2[0]),
                 com[1] + (L[0] * o[1] + L[1] * o1[1] + L[2] * o2[1])};
  int nit = 0;
  double hz = sea.solve(s->wn.data(), com[0], com[1], a, c.sc, c.tmp, &nit);
  s->niter[c.slot] += nit;
  s->nsolve[c.slot]++;
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

// pass 1 over the hull's triangles [k0, k1): a triangle with no vertex
// below the surface has no wet part; with a vector level the wholly wet
// ones and the cut ones go through the lanes (trivec.h) by kind, else
// pass1Tri; wl: 4 (k1 - k0) ints of scratch
static void pass1Chunk(Pass1& q, int k0, int k1, int* wl) {
  State* s = q.s;
  const int nt = k1 - k0;
  if (simdLevel() == kSimdScalar) {
    for (int k = k0; k < k1; k++) {
      const int* fc = q.b.face.data() + 3 * k;
      if (s->h[fc[0]] >= 0 && s->h[fc[1]] >= 0 && s->h[fc[2]] >= 0) {
        s->tri.area[k] = 0;
      } else {
        pass1Tri(q, k);
      }
    }
    return;
  }
  // dry triangles keep the zero area; the others are written below
  std::memset(&s->tri.area[k0], 0, nt * sizeof(double));
  // lists by kind (trisort.h), nt ints each; the lanes' rest after them
  TriSort ks{q.b.face.data(), s->h.data(), k0, nt, {wl, wl + nt, wl + 2 * nt, wl + 3 * nt},
             {0, 0, 0, 0}};
  if (simdLevel() == kSimdAvx512) {
    sortKindsAvx512(&ks);
  } else {
    sortKindsAvx2(&ks);
  }
  // a height not finite: the scalar path, which reports it
  for (int i = 0; i < ks.n[kKindOther]; i++) pass1Tri(q, ks.list[kKindOther][i]);
  TriIn in = triIn(q);
  for (int kind = 0; kind < 3; kind++) {
    if (ks.n[kind] > 0) pass1Lanes(q, in, kind, ks.list[kind], ks.n[kind], wl + 3 * nt);
  }
}

// Kerner's per-triangle form factor's mean position: 1+k_i = (1+k)(1 +
// sbar - s_i), s in [0, 1] from rear to front along dir, whose
// area-weighted mean is the hull's 1+k: sbar = sum A_i (c_i . dir - lo) /
// (len wet), from pass 1's sums wet = sum A_i and wdir = sum A_i c_i . dir
// and the extent [lo, hi] along dir
static double formMean(double wet, double wdir, double lo, double hi) {
  const double len = hi > lo ? hi - lo : 0;
  if (!(wet > 0 && len > 0)) return 0;
  return (wdir - lo * wet) / (len * wet);
}

// pass 2's scalar reference for wet triangle k: viscous, drag and slamming
// at its centroid with its relative velocity v (stored at ts.v)
static void pass2Tri(const HullCall& c, const double vel[6], const Rigid& rig,
                     const double dir[3], const Flow2& f2, int k, double* const w[]) {
  const HullParams& par = c.hl.par;
  State* s = c.s;
  const TriScr& ts = c.ts;
  double* v = ts.at(ts.v, k);
  double A = s->tri.area[k];
  const double* cc = ts.at(ts.c, k);
  const double* n = ts.at(ts.n, k);
  const double* uwk = ts.at(ts.u, k);
  double wc[3];
  cross(vel, cc, wc);
  for (int j = 0; j < 3; j++) v[j] = vel[3 + j] + wc[j] - uwk[j];
  double g[3];
  if (par.viscous > 0) {
    double sk = f2.len > 0 ? (dot(cc, dir) - f2.lo) / f2.len : f2.sbar;
    viscousForce(c.b.cfg.sea.rho, f2.cf, par.viscous * (1 + f2.sbar - sk), A, n, v, g);
    add(w[mjbPART_VISCOUS], g, cc);
  }
  dragForce(par.drag, par.suction, par.vref, A, n, v, g);
  add(w[mjbPART_DRAG], g, cc);
  if (!s->hasPrev) return;
  // the stopping force is sized by the effective mass of the rigid group
  // at this point along v (docs/physics.md, "Slamming with the effective
  // mass"), not its mass: it acts off the COM
  double sp = std::sqrt(dot(v, v)), meff = 0;
  if (sp > 0) {
    double u[3] = {v[0] / sp, v[1] / sp, v[2] / sp}, pw[3];
    for (int j = 0; j < 3; j++) pw[j] = cc[j] + c.com[j];
    meff = effMass(rig, pw, u);
  }
  slamForce(par.slam[0], par.slam[1], par.slam[2], c.hl.share * meff, c.hl.area, c.b.tarea[k],
            A, v, s->prevA[k], &s->prevV[3 * k], n, f2.dt, g);
  add(w[mjbPART_SLAM], g, cc);
}

// pass 2 over triangles [k0, k1): hydrodynamic forces at each wet
// centroid, with the water's velocity averaged over the wet part (pass 1;
// docs/physics.md, "Cost"); with a vector level in lanes (trivec.h) when
// the exponents allow; dry triangles get v = 0; wl: k1 - k0 ints of scratch
static void pass2Chunk(const HullCall& c, const double vel[6], const Rigid& rig,
                       const double dir[3], const Flow2& f2, int k0, int k1, int* wl,
                       double* const w[]) {
  const Hull& hl = c.hl;
  State* s = c.s;
  const bool lanes = simdLevel() != kSimdScalar && flowExponents(hl.par, s->hasPrev);
  int nf = 0;
  if (lanes) {  // the lanes write v of the wet triangles
    std::memset(c.ts.at(c.ts.v, k0), 0, 3 * (k1 - k0) * sizeof(double));
    for (int k = k0; k < k1; k++) {
      wl[nf] = k;
      nf += s->tri.area[k] > 0;
    }
    if (nf > 0) pass2Lanes(c.b, hl, s, c.ts, vel, c.com, rig, dir, f2, wl, nf, w);
    return;
  }
  for (int k = k0; k < k1; k++) {
    if (s->tri.area[k] > 0) {
      pass2Tri(c, vel, rig, dir, f2, k, w);
    } else {
      double* v = c.ts.at(c.ts.v, k);
      v[0] = v[1] = v[2] = 0;
    }
  }
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
// and scratch, the body's motion, the flow (hullFlow), pass 1's results
// pass 2 reads, and the chunks' sums (the owner's)
struct HullRun {
  HullCall c;
  HullScr hs;
  const double* vel;
  const Rigid* rig;
  double dir[3], speed, wet;
  Flow2 f2;
  int nc;
  ChunkSum* cs;
};

static HullCall hullCall(const Buoy& b, int ih, const mjData* d, bool first, State* s,
                         int slot) {
  const Hull& hl = b.hull[ih];
  HullCall c{b, hl, ih, d->xpos + 3 * hl.body, d->xmat + 9 * hl.body, d->xipos + 3 * hl.body,
             {0, 0, 0}, first, s, slot, s->scr.data() + s->per * slot, nullptr,
             triScr(s, slot, hl.t0)};
  c.tmp = c.sc + 2 * b.cfg.sea.waves.size();
  return c;
}

// the running thread's view of r: its own Newton and exp scratch (tmp,
// hs->arg) over the hull's shared scratch
static HullCall chunkCall(const HullRun& r, int slot, HullScr* hs) {
  HullCall c = r.c;
  State* s = c.s;
  c.slot = slot;
  c.sc = s->scr.data() + s->per * slot;
  c.tmp = c.sc + 2 * c.b.cfg.sea.waves.size();
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

// stage 2, chunk i: pass 1 into the chunk's sums
static void pass1Part(const HullRun& r, int i, int slot) {
  HullScr hs;
  const HullCall c = chunkCall(r, slot, &hs);
  const Hull& hl = c.hl;
  ChunkSum& cs = r.cs[i];
  for (int j = 0; j < 6; j++) cs.wp[j] = 0;
  Pass1 q{c.b, c.b.cfg.sea, c.s, hs, hl, c.com, r.dir, c.ts, cs.wp, 0, 0, INFINITY, -INFINITY};
  int* wl = c.s->iscr.data() + c.s->iper * slot;
  pass1Chunk(q, hl.t0 + chunkAt(hl.nt, r.nc, i), hl.t0 + chunkAt(hl.nt, r.nc, i + 1), wl);
  cs.wet = q.wet;
  cs.wdir = q.wdir;
  cs.lo = q.lo;
  cs.hi = q.hi;
}

// stage 3, chunk i: pass 2 into the chunk's sums; on a step's first call
// the wet areas into the slamming history
static void pass2Part(const HullRun& r, int i, int slot) {
  HullScr hs;
  const HullCall c = chunkCall(r, slot, &hs);
  const Hull& hl = c.hl;
  ChunkSum& cs = r.cs[i];
  for (int j = 0; j < 6; j++) cs.wv[j] = cs.wd[j] = cs.ws[j] = 0;
  double* w[mjbNPART] = {};
  w[mjbPART_VISCOUS] = cs.wv;
  w[mjbPART_DRAG] = cs.wd;
  w[mjbPART_SLAM] = cs.ws;
  const int k0 = hl.t0 + chunkAt(hl.nt, r.nc, i), k1 = hl.t0 + chunkAt(hl.nt, r.nc, i + 1);
  int* wl = c.s->iscr.data() + c.s->iper * slot;
  pass2Chunk(c, r.vel, *r.rig, r.dir, r.f2, k0, k1, wl, w);
  double* area = c.s->tri.area.data();
  if (c.first) std::memcpy(&c.s->curA[k0], area + k0, (k1 - k0) * sizeof(double));
}

// before the stages: false when the whole hull is above the highest crest
// (dryHull); else the guesses' weights, the scratch layout and the flow
static bool hullStart(HullRun* r, const mjData* d) {
  const HullCall& c = r->c;
  const Hull& hl = c.hl;
  State* s = c.s;
  if (c.x[2] - hl.rad > s->crest + 1e-6 * (1 + std::fabs(c.x[2]) + hl.rad)) {
    dryHull(hl, c.ih, c.first, s);
    return false;
  }
  if (c.first) s->hvNew[c.ih] = 1;
  hullGuess(*s, c.ih, d->time, r->c.L);
  r->hs = hullScr(c.b.cfg.sea, c.sc, s->mi, hl.nv);
  r->speed = hullFlow(c, r->vel, r->dir);
  r->nc = hullChunks(hl.nt);
  r->cs = s->csum.data() + s->cper * c.slot;
  return true;
}

// between passes 1 and 2: the chunks' pressure wrenches added in order
// into w, and what pass 2 reads: the wet extent along the flow, ITTC
// 1957's C_F at the hull's Reynolds number over that wetted length, the
// form factor's mean position (formMean), the slamming dt
static void hullMid(HullRun* r, const mjData* d, double* const w[]) {
  State* s = r->c.s;
  double wet = 0, wdir = 0, lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i < r->nc; i++) {
    const ChunkSum& cs = r->cs[i];
    for (int j = 0; j < 6; j++) w[mjbPART_PRESSURE][j] += cs.wp[j];
    wet += cs.wet;
    wdir += cs.wdir;
    lo = std::min(lo, cs.lo);
    hi = std::max(hi, cs.hi);
  }
  const double len = hi > lo ? hi - lo : 0;
  const double cf = ittc57(r->speed * len / r->c.b.cfg.sea.nu);
  r->wet = wet;
  r->f2 = Flow2{lo, len, formMean(wet, wdir, lo, hi), cf, s->hasPrev ? d->time - s->tprev : 0};
  // slamming history: the last call at this step's time; pass 2 writes
  // the velocities there itself (no copy of 24 bytes a triangle)
  if (r->c.first) r->c.ts.v = &s->curV[3 * r->c.hl.t0];
}

// after pass 2: the chunks' wrenches added in order, and the simple
// damping (Cruz 2023), scaled by the wet fraction r_s = S_wet / S
static void hullEnd(const HullRun& r, double* const w[]) {
  for (int i = 0; i < r.nc; i++) {
    for (int j = 0; j < 6; j++) {
      w[mjbPART_VISCOUS][j] += r.cs[i].wv[j];
      w[mjbPART_DRAG][j] += r.cs[i].wd[j];
      w[mjbPART_SLAM][j] += r.cs[i].ws[j];
    }
  }
  const HullParams& par = r.c.hl.par;
  const double rs = r.wet / r.c.hl.area;
  for (int j = 0; j < 3; j++) {
    w[mjbPART_DAMPING][j] -= par.damp[0] * rs * r.vel[3 + j];
    w[mjbPART_DAMPING][3 + j] -= par.damp[1] * rs * r.vel[j];
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
static void hullWrench(const Buoy& b, int ih, const mjData* d, const double vel[6],
                       const Rigid& rig, bool first, State* s, int slot, double* const w[],
                       Pool* pool) {
  HullRun r{hullCall(b, ih, d, first, s, slot), {}, vel, &rig, {0, 0, 0}, 0, 0, {}, 0, nullptr};
  if (!hullStart(&r, d)) return;
  stage(pool, r, vertexPart);
  // pass 1: cut, pressure force and torque: Kerner's rho g (eta - z), linear
  // in the cut's depth, exactly (-rho g dA n, -rho g drA x n); or linear
  // wave theory (wavepress.h), which flat water reduces to the same
  stage(pool, r, pass1Part);
  hullMid(&r, d, w);
  stage(pool, r, pass2Part);
  hullEnd(r, w);
}

// hulls [h0, h1), which own whole bodies, with scratch slot i; pool: each
// hull split among its threads (cpuWrench)
struct Job {
  const Buoy* b;
  const mjModel* m;
  const mjData* d;
  State* s;
  bool first;
};

static void hullRange(const Job& j, int h0, int h1, int slot, Pool* pool) {
  const Buoy& b = *j.b;
  State* s = j.s;
  const int nb6 = 6 * j.m->nbody;
  for (int ih = h0; ih < h1; ih++) {
    const int bd = b.hull[ih].body;
    mjtNum vel[6];  // [angular; linear] at the COM, world frame
    mj_objectVelocity(j.m, j.d, mjOBJ_BODY, bd, vel, 0);
    if (!finite(j.d->xpos + 3 * bd, 3) || !finite(j.d->xmat + 9 * bd, 9) ||
        !finite(j.d->xipos + 3 * bd, 3) || !finite(vel, 6)) {
      s->bad[bd] = 1;
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
    hullWrench(b, ih, j.d, vel, rig, j.first, s, slot, w, pool);
  }
}

static void runChunk(void* arg, int c, int slot) {
  const Job& j = *static_cast<const Job*>(arg);
  hullRange(j, j.b->split[c], j.b->split[c + 1], slot, nullptr);
}

void noteBad(const Buoy& b, const mjModel* m, const mjData* d, State* s) {
  for (int bd : b.body) {
    if (!s->bad[bd] || s->told[bd]) continue;
    s->told[bd] = 1;
    char line[256];
    std::snprintf(line, sizeof(line),
                  "body \"%s\": position or velocity not finite at t = %g s; "
                  "mjbuoy adds no force to it\n", m->names + m->name_bodyadr[bd], d->time);
    // within the capacity reserved in makeState: no allocation while stepping
    if (s->notices.size() + std::strlen(line) < s->notices.capacity()) s->notices += line;
  }
}

void cpuWrench(const Buoy& b, const mjModel* m, const mjData* d, State* s) {
  std::memset(s->part.data(), 0, s->part.size() * sizeof(double));
  std::memset(s->bad.data(), 0, s->bad.size());
  int clock = stepClock(m, d, s);
  if (clock == kNewStep) {
    std::swap(s->prevA, s->curA);
    std::swap(s->prevV, s->curV);
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
  const Sea& sea = b.cfg.sea;
  sea.now(d->time, s->wn.data());
  if (!sea.waves.empty()) s->tab.fill(sea, s->wn.data());
  s->crest = sea.level;
  for (const Wave& wv : sea.waves) s->crest += std::fabs(wv.amp);
  // many hulls: chunks of hulls shared among the pool's threads; a chunk
  // owns whole bodies and each thread its own scratch. Fewer hulls than
  // the pool balances (glue.cc threads): one hull after the other, each
  // split among the threads. Either way the result does not depend on who
  // runs what. Another mjData holding the pool: serial
  Job job{&b, m, d, s, clock != kMidStep};
  if (b.pool && b.splitHulls) {
    hullRange(job, 0, b.hull.size(), 0, b.pool);
  } else if (!b.pool || !poolRun(b.pool, runChunk, &job, int(b.split.size()) - 1)) {
    hullRange(job, 0, b.hull.size(), 0, nullptr);
  }
  finishWrench(b, m, d, s);
}

void finishWrench(const Buoy& b, const mjModel* m, const mjData* d, State* s) {
  static const char* kFamily[mjbNPART] = {"pressure", "viscous", "drag", "slamming", "damping"};
  noteBad(b, m, d, s);
  const int nb6 = 6 * m->nbody;
  std::memset(s->wrench.data(), 0, s->wrench.size() * sizeof(double));
  for (int bd : b.body) {
    for (int p = 0; p < mjbNPART; p++) {
      double* wp = s->part.data() + p * nb6 + 6 * bd;
      char& bad = s->badPart[mjbNPART * bd + p];
      bad = !s->bad[bd] && !finite(wp, 6);
      if (s->bad[bd] || bad) std::memset(wp, 0, 6 * sizeof(double));
      if (bad && !s->toldPart[mjbNPART * bd + p]) {
        s->toldPart[mjbNPART * bd + p] = 1;
        char line[256];
        std::snprintf(line, sizeof(line),
                      "body \"%s\": %s force not finite at t = %g s (an intermediate "
                      "overflowed or was NaN); mjbuoy leaves it out of the wrench\n",
                      m->names + m->name_bodyadr[bd], kFamily[p], d->time);
        // within the capacity reserved in makeState: no allocation while stepping
        if (s->notices.size() + std::strlen(line) < s->notices.capacity()) s->notices += line;
      }
      for (int j = 0; j < 6; j++) s->wrench[6 * bd + j] += wp[j];
    }
  }
}

}  // namespace mjb
