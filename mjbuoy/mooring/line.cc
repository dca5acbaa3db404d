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
// EA e plus internal damping BA de/dt, never compressive (docs/mooring.md);
// the end segments' force on the bodies (lineEndForce)
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
  // the inverse masses across and along each node: dry, or with added mass
  const double rv = sea.rho * l.vnode;
  for (int j = 0; j <= l.nseg; j++) {
    s->im[2 * j] = 1 / (l.mnode + (s->wet[j] ? rv * l.t.can : 0));
    s->im[2 * j + 1] = 1 / (l.mnode + (s->wet[j] ? rv * l.t.cat : 0));
  }
}

// the explicit forces on every inner node (f): the segments' elastic
// tension EA e (s->tseg, along s->qs), weight, buoyancy, drag, Froude-Krylov
// and added mass, with the nodes at s->r, s->v; and each node's inverse
// masses across and along with its drag linearly implicit over a sub-step
// h (s->ie): 1 / (m + h c), c = 2 k |v_r| the slope of the quadratic drag k
// |v_r| v_r, so fast nodes stay stable (docs/mooring.md "Integration").
// The axial tension's change, internal damping and the seabed are the
// implicit part of the sub-step (subStep)
void nodeForces(const LineWater& w, const Line& l, double tau, double h, LineState* s) {
  const Sea& sea = *w.sea;
  const int n = l.nseg;
  double* f = s->f.data();
  std::fill(s->f.begin(), s->f.end(), 0.0);
  for (int i = 0; i < n; i++) {
    const double* a = &s->r[3 * i];
    const double* b = &s->r[3 * i + 3];
    double* q = &s->qs[3 * i];
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double len = std::sqrt(dot3(d, d)), T = 0;
    q[0] = q[1] = q[2] = 0;
    s->es[i] = len / l.l0 - 1;
    if (len > 0) {
      const double il = 1 / len;
      for (int k = 0; k < 3; k++) q[k] = d[k] * il;
      T = l.t.ea * std::max(s->es[i], 0.0);
      for (int k = 0; k < 3; k++) {
        f[3 * i + k] += T * q[k];
        f[3 * i + 3 + k] -= T * q[k];
      }
    }
    s->tseg[i] = T;
  }
  const double rho = sea.rho, g = sea.g, dia = l.t.diam;
  // drag acts on the stretched length a node stands for: half the chord
  // of its neighbours
  const double dn = 0.5 * rho * l.t.cdn * dia, dt = 0.5 * rho * l.t.cdt * M_PI * dia;
  for (int j = 1; j < n; j++) {
    double* fj = f + 3 * j;
    double* q = &s->q[3 * j];
    const double ls = 0.5 * lineTangent(s->r.data(), j, q);
    fj[2] -= l.mnode * g;
    const double* v = &s->v[3 * j];
    s->ie[2 * j] = s->im[2 * j];
    s->ie[2 * j + 1] = s->im[2 * j + 1];
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
    // 1 / (m + h c) = im / (1 + h c im)
    s->ie[2 * j] /= 1 + 2 * h * ls * dn * nn * s->ie[2 * j];
    s->ie[2 * j + 1] /= 1 + 2 * h * ls * dt * std::fabs(vq) * s->ie[2 * j + 1];
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
    const double in = 1 / n;
    for (int k = 0; k < 3; k++) q[k] = d[k] * in;
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
// the most sub-steps of one step
static const int kMaxSub = 10000;

double lineStableStep(const LineWater& w, const Line& l) {
  // the axial stiffness, internal damping and bed are implicit (backward
  // Euler: every axial mode is stable at any step); the transverse modes of
  // a segment of tension T, stiffness T / l0, are explicit and undamped:
  // the highest, neighbours against each other, has omega_t = 2 sqrt(T /
  // (l0 m)), stable for h < 2 / omega_t = sqrt(l0 m / T) (docs/mooring.md
  // "Integration"). Added mass only slows the modes, so the dry mass gives
  // the bound; here at T = kOverStrain EA
  (void)w;
  return kSafety * std::sqrt(l.l0 * l.mnode / (kOverStrain * l.t.ea));
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
  s->qs.assign(3 * l.nseg, 0.0);
  s->im.assign(2 * (l.nseg + 1), 0.0);
  s->ie.assign(2 * (l.nseg + 1), 0.0);
  s->tseg.assign(l.nseg, 0.0);
  s->td.assign(l.nseg, 0.0);
  s->tri.assign(4 * l.nseg, 0.0);
  s->es.assign(l.nseg, 0.0);
  s->wet.assign(l.nseg + 1, 1);
  s->st.assign(34 * (l.nseg + 1), 0.0);
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

// v_j += h M_j^-1 f
static inline void pushNode(LineState* s, int j, double h, const double f[3]) {
  const double* q = &s->q[3 * j];
  const double imn = s->ie[2 * j], imt = s->ie[2 * j + 1], fq = dot3(f, q);
  double* v = &s->v[3 * j];
  for (int k = 0; k < 3; k++) v[k] += h * (imn * f[k] + (imt - imn) * fq * q[k]);
}

// solve for the implicit tension increments d_s of the segments at the end
// of a sub-step (backward Euler in the axial stiffness and internal
// damping: docs/mooring.md "Integration"): d_s = c_s q_s . (v'_{s+1} -
// v'_s) + o_s, v' = v* + h M^-1 (d_j q_j - d_{j-1} q_{j-1}), c_s = (h EA +
// BA) / l0 on a segment in the solve (o_s = EA e_s < 0 on one slack now,
// else 0), c_s = 0 off it: a tridiagonal system in the scalars d_s solved
// by the Thomas algorithm. Its coefficients a . M_j^-1 b = imn_j a . b +
// (imt_j - imn_j) (a . t_j) (b . t_j) (node j's inverse masses across and
// along its tangent t_j, drag implicit: s->ie) take three dot products per segment: q_s . t_s,
// q_s . t_{s+1} and q_s . q_{s+1} (q_s . q_s = 1). Segments in fix hold
// d_s = -tseg_s (their total tension is zero)
static void tensionSolve(const Line& l, double h, const char* fix, LineState* s) {
  const int n = l.nseg;
  double* cp = s->tri.data();
  double* dp = cp + n;
  const double* cs = dp + n;
  const double* os = cs + n;
  // carried from segment s - 1: q_{s-1} . t_s and q_{s-1} . q_s
  double prevAt = 0, prevQq = 0;
  for (int i = 0; i < n; i++) {
    const double* q = &s->qs[3 * i];
    double c = cs[i], lo = 0, up = 0, diag = 1, rhs = 0;
    const double at0 = i > 0 ? dot3(q, &s->q[3 * i]) : 0;  // q_s . t_s
    const double at1 = i + 1 < n ? dot3(q, &s->q[3 * i + 3]) : 0;  // q_s . t_{s+1}
    const double qq = i + 1 < n ? dot3(q, q + 3) : 0;  // q_s . q_{s+1}
    if (fix && fix[i]) {
      rhs = -s->tseg[i];
    } else if (c > 0) {
      const double* va = &s->v[3 * i];
      const double* vb = &s->v[3 * i + 3];
      rhs = c * (q[0] * (vb[0] - va[0]) + q[1] * (vb[1] - va[1]) + q[2] * (vb[2] - va[2])) + os[i];
      if (i + 1 < n) {
        const double imn = s->ie[2 * i + 2], dm = s->ie[2 * i + 3] - imn;
        const double bt = dot3(q + 3, &s->q[3 * i + 3]);  // q_{s+1} . t_{s+1}
        diag += h * c * (imn + dm * at1 * at1);
        up = -h * c * (imn * qq + dm * at1 * bt);
      }
      if (i > 0) {
        const double imn = s->ie[2 * i], dm = s->ie[2 * i + 1] - imn;
        diag += h * c * (imn + dm * at0 * at0);
        lo = -h * c * (imn * prevQq + dm * at0 * prevAt);
      }
    }
    prevAt = at1;
    prevQq = qq;
    const double iden = 1 / (diag - (i > 0 ? lo * cp[i - 1] : 0));
    cp[i] = up * iden;
    dp[i] = (rhs - (i > 0 ? lo * dp[i - 1] : 0)) * iden;
  }
  s->td[n - 1] = dp[n - 1];
  for (int i = n - 2; i >= 0; i--) s->td[i] = dp[i] - cp[i] * s->td[i + 1];
}

// the implicit tension increments (tensionSolve) of the segments taut now
// or taut at the end of the sub-step by v* (a slack one enters with its
// EA e < 0), kept from making a segment's total tension compressive: a
// segment whose EA e + d_s < 0 is solved again with a total of zero (one
// pass); then applied to the inner nodes' v. s->tseg becomes the tension
// at the end of the sub-step
static void tensionStep(const Line& l, double h, LineState* s) {
  const int n = l.nseg;
  double* cs = s->tri.data() + 2 * n;
  double* os = cs + n;
  const double c0 = (h * l.t.ea + std::max(l.t.ba, 0.0)) / l.l0;
  bool any = false;
  for (int i = 0; i < n; i++) {
    const double* q = &s->qs[3 * i];
    const double* va = &s->v[3 * i];
    const double* vb = &s->v[3 * i + 3];
    // the strain now (segment length in tseg's stead when slack: es)
    const double e = s->es[i];
    const double de = h * (q[0] * (vb[0] - va[0]) + q[1] * (vb[1] - va[1]) +
                           q[2] * (vb[2] - va[2])) / l.l0;
    const bool in = e > 0 || e + de > 0;
    cs[i] = in ? c0 : 0;
    os[i] = in && e < 0 ? l.t.ea * e : 0;
    any |= in;
  }
  if (!any) return;
  tensionSolve(l, h, nullptr, s);
  any = false;
  for (int i = 0; i < n; i++) any |= s->tseg[i] + s->td[i] < 0;
  if (any) {
    char fix[1024];  // nseg <= 1000 (moorconfig.cc)
    for (int i = 0; i < n; i++) fix[i] = s->tseg[i] + s->td[i] < 0;
    tensionSolve(l, h, fix, s);
  }
  for (int j = 1; j < n; j++) {
    const double *qa = &s->qs[3 * j - 3], *qb = &s->qs[3 * j];
    const double da = s->td[j - 1], db = s->td[j];
    const double f[3] = {db * qb[0] - da * qa[0], db * qb[1] - da * qa[1],
                         db * qb[2] - da * qa[2]};
    pushNode(s, j, h, f);
  }
  for (int i = 0; i < n; i++) s->tseg[i] = std::max(s->tseg[i] + s->td[i], 0.0);
}

// node j on the bed: its vertical spring k and damper c per contact area
// in backward Euler, linearised (v_z' = (v_z + h k' p / m) / (1 + h (c' +
// h k') / m), k' = k d l0, p the penetration), then friction: a damper of
// coefficient mu F_n / max(|v|, vs) along and across the line, implicit
// too, so neither sets a step limit (docs/mooring.md "Seabed")
static void bedStep(const LineWater& w, const Line& l, double h, int j, LineState* s) {
  const Seabed& bed = *w.bed;
  const double pen = bed.z - s->r[3 * j + 2];
  if (!(pen > 0)) return;
  double* v = &s->v[3 * j];
  const double* q = &s->q[3 * j];
  const double kb = bed.k * l.t.diam * l.l0, cb = bed.c * l.t.diam * l.l0;
  const double m = 1 / s->ie[2 * j];
  const double vz = (v[2] + h * kb * pen / m) / (1 + h * (cb + h * kb) / m);
  const double fn = kb * (pen - h * vz) - cb * vz;
  if (!(fn > 0)) return;  // lifting off: no contact force
  v[2] = vz;
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

// one sub-step of length h of the inner nodes: v from the explicit forces
// at (r, v), the axial stiffness and internal damping (linearised along
// each segment) and the seabed implicitly at the new v, then r from the
// new v (backward Euler in those, symplectic Euler in the transverse
// elastic and fluid forces; docs/mooring.md "Integration"). The end nodes' velocities are already
// those at the end of the sub-step
static void subStep(const LineWater& w, const Line& l, double h, double tau, LineState* s) {
  nodeForces(w, l, tau, h, s);
  for (int j = 1; j < l.nseg; j++) pushNode(s, j, h, &s->f[3 * j]);
  tensionStep(l, h, s);
  for (int j = 1; j < l.nseg; j++) {
    bedStep(w, l, h, j, s);
    for (int k = 0; k < 3; k++) s->r[3 * j + k] += h * s->v[3 * j + k];
  }
}

// the unstretched length resting on the bed [m]: each inner node counts
// for the share of its weight w_j l0 (submerged, or dry above the surface)
// the bed carries, F_n / (w_j l0) clipped to [0, 1], times l0, so the
// touchdown falls between nodes where the bed carries part of one; an end
// on the bed adds its half segment when its neighbour rests. In a static
// line this is L - (V_F + V_A) / w, the length whose weight the fairlead
// and anchor do not carry, the catenary's L_B (Jonkman 2007 eq. 4-3);
// a line lighter than water counts the nodes below the bed
static double bedLength(const LineWater& w, const Line& l, const LineState& s) {
  const Seabed& bed = *w.bed;
  const double kb = bed.k * l.t.diam * l.l0, cb = bed.c * l.t.diam * l.l0;
  const double wd = l.mnode * w.sea->g, wb = w.sea->rho * l.vnode * w.sea->g;
  const int n = l.nseg;
  double on = 0, first = 0, last = 0;
  for (int j = 1; j < n; j++) {
    const double pen = bed.z - s.r[3 * j + 2];
    if (!(pen > 0)) continue;
    const double wj = wd - (s.wet[j] ? wb : 0);
    const double fn = std::max(kb * pen - cb * s.v[3 * j + 2], 0.0);
    const double f = wj > 0 ? std::min(fn / wj, 1.0) : 1.0;
    on += f;
    if (j == 1) first = f;
    if (j == n - 1) last = f;
  }
  const double tol = 1e-3 * l.t.diam;
  if (s.r[2] <= bed.z + tol) on += 0.5 * first;
  if (s.r[3 * n + 2] <= bed.z + tol) on += 0.5 * last;
  return on * l.l0;
}

void lineStep(const LineWater& w, const Line& l, double t, double dt, const double e0[6],
              const double e1[6], LineState* s) {
  setEnds(l, 0, e0, e1, s);
  if (!(s->tw >= 0) || t < s->tw || t - s->tw >= w.refresh) waterAt(w, l, t, s);
  // sub-steps as long as the step while the largest tension T (at the end
  // of the last sub-step) keeps the explicit transverse modes stable,
  // else 0.8 of 2 / omega_t, omega_t = 2 sqrt(T / (l0 m)) (lineStableStep);
  // at most kMaxSub of them (past that the line goes non-finite and is named)
  double done = 0;
  for (int i = 0; done < dt; i++) {
    double tmax = 0;
    for (int k = 0; k < l.nseg; k++) tmax = std::max(tmax, s->tseg[k]);
    double hs = dt - done;
    if (tmax * hs * hs > kSafety * kSafety * l.l0 * l.mnode) {
      hs = kSafety * std::sqrt(l.l0 * l.mnode / tmax);
    }
    double left = std::ceil((dt - done) / hs * (1 - 1e-12));
    if (!(left > 1) || i + 1 >= kMaxSub) left = 1;
    const double h = (dt - done) / left;
    const double a = left == 1 ? 1.0 : (done + h) / dt;
    // the ends' velocities at the end of the sub-step (the implicit
    // damping's boundary values), their positions at its start
    for (int k = 3; k < 6; k++) {
      s->v[k - 3] = s->end0[k] + a * (e0[k] - s->end0[k]);
      s->v[3 * l.nseg + k - 3] = s->end1[k] + a * (e1[k] - s->end1[k]);
    }
    subStep(w, l, h, t + done - s->tw, s);
    done = left == 1 ? dt : done + h;
    setEnds(l, a, e0, e1, s);
  }
  std::copy(e0, e0 + 6, s->end0);
  std::copy(e1, e1 + 6, s->end1);
  // overload, and what rests on the bed
  s->over = 0;
  const double lmax2 = (1 + kOverStrain) * l.l0 * (1 + kOverStrain) * l.l0;
  for (int i = 0; i < l.nseg; i++) {
    const double* a = &s->r[3 * i];
    const double* b = &s->r[3 * i + 3];
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    if (dot3(d, d) > lmax2) s->over++;
  }
  s->bedlen = bedLength(w, l, *s);
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
  // the continuous catenary is the start of the discrete line's own
  // equilibrium: with long segments its nodes' chords fall short of the
  // stretched arc, and the line would start slack (docs/mooring.md)
  const bool eq = lineStatic(w, l, s);
  s->bedlen = ok ? c.lb : 0;
  s->tw = -1;
  return eq;
}

}  // namespace mjb
