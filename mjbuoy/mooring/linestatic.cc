// linestatic: the discrete static equilibrium of a lumped-mass line
// (line.h lineStatic; docs/mooring.md "Initial state")
#include <algorithm>
#include <cmath>
#include <limits>

#include "mooring/line.h"

namespace mjb {

namespace {

// the scratch of the solve, in LineState::st (34 per node)
struct Scratch {
  double* c;   // 9 per node: the diagonal blocks, then their Schur complements' inverses
  double* k;   // 9 per segment: the segment's stiffness block
  double* g;   // 3 per node: the energy's gradient (minus the net force) [N]
  double* dx;  // 3 per node: the step [m]
  double* r0;  // 3 per node: the positions before the step [m]
};

Scratch scratch(const Line& l, LineState* s) {
  const int m = l.nseg + 1;
  double* p = s->st.data();
  return {p, p + 9 * m, p + 18 * m, p + 21 * m, p + 24 * m};
}

// the weights of node j: dry w l0 g and its buoyancy rho A l0 g [N]
struct NodeLoad {
  double wd, wb, kb, level, bedz;
};

NodeLoad nodeLoad(const LineWater& w, const Line& l) {
  const Sea& sea = *w.sea;
  return {l.mnode * sea.g, sea.rho * l.vnode * sea.g, w.bed->k * l.t.diam * l.l0, sea.level,
          w.bed->z};
}

// the line's potential energy [J] at s->r: EA / (2 l0) (len - l0)^2 per taut
// segment, w_d z - w_b min(z - level, 0) per inner node (weight and, below
// the surface, buoyancy) and k_b / 2 p^2 per node sunk p into the bed
// (bedStep's spring, k_b = k d l0); all convex in the positions. mag: the sum
// of the terms' sizes, the scale of its rounding
double energy(const Line& l, const NodeLoad& nl, const double* r, double* mag) {
  double e = 0, a = 0;
  const double k = l.t.ea / l.l0;
  for (int i = 0; i < l.nseg; i++) {
    const double* p = r + 3 * i;
    const double d[3] = {p[3] - p[0], p[4] - p[1], p[5] - p[2]};
    const double x = std::max(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - l.l0, 0.0);
    e += 0.5 * k * x * x;
  }
  a += std::fabs(e);
  for (int j = 1; j < l.nseg; j++) {
    const double z = r[3 * j + 2], pen = std::max(nl.bedz - z, 0.0);
    const double t = nl.wd * z - nl.wb * std::min(z - nl.level, 0.0) + 0.5 * nl.kb * pen * pen;
    e += t;
    a += std::fabs(nl.wd * z) + std::fabs(nl.wb * (z - nl.level));
  }
  *mag = a;
  return e;
}

// the gradient (sc.g) and the Hessian's blocks (sc.c diagonal, sc.k per
// segment) at s->r; returns the largest node residual |g_j| [N] (NaN when
// one is not finite). A taut
// segment's stiffness is EA / l0 q q^T + T / len (I - q q^T)
double assemble(const Line& l, const NodeLoad& nl, LineState* s, const Scratch& sc) {
  const int n = l.nseg;
  const double ka = l.t.ea / l.l0;
  std::fill(sc.c, sc.c + 9 * (n + 1), 0.0);
  std::fill(sc.g, sc.g + 3 * (n + 1), 0.0);
  for (int i = 0; i < n; i++) {
    const double* p = &s->r[3 * i];
    double* kb = sc.k + 9 * i;
    const double d[3] = {p[3] - p[0], p[4] - p[1], p[5] - p[2]};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    std::fill(kb, kb + 9, 0.0);
    s->tseg[i] = 0;
    if (!(len > l.l0)) continue;
    const double T = ka * (len - l.l0), tl = T / len;
    s->tseg[i] = T;
    double q[3];
    for (int a = 0; a < 3; a++) q[a] = d[a] / len;
    for (int a = 0; a < 3; a++) {
      sc.g[3 * i + a] -= T * q[a];
      sc.g[3 * i + 3 + a] += T * q[a];
      for (int b = 0; b < 3; b++) kb[3 * a + b] = (ka - tl) * q[a] * q[b] + (a == b ? tl : 0);
    }
    for (int a = 0; a < 9; a++) {
      sc.c[9 * i + a] += kb[a];
      sc.c[9 * i + 9 + a] += kb[a];
    }
  }
  double res = 0;
  bool bad = false;
  for (int j = 1; j < n; j++) {
    const double z = s->r[3 * j + 2], pen = nl.bedz - z;
    double* g = sc.g + 3 * j;
    g[2] += nl.wd - (z < nl.level ? nl.wb : 0);
    if (pen > 0) {
      g[2] -= nl.kb * pen;
      sc.c[9 * j + 8] += nl.kb;
    }
    const double gn = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (!(gn <= res)) res = gn;
    if (!std::isfinite(gn)) bad = true;
  }
  return bad ? NAN : res;
}

// inverse of the symmetric 3x3 a into b; false when a is not positive definite
bool inv3(const double* a, double* b) {
  b[0] = a[4] * a[8] - a[5] * a[7];
  b[1] = a[2] * a[7] - a[1] * a[8];
  b[2] = a[1] * a[5] - a[2] * a[4];
  const double det = a[0] * b[0] + a[3] * b[1] + a[6] * b[2];
  if (!(det > 0) || !(a[0] > 0) || !std::isfinite(det)) return false;
  b[3] = a[5] * a[6] - a[3] * a[8];
  b[4] = a[0] * a[8] - a[2] * a[6];
  b[5] = a[2] * a[3] - a[0] * a[5];
  b[6] = a[3] * a[7] - a[4] * a[6];
  b[7] = a[1] * a[6] - a[0] * a[7];
  b[8] = a[0] * a[4] - a[1] * a[3];
  for (int i = 0; i < 9; i++) b[i] /= det;
  return true;
}

// y = a x for 3x3 a
inline void mul3(const double* a, const double* x, double* y) {
  for (int i = 0; i < 3; i++) y[i] = a[3 * i] * x[0] + a[3 * i + 1] * x[1] + a[3 * i + 2] * x[2];
}

// solve (H + lam I) dx = -g over the inner nodes by block LDL^T of the
// block-tridiagonal H (diagonal sc.c, off-diagonal -K of the segment
// between two inner nodes); overwrites sc.c with the inverses of the
// Schur complements. False when a block is not positive definite
bool solve(const Line& l, double lam, const Scratch& sc) {
  const int n = l.nseg;
  double ci[9], t[9], y[3];
  for (int j = 1; j < n; j++) {
    double* c = sc.c + 9 * j;
    double* dx = sc.dx + 3 * j;
    for (int a = 0; a < 3; a++) c[4 * a] += lam, dx[a] = -sc.g[3 * j + a];
    if (j > 1) {
      // C_j -= K C_{j-1}^-1 K, y_j += K C_{j-1}^-1 y_{j-1} (K = K_{j-1}, symmetric)
      const double* k = sc.k + 9 * (j - 1);
      const double* cp = sc.c + 9 * (j - 1);
      for (int a = 0; a < 3; a++) {
        for (int b = 0; b < 3; b++) {
          t[3 * a + b] = k[3 * a] * cp[b] + k[3 * a + 1] * cp[3 + b] + k[3 * a + 2] * cp[6 + b];
        }
      }
      for (int a = 0; a < 3; a++) {
        for (int b = 0; b < 3; b++) {
          c[3 * a + b] -= t[3 * a] * k[b] + t[3 * a + 1] * k[3 + b] + t[3 * a + 2] * k[6 + b];
        }
      }
      mul3(t, dx - 3, y);
      for (int a = 0; a < 3; a++) dx[a] += y[a];
    }
    if (!inv3(c, ci)) return false;
    std::copy(ci, ci + 9, c);
  }
  for (int j = n - 1; j >= 1; j--) {
    double* dx = sc.dx + 3 * j;
    double b[3] = {dx[0], dx[1], dx[2]};
    if (j + 1 < n) {
      mul3(sc.k + 9 * j, dx + 3, y);
      for (int a = 0; a < 3; a++) b[a] += y[a];
    }
    mul3(sc.c + 9 * j, b, dx);
  }
  return true;
}

}  // namespace

// Newton with a Levenberg-Marquardt shift lam = mu EA / l0 (slack segments
// and nodes off the bed have no stiffness across) and each node's move
// capped at l0 / 4; a step is taken when it lowers the energy, else mu
// grows tenfold. The energy is convex, so this reaches its minimum from
// any start (the catenary's nodes, or the straight line)
bool lineStatic(const LineWater& w, const Line& l, LineState* s) {
  const int n = l.nseg;
  if (n < 2) return true;
  const NodeLoad nl = nodeLoad(w, l);
  const Scratch sc = scratch(l, s);
  double ext = 0;
  for (double x : s->r) ext = std::max(ext, std::fabs(x));
  const double ka = l.t.ea / l.l0, eps = std::numeric_limits<double>::epsilon();
  // the residual Newton can reach in double: rounding of the positions times
  // the segments' stiffness
  const double tol = std::max(1e-6 * nl.wd, 64 * eps * ka * (ext + l.len));
  double mag, e = energy(l, nl, s->r.data(), &mag), mu = 1e-9;
  for (int it = 0; it < 500; it++) {
    if (assemble(l, nl, s, sc) <= tol) return true;  // a NaN residual is not converged
    bool moved = false;
    for (int tries = 0; tries < 40 && !moved; tries++, mu *= 10) {
      if (tries > 0) assemble(l, nl, s, sc);
      if (!solve(l, mu * ka, sc)) continue;
      double big = 0;
      for (int j = 1; j < n; j++) {
        const double* d = sc.dx + 3 * j;
        big = std::max(big, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      }
      const double f = big > 0.25 * l.l0 ? 0.25 * l.l0 / big : 1;
      std::copy(s->r.begin(), s->r.end(), sc.r0);
      for (int j = 3; j < 3 * n; j++) s->r[j] += f * sc.dx[j];
      double m2, e2 = energy(l, nl, s->r.data(), &m2);
      if (e2 <= e + 1e-14 * std::max(mag, m2)) {
        e = e2;
        mag = m2;
        moved = true;
        mu = std::max(mu * 1e-2, 1e-13);  // the loop's *10 follows
      } else {
        std::copy(sc.r0, sc.r0 + 3 * (n + 1), s->r.begin());
      }
    }
    if (!moved) break;
  }
  return assemble(l, nl, s, sc) <= tol;
}

}  // namespace mjb
