// roofline: the reference kernel (roofline.h). The cpu backend's work per
// step, written as structure-of-arrays loops the compiler vectorises (AVX2
// and FMA when the cpu has them, chosen at run time by target_clones) and
// sin, cos, exp from libmvec (mjb::vSinCos, mjb::vExp):
// - per vertex (half a vertex per triangle, as on the Wigley meshes): the
//   body-to-world transform, the phase of every component at the label
//   guess, its sin and cos, one Newton step of the label search (residual,
//   2x2 Jacobian, solve) and the surface height;
// - per triangle: its corners gathered, the area vector (cross product),
//   a wet depth, the hydrostatic force and its moment, and per component
//   one exp (the depth decay) times the mean phase cosine (the dynamic
//   pressure), as the closed-form integrals do once per wet piece.
// It leaves out the cut's branches, hydrodynamics and the history: a rate
// the real code cannot beat, not a model of it.
#include "roofline.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <vector>

#include "util/vmath.h"

namespace mjbtool {
namespace {

constexpr int kB = 256;  // points per block

struct Waves {
  std::vector<double> k, dx, dy, wt, qx, qy, qk, amp;
};

struct Mesh {
  int nv, nt;
  std::vector<double> px, py, pz, ox, oy;  // body frame; label offsets
  std::vector<int> i0, i1, i2;
  // per vertex: world position, height above the surface; cos of every
  // component's phase (component-major)
  std::vector<double> X, Y, Z, H, C;
};

#define MJB_CLONES __attribute__((target_clones("arch=haswell", "default")))

// transform and phases of vertices [v0, v0 + n)
MJB_CLONES void vertexPhases(const Waves& w, int nw, const double* R, const double* x, Mesh* m,
                             int v0, int n, double* ph) {
  for (int i = 0; i < n; i++) {
    const int v = v0 + i;
    m->X[v] = R[0] * m->px[v] + R[1] * m->py[v] + R[2] * m->pz[v] + x[0];
    m->Y[v] = R[3] * m->px[v] + R[4] * m->py[v] + R[5] * m->pz[v] + x[1];
    m->Z[v] = R[6] * m->px[v] + R[7] * m->py[v] + R[8] * m->pz[v] + x[2];
  }
  for (int j = 0; j < nw; j++) {
    for (int i = 0; i < n; i++) {
      const int v = v0 + i;
      ph[j * kB + i] = w.k[j] * (w.dx[j] * (m->X[v] + m->ox[v]) + w.dy[j] * (m->Y[v] + m->oy[v])) -
                       w.wt[j];
    }
  }
}

// one Newton step of the label search and the height, from sin s, cos c
MJB_CLONES void vertexNewton(const Waves& w, int nw, Mesh* m, int v0, int n, const double* s,
                             const double* c, double* acc) {
  double f0[kB], f1[kB], j00[kB], j01[kB], j11[kB], eta[kB];
  for (int i = 0; i < n; i++) {
    f0[i] = m->ox[v0 + i];
    f1[i] = m->oy[v0 + i];
    j00[i] = j11[i] = 1;
    j01[i] = eta[i] = 0;
  }
  for (int j = 0; j < nw; j++) {
    const double qx = w.qx[j], qy = w.qy[j], qk = w.qk[j], a = w.amp[j];
    const double xx = w.dx[j] * w.dx[j], xy = w.dx[j] * w.dy[j], yy = w.dy[j] * w.dy[j];
    for (int i = 0; i < n; i++) {
      const double sn = s[j * kB + i], cs = c[j * kB + i], jc = qk * cs;
      f0[i] -= qx * sn;
      f1[i] -= qy * sn;
      j00[i] -= jc * xx;
      j01[i] -= jc * xy;
      j11[i] -= jc * yy;
      eta[i] += a * cs;
      m->C[size_t(j) * m->nv + v0 + i] = cs;
    }
  }
  for (int i = 0; i < n; i++) {
    const int v = v0 + i;
    const double det = j00[i] * j11[i] - j01[i] * j01[i];
    m->ox[v] -= (j11[i] * f0[i] - j01[i] * f1[i]) / det;
    m->oy[v] -= (j00[i] * f1[i] - j01[i] * f0[i]) / det;
    m->H[v] = m->Z[v] - eta[i];
  }
  acc[0] += m->ox[v0] + m->H[v0];
}

// triangles [t0, t0 + n): geometry and the exp arguments of every component
MJB_CLONES void triangleArgs(const Waves& w, int nw, const Mesh& m, int t0, int n, double* geo,
                             double* arg) {
  for (int i = 0; i < n; i++) {
    const int t = t0 + i, a = m.i0[t], b = m.i1[t], c = m.i2[t];
    const double ux = m.X[b] - m.X[a], uy = m.Y[b] - m.Y[a], uz = m.Z[b] - m.Z[a];
    const double vx = m.X[c] - m.X[a], vy = m.Y[c] - m.Y[a], vz = m.Z[c] - m.Z[a];
    const double h = (m.H[a] + m.H[b] + m.H[c]) / 3;
    geo[0 * kB + i] = 0.5 * (uy * vz - uz * vy);
    geo[1 * kB + i] = 0.5 * (uz * vx - ux * vz);
    geo[2 * kB + i] = 0.5 * (ux * vy - uy * vx);
    geo[3 * kB + i] = std::min(h, 0.0);
    geo[4 * kB + i] = (m.X[a] + m.X[b] + m.X[c]) / 3;
    geo[5 * kB + i] = (m.Y[a] + m.Y[b] + m.Y[c]) / 3;
    geo[6 * kB + i] = (m.Z[a] + m.Z[b] + m.Z[c]) / 3;
  }
  for (int j = 0; j < nw; j++) {
    for (int i = 0; i < n; i++) arg[j * kB + i] = w.k[j] * geo[3 * kB + i];
  }
}

// triangles' dynamic pressure, force and moment, summed into acc
MJB_CLONES void triangleForces(const Waves& w, int nw, const Mesh& m, int t0, int n,
                               const double* geo, const double* e, double* acc) {
  double pd[kB];
  for (int i = 0; i < n; i++) pd[i] = -9810 * geo[3 * kB + i];
  for (int j = 0; j < nw; j++) {
    const double* C = m.C.data() + size_t(j) * m.nv;
    const double a = 9810 * w.amp[j] / 3;
    for (int i = 0; i < n; i++) {
      const int t = t0 + i;
      pd[i] += a * e[j * kB + i] * (C[m.i0[t]] + C[m.i1[t]] + C[m.i2[t]]);
    }
  }
  double f[6] = {0, 0, 0, 0, 0, 0};
  for (int i = 0; i < n; i++) {
    const double fx = pd[i] * geo[i], fy = pd[i] * geo[kB + i], fz = pd[i] * geo[2 * kB + i];
    const double rx = geo[4 * kB + i], ry = geo[5 * kB + i], rz = geo[6 * kB + i];
    f[0] += fx;
    f[1] += fy;
    f[2] += fz;
    f[3] += ry * fz - rz * fy;
    f[4] += rz * fx - rx * fz;
    f[5] += rx * fy - ry * fx;
  }
  for (int j = 0; j < 6; j++) acc[j] += f[j];
}

double threadCpu() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

}  // namespace

double rooflineNs(int nw) {
  const int nt = 7744, nv = nt / 2 + 64;
  Waves w;
  for (int j = 0; j < nw; j++) {
    const double k = 2 * M_PI / (5 + 30.0 * j / std::max(1, nw)), d = 0.3 * j;
    w.k.push_back(k);
    w.dx.push_back(std::cos(d));
    w.dy.push_back(std::sin(d));
    w.wt.push_back(1.7 * j);
    w.qk.push_back(0.3 / std::max(1, nw));
    w.amp.push_back(w.qk.back() / k);
    w.qx.push_back(w.amp.back() * w.qk.back() * w.dx.back());
    w.qy.push_back(w.amp.back() * w.qk.back() * w.dy.back());
  }
  Mesh m;
  m.nv = nv;
  m.nt = nt;
  for (int v = 0; v < nv; v++) {
    m.px.push_back(4.0 * v / nv - 2);
    m.py.push_back(0.25 * std::sin(0.37 * v));
    m.pz.push_back(0.2 * std::cos(0.11 * v) - 0.1);
    m.ox.push_back(0);
    m.oy.push_back(0);
  }
  for (int t = 0; t < nt; t++) {
    m.i0.push_back(t / 2);
    m.i1.push_back((t / 2 + 1) % nv);
    m.i2.push_back((t / 2 + 62) % nv);
  }
  m.X.assign(nv, 0);
  m.Y.assign(nv, 0);
  m.Z.assign(nv, 0);
  m.H.assign(nv, 0);
  m.C.assign(size_t(std::max(nw, 1)) * nv, 0);
  std::vector<double> ph(std::max(nw, 1) * kB), s(ph.size()), c(ph.size());
  std::vector<double> geo(7 * kB);
  const double R[9] = {0.99, -0.1, 0.02, 0.1, 0.99, 0.01, -0.02, 0, 1}, x[3] = {3, 1, 0.03};
  double acc[6] = {0, 0, 0, 0, 0, 0}, best = INFINITY;
  for (int pass = 0; pass < 6; pass++) {
    const double t0 = threadCpu();
    for (int v = 0; v < nv; v += kB) {
      const int n = std::min(kB, nv - v);
      vertexPhases(w, nw, R, x, &m, v, n, ph.data());
      mjb::vSinCos(nw * kB, ph.data(), s.data(), c.data());
      vertexNewton(w, nw, &m, v, n, s.data(), c.data(), acc);
    }
    for (int t = 0; t < nt; t += kB) {
      const int n = std::min(kB, nt - t);
      triangleArgs(w, nw, m, t, n, geo.data(), ph.data());
      mjb::vExp(nw * kB, ph.data(), s.data());
      triangleForces(w, nw, m, t, n, geo.data(), s.data(), acc);
    }
    if (pass > 0) best = std::min(best, threadCpu() - t0);
  }
  // the sums keep the work from being optimised away
  volatile double sink = acc[0] + acc[1] + acc[2] + acc[3] + acc[4] + acc[5];
  (void)sink;
  return best * 1e9 / nt;
}

}  // namespace mjbtool
