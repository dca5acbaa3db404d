// radiation per step, inside mjcb_passive (docs/physics.md section 14):
// A_inf into MuJoCo's inertia matrix, Kirchhoff and memory forces
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "radiation/radiation.h"
#include "radiation/radspeed.h"
#include "sea/sea.h"
#include "util/bodylabel.h"
#include "util/stepclock.h"
#include "util/vmath.h"

namespace mjb {

namespace {

void cross(const double* a, const double* b, double* c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

double dot6(const double* a, const double* b) {
  double s = 0;
  for (int i = 0; i < 6; i++) s += a[i] * b[i];
  return s;
}

void mul6(const double* A, const double* x, double* y) {
  for (int i = 0; i < 6; i++) y[i] = dot6(A + 6 * i, x);
}

// sum_k K[a + k] x[i - k], k < n, from Kr (K reversed, nk samples): a
// forward dot product of contiguous arrays, which runs in vector lanes
// (vmath.h); Kr[nk - a - n + m] = K[a + n - 1 - m] meets x[i - n + 1 + m]
double dotBack(const double* Kr, int nk, int a, const double* x, int i, int n) {
  if (n <= 0) return 0;
  return vDot(n, Kr + nk - a - n, x + i - n + 1);
}

// the parts of pair p's sum over n >= 2 samples that do not read the
// newest one (at head): the oldest sample's trapezoid product q[0], the
// samples 1 .. k1 back without wrap q[1] and the rest q[2], k1 = min(n -
// 2, head); all of the sum's work, done before the newest sample exists
void pairParts(const RadBody& rb, size_t p, const double* hist, int nh, int head, int n,
               double q[3]) {
  const double* Kr = rb.Kr->data() + p * rb.nk;  // K[k] = Kr[nk - 1 - k]
  const double* h = hist + nh * (rb.pair[p] % 6);
  const int k1 = std::min(n - 2, head);
  q[0] = Kr[rb.nk - n] * h[(head - n + 1 + nh) % nh];
  q[1] = dotBack(Kr, rb.nk, 1, h, head - 1, k1);
  q[2] = dotBack(Kr, rb.nk, k1 + 1, h, head - k1 - 1 + nh, n - 2 - k1);
}

// rb's memory wrench f from its pairs' parts q (3 each, pairParts) and the
// newest samples: f_i -= dt (K(0) nu_j(t) / 2 + q[0] / 2 + q[1] + q[2])
void memoryFrom(const RadBody& rb, const double* hist, int nh, int head, int n, double dt,
                const double* q, double* f) {
  std::memset(f, 0, 6 * sizeof(double));
  if (n < 2) return;
  for (size_t p = 0; p < rb.pair.size(); p++) {
    const double* Kr = rb.Kr->data() + p * rb.nk;
    const double* h = hist + nh * (rb.pair[p] % 6);
    double sum = 0.5 * (Kr[rb.nk - 1] * h[head] + q[3 * p]);
    sum += q[3 * p + 1];
    sum += q[3 * p + 2];
    f[rb.pair[p] / 6] -= dt * sum;
  }
}

// samples a convolution body uses now (0: none, or state-space memory)
int convSamples(const RadBody& rb, int count) {
  return rb.nk && !rb.ss.size() ? std::min(count, rb.nk) : 0;
}

// the pairs' parts (RadState pre) of chunk c of nc of all bodies' pairs
struct PreJob {
  const Radiation* r;
  RadState* s;
  int nc;
};
void preChunk(void* arg, int c, int) {
  const PreJob& j = *static_cast<const PreJob*>(arg);
  const RadState& s = *j.s;
  const int np = s.poff.back();
  const int g0 = int(long(np) * c / j.nc), g1 = int(long(np) * (c + 1) / j.nc);
  size_t ib = std::upper_bound(s.poff.begin(), s.poff.end(), g0) - s.poff.begin() - 1;
  for (int g = g0; g < g1; g++) {
    while (g >= s.poff[ib + 1]) ib++;
    const RadBody& rb = j.r->rb[ib];
    const int n = convSamples(rb, s.count);
    if (n < 2) continue;
    pairParts(rb, g - s.poff[ib], s.hist.data() + 6 * j.r->nh * ib, j.r->nh, s.head, n,
              j.s->pre.data() + 3 * g);
  }
}

// multiply-adds of the convolutions below which the pool's hand-over
// (about a microsecond with its workers polling) is not worth it
const long kPoolWork = 16384;

// every convolution body's pairParts for this step, shared among the
// pool's threads when there is enough work; the same values either way
void preParts(const Radiation& r, RadState* s, Pool* pool) {
  long work = 0;
  for (size_t ib = 0; ib < r.rb.size(); ib++) {
    work += long(convSamples(r.rb[ib], s->count)) * long(r.rb[ib].pair.size());
  }
  if (work == 0) return;
  PreJob j{&r, s, std::min(s->poff.back(), 16)};
  if (pool && work >= kPoolWork && poolRun(pool, preChunk, &j, j.nc)) return;
  j.nc = 1;
  preChunk(&j, 0, 0);
}

}  // namespace

// the body at rest before the first sample (radiation.h)
void radMemory(const RadBody& rb, const double* hist, int nh, int head, int count, double dt,
               double* f) {
  const int n = std::min(count, rb.nk);
  double q[3 * 36];  // (at most 36 pairs)
  for (size_t p = 0; n >= 2 && p < rb.pair.size(); p++) {
    pairParts(rb, p, hist, nh, head, n, q + 3 * p);
  }
  memoryFrom(rb, hist, nh, head, n, dt, q, f);
}

namespace {

// body-axes Jacobian J (6 x n, column k for rb.dof[k]) at rb's reference
// point p, its velocity nu = J qdot, and bias, the rate of change of nu
// with qacc = 0: the spatial acceleration sum cdof_dot qdot (alpha, a_o at
// o) moved to p and turned into body axes (docs/physics.md section 14)
void kinematics(const RadBody& rb, const mjModel* m, const mjData* d, double* J, double nu[6],
                double bias[6]) {
  const mjtNum* R = d->xmat + 9 * rb.body;
  const mjtNum* o = d->subtree_com + 3 * m->body_rootid[rb.body];
  double p[3], po[3], ab[6] = {0};
  mju_rotVecMat(p, rb.ref, R);
  mju_addTo3(p, d->xpos + 3 * rb.body);
  mju_sub3(po, p, o);
  std::memset(nu, 0, 6 * sizeof(double));
  for (size_t k = 0; k < rb.dof.size(); k++) {
    const int i = rb.dof[k];
    const mjtNum* c = d->cdof + 6 * i;  // [angular; linear at o]
    double lin[3];
    cross(c, po, lin);
    mju_addTo3(lin, c + 3);
    mju_rotVecMatT(J + 6 * k, lin, R);
    mju_rotVecMatT(J + 6 * k + 3, c, R);
    for (int j = 0; j < 6; j++) {
      nu[j] += J[6 * k + j] * d->qvel[i];
      ab[j] += d->cdof_dot[6 * i + j] * d->qvel[i];
    }
  }
  double ap[3];
  cross(ab, po, ap);
  mju_addTo3(ap, ab + 3);
  mju_rotVecMatT(bias, ap, R);
  mju_rotVecMatT(bias + 3, ab, R);
}

// the added mass's velocity wrench in body axes at ref: -A bias plus
// Kirchhoff's terms, with (p, h) = A nu: F = -w x p, M = -w x h - v x p
// [Newman 1977, sec. 4.13; Fossen 2011, -C_A(nu) nu]
void kirchhoff(const double A[36], const double nu[6], const double bias[6], double W[6]) {
  double P[6], t[3];
  mul6(A, nu, P);
  mul6(A, bias, W);
  for (int j = 0; j < 6; j++) W[j] = -W[j];
  cross(nu + 3, P, t);
  mju_subFrom3(W, t);
  cross(nu + 3, P + 3, t);
  mju_subFrom3(W + 3, t);
  cross(nu, P, t);
  mju_subFrom3(W + 3, t);
}

// nu and its rate relative to the water moving at U (world): v - R^T U,
// and since d(R^T U)/dt = -w x R^T U for a steady U the rate gains
// w x R^T U (docs/physics.md section 14, "Current"); the rate of a wave's
// U is the incident flow's acceleration, whose force is the excitation's
// (Froude-Krylov and diffraction, section 15), not added here
void relative(const mjtNum* R, const double U[3], double nu[6], double bias[6]) {
  double u[3], t[3];
  mju_rotVecMatT(u, U, R);
  mju_subFrom3(nu, u);
  cross(nu + 3, u, t);
  mju_addTo3(bias, t);
}

// rate [1/s] of the immersion factor si on the memory's clock, from the
// factor at the last step's time and this step's (ss[0], ss[1], kept
// here); an RK4 stage takes its slope from the step's start at tcur
double immRate(int tick, double si, double t, double tcur, double h, double* ss) {
  if (tick == kTickRestart) ss[0] = ss[1] = si;
  if (tick == kTickNew) ss[0] = ss[1];
  if (tick == kTickMid) return t > tcur ? (si - ss[1]) / (t - tcur) : 0;
  ss[1] = si;
  return (ss[1] - ss[0]) / h;
}

// opt.timestep h differs from the step r.dt the memory was made at
// (docs/physics.md section 14, "Changed timestep"): the state-space modes
// step with exp(p h) (s->ssLam, computed once per new h, no allocation);
// a convolution's samples are at r.dt, so its memory is left out. Noted
// once per history
void timestepMoved(const Radiation& r, const mjModel* m, double h, RadState* s,
                   std::string* notices) {
  if (s->ssDt != h) {
    for (const RadBody& rb : r.rb)
      for (int k = 0; k < rb.ss.size(); k++) s->ssLam[rb.soff + k] = std::exp(rb.ss.p[k] * h);
    s->ssDt = h;
  }
  if (s->dtTold) return;
  s->dtTold = true;
  for (const RadBody& rb : r.rb) {
    char line[512], who[128];
    const char* name = bodyLabel(m, rb.body, who, sizeof who);
    if (rb.ss.size()) {
      std::snprintf(line, sizeof line, "body %s: opt.timestep is %g s, not the %g s of "
                    "mjb_attach: its state-space radiation memory follows the new step\n",
                    name, h, r.dt);
    } else if (rb.nk) {
      std::snprintf(line, sizeof line, "body %s: opt.timestep is %g s, but its convolution "
                    "radiation memory is sampled at the %g s of mjb_attach: the memory is left "
                    "out; set opt.timestep before mjb_attach, or use "
                    "mjbuoy.radiation.memorymodel statespace\n", name, h, r.dt);
    } else {
      continue;
    }
    if (notices->size() + std::strlen(line) < notices->capacity()) *notices += line;
  }
}

// sum of qM's diagonal over the dofs that move rb
double diagSum(const mjModel* m, const mjData* d, const RadBody& rb) {
  double q = 0;
  for (int i : rb.dof) q += d->qM[m->dof_Madr[i]];
  return q;
}

}  // namespace

void radImmersion(const Radiation& r, const double* part, const char* bad, const char* badp,
                  int np, double rhog, RadState* s) {
  for (size_t ib = 0; ib < r.rb.size(); ib++) {
    const RadBody& rb = r.rb[ib];
    if (!(rb.veq > 0)) {
      s->imm[ib] = 1;
      continue;
    }
    // V = F_z / (rho g): -sum dA n_z of the wet pieces on flat water
    // (eqdraft.h), the same below the wave surface in waves
    double fz = 0;
    bool ok = true;
    for (int b : rb.hb) {
      ok = ok && !bad[b] && !badp[np * b] && std::isfinite(part[6 * b + 2]);
      fz += part[6 * b + 2];
    }
    // a pressure that is not finite is named by finishWrench: keep the last
    if (!ok) continue;
    const double v = fz / (rhog * kImmKnee * rb.veq);
    s->imm[ib] = v >= 1 ? 1.0 : v > 0 ? v : 0.0;
  }
}

namespace {

// moves the history's ring (head, count) on a new step or a restart
void advanceHistory(const Radiation& r, int tick, RadState* s) {
  if (tick == kTickRestart) {
    s->head = 0;
    s->count = 0;
  }
  if (tick == kTickNew) s->head = (s->head + 1) % r.nh;
  if (tick == kTickNew || tick == kTickRestart) s->count = std::min(s->count + 1, r.nh);
}

// whether qM lacks A_inf: rebuilt since the last add (pos: mj_fwdPosition's count)
bool massLacksAdded(const Radiation& r, const mjModel* m, const mjData* d, const RadState* s,
                    long pos) {
  // with the same count mj_crb may still have rebuilt qM since (a reset in
  // between): then some body's diagonal sum is not the one left after adding
  bool addM = pos != s->mstamp;
  for (size_t ib = 0; ib < r.rb.size() && !addM; ib++)
    addM = !(diagSum(m, d, r.rb[ib]) == s->mdiag[ib]);
  return addM;
}

// body velocity relative to the current (nu, bias) and to current and waves (nw, bw); false if
// one is not finite
bool waterRelative(const RadBody& rb, const mjModel* m, const mjData* d, const Sea& sea,
                   const double cur[3], double* J, double nu[6], double bias[6], double nw[6],
                   double bw[6]) {
  kinematics(rb, m, d, J, nu, bias);
  // the Kirchhoff terms see the water at the COM (current and waves), the
  // memory only the current (docs/physics.md section 14, "Kirchhoff terms
  // in waves")
  double uw[3];
  sea.velocity(d->xipos + 3 * rb.body, d->time, uw);
  for (int j = 0; j < 6; j++) {
    nw[j] = nu[j];
    bw[j] = bias[j];
  }
  relative(d->xmat + 9 * rb.body, uw, nw, bw);
  relative(d->xmat + 9 * rb.body, cur, nu, bias);
  return std::isfinite(dot6(nu, nu)) && std::isfinite(dot6(bias, bias)) &&
         std::isfinite(dot6(nw, nw)) && std::isfinite(dot6(bw, bw));
}

// adds s J^T A_inf J to the body's dofs in qM (kg, kg m, kg m^2)
void addBodyMass(const RadBody& rb, const mjModel* m, mjData* d, RadState* s, double si,
                 const double* J) {
  const int n = rb.dof.size();
  // M(dof[a], dof[b]) += J_a^T A J_b, b an ancestor (later in the chain)
  double* AJ = s->ajac.data();
  for (int k = 0; k < n; k++) mul6(rb.A, J + 6 * k, AJ + 6 * k);
  for (int a = 0; a < n; a++) {
    const int adr = m->dof_Madr[rb.dof[a]];
    for (int b = a; b < n; b++) d->qM[adr + b - a] += si * dot6(J + 6 * a, AJ + 6 * b);
  }
}

// the wrench without memory (N, N m): s times the Kirchhoff terms, water entry, viscous roll
void instantWrench(const Radiation& r, const RadBody& rb, size_t ib, int tick, double si,
                   double t, double h, const double nw[6], const double bw[6],
                   const double nu[6], RadState* s, double W[6]) {
  kirchhoff(rb.A, nw, bw, W);
  for (int j = 0; j < 6; j++) W[j] *= si;  // linear in A: the terms of s A_inf
  // water entry: the hull takes up the momentum s A nu_w of the water
  // it wets as s rises, -ds/dt A nu_w; on exit the water keeps its own
  // (docs/physics.md section 14, "Water entry")
  const double ds = immRate(tick, si, t, s->tcur, h, s->sstep.data() + 2 * ib);
  if (r.entry && ds > 0) {
    double P[6];
    mul6(rb.A, nw, P);
    for (int j = 0; j < 6; j++) W[j] -= ds * P[j];
  }
  // viscous roll damping about the body's x axis, on the wetted share
  // (docs/physics.md section 14, "Viscous roll damping")
  const double p = nu[3];
  W[3] -= si * (rb.roll[0] + rb.roll[1] * std::fabs(p)) * p;
}

// memory force fm (N, N m) of the wetted velocity s nu; the step's first call records nu and
// evaluates the state space or the convolution
void memoryForce(const Radiation& r, const RadBody& rb, size_t ib, int tick, bool moved,
                 double h, const double nu[6], RadState* s, double* fm) {
  double* hist = s->hist.data() + 6 * r.nh * ib;
  if (rb.ss.size() && tick != kTickMid) {
    // state-space memory (radss.cc), on the same clock as the history
    SsState st{s->ssX.data() + rb.soff, s->ssPw.data() + rb.soff, s->ssNu.data() + 12 * ib,
               s->ssNu.data() + 12 * ib + 6};
    const cplx* lam = moved ? s->ssLam.data() + rb.soff : nullptr;
    if (tick == kTickRestart) {
      ssRestart(rb.ss, st, nu);
    } else if (tick == kTickNew) {
      ssNew(rb.ss, st, nu, lam);
    } else {
      ssSame(st, nu, s->count == 1);
    }
    ssForce(rb.ss, st, h, fm, lam);
  } else if (rb.nk && moved) {
    std::memset(fm, 0, 6 * sizeof(double));
  } else if (rb.nk && tick != kTickMid) {
    for (int j = 0; j < 6; j++) hist[r.nh * j + s->head] = nu[j];
    memoryFrom(rb, hist, r.nh, s->head, convSamples(rb, s->count), r.dt,
               s->pre.data() + 3 * s->poff[ib], fm);
  }
}

// moves the forward-speed terms' ring on a new step or a restart (as advanceHistory)
void advanceSpeedHistory(const Radiation& r, int tick, RadState* s) {
  if (tick == kTickRestart) s->shead = s->scount = 0;
  if (tick == kTickNew) s->shead = (s->shead + 1) % r.nsh;
  if (tick == kTickNew || tick == kTickRestart) s->scount = std::min(s->scount + 1, r.nsh);
}

// Salvesen-Tuck-Faltinsen's forward-speed terms that body axes and the
// Kirchhoff terms leave out: pitch U (L33 * w), yaw -U (L22 * v), U the
// surge speed through the water, w and v the wetted heave and sway
// velocities recorded (docs/physics.md section 14, "Forward speed"); added to fm.
// A state-space memory's own states give them (radspeed.h speedSs), else the ring
void speedForce(const Radiation& r, const RadBody& rb, size_t ib, double u, bool moved,
                double h, const double nu[6], RadState* s, double* fm) {
  if (rb.ss.size()) {
    // the state-space memory's states, just advanced by memoryForce: O(modes)
    SsState st{s->ssX.data() + rb.soff, s->ssPw.data() + rb.soff, s->ssNu.data() + 12 * ib,
               s->ssNu.data() + 12 * ib + 6};
    double c[2];
    speedSs(rb.ss, st, h, c, moved ? s->ssLam.data() + rb.soff : nullptr);
    fm[4] += u * c[1];
    fm[5] -= u * c[0];
    return;
  }
  double* ring = s->shist.data() + 2 * r.nsh * ib;
  ring[s->shead] = nu[1];
  ring[r.nsh + s->shead] = nu[2];
  const double cv = speedConv(rb.Ls, rb.nls, 0, ring, r.nsh, s->shead, s->scount, r.dt);
  const double cw = speedConv(rb.Ls, rb.nls, 1, ring + r.nsh, r.nsh, s->shead, s->scount, r.dt);
  fm[4] += u * cw;
  fm[5] -= u * cv;
}

// names a body whose radiation force is not finite, once, within the notices' reserve
void noteNotFinite(const RadBody& rb, size_t ib, const mjModel* m, const mjData* d,
                   RadState* s, std::string* notices) {
  if (s->told[ib]) return;
  s->told[ib] = 1;
  char line[256], who[128];
  std::snprintf(line, sizeof(line),
                "body %s: radiation force not finite at t = %g s; mjbuoy leaves it out\n",
                bodyLabel(m, rb.body, who, sizeof who), d->time);
  // within the capacity reserved in makeState: no allocation while stepping
  if (notices->size() + std::strlen(line) < notices->capacity()) *notices += line;
}

// moves the couplings' ring on a new step or a restart (as advanceHistory)
void advanceCoupleHistory(const Radiation& r, int tick, RadState* s) {
  if (r.cp.empty()) return;
  if (tick == kTickRestart) s->chead = s->ccount = 0;
  if (tick == kTickNew) s->chead = (s->chead + 1) % r.nch;
  if (tick == kTickNew || tick == kTickRestart) s->ccount = std::min(s->ccount + 1, r.nch);
}

// coupling c's wrench f on body i (body frame) from body j's wetted
// velocities: the memory -dt sum_k w_k K(k dt) nu_j(t - k dt) (trapezoid
// weights) and -A_ij(inf) (nu_j(t) - nu_j(t - dt)) / dt, the last step's
// acceleration (docs/physics.md section 14, "Interaction")
void coupleWrench(const Radiation& r, const RadCouple& c, const RadState* s, double dt,
                  double f[6]) {
  std::memset(f, 0, 6 * sizeof(double));
  const double* h = s->chist.data() + 6 * r.nch * c.j;
  const int n = std::min(s->ccount, c.nk);
  const int hd = s->chead, nk = c.nk;
  const int na = std::min(n, hd + 1);  // the samples back to the ring's start
  for (size_t p = 0; p < c.pair.size() && n >= 2; p++) {
    // Kr[nk - 1 - k] = K(k dt): two forward dot products over the ring
    const double* Kr = c.K.data() + p * nk;
    const double* x = h + r.nch * (c.pair[p] % 6);
    double sum = dotBack(Kr, nk, 0, x, hd, na);
    sum += dotBack(Kr, nk, na, x, hd - na + r.nch, n - na);
    sum -= 0.5 * (Kr[nk - 1] * x[hd] + Kr[nk - n] * x[(hd - n + 1 + r.nch) % r.nch]);
    f[c.pair[p] / 6] -= dt * sum;
  }
  if (s->ccount < 2) return;
  double a[6];
  for (int b = 0; b < 6; b++)
    a[b] = (h[r.nch * b + s->chead] - h[r.nch * b + (s->chead - 1 + r.nch) % r.nch]) / dt;
  for (int k = 0; k < 6; k++) f[k] -= dot6(c.A + 6 * k, a);
}

// every coupling's wrench on its body i, times i's immersion factor, into
// qfrc_passive; recomputed on a step's first call (none after a change of
// timestep: the kernels are sampled at the attach's)
void coupleStep(const Radiation& r, const mjModel* m, mjData* d, RadState* s, int tick,
                bool moved, std::string* notices) {
  for (size_t ic = 0; ic < r.cp.size(); ic++) {
    const RadCouple& c = r.cp[ic];
    double* f = s->fcp.data() + 6 * ic;
    if (moved) {
      std::memset(f, 0, 6 * sizeof(double));
    } else if (tick != kTickMid) {
      coupleWrench(r, c, s, r.dt, f);
    }
    const RadBody& rb = r.rb[c.i];
    double* J = s->jac.data();
    double nu[6], bias[6], W[6];
    kinematics(rb, m, d, J, nu, bias);
    for (int k = 0; k < 6; k++) W[k] = s->imm[c.i] * f[k];
    if (!std::isfinite(dot6(W, W))) {
      noteNotFinite(rb, c.i, m, d, s, notices);
      continue;
    }
    for (size_t k = 0; k < rb.dof.size(); k++) d->qfrc_passive[rb.dof[k]] += dot6(J + 6 * k, W);
  }
}

// one body's radiation: s A_inf into qM (if addM), the wrench into qfrc_passive
void radiateBody(const Radiation& r, const mjModel* m, mjData* d, RadState* s, const Sea& sea,
                 const double cur[3], size_t ib, int tick, bool moved, bool addM,
                 std::string* notices) {
  const RadBody& rb = r.rb[ib];
  const int n = rb.dof.size();
  const double h = m->opt.timestep;
  const double si = s->imm[ib];  // immersion factor (radImmersion)
  double* J = s->jac.data();
  double nu[6], bias[6], nw[6], bw[6];
  if (!waterRelative(rb, m, d, sea, cur, J, nu, bias, nw, bw)) return;
  if (addM) addBodyMass(rb, m, d, s, si, J);

  double W[6];
  instantWrench(r, rb, ib, tick, si, d->time, h, nw, bw, nu, s, W);
  // the memory's input is the wetted surface's velocity s nu: a dry
  // body radiates no waves (docs/physics.md, "Immersion factor")
  const double u = nu[0];  // surge speed through the water [m/s]
  for (int j = 0; j < 6; j++) nu[j] *= si;
  double* fm = s->fmem.data() + 6 * ib;
  if (!r.cp.empty() && tick != kTickMid)
    for (int j = 0; j < 6; j++) s->chist[6 * r.nch * ib + r.nch * j + s->chead] = nu[j];
  memoryForce(r, rb, ib, tick, moved, h, nu, s, fm);
  // the convolution's at the step of attach only; the state space's at any
  if (rb.nls && (rb.ss.size() || (rb.nk && !moved)) && tick != kTickMid)
    speedForce(r, rb, ib, u, moved, h, nu, s, fm);
  for (int j = 0; j < 6; j++) W[j] += si * fm[j];

  if (!std::isfinite(dot6(W, W))) {
    noteNotFinite(rb, ib, m, d, s, notices);
    return;
  }
  for (int k = 0; k < n; k++) d->qfrc_passive[rb.dof[k]] += dot6(J + 6 * k, W);
}

}  // namespace

void radiationStep(const Radiation& r, const mjModel* m, mjData* d, RadState* s, const Sea& sea,
                   std::string* notices, Pool* pool) {
  const double cur[3] = {sea.current[0], sea.current[1], 0};
  if (r.rb.empty()) return;
  const int tick = stepTick(m, d, s);
  // the step in force: another than at attach is followed or noted
  const double h = m->opt.timestep;
  const bool moved = h != r.dt;
  if (moved) timestepMoved(r, m, h, s, notices);
  advanceHistory(r, tick, s);
  advanceSpeedHistory(r, tick, s);
  advanceCoupleHistory(r, tick, s);
  // qM is rebuilt by every mj_fwdPosition; a second callback after the same
  // one (mj_forwardSkip from the velocity stage) finds A_inf in it already
  const long pos = d->timer[mjTIMER_POSITION].number;
  const bool addM = massLacksAdded(r, m, d, s, pos);
  if (tick != kTickMid && !moved) preParts(r, s, pool);
  for (size_t ib = 0; ib < r.rb.size(); ib++)
    radiateBody(r, m, d, s, sea, cur, ib, tick, moved, addM, notices);
  coupleStep(r, m, d, s, tick, moved, notices);
  if (addM) {
    // as mj_fwdPosition does after mj_crb: the integrators, the constraint
    // solver and mj_implicit then all see M + J^T A J
    mj_factorM(m, d);
    if (d->nefc > 0) mj_projectConstraint(m, d);
    s->mstamp = pos;
    for (size_t ib = 0; ib < r.rb.size(); ib++) s->mdiag[ib] = diagSum(m, d, r.rb[ib]);
  }
}

}  // namespace mjb
