// hullstate: what the backends keep per mjData for the hulls: the
// wrenches they fill, the histories carried from step to step (label
// guesses, slamming), the step clock and the notices; sized at creation,
// never resized while stepping. Each backend's scratch is its own
// (cpu/cpu.h CpuState, gl/gl.h GlState)
#ifndef MJBUOY_HULLSTATE_H_
#define MJBUOY_HULLSTATE_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "hull/hullset.h"
#include "sea/waveint.h"
#include "sea/wavenow.h"

namespace mjb {

struct HullState {
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
  // (guessWeights); per hull whether offNew, off, offOld, offOld2
  // hold a solve (1) or are cold (0), and the times off, offOld, offOld2
  // were taken [s]
  std::vector<float> offOld, offOld2;
  std::vector<double> hoffOld, hoffOld2;
  std::vector<char> hv, hvNew, hvOld, hvOld2;
  double tgOff = 0, tgOld = 0, tgOld2 = 0;  // (the gl backend's too: GlState::offbuf)
  std::vector<WaveNow> wn;     // wave constants of this call
  WaveTab tab;                 // the same by wave number, for waveint.h
  double crest = 0;            // highest possible surface height [m]
  std::vector<char> bad;       // per body: state not finite in the last call
  std::vector<char> told;      // per body: already named in notices
  // per body and force family (body-major): non-finite in the last call,
  // already named in notices
  std::vector<char> badPart, toldPart;
  std::string notices;         // capacity reserved up front
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
};

// size s for the hulls hs of model hs.m and nw wave components (their
// capacity: mjb_setSea never grows them)
void makeHullState(const HullSet& hs, size_t nw, HullState* s);
// about the bytes of makeHullState's per-vertex, per-triangle and
// per-wave arrays
size_t hullStateBytes(const HullSet& hs, size_t nw);

// slamming clock (hullstate.cc): kSameStep for another call at the current step's
// time (it records the history again: the last evaluation at a time wins),
// kNewStep when time has moved on by a step since (the caller moves the
// current history to the previous), kRestart after mj_resetData or time
// going backwards (no previous history), kMidStep for an intermediate RK4
// stage (records nothing)
enum { kSameStep = 0, kNewStep, kRestart, kMidStep };  // util/stepclock.h's StepTick
int stepClock(const mjModel* m, const mjData* d, HullState* s);

// the weights L of the last n (0 to 3) steps' label offsets, taken at times
// tk[0] > tk[1] > tk[2] [s], in the label guess at time t [s] (hullstate.cc): the
// Lagrange polynomial through them evaluated at t, so a smooth offset is
// off by O(dt^n); the last offset alone (or nothing, n = 0) when the times
// are not increasing or t is more than two steps past tk[0]
void guessWeights(double t, const double tk[3], int n, double L[3]);

// name each body of hs with a non-finite state in s->notices, once
void noteBad(const HullSet& hs, const mjModel* m, const mjData* d, HullState* s);

// from s->part: leave out (zero) and name once in s->notices each force
// family that came out non-finite for a body, then sum s->wrench (a body
// with a non-finite state gets no force at all); both backends end with it
void finishWrench(const HullSet& hs, const mjModel* m, const mjData* d, HullState* s);

}  // namespace mjb

#endif  // MJBUOY_HULLSTATE_H_
