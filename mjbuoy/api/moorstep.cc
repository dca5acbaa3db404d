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
  moorRestart(s);
}

void moorRestart(MoorState* s) {
  s->key = -1;
  s->tcur = 0;
  std::fill(s->told.begin(), s->told.end(), 0);
  std::fill(s->bad.begin(), s->bad.end(), 0);
  std::fill(s->wrench.begin(), s->wrench.end(), 0.0);
}

void moorStep(const Mooring& mo, const Sea& sea, const mjModel* m, const mjData* d,
              MoorState* s, std::string* notices) {
  const double t0 = s->tcur;
  const int r = stepTick(m, d, s);
  // the water at the nodes is taken 32 times per period of the shortest
  // wave and carried on by its acceleration in between (docs/mooring.md)
  double crest = sea.level, omax = 0;
  for (const Wave& w : sea.waves) crest += w.amp, omax = std::max(omax, w.omega);
  const LineWater w = {&sea, &mo.bed, crest, omax > 0 ? 2 * M_PI / omax / 32 : 0};
  for (int b : mo.body) std::fill(&s->wrench[6 * b], &s->wrench[6 * b] + 6, 0.0);
  for (size_t i = 0; i < mo.line.size(); i++) {
    const MoorLine& L = mo.line[i];
    LineState& ls = s->ls[i];
    double e[2][6];
    for (int k = 0; k < 2; k++) endNow(m, d, L.end[k], e[k]);
    if (r == kTickRestart) {
      s->bad[i] = 0;
      if (!lineRest(w, L.line, e[0], e[1], &ls)) {
        *notices += "mjbuoy: line \"" + L.line.name + "\" at t = " + fmt(d->time) +
                    " s: no static equilibrium found for its start (its nodes' forces do "
                    "not balance); it starts from the nearest shape found and settles\n";
      }
      std::copy(e[0], e[0] + 6, ls.end0);
      std::copy(e[1], e[1] + 6, ls.end1);
    } else if (r == kTickNew && !s->bad[i]) {
      lineStep(w, L.line, t0, d->time - t0, e[0], e[1], &ls);
      if (!finite(ls)) {
        s->bad[i] = 1;
        *notices += "mjbuoy: line \"" + L.line.name + "\" at t = " + fmt(d->time) +
                    " s: its nodes are not finite (an end not finite, or a step past the "
                    "line's stability); it puts no force on its bodies until mj_resetData\n";
      } else if (ls.over && !(s->told[i] & 1)) {
        s->told[i] |= 1;
        *notices += "mjbuoy: line \"" + L.line.name + "\" at t = " + fmt(d->time) + " s: " +
                    std::to_string(ls.over) + " segment(s) stretched past " +
                    fmt(100 * kOverStrain) + "% strain: the line is overloaded (taut past its "
                    "length); it stays linear elastic\n";
      }
    }
    for (int k = 0; k < 2; k++) {
      double f[3] = {0, 0, 0};
      double T = s->bad[i] ? NAN : lineEndForce(w, L.line, ls, k, e[k], d->time, d->time - s->tcur, f);
      s->tend[2 * i + k] = T;
      for (int j = 0; j < 3; j++) s->fend[6 * i + 3 * k + j] = s->bad[i] ? NAN : f[j];
      if (s->bad[i] || !L.end[k].moves) continue;
      const int b = L.end[k].body;
      double* wr = &s->wrench[6 * b];
      const mjtNum* c = d->xipos + 3 * b;
      double a[3] = {e[k][0] - c[0], e[k][1] - c[1], e[k][2] - c[2]};
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
