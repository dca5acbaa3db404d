// line: lumped-mass mooring line dynamics (line.h; docs/mooring.md)
#include "mooring/line.h"

#include <algorithm>
#include <cmath>

#include "mooring/catenary.h"

namespace mjb {

namespace {

inline double dot3(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// a segment's tension from its length l and stretch rate ld [N]: Hooke's
// EA e plus internal damping BA de/dt, never compressive (docs/mooring.md)
inline double tension(const Line& l, double len, double ld) {
  double e = len / l.l0 - 1;
  if (e <= 0) return 0;
  return std::max(l.t.ea * e + l.t.ba * ld / l.l0, 0.0);
}

// water velocity, acceleration and wetness at each inner node at time t
void waterAt(const LineWater& w, const Line& l, double t, LineState* s) {
  const Sea& sea = *w.sea;
  double amp = 0;
  for (const Wave& wv : sea.waves) amp += wv.amp;
  s->tw = t;
  for (int j = 0; j <= l.nseg; j++) {
    const double* p = &s->r[3 * j];
    double* u = &s->uw[3 * j];
    double* a = &s->aw[3 * j];
    if (p[2] > w.crest) {
      s->wet[j] = 0;
      continue;
    }
    if (sea.waves.empty()) {
      u[0] = sea.current[0];
      u[1] = sea.current[1];
      u[2] = a[0] = a[1] = a[2] = 0;
      s->wet[j] = p[2] < sea.level;
      continue;
    }
    sea.velocity(p, t, u, a);
    s->wet[j] = p[2] < sea.level - amp || p[2] < sea.height(p[0], p[1], t);
  }
}

// the forces on every inner node but seabed friction (f), segment tensions
// (s->tseg), with the nodes at s->r, s->v
void nodeForces(const LineWater& w, const Line& l, double tau, LineState* s) {
  const Sea& sea = *w.sea;
  const Seabed& bed = *w.bed;
  const int n = l.nseg;
  double* f = s->f.data();
  std::fill(s->f.begin(), s->f.end(), 0.0);
  for (int i = 0; i < n; i++) {
    const double* a = &s->r[3 * i];
    const double* b = &s->r[3 * i + 3];
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double len = std::sqrt(dot3(d, d)), T = 0;
    if (len > 0) {
      double q[3] = {d[0] / len, d[1] / len, d[2] / len};
      double dv[3] = {s->v[3 * i + 3] - s->v[3 * i], s->v[3 * i + 4] - s->v[3 * i + 1],
                      s->v[3 * i + 5] - s->v[3 * i + 2]};
      T = tension(l, len, dot3(dv, q));
      for (int k = 0; k < 3; k++) {
        f[3 * i + k] += T * q[k];
        f[3 * i + 3 + k] -= T * q[k];
      }
    }
    s->tseg[i] = T;
  }
  const double rho = sea.rho, g = sea.g, dia = l.t.diam, l0 = l.l0;
  // drag acts on the stretched length a node stands for: half the chord
  // of its neighbours
  const double dn = 0.5 * rho * l.t.cdn * dia, dt = 0.5 * rho * l.t.cdt * M_PI * dia;
  for (int j = 1; j < n; j++) {
    double* fj = f + 3 * j;
    double* q = &s->q[3 * j];
    const double ls = 0.5 * lineTangent(s->r.data(), j, q);
    fj[2] -= l.mnode * g;
    const double* v = &s->v[3 * j];
    double pen = bed.z - s->r[3 * j + 2];
    if (pen > 0) fj[2] += std::max(bed.k * pen - bed.c * v[2], 0.0) * dia * l0;
    if (!s->wet[j]) continue;
    fj[2] += rho * l.vnode * g;
    const double* u = &s->uw[3 * j];
    const double* aw = &s->aw[3 * j];
    // the water's velocity carried on by its acceleration since it was taken
    double vr[3] = {u[0] + tau * aw[0] - v[0], u[1] + tau * aw[1] - v[1],
                    u[2] + tau * aw[2] - v[2]};
    double vq = dot3(vr, q), aq = dot3(aw, q);
    double vn[3], an[3];
    for (int k = 0; k < 3; k++) {
      vn[k] = vr[k] - vq * q[k];
      an[k] = aw[k] - aq * q[k];
    }
    double nn = std::sqrt(dot3(vn, vn));
    // Morison: drag on the relative flow, Froude-Krylov plus added mass on
    // the water's acceleration (docs/mooring.md eq. 3)
    for (int k = 0; k < 3; k++) {
      fj[k] += ls * (dn * nn * vn[k] + dt * std::fabs(vq) * vq * q[k]);
      fj[k] += rho * l.vnode * ((1 + l.t.can) * an[k] + (1 + l.t.cat) * aq * q[k]);
    }
  }
}

}  // namespace

double lineTangent(const double* r, int j, double q[3]) {
  double d[3] = {r[3 * j + 3] - r[3 * j - 3], r[3 * j + 4] - r[3 * j - 2],
                 r[3 * j + 5] - r[3 * j - 1]};
  double n = std::sqrt(dot3(d, d));
  if (n > 0) {
    for (int k = 0; k < 3; k++) q[k] = d[k] / n;
  } else {
    q[0] = q[1] = 0;
    q[2] = 1;
  }
  return n;
}

double lineWetWeight(const Sea& sea, const LineType& t) {
  return (t.mass - sea.rho * M_PI * t.diam * t.diam / 4) * sea.g;
}

// the fraction of the linear bound taken: room for the geometric
// nonlinearity and the drag the bound leaves out
static const double kSafety = 0.8;

double lineStableStep(const LineWater& w, const Line& l) {
  // the highest mode of a chain of masses m and springs k, c moves
  // neighbours against each other: stiffness 4k and damping 4c on each
  // node; the bed adds its own spring and damper (vertical). Added mass
  // only slows it, so the dry mass gives the bound
  const double m = l.mnode, k = l.t.ea / l.l0, c = l.t.ba / l.l0;
  const double kb = w.bed->k * l.t.diam * l.l0, cb = w.bed->c * l.t.diam * l.l0;
  const double om = std::sqrt((4 * k + kb) / m), z = (4 * c + cb) / (2 * m * om);
  return kSafety * 2 / om * (std::sqrt(1 + z * z) - z);
}

std::string lineDerive(const LineWater& w, Line* l) {
  l->l0 = l->len / l->nseg;
  l->mnode = l->t.mass * l->l0;
  l->vnode = M_PI * l->t.diam * l->t.diam / 4 * l->l0;
  // a negative damping is a ratio of the critical damping 2 sqrt(k m) of a
  // segment's axial mode (k = EA / l0), as MoorDyn's BA < 0
  if (l->t.ba < 0) l->t.ba = -l->t.ba * 2 * std::sqrt(l->t.ea / l->l0 * l->mnode) * l->l0;
  l->hmax = lineStableStep(w, *l);
  if (!(l->hmax > 0) || !std::isfinite(l->hmax)) {
    return "mjbuoy: line \"" + l->name + "\": no stable step exists for its properties";
  }
  return "";
}

void lineMake(const Line& l, LineState* s) {
  const size_t n3 = 3 * (l.nseg + 1);
  s->r.assign(n3, 0.0);
  s->v.assign(n3, 0.0);
  s->uw.assign(n3, 0.0);
  s->aw.assign(n3, 0.0);
  s->f.assign(n3, 0.0);
  s->q.assign(n3, 0.0);
  s->tseg.assign(l.nseg, 0.0);
  s->wet.assign(l.nseg + 1, 1);
  s->tw = -1;
}

// set the end nodes at fraction a of the way from the last step's ends to e0, e1
static void setEnds(const Line& l, double a, const double e0[6], const double e1[6],
                    LineState* s) {
  const int n = l.nseg;
  for (int k = 0; k < 3; k++) {
    s->r[k] = s->end0[k] + a * (e0[k] - s->end0[k]);
    s->v[k] = s->end0[3 + k] + a * (e0[3 + k] - s->end0[3 + k]);
    s->r[3 * n + k] = s->end1[k] + a * (e1[k] - s->end1[k]);
    s->v[3 * n + k] = s->end1[3 + k] + a * (e1[3 + k] - s->end1[3 + k]);
  }
}

// one semi-implicit Euler sub-step of length h of the inner nodes: v from
// the forces at (r, v), then r from the new v. Seabed friction is a
// damper of coefficient mu N / max(|v|, vs) along and across the line,
// taken implicitly so its stiffness sets no step limit (docs/mooring.md)
static void subStep(const LineWater& w, const Line& l, double h, double tau, LineState* s) {
  nodeForces(w, l, tau, s);
  const Seabed& bed = *w.bed;
  const double rv = w.sea->rho * l.vnode;
  for (int j = 1; j < l.nseg; j++) {
    double* v = &s->v[3 * j];
    double* fj = &s->f[3 * j];
    const double* q = &s->q[3 * j];
    const bool wet = s->wet[j];
    const double mn = l.mnode + (wet ? rv * l.t.can : 0), mt = l.mnode + (wet ? rv * l.t.cat : 0);
    double fq = dot3(fj, q);
    for (int k = 0; k < 3; k++) v[k] += h * ((fj[k] - fq * q[k]) / mn + fq * q[k] / mt);
    double pen = bed.z - s->r[3 * j + 2];
    if (pen > 0) {
      double fn = std::max(bed.k * pen - bed.c * v[2], 0.0) * l.t.diam * l.l0;
      double ax[2] = {q[0], q[1]}, an = std::sqrt(q[0] * q[0] + q[1] * q[1]);
      if (an > 1e-9) {
        ax[0] /= an;
        ax[1] /= an;
      } else {
        ax[0] = 1;
        ax[1] = 0;
      }
      double va = v[0] * ax[0] + v[1] * ax[1];
      double vl = -v[0] * ax[1] + v[1] * ax[0];
      va /= 1 + h * bed.mu[0] * fn / (std::max(std::fabs(va), bed.vs) * l.mnode);
      vl /= 1 + h * bed.mu[1] * fn / (std::max(std::fabs(vl), bed.vs) * l.mnode);
      v[0] = va * ax[0] - vl * ax[1];
      v[1] = va * ax[1] + vl * ax[0];
    }
    for (int k = 0; k < 3; k++) s->r[3 * j + k] += h * v[k];
  }
}

void lineStep(const LineWater& w, const Line& l, double t, double dt, const double e0[6],
              const double e1[6], LineState* s) {
  setEnds(l, 0, e0, e1, s);
  if (!(s->tw >= 0) || t < s->tw || t - s->tw >= w.refresh) waterAt(w, l, t, s);
  int nsub = std::max(1, int(std::ceil(dt / l.hmax)));
  const double h = dt / nsub;
  for (int i = 0; i < nsub; i++) {
    subStep(w, l, h, t + i * h - s->tw, s);
    setEnds(l, double(i + 1) / nsub, e0, e1, s);
  }
  std::copy(e0, e0 + 6, s->end0);
  std::copy(e1, e1 + 6, s->end1);
  // what rests on the bed, and overload
  int on = 0;
  s->over = 0;
  for (int i = 0; i < l.nseg; i++) {
    const double* a = &s->r[3 * i];
    const double* b = &s->r[3 * i + 3];
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    if (std::sqrt(dot3(d, d)) > (1 + kOverStrain) * l.l0) s->over++;
    if (a[2] <= w.bed->z + 1e-3 * l.t.diam && b[2] <= w.bed->z + 1e-3 * l.t.diam) on++;
  }
  s->bedlen = on * l.l0;
}

double lineEndForce(const LineWater& w, const Line& l, const LineState& s, int end,
                    const double e[6], double t, double tau, double f[3]) {
  const int j = end ? l.nseg - 1 : 1;
  const double* v = &s.v[3 * j];
  // the neighbour carried on by its velocity to the time of this call
  const double r[3] = {s.r[3 * j] + tau * v[0], s.r[3 * j + 1] + tau * v[1],
                       s.r[3 * j + 2] + tau * v[2]};
  double d[3] = {r[0] - e[0], r[1] - e[1], r[2] - e[2]};
  double len = std::sqrt(dot3(d, d)), T = 0;
  double q[3] = {0, 0, 1};
  f[0] = f[1] = f[2] = 0;
  if (len > 0) {
    for (int k = 0; k < 3; k++) q[k] = d[k] / len;
    double dv[3] = {v[0] - e[3], v[1] - e[4], v[2] - e[5]};
    T = tension(l, len, dot3(dv, q));
    for (int k = 0; k < 3; k++) f[k] = T * q[k];
  }
  // the end node's half segment: its weight, and when wet its buoyancy
  // and drag (the same Morison terms as an inner node's, on l0 / 2)
  // (the water as the last step took it at the end node, else now)
  const Sea& sea = *w.sea;
  const int en = end ? l.nseg : 0;
  double u[3] = {sea.current[0], sea.current[1], 0};
  bool wet;
  if (s.tw >= 0) {
    wet = s.wet[en];
    for (int k = 0; k < 3; k++) u[k] = s.uw[3 * en + k] + (t - s.tw) * s.aw[3 * en + k];
  } else {
    wet = e[2] < w.crest && (sea.waves.empty() ? e[2] < sea.level
                                               : e[2] < sea.height(e[0], e[1], t));
    if (wet && !sea.waves.empty()) sea.velocity(e, t, u);
  }
  f[2] -= 0.5 * l.l0 * (wet ? lineWetWeight(sea, l.t) : l.t.mass * sea.g);
  if (!wet) return T;
  double vr[3] = {u[0] - e[3], u[1] - e[4], u[2] - e[5]}, vq = dot3(vr, q), vn[3];
  for (int k = 0; k < 3; k++) vn[k] = vr[k] - vq * q[k];
  const double nn = std::sqrt(dot3(vn, vn)), h = 0.5 * 0.5 * sea.rho * l.t.diam * len;
  for (int k = 0; k < 3; k++) {
    f[k] += h * (l.t.cdn * nn * vn[k] + l.t.cdt * M_PI * std::fabs(vq) * vq * q[k]);
  }
  return T;
}

bool lineRest(const LineWater& w, const Line& l, const double e0[3], const double e1[3],
              LineState* s) {
  const int n = l.nseg;
  // the lower end is the catenary's anchor
  const bool flip = e1[2] < e0[2];
  const double* A = flip ? e1 : e0;
  const double* B = flip ? e0 : e1;
  double hx = B[0] - A[0], hy = B[1] - A[1], X = std::hypot(hx, hy), Z = B[2] - A[2];
  const double W = lineWetWeight(*w.sea, l.t);
  const double tol = std::max(1e-3 * l.len, l.t.diam);
  const bool bed = A[2] <= w.bed->z + tol;
  Catenary c;
  bool ok = W > 0 && catenarySolve(X, Z, l.len, l.t.ea, W, bed, &c);
  // grounded nodes rest sunk by the bed's static deflection w / (k d)
  const double sink = W > 0 ? W / (w.bed->k * l.t.diam) : 0;
  for (int j = 0; j <= n; j++) {
    int i = flip ? n - j : j;
    double* p = &s->r[3 * i];
    if (ok) {
      double x, z, T;
      catenaryPoint(c, j * l.l0, &x, &z, &T);
      double ux = X > 0 ? hx / X : 1, uy = X > 0 ? hy / X : 0;
      p[0] = A[0] + x * ux;
      p[1] = A[1] + x * uy;
      p[2] = A[2] + z - (bed && j > 0 && j < n && j * l.l0 < c.lb ? sink : 0);
    } else {
      double a = double(j) / n;
      for (int k = 0; k < 3; k++) p[k] = A[k] + a * (B[k] - A[k]);
    }
  }
  std::fill(s->v.begin(), s->v.end(), 0.0);
  for (int k = 0; k < 3; k++) {
    s->end0[k] = e0[k];
    s->end1[k] = e1[k];
    s->end0[3 + k] = s->end1[3 + k] = 0;
  }
  s->bedlen = ok ? c.lb : 0;
  s->tw = -1;
  return ok;
}

}  // namespace mjb
