// hullstate: the backends' per-mjData state of the hulls, the step clock,
// the label guesses' weights and the wrench's last checks (hullstate.h)
#include "hull/hullstate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "mjbuoy.h"
#include "util/bodylabel.h"
#include "util/stepclock.h"

namespace mjb {

static bool finite(const double* x, int n) {
  for (int i = 0; i < n; i++) if (!std::isfinite(x[i])) return false;
  return true;
}

void makeHullState(const HullSet& hs, size_t nw, HullState* s) {
  const mjModel* m = hs.m;
  const size_t nv = hs.vert.size() / 3, nt = hs.face.size() / 3, nh = hs.hull.size();
  s->wrench.assign(6 * m->nbody, 0);
  s->part.assign(mjbNPART * 6 * m->nbody, 0);
  s->h.assign(nv, 0);
  s->bad.assign(m->nbody, 0);
  s->told.assign(m->nbody, 0);
  s->badPart.assign(m->nbody * mjbNPART, 0);
  s->toldPart.assign(m->nbody * mjbNPART, 0);
  s->notices.clear();
  s->notices.reserve(4096);
  s->hwet.assign(nh, 0);
  s->curQ.assign(3 * nt, 0);
  s->prevQ.assign(3 * nt, 0);
  s->off.assign(nv * 2, 0);
  s->offNew.assign(nv * 2, 0);
  s->hoff.assign(2 * nh, 0);
  s->hoffNew.assign(2 * nh, 0);
  s->offOld.assign(nv * 2, 0);
  s->offOld2.assign(nv * 2, 0);
  s->hoffOld.assign(2 * nh, 0);
  s->hoffOld2.assign(2 * nh, 0);
  s->hv.assign(nh, 0);
  s->hvNew.assign(nh, 0);
  s->hvOld.assign(nh, 0);
  s->hvOld2.assign(nh, 0);
  s->wn.assign(nw, WaveNow{});
  s->tab.reserve(nw);
  s->key = -1;
  s->hasPrev = false;
}

size_t hullStateBytes(const HullSet& hs, size_t nw) {
  const size_t nt = hs.face.size() / 3, nv = hs.vert.size() / 3;
  size_t n = 2 * 3 * nt * sizeof(float);                  // curQ, prevQ
  n += 4 * 2 * nv * sizeof(float) + nv * sizeof(double);  // label offsets, h
  n += nw * (sizeof(WaveNow) + 16 * sizeof(double));      // wn, tab
  return n;
}

// advance the slamming history when time has moved on by a step, whatever
// loop moved it (mj_step, mj_forward + mj_Euler, ...): a call at a time at
// least 3/4 of opt.timestep past the current step's opens a new step; a
// call at the current step's time records (the last evaluation at that time
// is the step's history); a call in between is an RK4 stage (t + h/2) and
// records nothing. Time going backwards, or the step counter
// timer[mjTIMER_STEP] dropping (mj_resetData zeroes it), restarts
int stepClock(const mjModel* m, const mjData* d, HullState* s) {
  const double was = s->tcur;
  const int r = stepTick(m, d, s);  // the same states, in the same order
  if (r == kTickRestart) s->hasPrev = false;
  if (r == kTickNew) s->tprev = was, s->hasPrev = true;
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

void noteBad(const HullSet& hs, const mjModel* m, const mjData* d, HullState* s) {
  for (int bd : hs.body) {
    if (!s->bad[bd] || s->told[bd]) continue;
    s->told[bd] = 1;
    char line[256], who[128];
    std::snprintf(line, sizeof(line),
                  "body %s: position or velocity not finite at t = %g s; "
                  "mjbuoy adds no force to it\n", bodyLabel(m, bd, who, sizeof who), d->time);
    // within the capacity reserved in makeState: no allocation while stepping
    if (s->notices.size() + std::strlen(line) < s->notices.capacity()) s->notices += line;
  }
}

void finishWrench(const HullSet& hs, const mjModel* m, const mjData* d, HullState* s) {
  static const char* kFamily[mjbNPART] = {"pressure", "viscous", "drag", "slamming", "damping"};
  noteBad(hs, m, d, s);
  const int nb6 = 6 * m->nbody;
  std::memset(s->wrench.data(), 0, s->wrench.size() * sizeof(double));
  for (int bd : hs.body) {
    for (int p = 0; p < mjbNPART; p++) {
      double* wp = s->part.data() + p * nb6 + 6 * bd;
      char& bad = s->badPart[mjbNPART * bd + p];
      bad = !s->bad[bd] && !finite(wp, 6);
      if (s->bad[bd] || bad) std::memset(wp, 0, 6 * sizeof(double));
      if (bad && !s->toldPart[mjbNPART * bd + p]) {
        s->toldPart[mjbNPART * bd + p] = 1;
        char line[256], who[128];
        std::snprintf(line, sizeof(line),
                      "body %s: %s force not finite at t = %g s (an intermediate "
                      "overflowed or was NaN); mjbuoy leaves it out of the wrench\n",
                      bodyLabel(m, bd, who, sizeof who), kFamily[p], d->time);
        // within the capacity reserved in makeState: no allocation while stepping
        if (s->notices.size() + std::strlen(line) < s->notices.capacity()) s->notices += line;
      }
      for (int j = 0; j < 6; j++) s->wrench[6 * bd + j] += wp[j];
    }
  }
}

}  // namespace mjb
