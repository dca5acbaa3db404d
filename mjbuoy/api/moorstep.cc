// moorstep: mooring lines inside mjcb_passive (moorstep.h)
#include "api/moorstep.h"

#include <algorithm>
#include <cmath>

#include "util/fmt.h"
#include "util/stepclock.h"

namespace mjb {

namespace {

// an end's position and velocity now [m, m/s]
void endNow(const mjModel* m, const mjData* d, const LineEnd& n, double e[6]) {
  if (n.site < 0) {
    for (int k = 0; k < 3; k++) e[k] = n.p[k], e[3 + k] = 0;
    return;
  }
  mjtNum v[6];
  mj_objectVelocity(m, d, mjOBJ_SITE, n.site, v, 0);  // world frame: [rot; lin]
  for (int k = 0; k < 3; k++) e[k] = d->site_xpos[3 * n.site + k], e[3 + k] = v[3 + k];
}

bool finite(const LineState& s) {
  double a = 0;
  for (double x : s.r) a += x;
  for (double x : s.v) a += x;
  return std::isfinite(a);
}

}  // namespace

void moorMakeState(const Mooring& mo, int nbody, MoorState* s) {
  const size_t n = mo.line.size();
  s->ls.resize(n);
  for (size_t i = 0; i < n; i++) lineMake(mo.line[i].line, &s->ls[i]);
  s->wrench.assign(6 * nbody, 0.0);
  s->tend.assign(2 * n, 0.0);
  s->fend.assign(6 * n, 0.0);
  s->told.assign(n, 0);
  s->bad.assign(n, 0);
  s->eend.assign(12 * n, 0.0);
  s->ev.assign(n, 0);
  moorRestart(s);
}

void moorRestart(MoorState* s) {
  s->key = -1;
  s->tcur = 0;
  std::fill(s->told.begin(), s->told.end(), 0);
  std::fill(s->bad.begin(), s->bad.end(), 0);
  std::fill(s->wrench.begin(), s->wrench.end(), 0.0);
}

namespace {

// what one line's evaluation has to report (MoorState::ev)
enum LineEvent : char { kEvNone = 0, kEvRest, kEvBad, kEvOver };

// one evaluation's shared inputs, for the pool's chunks
struct MoorJob {
  const Mooring* mo;
  const mjModel* m;
  const mjData* d;
  MoorState* s;
  LineWater w;
  int tick;
  double t0;
  int nc;  // chunks
};

// line i: its ends now, its step (or its rest after a restart) and its
// end forces; writes only line i's entries of s
void lineEval(const MoorJob& j, size_t i) {
  const MoorLine& L = j.mo->line[i];
  MoorState* s = j.s;
  LineState& ls = s->ls[i];
  double* e0 = &s->eend[12 * i];
  double* e1 = e0 + 6;
  endNow(j.m, j.d, L.end[0], e0);
  endNow(j.m, j.d, L.end[1], e1);
  s->ev[i] = kEvNone;
  if (j.tick == kTickRestart) {
    s->bad[i] = 0;
    if (!lineRest(j.w, L.line, e0, e1, &ls)) s->ev[i] = kEvRest;
    std::copy(e0, e0 + 6, ls.end0);
    std::copy(e1, e1 + 6, ls.end1);
  } else if (j.tick == kTickNew && !s->bad[i]) {
    lineStep(j.w, L.line, j.t0, j.d->time - j.t0, e0, e1, &ls);
    if (!finite(ls)) {
      s->bad[i] = 1;
      s->ev[i] = kEvBad;
    } else if (ls.over && !(s->told[i] & 1)) {
      s->told[i] |= 1;
      s->ev[i] = kEvOver;
    }
  }
  for (int k = 0; k < 2; k++) {
    double f[3] = {0, 0, 0};
    const double* e = k ? e1 : e0;
    double T = s->bad[i] ? NAN
                         : lineEndForce(j.w, L.line, ls, k, e, j.d->time, j.d->time - s->tcur, f);
    s->tend[2 * i + k] = T;
    for (int q = 0; q < 3; q++) s->fend[6 * i + 3 * k + q] = s->bad[i] ? NAN : f[q];
  }
}

void lineChunk(void* arg, int c, int slot) {
  (void)slot;
  const MoorJob& j = *static_cast<const MoorJob*>(arg);
  const size_t n = j.mo->line.size();
  for (size_t i = n * c / j.nc; i < n * (c + 1) / j.nc; i++) lineEval(j, i);
}

// nodes stepped per evaluation below which the pool's hand-over costs
// more than it saves (a few microseconds against about 0.1 us per node)
const int kPoolNodes = 400;

}  // namespace

void moorStep(const Mooring& mo, const Sea& sea, const mjModel* m, const mjData* d,
              MoorState* s, std::string* notices, Pool* pool) {
  const double t0 = s->tcur;
  const int r = stepTick(m, d, s);
  // the water at the nodes is taken 32 times per period of the shortest
  // wave and carried on by its acceleration in between (docs/mooring.md)
  double crest = sea.level, omax = 0;
  for (const Wave& w : sea.waves) crest += w.amp, omax = std::max(omax, w.omega);
  const size_t n = mo.line.size();
  MoorJob job = {&mo, m, d, s, {&sea, &mo.bed, crest, omax > 0 ? 2 * M_PI / omax / 32 : 0},
                 r, t0, 1};
  int nodes = 0;
  for (const MoorLine& L : mo.line) nodes += L.line.nseg + 1;
  job.nc = int(std::min<size_t>(n, 64));
  if (!(pool && r != kTickSame && nodes >= kPoolNodes && job.nc > 1 &&
        poolRun(pool, lineChunk, &job, job.nc))) {
    for (size_t i = 0; i < n; i++) lineEval(job, i);
  }
  // reports and wrenches in line order, on this thread
  for (int b : mo.body) std::fill(&s->wrench[6 * b], &s->wrench[6 * b] + 6, 0.0);
  for (size_t i = 0; i < n; i++) {
    const MoorLine& L = mo.line[i];
    if (s->ev[i] == kEvRest) {
      *notices += "mjbuoy: line \"" + L.line.name + "\" at t = " + fmt(d->time) +
                  " s: no static equilibrium found for its start (its nodes' forces do "
                  "not balance); it starts from the nearest shape found and settles\n";
    } else if (s->ev[i] == kEvBad) {
      *notices += "mjbuoy: line \"" + L.line.name + "\" at t = " + fmt(d->time) +
                  " s: its nodes are not finite (an end not finite, or a step past the "
                  "line's stability); it puts no force on its bodies until mj_resetData\n";
    } else if (s->ev[i] == kEvOver) {
      *notices += "mjbuoy: line \"" + L.line.name + "\" at t = " + fmt(d->time) + " s: " +
                  std::to_string(s->ls[i].over) + " segment(s) stretched past " +
                  fmt(100 * kOverStrain) + "% strain: the line is overloaded (taut past its "
                  "length); it stays linear elastic\n";
    }
    s->ev[i] = kEvNone;
    for (int k = 0; k < 2; k++) {
      if (s->bad[i] || !L.end[k].moves) continue;
      const double* e = &s->eend[12 * i + 6 * k];
      const double* f = &s->fend[6 * i + 3 * k];
      const int b = L.end[k].body;
      double* wr = &s->wrench[6 * b];
      const mjtNum* c = d->xipos + 3 * b;
      double a[3] = {e[0] - c[0], e[1] - c[1], e[2] - c[2]};
      wr[0] += f[0];
      wr[1] += f[1];
      wr[2] += f[2];
      wr[3] += a[1] * f[2] - a[2] * f[1];
      wr[4] += a[2] * f[0] - a[0] * f[2];
      wr[5] += a[0] * f[1] - a[1] * f[0];
    }
  }
}

}  // namespace mjb
