// cpu backend: passes 1 (cut, pressure) and 2 (viscous, drag, slamming)
// over a chunk of a hull's triangles, scalar reference and lanes
#include <algorithm>
#include <cmath>
#include <cstring>

#include "cpu/cpuhull.h"
#include "hull/hydro.h"
#include "hull/pressure.h"
#include "cpu/trisort.h"
#include "cpu/trivec.h"
#include "util/vmath.h"
#include "sea/waveint.h"
#include "hull/wavepress.h"

namespace mjb {

// the dynamic pressure integrals Pd, Pr (docs/physics.md, "Pressure") and
// the integral of the water's wave velocity V over the wet polygon of wt,
// in closed form on the fan from one of its hull vertices (waveint.h);
// fc the triangle's global vertex indices, v0 the hull's first; Pr only
// with moments
static void wetWaves(const Sea& sea, const WaveTab& t, size_t nw, const Wet& wt, const int* fc,
                     int v0, const HullScr& hs, bool moments, double* Pd, double Pr[3],
                     double V[3]) {
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
    const double *la = hs.lab + 2 * (a - v0), *lb = hs.lab + 2 * (b - v0);
    for (int j = 0; j < 2; j++) lq[i][j] = la[j] + u * (lb[j] - la[j]);
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

TriScr triScr(CpuState* cs, int slot, int t0) {
  const size_t o = 3 * cs->tri.per * slot;
  return {cs->tri.area.data() + cs->tri.per * slot, cs->tri.c.data() + o, cs->tri.n.data() + o,
          cs->tri.u.data() + o, t0};
}

// cut, pressure force and torque of triangle k, the water's mean wave
// velocity over its wet part; the scalar reference of pass1Lanes
static void pass1Tri(Pass1& q, int k) {
  const HullSet& b = q.b;
  const Sea& sea = q.sea;
  HullState* s = q.s;
  const size_t nw = sea.waves.size();
  const bool linear = !sea.kerner && nw > 0;
  const double rg = sea.rho * sea.g;
  double* wp = q.wp;
  const int* fc = b.face.data() + 3 * k;
  double p[3][3], h[3] = {s->h[fc[0]], s->h[fc[1]], s->h[fc[2]]};
  for (int e = 0; e < 3; e++) {
    std::memcpy(p[e], q.hs.rel + 3 * (fc[e] - q.hl.v0), 3 * sizeof(double));
  }
  Wet wt;
  wetTriangle(p, h, &wt);
  if (!std::isfinite(wt.area) || !std::isfinite(wt.dA)) {
    wp[0] += NAN;  // reported by finishWrench, never a silent zero
    q.ts.area(k) = 0;
    return;
  }
  q.ts.area(k) = wt.area > 0 ? wt.area : 0;
  if (!(wt.area > 0)) return;
  const double* n = wt.n;
  double mo[3], P = rg * wt.dA, Pr[3] = {rg * wt.drA[0], rg * wt.drA[1], rg * wt.drA[2]};
  // the water's mean wave velocity over the wet part, and with linear
  // pressure the dynamic part, both in closed form (waveint.h)
  double* uq = q.ts.at(q.ts.u, k);
  for (int j = 0; j < 3; j++) uq[j] = j < 2 ? sea.current[j] : 0;
  if (nw > 0) {
    double Pd, Prd[3], V[3];
    wetWaves(sea, s->tab, nw, wt, fc, q.hl.v0, q.hs, linear, &Pd, Prd, V);
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
  HullState* s = q.s;
  const WaveTab& t = s->tab;
  TriIn in;
  in.face = q.b.face.data();
  in.v0 = q.hl.v0;
  in.rel = q.hs.rel;
  in.h = s->h.data();
  in.lab = q.hs.lab;
  in.rec = q.hs.rec;
  in.zs = q.hs.ZS;
  in.E = q.hs.E;
  in.nw = int(sea.waves.size());
  in.es = int(eStride(sea));
  in.vs = vertexMode(sea) ? q.hs.VS : nullptr;
  in.n = in.nw > 0 ? t.n : 0;
  in.finite = t.finite;
  in.depth = t.depth;
  in.k = t.k.data();
  in.kdx = t.kdx.data();
  in.kdy = t.kdy.data();
  in.gm = t.gm.data();
  in.lc = t.lc;
  in.ldx = t.ldx;
  in.ldy = t.ldy;
  in.lgm = t.lgm;
  for (int f = 0; f < 2; f++) {
    in.wp[f] = t.wp[f].data();
    in.wux[f] = t.wux[f].data();
    in.wuy[f] = t.wuy[f].data();
    in.wz[f] = t.wz[f].data();
  }
  in.linear = !sea.kerner && in.nw > 0;
  // the force bound tol rho g V split evenly among the n_f n series, over
  // at most the hull's whole area (docs/physics.md "Series tolerance")
  const double tv = sea.seriestol * q.hl.vol;
  in.sscale = in.linear && tv > 0 ? 2 * q.hl.area * (t.finite ? 2 : 1) * in.n / tv : 0;
  in.rg = sea.rho * sea.g;
  in.level = sea.level;
  in.comz = q.com[2];
  in.cur[0] = sea.current[0];
  in.cur[1] = sea.current[1];
  for (int j = 0; j < 3; j++) in.dir[j] = q.dir[j];
  in.area = q.ts.a;
  in.c = q.ts.c;
  in.nrm = q.ts.n;
  in.u = q.ts.u;
  in.t0 = q.ts.t0;
  return in;
}

static void pass2Tri(const Pass2& p, int k);

// triangle k on the scalar path, beside lanes that run pass 2 (fused):
// pass 1, then pass 2 when it is wet
static void scalarTri(Pass1& q, const Pass2& p2, bool fused, int k) {
  pass1Tri(q, k);
  if (fused && q.ts.area(k) > 0) pass2Tri(p2, k);
}

// the triangles wl[0, nl) of one kind (trivec.h triLanes) in vector
// lanes, with pass 2 in the same lanes when in.fl is set (p2: its sums);
// those the lanes leave (a piece too coarse for the series, not finite)
// through pass1Tri (and pass2Tri); rest: nl ints of scratch
static void pass1Lanes(Pass1& q, TriIn& in, int kind, const int* wl, int nl, int* rest,
                       const Pass2& p2) {
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
  if (in.fl) {
    for (int j = 0; j < 6; j++) {
      p2.cs->wv1[j] += in.fl->wv1[j];
      p2.cs->wvd[j] += in.fl->wvd[j];
      p2.cs->wd[j] += in.fl->wd[j];
      p2.cs->ws[j] += in.fl->ws[j];
    }
  }
  for (int i = 0; i < in.nrest; i++) scalarTri(q, p2, in.fl != nullptr, rest[i]);
}

// whether pass 2 can run in lanes: every exponent it raises to is 0.5, 1
// or 2 (hydro.cc's powp without the general pow)
static bool flowExponents(const HullParams& par, bool slam) {
  auto ok = [](double p) { return p == 0.5 || p == 1 || p == 2; };
  return ok(par.drag[2]) && ok(par.suction[2]) && (!slam || ok(par.slam[2]));
}

// pass 2's parameters for the lanes (trivec.h)
static FlowIn flowIn(const Pass2& p) {
  const HullCall& c = p.c;
  const Hull& hl = c.hl;
  const HullParams& par = hl.par;
  HullState* s = c.s;
  FlowIn in;
  in.tarea = c.b.tarea.data();
  in.q = c.first ? s->curQ.data() : nullptr;
  in.prevQ = s->prevQ.data();
  for (int j = 0; j < 6; j++) in.vel[j] = p.vel[j];
  for (int j = 0; j < 3; j++) {
    in.com[j] = c.com[j];
    in.dir[j] = p.dir[j];
    in.drag[j] = par.drag[j];
    in.suction[j] = par.suction[j];
    in.gcom[j] = p.rig.com[j];
  }
  in.visc = par.viscous > 0;
  in.vref = par.vref;
  in.slam = s->hasPrev && par.slam[0] > 0 && p.dt > 0;
  in.gain = par.slam[0];
  in.gmax = par.slam[1];
  in.pw = par.slam[2];
  in.share = hl.share;
  in.shull = hl.area;
  in.dt = p.dt;
  in.minv = p.rig.minv;
  for (int j = 0; j < 6; j++) in.iinv[j] = p.rig.iinv[j];
  return in;
}

// pass 1 over the hull's triangles [k0, k1) in lanes (trivec.h) by kind
// (a triangle with no vertex below the surface has no wet part), with
// pass 2 in the same lanes when fused; wl: 4 (k1 - k0) ints of scratch
static void passLanes(Pass1& q, const Pass2& p2, bool fused, int k0, int k1, int* wl) {
  HullState* s = q.s;
  const int nt = k1 - k0;
  // unfused: dry triangles keep the zero area pass 2 reads
  if (!fused) std::memset(&q.ts.area(k0), 0, nt * sizeof(double));
  // lists by kind (trisort.h), nt ints each; the lanes' rest after them
  TriSort ks{q.b.face.data(), s->h.data(), k0, nt, {wl, wl + nt, wl + 2 * nt, wl + 3 * nt},
             {0, 0, 0, 0}};
  if (simdLevel() == kSimdAvx512) {
    sortKindsAvx512(&ks);
  } else {
    sortKindsAvx2(&ks);
  }
  // a height not finite: the scalar path, which reports it
  for (int i = 0; i < ks.n[kKindOther]; i++) scalarTri(q, p2, fused, ks.list[kKindOther][i]);
  TriIn in = triIn(q);
  FlowIn fl;
  if (fused) fl = flowIn(p2);
  in.fl = fused ? &fl : nullptr;
  for (int kind = 0; kind < 3; kind++) {
    if (ks.n[kind] > 0) pass1Lanes(q, in, kind, ks.list[kind], ks.n[kind], wl + 3 * nt, p2);
  }
}

// Kerner's per-triangle form factor's mean position: 1+k_i = (1+k)(1 +
// sbar - s_i), s in [0, 1] from rear to front along dir, whose
// area-weighted mean is the hull's 1+k: sbar = sum A_i (c_i . dir - lo) /
// (len wet), from pass 1's sums wet = sum A_i and wdir = sum A_i c_i . dir
// and the extent [lo, hi] along dir
double formMean(double wet, double wdir, double lo, double hi) {
  const double len = hi > lo ? hi - lo : 0;
  if (!(wet > 0 && len > 0)) return 0;
  return (wdir - lo * wet) / (len * wet);
}

// pass 2's scalar reference for wet triangle k: viscous (unit, and its
// moment along dir: passChunk), drag and slamming at its centroid with
// its relative velocity v; on a step's first call its swept-volume rate
// into the slamming history
static void pass2Tri(const Pass2& p, int k) {
  const HullCall& c = p.c;
  const double* vel = p.vel;
  ChunkSum* cs = p.cs;
  const HullParams& par = c.hl.par;
  HullState* s = c.s;
  const TriScr& ts = c.ts;
  double A = ts.area(k);
  const double* cc = ts.at(ts.c, k);
  const double* n = ts.at(ts.n, k);
  const double* uwk = ts.at(ts.u, k);
  double wc[3], v[3];
  cross(vel, cc, wc);
  for (int j = 0; j < 3; j++) v[j] = vel[3 + j] + wc[j] - uwk[j];
  float qf[3];
  sweptRate(A, v, qf);
  if (c.first) std::memcpy(&s->curQ[3 * k], qf, sizeof qf);
  const double q[3] = {qf[0], qf[1], qf[2]};
  double g[3];
  if (par.viscous > 0) {
    viscousForce(1, 1, 1, A, n, v, g);
    add(cs->wv1, g, cc);
    const double cd = dot(cc, p.dir);
    for (int j = 0; j < 3; j++) g[j] *= cd;
    add(cs->wvd, g, cc);
  }
  dragForce(par.drag, par.suction, par.vref, A, n, v, g);
  add(cs->wd, g, cc);
  if (!s->hasPrev) return;
  // the stopping force is sized by the effective mass of the rigid group
  // at this point along v (docs/physics.md, "Slamming with the effective
  // mass"), not its mass: it acts off the COM
  double sp = std::sqrt(dot(v, v)), meff = 0;
  if (sp > 0) {
    double u[3] = {v[0] / sp, v[1] / sp, v[2] / sp}, pw[3];
    for (int j = 0; j < 3; j++) pw[j] = cc[j] + c.com[j];
    meff = effMass(p.rig, pw, u);
  }
  const float* qpf = &s->prevQ[3 * k];
  const double qp[3] = {qpf[0], qpf[1], qpf[2]};
  slamForce(par.slam[0], par.slam[1], par.slam[2], c.hl.share * meff, c.hl.area, c.b.tarea[k],
            A, v, q, qp, n, p.dt, g);
  add(cs->ws, g, cc);
}

void passChunk(Pass1& q, const Pass2& p2, int k0, int k1, int* wl) {
  const HullCall& c = p2.c;
  HullState* s = c.s;
  // dry triangles' history is zero; wet ones' are written by pass 2
  if (c.first) std::memset(&s->curQ[3 * k0], 0, 3 * (k1 - k0) * sizeof(float));
  const bool lanes = simdLevel() != kSimdScalar;
  const bool fused = lanes && flowExponents(c.hl.par, s->hasPrev);
  if (lanes) {
    passLanes(q, p2, fused, k0, k1, wl);
  } else {
    for (int k = k0; k < k1; k++) {
      const int* fc = q.b.face.data() + 3 * k;
      if (s->h[fc[0]] >= 0 && s->h[fc[1]] >= 0 && s->h[fc[2]] >= 0) {
        q.ts.area(k) = 0;
      } else {
        pass1Tri(q, k);
      }
    }
  }
  if (fused) return;
  for (int k = k0; k < k1; k++) {
    if (q.ts.area(k) > 0) pass2Tri(p2, k);
  }
}

void viscousWrench(double rcf, double kv, double lo, double len, double sbar,
                   const double v1[6], const double vd[6], double w[6]) {
  const double a = len > 0 ? 1 + sbar + lo / len : 1, b = len > 0 ? 1 / len : 0;
  for (int j = 0; j < 6; j++) w[j] += rcf * kv * (a * v1[j] - b * vd[j]);
}

}  // namespace mjb
