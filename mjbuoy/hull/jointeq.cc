// jointeq: equilibrium of a hull along its slide and hinge joints (jointeq.h)
#include "hull/jointeq.h"

#include <algorithm>
#include <cmath>

#include "hull/pressure.h"
#include "util/fmt.h"

namespace mjb {

void jointForce(const mjModel* m, mjData* d, const EqWater& w, const std::vector<int>& jnt,
                double* q) {
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mju_zero(d->qvel, m->nv);
  mj_comVel(m, d);
  // qvel 0: the bias force is gravity's, -Q_gravity
  mju_zero(d->qfrc_applied, m->nv);
  mj_rne(m, d, 0, d->qfrc_applied);
  mju_scl(d->qfrc_applied, d->qfrc_applied, -1, m->nv);
  // flat-water pressure rho g depth on each wet triangle: force
  // -rho g dA n, torque -rho g drA x n about the body origin (pressure.h)
  const double rg = w.rho * w.g;
  for (const EqHull& h : w.hull) {
    const mjtNum* R = d->xmat + 9 * h.body;
    const mjtNum* x = d->xpos + 3 * h.body;
    double f[3] = {0, 0, 0}, t[3] = {0, 0, 0};
    for (int i = h.t0; i < h.t0 + h.nt; i++) {
      double p[3][3], ht[3];
      for (int k = 0; k < 3; k++) {
        mju_rotVecMat(p[k], w.vert + 3 * w.face[3 * i + k], R);
        ht[k] = x[2] + p[k][2] - w.level;
      }
      Wet wt;
      wetTriangle(p, ht, &wt);
      double c[3];
      mju_cross(c, wt.drA, wt.n);
      for (int k = 0; k < 3; k++) f[k] -= rg * wt.dA * wt.n[k], t[k] -= rg * c[k];
    }
    mjtNum pt[3] = {x[0], x[1], x[2]};
    mj_applyFT(m, d, f, t, pt, h.body, d->qfrc_applied);
  }
  for (size_t k = 0; k < jnt.size(); k++) {
    const int j = jnt[k], a = m->jnt_qposadr[j];
    q[k] = d->qfrc_applied[m->jnt_dofadr[j]] -
           m->jnt_stiffness[j] * (d->qpos[a] - m->qpos_spring[a]);
  }
  mju_zero(d->qfrc_applied, m->nv);
}

namespace {

// x solving A x = b (n x n, row-major; A overwritten) by Gaussian
// elimination with partial pivoting; false if singular
bool solve(int n, std::vector<double> A, std::vector<double>* b) {
  std::vector<double>& x = *b;
  for (int c = 0; c < n; c++) {
    int p = c;
    for (int r = c + 1; r < n; r++)
      if (std::fabs(A[n * r + c]) > std::fabs(A[n * p + c])) p = r;
    if (!(std::fabs(A[n * p + c]) > 0)) return false;
    for (int k = 0; k < n; k++) std::swap(A[n * c + k], A[n * p + k]);
    std::swap(x[c], x[p]);
    for (int r = c + 1; r < n; r++) {
      double f = A[n * r + c] / A[n * c + c];
      for (int k = c; k < n; k++) A[n * r + k] -= f * A[n * c + k];
      x[r] -= f * x[c];
    }
  }
  for (int c = n - 1; c >= 0; c--) {
    for (int k = c + 1; k < n; k++) x[c] -= A[n * c + k] * x[k];
    x[c] /= A[n * c + c];
  }
  return true;
}

// whether the symmetric part of -J (J scaled by the caps s, so that every
// entry is an energy) is positive semi-definite: the equilibrium is stable
// (LDL^T pivots >= -1e-6 of the largest diagonal entry)
bool stable(int n, const std::vector<double>& J, const std::vector<double>& s) {
  std::vector<double> S(n * n);
  double big = 0;
  for (int i = 0; i < n; i++)
    for (int k = 0; k < n; k++) {
      S[n * i + k] = -0.5 * (J[n * i + k] + J[n * k + i]) * s[i] * s[k];
      if (i == k) big = std::max(big, std::fabs(S[n * i + i]));
    }
  for (int c = 0; c < n; c++) {
    double p = S[n * c + c];
    if (p < -1e-6 * big) return false;
    if (p <= 1e-12 * big) continue;  // a neutral direction (a yaw hinge)
    for (int r = c + 1; r < n; r++) {
      double f = S[n * r + c] / p;
      for (int k = c; k < n; k++) S[n * r + k] -= f * S[n * c + k];
    }
  }
  return true;
}

// joint j for messages: joint "name", or joint k of body "name"
std::string jointName(const mjModel* m, int j) {
  const char* nm = m->names + m->name_jntadr[j];
  if (*nm) return "joint \"" + std::string(nm) + "\"";
  const int b = m->jnt_bodyid[j];
  return "joint " + std::to_string(j - m->body_jntadr[b] + 1) + " of body \"" +
         std::string(m->names + m->name_bodyadr[b]) + "\"";
}

// the hulls' vertical extent [m] at d (after mj_kinematics)
double hullHeight(const mjData* d, const EqWater& w) {
  double lo = INFINITY, hi = -INFINITY;
  for (const EqHull& h : w.hull)
    for (int i = h.t0; i < h.t0 + h.nt; i++)
      for (int k = 0; k < 3; k++) {
        const double* v = w.vert + 3 * w.face[3 * i + k];
        const mjtNum* R = d->xmat + 9 * h.body;
        double z = d->xpos[3 * h.body + 2] + R[6] * v[0] + R[7] * v[1] + R[8] * v[2];
        lo = std::min(lo, z), hi = std::max(hi, z);
      }
  return hi > lo ? hi - lo : 0;
}

// why no balance was found: the joint still pushed hardest (Q [N or N m],
// s its step cap) after the search
std::string unbalanced(const mjModel* m, const std::vector<int>& jnt,
                       const std::vector<double>& Q, const std::vector<double>& s) {
  int worst = 0;
  for (int k = 0; k < (int)jnt.size(); k++)
    if (std::fabs(Q[k] * s[k]) > std::fabs(Q[worst] * s[worst])) worst = k;
  return "gravity, its joints' springs and the flat-water buoyancy do not balance along "
         "its joints (" + jointName(m, jnt[worst]) + " is still " +
         "pushed with " + fmt(Q[worst]) + (m->jnt_type[jnt[worst]] == mjJNT_SLIDE ? " N" :
         " N m") + " after 200 steps: it sinks, flies off or is held by nothing)";
}

// "" or the first limited joint whose equilibrium q lies outside its range
std::string beyondRange(const mjModel* m, const std::vector<int>& jnt,
                        const std::vector<double>& q) {
  for (int k = 0; k < (int)jnt.size(); k++) {
    const int j = jnt[k];
    if (!m->jnt_limited[j]) continue;
    const double lo = m->jnt_range[2 * j], hi = m->jnt_range[2 * j + 1];
    if (q[k] < lo || q[k] > hi) {
      return "its equilibrium " + fmt(q[k]) + " along " + jointName(m, j) +
             " is beyond the joint's range [" + fmt(lo) + ", " + fmt(hi) + "]";
    }
  }
  return "";
}

}  // namespace

std::string jointEquilibrium(const mjModel* m, mjData* d, const EqWater& w,
                             const std::vector<int>& jnt) {
  const int n = jnt.size();
  std::vector<double> q0(n), s(n), Q(n), Qt(n), J(n * n), dq(n);
  for (int k = 0; k < n; k++) q0[k] = d->qpos[m->jnt_qposadr[jnt[k]]];
  auto set = [&](const std::vector<double>& q) {
    for (int k = 0; k < n; k++) d->qpos[m->jnt_qposadr[jnt[k]]] = q[k];
  };
  mj_kinematics(m, d);
  const double H = std::max(hullHeight(d, w), 1e-3);
  // steps of at most a quarter of the hulls' height or 0.25 rad; s_i Q_i
  // is then an energy [J], and the merit sum (s_i Q_i)^2 mixes none of units
  for (int k = 0; k < n; k++) s[k] = m->jnt_type[jnt[k]] == mjJNT_SLIDE ? 0.25 * H : 0.25;
  // converged: every s_i Q_i within 1e-9 of the weight times the height
  const double tol = 1e-9 * (m->body_subtreemass[0] * w.g + 1e-9) * H;
  auto merit = [&](const std::vector<double>& f) {
    double e = 0, big = 0;
    for (int k = 0; k < n; k++) e += f[k] * s[k] * f[k] * s[k], big = std::max(big, std::fabs(f[k] * s[k]));
    return std::make_pair(e, big);
  };
  std::vector<double> q = q0;
  // J = dQ/dq by forward differences of 1e-7 of each cap
  auto jacobian = [&](const std::vector<double>& x) {
    for (int c = 0; c < n; c++) {
      std::vector<double> qh = x;
      const double h = 1e-7 * s[c];
      qh[c] += h;
      set(qh);
      jointForce(m, d, w, jnt, Qt.data());
      for (int r = 0; r < n; r++) J[n * r + c] = (Qt[r] - Q[r]) / h;
    }
  };
  set(q);
  jointForce(m, d, w, jnt, Q.data());
  double mu = 1e-3;
  bool done = false;
  for (int it = 0; it < 200 && !done; it++) {
    if (merit(Q).second <= tol) {
      done = true;
      break;
    }
    jacobian(q);
    // (mu D - J) dq = Q: Newton's step for small mu, a step along the
    // force where J vanishes (a dry or fully submerged hull on a slide)
    bool moved = false;
    for (int tries = 0; tries < 16 && !moved; tries++, mu *= 10) {
      std::vector<double> A(n * n);
      for (int i = 0; i < n * n; i++) A[i] = -J[i];
      for (int i = 0; i < n; i++)
        A[n * i + i] += mu * std::max({std::fabs(J[n * i + i]), std::fabs(Q[i]) / s[i], 1e-300});
      dq = Q;
      if (!solve(n, A, &dq)) continue;
      double r = 0;
      for (int k = 0; k < n; k++) r = std::max(r, std::fabs(dq[k]) / s[k]);
      if (!(r < INFINITY)) continue;
      std::vector<double> qt = q;
      for (int k = 0; k < n; k++) qt[k] += dq[k] / std::max(r, 1.0);
      set(qt);
      jointForce(m, d, w, jnt, Qt.data());
      if (merit(Qt).first <= merit(Q).first) {
        q = qt, Q = Qt, moved = true;
        mu = std::max(mu / 100, 1e-9);
      }
    }
    if (!moved) break;
  }
  std::string why;
  if (!done) {
    why = unbalanced(m, jnt, Q, s);
  } else if (set(q), jacobian(q), !stable(n, J, s)) {
    why = "its only balance of gravity, joint springs and flat-water buoyancy along its "
          "joints is unstable";
  }
  if (why.empty()) why = beyondRange(m, jnt, q);
  set(why.empty() ? q : q0);
  mj_kinematics(m, d);
  mj_comPos(m, d);
  return why;
}

}  // namespace mjb
