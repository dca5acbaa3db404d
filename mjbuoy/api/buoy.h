// buoy: what mjbuoy keeps per attached model (static) and per mjData (state)
#ifndef MJBUOY_BUOY_H_
#define MJBUOY_BUOY_H_

#include <string>
#include <utility>
#include <vector>

#include <mujoco/mujoco.h>

#include "api/config.h"
#include "hull/hullset.h"
#include "hull/windload.h"
#include "radiation/diffract.h"
#include "mjbuoy.h"
#include "mooring/mooring.h"
#include "radiation/radcache.h"
#include "radiation/radiation.h"
#include "api/sensor.h"
#include "sea/waveint.h"

namespace mjb {

struct GlBackend;
struct Pool;

// static data of one attached model, built once by mjb_attach: its hulls
// (the HullSet base: m, hull, vert, face, tarea, body) and the rest
struct Buoy : HullSet {
  Config cfg;
  std::vector<Sensor> sensor;  // user sensors mjbuoy fills (sensor.h)
  std::string warnings;        // newline-separated
  std::string renderer;
  GlBackend* gl = nullptr;     // gl backend, when it runs
  // cpu backend threads: chunk c is hulls [split[c], split[c + 1]); the
  // pool has nthreads - 1 workers (none when the scene is small);
  // splitHulls: too few hulls to balance, so each hull's chunks
  // (hullChunks) are shared among the threads instead
  int nthreads = 1;
  std::vector<int> split;
  bool splitHulls = false;
  Pool* pool = nullptr;
  size_t wcap = 0;             // wave components reserved (cpu scratch, gl buffers)
  Wind wind;                   // hull/windload.h
  Radiation rad;               // radiation.h: bodies with added mass and memory
  // the panel solver's coefficients set at attach (radattach.cc): body id
  // and its HydroCoef (about the body COM, body axes), for mjbuoy-hydro
  std::vector<std::pair<int, HydroCoef>> coef;
  Diffraction diff;            // diffract.h: diffraction excitation of those bodies
  RadCacheStats radcache;      // the panel solver's cache at attach (radcache.h)
  Mooring moor;                // mooring lines and the seabed (moorconfig.h)
};

// the static data of an attached model (glue.cc; tools only)
const Buoy* buoyOf(const mjbBuoy* b);

// one chunk of a hull's sums (cpu.cc hullChunks): pass 1's pressure
// wrench [N, N m], wet area [m^2], its first moment along the flow [m^3]
// and the wet extent along it [m]; pass 2's unit viscous wrench and its
// first moment along the flow (cpuhull.h passChunk), drag and slamming
// wrenches
struct ChunkSum {
  double wp[6], wet, wdir, lo, hi;
  double wv1[6], wvd[6], wd[6], ws[6];
};

// wet triangle data of one call, per thread for the largest hull, reused
// hull after hull so it stays in cache (cpuhull.h TriScr)
struct TriState {
  std::vector<double> area;    // wet area [m^2], 1 each
  std::vector<double> c;       // wet centroid relative to the body COM, 3 each [m]
  std::vector<double> n;       // outward unit normal, 3 each
  std::vector<double> u;       // water velocity, mean over the wet part, 3 each [m/s]
  size_t per = 0;              // triangles per thread
};

// per-mjData state; sized at creation, never resized while stepping
struct State {
  std::vector<double> wrench;  // nbody x 6: force, torque about xipos (world)
  std::vector<double> part;    // mjbNPART x nbody x 6: wrench by force family
  std::vector<double> h;       // vertex heights above the surface [m]
  // label minus position of each vertex, 2 each [m], the guess of the label
  // search: off is read, from the first call of the previous step (zero
  // after a restart) so every call of a step sees the same guess and gives
  // the same bits; offNew is written by the first call of this step. In
  // float: a guess needs no more (its 1e-8 m resolution of an offset of
  // a metre is far below what one Newton step corrects), and the vertex
  // stage streams them every step
  std::vector<float> off, offNew;
  std::vector<double> hoff, hoffNew;  // the same for each hull's COM [m]
  // the two steps before off's (offOld, then offOld2; hoffOld, hoffOld2),
  // so the guess extrapolates the last three steps' offsets in time
  // (cpustate.cc guessWeights); per hull whether offNew, off, offOld, offOld2
  // hold a solve (1) or are cold (0), and the times off, offOld, offOld2
  // were taken [s]
  std::vector<float> offOld, offOld2;
  std::vector<double> hoffOld, hoffOld2;
  std::vector<char> hv, hvNew, hvOld, hvOld2;
  double tgOff = 0, tgOld = 0, tgOld2 = 0;  // (the gl backend's too: offbuf)
  std::vector<WaveNow> wn;     // wave constants of this call
  WaveTab tab;                 // the same by wave number, for waveint.h
  // per thread: Newton and structure-of-arrays scratch (cpustate.cc
  // scratchSize), per doubles each
  std::vector<double> scr;
  size_t per = 0, mi = 0;
  // per thread: triangle indices for the lane kernels (cpupass.cc, trivec.h),
  // 4 per triangle of the largest hull
  std::vector<int> iscr;
  size_t iper = 0;
  // per thread: the chunk sums of the hull it owns, cper each
  std::vector<ChunkSum> csum;
  size_t cper = 0;
  // per thread: surface solves done and Newton steps they took (cpu
  // backend; mjbuoy-bench reports steps per solve)
  std::vector<long> nsolve, niter;
  // per thread: wall seconds in the vertex stage (cpu backend: transform,
  // surface search, e^L at wet vertices; mjbuoy-bench reports it)
  std::vector<double> vsec;
  double crest = 0;            // highest possible surface height [m]
  std::vector<char> bad;       // per body: state not finite in the last call
  std::vector<char> told;      // per body: already named in notices
  // per body and force family (body-major): non-finite in the last call,
  // already named in notices
  std::vector<char> badPart, toldPart;
  std::string notices;         // capacity reserved up front
  TriState tri;                // this call
  // per hull: its wet area at the last call [m^2] (wetted_area sensors;
  // NaN when its body's state was not finite)
  std::vector<double> hwet;
  // slamming history: each triangle's swept-volume rate Q = A v [m^3/s],
  // 3 each, at the last call at the current step's time (cur) and at the
  // previous step's (prev). In float (hydro.h sweptRate): Gamma needs no
  // more, and it is the one per-triangle array streamed every step
  std::vector<float> curQ, prevQ;
  long key = -1;               // mjTIMER_STEP count at the last call (-1: none yet)
  double tcur = 0, tprev = 0;  // times of those steps [s]
  bool hasPrev = false;
  unsigned slambuf[2] = {0, 0};  // gl backend: history buffers, [slamcur] = this step's
  int slamcur = 0;
  // gl backend: the label offsets' ring (shaders/pipeline.h B_OFF), the
  // slot this step's first call writes, and how many steps before it the
  // ring holds (0 to 2; their times tgOff, tgOld)
  unsigned offbuf = 0;
  int offslot = 0, offn = 0;
  // stamp of the mjData this state last served (glue.cc, docs/robustness.md):
  // its buffer and its fwdVelocity count (the stage mjcb_passive runs in)
  // at the last callback; with tcur above. A count or time below these, or
  // another buffer, means d is a new mjData at a recycled address or reset
  const void* buf = nullptr;
  long vcount = -1;
  RadState rad;                // radiation.h: memory history, qM stamp
  // diffraction (diffract.h): per body of Buoy::diff its world wrench at
  // the COM, and whether a non-finite one was named
  std::vector<double> dwrench;
  std::vector<char> dtold;
  MoorState moor;              // mooring lines (moorstep.h)
};

// slamming clock (cpustate.cc): kSameStep for another call at the current step's
// time (it records the history again: the last evaluation at a time wins),
// kNewStep when time has moved on by a step since (the caller moves the
// current history to the previous), kRestart after mj_resetData or time
// going backwards (no previous history), kMidStep for an intermediate RK4
// stage (records nothing)
enum { kSameStep = 0, kNewStep, kRestart, kMidStep };
int stepClock(const mjModel* m, const mjData* d, State* s);

// the weights L of the last n (0 to 3) steps' label offsets, taken at times
// tk[0] > tk[1] > tk[2] [s], in the label guess at time t [s] (cpustate.cc): the
// Lagrange polynomial through them evaluated at t, so a smooth offset is
// off by O(dt^n); the last offset alone (or nothing, n = 0) when the times
// are not increasing or t is more than two steps past tk[0]
void guessWeights(double t, const double tk[3], int n, double L[3]);

// allocate s for b
void makeState(const Buoy& b, State* s);
// about the bytes makeState allocates with nthreads cpu threads (cpustate.cc)
size_t stateBytes(const Buoy& b, int nthreads);

// the chunks the cpu backend cuts a hull of nt triangles into (cpu.cc):
// fixed by nt alone, so results keep their bits for any thread count
int hullChunks(int nt);

// the cpu backend's surface solves for d so far and the Newton steps they
// took (glue.cc; tools only): false if d has no state
bool newtonStats(const mjbBuoy* b, const mjData* d, long* solves, long* steps);
// the cpu backend's seconds in the vertex stage for d so far, all threads
// (glue.cc; tools only): false if d has no state
bool vertexSeconds(const mjbBuoy* b, const mjData* d, double* sec);

// cpu backend: fill s->wrench and s->part from d's current state
void cpuWrench(const Buoy& b, const mjModel* m, const mjData* d, State* s);

// name each body with a non-finite state in s->notices, once
void noteBad(const Buoy& b, const mjModel* m, const mjData* d, State* s);

// from s->part: leave out (zero) and name once in s->notices each force
// family that came out non-finite for a body, then sum s->wrench (a body
// with a non-finite state gets no force at all); both backends end with it
void finishWrench(const Buoy& b, const mjModel* m, const mjData* d, State* s);

// gl backend (gl.cc): create it for b (false and err if GL is unusable),
// compute the wrench like cpuWrench, free it with its context
bool glMake(Buoy* b, std::string* err);
void glWrench(Buoy* b, const mjModel* m, const mjData* d, State* s);
void glFree(Buoy* b);
void glFreeState(Buoy* b, State* s);
// copy src's slamming history buffers into dst's (created if needed)
bool glCopyState(Buoy* b, State* dst, const State* src);
int glStageTimes(Buoy* b, const char** name, double* ms, int n);
// gl backend: upload b's current waves and current (mjb_setSea)
void glSetSea(Buoy* b);

}  // namespace mjb

#endif  // MJBUOY_BUOY_H_
