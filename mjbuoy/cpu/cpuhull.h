// cpuhull: the cpu backend's per-hull data and stages shared by its
// files: cpustate.cc (scratch, step clock, label guesses), cpuvert.cc
// (the vertex stage), cpupass.cc (passes 1 and 2 over triangles) and
// cpu.cc (chunks, threads, the wrench). Internal to mjbuoy
#ifndef MJBUOY_CPUHULL_H_
#define MJBUOY_CPUHULL_H_

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "cpu/cpu.h"
#include "cpu/cpuexp.h"
#include "hull/rigid.h"
#include "mjbuoy.h"
#include "util/vmath.h"

namespace mjb {

inline bool finite(const mjtNum* x, int n) {
  for (int i = 0; i < n; i++) if (!std::isfinite(x[i])) return false;
  return true;
}

inline double dot(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline void cross(const double* a, const double* b, double* c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

// add force f at c (relative to the COM) to the wrench w
inline void add(double* w, const double* f, const double* c) {
  double t[3];
  cross(c, f, t);
  for (int j = 0; j < 3; j++) {
    w[j] += f[j];
    w[3 + j] += t[j];
  }
}

// doubles per wave of e^L at a vertex: real and imaginary part of one
// exponent, two at finite depth (waveint.h; depth does not change after attach)
inline size_t eStride(const Sea& sea) { return sea.depth > 0 ? 4 : 2; }

// the exponents of e^L at stretched height zs [m] into a (t.finite ? 2 n
// : n): k z', then at finite depth -k (z' + 2 h) (waveint.h); e^L is the
// exp of each times the phase's sin and cos (vertexE)
inline void vertexExponents(const WaveTab& t, double zs, double* a) {
  const int n = t.n;
  for (int j = 0; j < n; j++) a[j] = t.k[j] * zs;
  if (t.finite) {
    for (int j = 0; j < n; j++) a[n + j] = -t.k[j] * (zs + 2 * t.depth);
  }
}

// one vertex's e^L into e (per family: nw real parts, then nw imaginary)
// from ex, its exponents exponentiated, and sc, the label search's sin and
// cos of its nw phases (unsorted: t.perm gives each sorted component's)
inline void vertexE(const WaveTab& t, size_t nw, const double* ex, const double* sc,
                    double* e) {
  const int n = t.n, nf = t.finite ? 2 : 1;
  for (int f = 0; f < nf; f++) {
    double* er = e + 2 * f * nw;
    double* ei = er + nw;
    const double* af = ex + f * n;
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

// a sea's constants for the fused e^L kernels (cpuexp.h); fast: vertex
// integration's exp (vExpFast's), else libmvec's (vExp's)
inline EIn eIn(const WaveTab& t, size_t nw, bool fast) {
  return EIn{t.k.data(), t.ident ? nullptr : t.perm.data(), t.n, int(nw), t.finite, t.depth,
             fast};
}

// the fused kernel of a vector level (cpuexp.h: vertexExponents, the exp
// and vertexE in one pass over lanes of components, the same bits);
// nullptr on the scalar level, which keeps those three
typedef void (*ELanesFn)(const EIn&, double, const double*, double*);
inline ELanesFn eLanesFn() {
  switch (simdLevel()) {
    case kSimdAvx512: return eLanesAvx512;
    case kSimdAvx2: return eLanesAvx2;
  }
  return nullptr;
}

// wet vertices whose e^L one vExp call computes (vertexWaves): a call per
// vertex cost more than the exp itself on a one-component sea
enum { kExpChunk = 32 };

// per-hull structure-of-arrays scratch of hullWrench (scratchSize): label
// search points, then per vertex the stretched height, phases and e^L,
// the position relative to the COM (rel, 3 each), the label (lab, 2
// each) and all of these with the height in one record (rec, zipkern.h
// kRec each, 64-byte aligned, for the triangle kernels), by the vertex's
// index in its hull. In the thread's scratch, not the CpuState's: a hull's
// vertex data stays in cache between the vertex stage and the passes and
// is never written back to memory. Then, with vertex integration, the
// vertex sums (VS, 4 each, cpusum.h)
struct HullScr {
  double *X, *Y, *A0, *A1, *Z, *ZS, *SC, *E, *rel, *lab, *rec, *arg, *VS;
};

// one hull's per-triangle results of pass 1 in the thread's scratch
// (TriState): triangle k's wet area at a[k - t0], the rest at 3 (k - t0)
struct TriScr {
  double *a, *c, *n, *u;
  int t0;
  double& area(int k) const { return a[k - t0]; }
  double* at(double* x, int k) const { return x + 3 * (k - t0); }
};

// pass 1's data for one hull (hullWrench): what the triangles read and the
// sums they add to (pressure wrench wp, wet area, its first moment along
// the flow wdir, the extent along the flow)
struct Pass1 {
  const HullSet& b;
  const Sea& sea;
  HullState* s;
  const HullScr& hs;
  const Hull& hl;
  const double* com;
  const double* dir;
  TriScr ts;
  double* wp;
  double wet, wdir, lo, hi;
};

// hullWrench's per-call data: the hulls b and the sea, the body's pose,
// the per-mjData state s and scratch cs, the thread's scratch and the
// label guesses' weights L (guessWeights)
struct HullCall {
  const HullSet& b;
  const Sea& sea;
  const Hull& hl;
  int ih;
  const mjtNum *x, *R, *com;
  double L[3];
  bool first;
  HullState* s;
  CpuState* cs;
  int slot;
  double *sc, *tmp;
  TriScr ts;
};

// the weights L of off, offOld, offOld2 in hull ih's label guesses at time
// t (guessWeights): through the last three steps' offsets (times tgOff,
// tgOld, tgOld2) when all three were solved, the last two, or the last
// alone when fewer were. The offset moves smoothly with the sea and the
// hull, so the quadratic guess is off by O(dt^3) (nanometres at dt = 2 ms)
// where the last step's label was off by O(dt) (millimetres), and Newton,
// converging quadratically, reaches its tolerance in one step instead of
// two; the tolerance is unchanged, so the labels differ only within it
void hullGuess(const HullState& s, int ih, double t, double L[3]);

// p rounded up to a 64-byte line: the lane kernels' scratch arrays start on
// one, so a vector of 8 doubles is one line (a store split over two lines
// is not forwarded to the load that reads it back: each costs a stall)
inline double* lineUp(double* p) {
  return reinterpret_cast<double*>((reinterpret_cast<uintptr_t>(p) + 63) & ~uintptr_t(63));
}

// the Newton scratch in the thread's scratch sc: after the phases (2 per
// wave), on a line (2 + kLaneTmp per wave, seavec.h)
inline double* laneTmp(double* sc, size_t nw) { return lineUp(sc + 2 * nw); }

// whether the lanes integrate by the vertex sums (cpusum.h): vertex
// integration, linear waves and a vector level (the scalar path is exact)
inline bool vertexMode(const Sea& sea) {
  return sea.integration == kIntegrateVertex && !sea.waves.empty() &&
         simdLevel() != kSimdScalar;
}
// the vertex stage's scratch layout in sc (scratchSize)
HullScr hullScr(const Sea& sea, double* sc, size_t mi, int nv);

// the vertex stage of vertices [q0, q1), timed into vsec: positions, the
// label search for all at once (structure of arrays), heights and e^L.
// The hull's scratch hs is shared by the threads of a split hull; tmp and
// hs.arg are the running thread's
void vertexStage(const HullCall& c, const HullScr& hs, int q0, int q1);

// the hull's flow: its COM velocity relative to the water there, its speed
// (returned) and direction dir (body x when at rest)
double hullFlow(const HullCall& c, const double vel[6], double dir[3]);

// the per-triangle scratch of thread slot for a hull whose first triangle is t0
TriScr triScr(CpuState* cs, int slot, int t0);

// Kerner's per-triangle form factor's mean position: 1+k_i = (1+k)(1 +
// sbar - s_i), s in [0, 1] from rear to front along dir, whose
// area-weighted mean is the hull's 1+k: sbar = sum A_i (c_i . dir - lo) /
// (len wet), from pass 1's sums wet = sum A_i and wdir = sum A_i c_i . dir
// and the extent [lo, hi] along dir
double formMean(double wet, double wdir, double lo, double hi);

// pass 2's data for one chunk (passChunk): the call, the body's velocity
// [angular; linear] at the COM, its rigid group, the flow direction, the
// slamming step dt [s], and the chunk's sums
struct Pass2 {
  const HullCall& c;
  const double* vel;
  const Rigid& rig;
  const double* dir;
  double dt;
  ChunkSum* cs;
};

// passes 1 and 2 over the hull's triangles [k0, k1). Pass 1: a triangle
// with no vertex below the surface has no wet part; with a vector level
// the wholly wet ones and the cut ones go through the lanes (trivec.h) by
// kind, else pass1Tri. Pass 2: hydrodynamic forces at each wet centroid,
// with the water's velocity averaged over the wet part (docs/physics.md,
// "Cost"), into p2's drag and slamming wrenches; in pass 1's lanes when
// the exponents allow, else over pass 1's stored results. The viscous
// force needs the hull's wet extent, known only after every chunk, and is
// linear in the position along the flow: the chunk gets the unit viscous
// wrench (rho C_F (1+k_i) = 1) and its first moment along dir, which
// viscousWrench combines (docs/physics.md 4.1). On a step's first call
// each triangle's swept-volume rate into the slamming history (0 when
// dry); wl: 4 (k1 - k0) ints of scratch
void passChunk(Pass1& q, const Pass2& p2, int k0, int k1, int* wl);

// the hull's viscous wrench from the chunks' unit sums v1 = sum (g_i; c_i
// x g_i) and vd = sum (c_i . dir) (g_i; c_i x g_i): with each triangle's
// 1+k_i = (1+k)(1 + sbar - (c_i . dir - lo) / len) (formMean), sum
// rho C_F (1+k_i) g_i = rho C_F (1+k) ((1 + sbar + lo / len) v1 - vd / len),
// or rho C_F (1+k) v1 when the wet extent has no length
void viscousWrench(double rcf, double kv, double lo, double len, double sbar,
                   const double v1[6], const double vd[6], double w[6]);

}  // namespace mjb

#endif  // MJBUOY_CPUHULL_H_
