// boundary-element solve of the radiation and diffraction problems
// (docs/physics.md section 13): constant-strength sources on flat panels,
// collocation at the centroids, the deep-water Green function of green.h
// or the finite-depth one of greenfd.h,
// a damped interior lid (dphi/dz = K (1 + i w) phi on the waterplane inside
// the hull, w 0 at the waterline) against irregular frequencies
#include "radiation/panel.h"
#include "radiation/panellid.h"
#include "radiation/panellu.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <complex>
#include <cstdio>
#include <memory>
#include <thread>

#include <Eigen/Dense>

#include "util/gauss.h"
#include "radiation/green.h"
#include "radiation/greenfd.h"
#include "radiation/greentab.h"
#include "radiation/rankine.h"
#include "sea/spectra.h"

namespace mjb {

namespace {

typedef std::complex<double> cplx;
typedef Eigen::MatrixXd MatR;
typedef Eigen::MatrixXcd MatC;
const double kPi = 3.14159265358979323846;

// the worker threads: the hardware's, at most 8
int panelThreads() {
  int nt = (int)std::thread::hardware_concurrency();
  return nt < 1 ? 1 : (nt > 8 ? 8 : nt);
}

// runs body(i) for i in [0, n) on up to panelThreads threads (rows
// interleaved: near and far rows cost about the same)
template <class Fn>
void parallelRows(int n, Fn body, int minn = 64) {
  int nt = panelThreads();
  if (nt == 1 || n < minn) {
    for (int i = 0; i < n; i++) body(i);
    return;
  }
  // a thread that cannot start has its rows run here (never an abort)
  std::vector<std::thread> th;
  std::vector<int> here;
  for (int t = 0; t < nt; t++) {
    try {
      th.emplace_back([=]() {
        for (int i = t; i < n; i += nt) body(i);
      });
    } catch (...) {
      here.push_back(t);
    }
  }
  for (int t : here)
    for (int i = t; i < n; i += nt) body(i);
  for (auto& t : th) t.join();
}

// quadrature point of a panel: position and weight [m^2]
struct QPoint {
  double p[3], w;
};

// 2x2 Gauss on the bilinear map of a quad, 3 interior points on a triangle
void panelRule(const Panel& pn, std::vector<QPoint>* q) {
  q->clear();
  if (pn.nv == 3) {
    const double b[3][3] = {{2. / 3, 1. / 6, 1. / 6}, {1. / 6, 2. / 3, 1. / 6}, {1. / 6, 1. / 6, 2. / 3}};
    for (int i = 0; i < 3; i++) {
      QPoint t;
      for (int k = 0; k < 3; k++) t.p[k] = b[i][0] * pn.v[0][k] + b[i][1] * pn.v[1][k] + b[i][2] * pn.v[2][k];
      t.w = pn.area / 3;
      q->push_back(t);
    }
    return;
  }
  const double g = 0.5 / std::sqrt(3.0);
  double wsum = 0;
  for (int a = 0; a < 2; a++)
    for (int b = 0; b < 2; b++) {
      double u = 0.5 + (a ? g : -g), v = 0.5 + (b ? g : -g);
      QPoint t;
      double du[3], dv[3];
      for (int k = 0; k < 3; k++) {
        t.p[k] = (1 - u) * (1 - v) * pn.v[0][k] + u * (1 - v) * pn.v[1][k] + u * v * pn.v[2][k] +
                 (1 - u) * v * pn.v[3][k];
        du[k] = -(1 - v) * pn.v[0][k] + (1 - v) * pn.v[1][k] + v * pn.v[2][k] - v * pn.v[3][k];
        dv[k] = -(1 - u) * pn.v[0][k] - u * pn.v[1][k] + u * pn.v[2][k] + (1 - u) * pn.v[3][k];
      }
      double c[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2],
                     du[0] * dv[1] - du[1] * dv[0]};
      t.w = 0.25 * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      wsum += t.w;
      q->push_back(t);
    }
  for (auto& t : *q) t.w *= pn.area / wsum;
}

// Duffy rule about the centroid (its 1/r and log singularity integrated
// exactly by the Jacobian u): triangles (c, v_k, v_k+1), 6x6 Gauss
void duffyRule(const Panel& pn, std::vector<QPoint>* q) {
  q->clear();
  const GaussRule& g = gaussRule(6);
  for (int e = 0; e < pn.nv; e++) {
    const double* a = pn.v[e];
    const double* b = pn.v[(e + 1) % pn.nv];
    double ea[3], eb[3], cr[3];
    for (int k = 0; k < 3; k++) {
      ea[k] = a[k] - pn.c[k];
      eb[k] = b[k] - pn.c[k];
    }
    cr[0] = ea[1] * eb[2] - ea[2] * eb[1];
    cr[1] = ea[2] * eb[0] - ea[0] * eb[2];
    cr[2] = ea[0] * eb[1] - ea[1] * eb[0];
    double at = std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);  // 2 x area
    for (int i = 0; i < g.n; i++)
      for (int j = 0; j < g.n; j++) {
        double u = 0.5 * (g.x[i] + 1), v = 0.5 * (g.x[j] + 1);
        QPoint t;
        for (int k = 0; k < 3; k++) t.p[k] = pn.c[k] + u * (ea[k] + v * (eb[k] - ea[k]));
        t.w = 0.25 * g.w[i] * g.w[j] * u * at;
        q->push_back(t);
      }
  }
}

// the problem: panels (body first, then lid) and their rules
struct Problem {
  std::vector<Panel> pn;
  int nb = 0, nl = 0;
  std::vector<std::vector<QPoint>> near, self;
  std::vector<double> lidw;  // per lid panel: its damping weight w (panellid.h)
  std::vector<int> bodyEnd;  // per body of a group: one past its last body panel
  double h = 0;              // water depth [m]; 0: deep water
  double gn[6];  // scratch
};

bool buildPanels(const PanelMesh& m, bool lid, Problem* pb, std::string* err) {
  const char* what = lid ? "lid" : "body";
  int nv = (int)m.vert.size() / 3;
  if (m.vert.size() % 3 || m.face.size() % 4) {
    *err = std::string("panel ") + what + ": vert must hold 3 and face 4 numbers per entry";
    return false;
  }
  for (int f = 0; f < m.nface(); f++) {
    const int* fi = &m.face[4 * f];
    int n = fi[3] < 0 ? 3 : 4;
    for (int k = 0; k < n; k++)
      if (fi[k] < 0 || fi[k] >= nv) {
        char b[200];
        std::snprintf(b, sizeof b, "panel %s face %d: vertex index %d outside 0..%d", what, f, fi[k], nv - 1);
        *err = b;
        return false;
      }
    const double* p[4];
    for (int k = 0; k < n; k++) p[k] = &m.vert[3 * fi[k]];
    for (int k = 0; k < n; k++)
      for (int c = 0; c < 3; c++)
        if (!std::isfinite(p[k][c])) {
          char b[200];
          std::snprintf(b, sizeof b, "panel %s face %d: vertex %d is not finite", what, f, fi[k]);
          *err = b;
          return false;
        }
    Panel pn;
    if (!makePanel(p[0], p[1], p[2], n == 4 ? p[3] : nullptr, &pn)) {
      char b[200];
      std::snprintf(b, sizeof b, "panel %s face %d: degenerate (zero area); remove it", what, f);
      *err = b;
      return false;
    }
    double tol = 1e-6 * (1 + pn.diam);
    for (int k = 0; k < pn.nv; k++)
      if ((lid && std::fabs(pn.v[k][2]) > tol) || (!lid && pn.v[k][2] > tol)) {
        char b[200];
        std::snprintf(b, sizeof b, "panel %s face %d: vertex z = %g m, accepted %s (clip the mesh at the waterline)",
                      what, f, pn.v[k][2], lid ? "0" : "<= 0");
        *err = b;
        return false;
      }
    if (lid) pn.v[0][2] = pn.v[1][2] = pn.v[2][2] = pn.v[3][2] = pn.c[2] = 0;
    pb->pn.push_back(pn);
  }
  return true;
}

// generalized normal: n, (c - ref) x n
void genNormal(const Panel& p, const double* ref, double* g) {
  double r[3] = {p.c[0] - ref[0], p.c[1] - ref[1], p.c[2] - ref[2]};
  g[0] = p.n[0];
  g[1] = p.n[1];
  g[2] = p.n[2];
  g[3] = r[1] * p.n[2] - r[2] * p.n[1];
  g[4] = r[2] * p.n[0] - r[0] * p.n[2];
  g[5] = r[0] * p.n[1] - r[1] * p.n[0];
}

// mirror image of a panel in z = 0
Panel mirror(const Panel& p) {
  double v[4][3];
  for (int i = 0; i < p.nv; i++) {
    v[i][0] = p.v[i][0];
    v[i][1] = p.v[i][1];
    v[i][2] = -p.v[i][2];
  }
  Panel m;
  makePanel(v[0], v[1], v[2], p.nv == 4 ? v[3] : nullptr, &m);
  return m;
}

// Rankine parts: S (potential, all rows) and D (normal derivative, body
// rows) of 1/r and of the image 1/r' separately
struct Rankine {
  MatR Sd, Si, Dd, Di;
};

// the wave frequencies' Rankine part G = 1/r + 1/r' (docs/physics.md
// section 13) on the solved rows only: S = Sd + Si on rows (body, then
// lid), D = Dd + Di on its body rows; a row-reduced copy, so that the full
// matrices (4 N^2 doubles) are freed after the infinite frequency
struct RankineRows {
  MatR S, D;
};

RankineRows rankineRows(Rankine&& rk, const std::vector<int>& rows, int nb) {
  std::vector<int> rb;
  for (int r : rows)
    if (r < nb) rb.push_back(r);
  RankineRows rr;
  rr.S = rk.Sd(rows, Eigen::all) + rk.Si(rows, Eigen::all);
  rk.Sd.resize(0, 0), rk.Si.resize(0, 0);
  rr.D = rk.Dd(rb, Eigen::all) + rk.Di(rb, Eigen::all);
  return rr;
}

void rankineMatrices(const Problem& pb, Rankine* rk) {
  int n = pb.nb + pb.nl, nb = pb.nb;
  rk->Sd.resize(n, n);
  rk->Si.resize(n, n);
  rk->Dd.resize(nb, n);
  rk->Di.resize(nb, n);
  std::vector<Panel> im(n);
  for (int j = 0; j < n; j++) im[j] = mirror(pb.pn[j]);
  parallelRows(n, [&](int i) {
    const Panel& pi = pb.pn[i];
    for (int j = 0; j < n; j++) {
      double phi, g[3], phm, gm[3];
      rankinePanel(pb.pn[j], pi.c, &phi, g);
      rankinePanel(im[j], pi.c, &phm, gm);
      rk->Sd(i, j) = phi;
      rk->Si(i, j) = phm;
      if (i < nb) {
        rk->Dd(i, j) = g[0] * pi.n[0] + g[1] * pi.n[1] + g[2] * pi.n[2];
        rk->Di(i, j) = gm[0] * pi.n[0] + gm[1] * pi.n[1] + gm[2] * pi.n[2];
      }
    }
  });
  // the flat self term (0) misses the curvature part of the principal
  // value, -(H/2) int dS/r: an O(h) error. The wetted surface and its
  // image close, so int over x of dG/dn_x (1/r) = -2 pi for each source
  // panel (Gauss); the column sums fix each diagonal to O(h^2)
  for (int j = 0; j < nb; j++) {
    double s = 0;
    for (int i = 0; i < nb; i++) {
      if (i != j) s += pb.pn[i].area * rk->Dd(i, j);
      s += pb.pn[i].area * rk->Di(i, j);
    }
    rk->Dd(j, j) = (-2 * kPi * pb.pn[j].area - s) / pb.pn[j].area;
  }
}

// wave part of G integrated over panel j at x: potential and gradient
void waveIntegral(const GreenTable* tab, const GreenFd* fd, const std::vector<QPoint>& q, double K,
                  const double* x, bool grad, cplx* s, cplx g[3]) {
  cplx ss = 0, gg[3] = {0, 0, 0};
  for (const QPoint& t : q) {
    double dx = x[0] - t.p[0], dy = x[1] - t.p[1];
    double R = std::sqrt(dx * dx + dy * dy);
    if (fd) {
      // finite depth (greenfd.h): everything but 1/r + 1/r'
      WaveFd f = greenFdWave(*fd, tab, R, x[2], t.p[2]);
      ss += t.w * f.G;
      double ux = R > 0 ? dx / R : 0, uy = R > 0 ? dy / R : 0;
      gg[0] += t.w * f.GR * ux;
      gg[1] += t.w * f.GR * uy;
      gg[2] += t.w * f.Gz;
      continue;
    }
    double X = K * R, Y = -K * (x[2] + t.p[2]);
    if (Y < 0) Y = 0;
    WaveF f = greenWaveTab(tab, X, Y);
    double ey = std::exp(-Y), j0 = f.J0;
    // G_w = 2K F + 2 pi i K e^-Y J0(X)
    ss += t.w * cplx(2 * K * f.F, 2 * kPi * K * ey * j0);
    if (grad) {
      double j1 = f.J1;
      // d/dR = K d/dX, d/dz = -K d/dY
      cplx dR = K * cplx(2 * K * f.FX, -2 * kPi * K * ey * j1);
      cplx dz = -K * cplx(2 * K * f.FY, -2 * kPi * K * ey * j0);
      double ux = R > 0 ? dx / R : 0, uy = R > 0 ? dy / R : 0;
      gg[0] += t.w * dR * ux;
      gg[1] += t.w * dR * uy;
      gg[2] += t.w * dz;
    }
  }
  *s = ss;
  if (grad) {
    g[0] = gg[0];
    g[1] = gg[1];
    g[2] = gg[2];
  }
}

// frequency-dependent wave matrices on the rows listed (body rows first):
// WS (all of them) and WD (the body rows)
void waveMatrices(const Problem& pb, const std::vector<int>& rows, const GreenTable* tab,
                  const GreenFd* fd, double K, bool par, MatC* WS, MatC* WD) {
  int n = pb.nb + pb.nl, nb = pb.nb, nr = (int)rows.size(), nrb = 0;
  for (int i : rows) nrb += i < nb;
  WS->resize(nr, n);
  WD->resize(nrb, n);
  parallelRows(nr, [&](int r) {
    std::vector<QPoint> one(1);
    int i = rows[r];
    const Panel& pi = pb.pn[i];
    bool grad = i < nb;
    for (int j = 0; j < n; j++) {
      const Panel& pj = pb.pn[j];
      const std::vector<QPoint>* q;
      double dx = pi.c[0] - pj.c[0], dy = pi.c[1] - pj.c[1], dz = pi.c[2] + pj.c[2];
      double d = std::sqrt(dx * dx + dy * dy + dz * dz);
      // finite depth: the image in the seabed too
      if (fd) d = std::fmin(d, std::sqrt(dx * dx + dy * dy + std::pow(dz + 2 * pb.h, 2)));
      if (i == j && i >= nb) {
        q = &pb.self[j];
      } else if (d < 2 * pj.diam) {
        q = &pb.near[j];
      } else {
        one[0].p[0] = pj.c[0];
        one[0].p[1] = pj.c[1];
        one[0].p[2] = pj.c[2];
        one[0].w = pj.area;
        q = &one;
      }
      cplx s, g[3];
      waveIntegral(tab, fd, *q, K, pi.c, grad, &s, g);
      (*WS)(r, j) = s;
      if (grad) (*WD)(r, j) = g[0] * pi.n[0] + g[1] * pi.n[1] + g[2] * pi.n[2];
    }
  }, par ? 64 : 1 << 30);
}

// the tabulated wave part covering every panel pair up to wavenumber K:
// X = K R <= K (horizontal diagonal of the bounding box), Y <= 2 K depth;
// finite depth: K the wavenumber k0, Y <= 4 k0 h (the farthest image)
std::shared_ptr<const GreenTable> waveTable(const Problem& pb, double K) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const Panel& p : pb.pn)
    for (int v = 0; v < p.nv; v++)
      for (int k = 0; k < 3; k++) lo[k] = std::fmin(lo[k], p.v[v][k]), hi[k] = std::fmax(hi[k], p.v[v][k]);
  double dh = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
  return greenTable(K * dh, pb.h > 0 ? 4 * K * pb.h : -2 * K * lo[2]);
}

bool finiteAll(const double* a, int n) {
  for (int i = 0; i < n; i++)
    if (!std::isfinite(a[i])) return false;
  return true;
}

// mirror symmetry of the panels about a vertical plane u . x = c (u a
// horizontal unit vector): mir[j] the image of panel j, rows the panels on
// the side u . x > c (body first)
struct Mirror {
  std::vector<int> mir, rows;
};

std::atomic<bool> gSymmetry{true};

// the image of point p in the plane u . x = c (u horizontal); d: 0 for a
// point, 1 for a direction (no offset)
void reflect(const double* p, const double* u, double c, double d, double* q) {
  double t = 2 * (p[0] * u[0] + p[1] * u[1] - d * c);
  q[0] = p[0] - t * u[0];
  q[1] = p[1] - t * u[1];
  q[2] = p[2];
}

// whether panels p and q are images of each other in u . x = c (centroid
// within tol, normal within 1e-6, area within 1e-6 relative)
bool images(const Panel& p, const Panel& q, const double* u, double c, double tol) {
  double pc[3], pn[3];
  reflect(p.c, u, c, 1, pc);
  reflect(p.n, u, c, 0, pn);
  for (int k = 0; k < 3; k++)
    if (std::fabs(pc[k] - q.c[k]) > tol || std::fabs(pn[k] - q.n[k]) > 1e-6) return false;
  return std::fabs(p.area - q.area) <= 1e-6 * p.area;
}

// symmetry about the vertical plane of normal u through the body's
// wetted-area centroid, within 1e-6 of the mesh size; a panel on the plane
// (its own image) or one without an image: none
bool findMirror(const Problem& pb, const double* u, Mirror* m) {
  int n = pb.nb + pb.nl;
  double c = 0, area = 0, lo = 1e300, hi = -1e300;
  for (int j = 0; j < pb.nb; j++) {
    const Panel& p = pb.pn[j];
    c += p.area * (p.c[0] * u[0] + p.c[1] * u[1]);
    area += p.area;
  }
  c /= area;
  for (const Panel& p : pb.pn)
    for (int v = 0; v < p.nv; v++)
      for (int k = 0; k < 3; k++) lo = std::fmin(lo, p.v[v][k]), hi = std::fmax(hi, p.v[v][k]);
  double tol = 1e-6 * (hi - lo);
  m->mir.assign(n, -1);
  m->rows.clear();
  for (int j = 0; j < n; j++) {
    double s = pb.pn[j].c[0] * u[0] + pb.pn[j].c[1] * u[1] - c;
    if (std::fabs(s) <= tol) return false;
    if (s > 0) m->rows.push_back(j);
    if (m->mir[j] >= 0) continue;
    int e = j < pb.nb ? pb.nb : n;  // body panels pair with body panels, lid with lid
    for (int k = j + 1; k < e && m->mir[j] < 0; k++)
      if (m->mir[k] < 0 && images(pb.pn[j], pb.pn[k], u, c, tol)) m->mir[j] = k, m->mir[k] = j;
    if (m->mir[j] < 0) return false;
  }
  return true;
}

// the symmetry group of the mesh: img[k][j] the image of panel j under
// element k (k = 0 the identity; 1 or 3 mirrors, each its own inverse),
// rows one panel of each orbit (body first); planes: bit 0 the first
// mirror found, bit 1 the second
struct Group {
  std::vector<std::vector<int>> img;
  std::vector<int> rows;
  int planes = 0;
};

// mirrors about the planes of normal y and x, else about the principal
// axes of the wetted surface's horizontal second moment (a hull yawed in
// the model's initial pose): both (4 elements), one, or none
Group symmetryGroup(const Problem& pb) {
  Group g;
  int n = pb.nb + pb.nl;
  double cx = 0, cy = 0, a = 0, ixx = 0, iyy = 0, ixy = 0;
  for (int j = 0; j < pb.nb; j++) {
    const Panel& p = pb.pn[j];
    cx += p.area * p.c[0], cy += p.area * p.c[1], a += p.area;
  }
  cx /= a, cy /= a;
  for (int j = 0; j < pb.nb; j++) {
    const Panel& p = pb.pn[j];
    double x = p.c[0] - cx, y = p.c[1] - cy;
    ixx += p.area * x * x, iyy += p.area * y * y, ixy += p.area * x * y;
  }
  double th = 0.5 * std::atan2(2 * ixy, ixx - iyy);
  const double axes[2][2][2] = {{{0, 1}, {1, 0}},
                                {{-std::sin(th), std::cos(th)}, {std::cos(th), std::sin(th)}}};
  Mirror m1, m2;
  bool h1 = false, h2 = false;
  for (int t = 0; t < 2 && !h1 && !h2; t++) {
    h1 = findMirror(pb, axes[t][0], &m1);
    h2 = findMirror(pb, axes[t][1], &m2);
  }
  std::vector<int> id(n);
  for (int j = 0; j < n; j++) id[j] = j;
  g.img.push_back(id);
  if (h1) g.img.push_back(m1.mir);
  if (h2) g.img.push_back(m2.mir);
  if (h1 && h2) {
    std::vector<int> b(n);
    for (int j = 0; j < n; j++) b[j] = m2.mir[m1.mir[j]];
    g.img.push_back(b);
  }
  std::vector<char> in1(n, !h1), in2(n, !h2);
  for (int j : m1.rows) in1[j] = h1;
  for (int j : m2.rows) in2[j] = h2;
  for (int j = 0; j < n; j++)
    if (in1[j] && in2[j]) g.rows.push_back(j);
  g.planes = (h1 ? 1 : 0) | (h2 ? 2 : 0);
  return g;
}

// where a solve writes: nm radiation modes (6 per body), row-major nm x nm
// matrices per frequency, nm exciting-force entries per (omega, heading);
// wref the point where the incident wave's amplitude is given [m]
struct CoefView {
  int nm = 6;
  double rho = 0, g = 0;
  const double* wref = nullptr;
  double *A, *B, *Ainf, *Xre, *Xim, *FKre, *FKim;
};

// one frequency's radiation and diffraction solve (panelSolve's inputs);
// false on a non-finite result
struct Freq {
  const Problem* pb;
  const RankineRows* rk;
  const MatR *Nn, *Na;
  const GreenTable* tab;
  const std::vector<GreenFd>* fd;  // per frequency; empty: deep water
  const std::vector<double>*omega, *heading;
  HydroCoef* out;
  bool outer;        // frequencies run in parallel: fill serially
  const Group* gr;  // rows: the reduced solve; else all rows
  std::vector<int> rows;
  const PanelFieldFn* field;  // the drift's hook (or nullptr)
  const PanelMesh* body;
  CoefView cv;
};

// the source strengths of M sig = rhs on the full mesh from the
// symmetry-adapted systems, one per character chi of the group (Z2 or
// Z2 x Z2; docs/physics.md section 13): M holds the rows gr.rows only;
// M(g i, g j) = M(i, j) for every element g, so with sig(g j) =
// sum_p chi_p(g) sig_p(j) and rhs_p(i) = (1/|G|) sum_g chi_p(g) rhs(g i),
// M_p(i, j) = sum_g chi_p(g) M(i, g j) decouples them
MatC groupSolve(const Group& gr, const MatC& M, const MatC& rhs) {
  int nr = (int)gr.rows.size(), nc = (int)rhs.cols(), ng = (int)gr.img.size();
  // chi_p(g): element k flips mirror bit b when bit b of k is set (k = 1:
  // the first mirror, 2: the second, 3: both)
  auto chi = [](int p, int k) { return __builtin_popcount(p & k) % 2 ? -1.0 : 1.0; };
  MatC sig = MatC::Zero(M.cols(), nc);
  for (int p = 0; p < ng; p++) {
    MatC Mp = MatC::Zero(nr, nr), rp = MatC::Zero(nr, nc);
    for (int c = 0; c < nr; c++)
      for (int k = 0; k < ng; k++) {
        Mp.col(c) += chi(p, k) * M.col(gr.img[k][gr.rows[c]]);
        rp.row(c) += (chi(p, k) / ng) * rhs.row(gr.img[k][gr.rows[c]]);
      }
    panelLuSolve(&Mp, &rp);
    for (int c = 0; c < nr; c++)
      for (int k = 0; k < ng; k++) sig.row(gr.img[k][gr.rows[c]]) += chi(p, k) * rp.row(c);
  }
  return sig;
}

// one frequency's system: the influence matrix M of the rows f.rows, the
// right-hand sides (6 radiation modes, nh diffraction problems), the
// incident potential phi0 [m^2/s per m of amplitude] and the wave part WS
// of the source potential (WD: of the normal velocity)
struct OmegaSystem {
  MatC WS, WD, M, rhs, phi0;
  int nrb;  // body rows (the rest: lid rows)
};

// assembles frequency w's system (docs/physics.md section 13)
void assembleOmega(const Freq& f, int w, OmegaSystem* s) {
  const Problem& pb = *f.pb;
  const RankineRows& rk = *f.rk;
  const MatR& Nn = *f.Nn;
  const std::vector<double>& heading = *f.heading;
  const std::vector<int>& rows = f.rows;
  int n = pb.nb + pb.nl, nb = pb.nb, nh = (int)heading.size(), nr = (int)rows.size();
  int nm = f.cv.nm;
  const double* ref = f.cv.wref;
  double grav = f.cv.g;
  double om = (*f.omega)[w], K = om * om / grav;
  const GreenFd* fd = f.fd->empty() || !((*f.fd)[w].h > 0) ? nullptr : &(*f.fd)[w];
  double kw = fd ? fd->k0 : K;  // the incident wave's wavenumber
  MatC &WS = s->WS, &WD = s->WD;
  waveMatrices(pb, rows, f.tab, fd, K, !f.outer, &WS, &WD);
  int nrb = s->nrb = (int)WD.rows();
  // lid rows: the damped lid, dphi/dz(0-) = K (1 + i w) phi on the lid's
  // interior side, w 0 at the waterline (docs/physics.md section 13); with
  // dphi/dz(0-) = K phi + 4 pi sigma (the free-surface condition of G plus
  // the jump of the doubled source sheet): -i w K phi + 4 pi sigma = 0
  MatC& M = s->M;
  M.resize(nr, n);
  M.topRows(nrb) = rk.D.cast<cplx>() + WD;
  WD.resize(0, 0);  // (its memory: N_r N complex)
  if (nr > nrb)
    M.bottomRows(nr - nrb) =
        K * (rk.S.bottomRows(nr - nrb).cast<cplx>() + WS.bottomRows(nr - nrb));
  for (int r = nrb; r < nr; r++) M.row(r) *= cplx(0, -pb.lidw[rows[r] - nb]);
  for (int r = 0; r < nr; r++) M(r, rows[r]) += rows[r] < nb ? -2 * kPi : 4 * kPi;
  // right-hand sides: nm radiation modes (dphi/dn = n_j on the moving
  // body's panels, 0 on the others'), nh diffraction problems
  // (dphi_D/dn = -dphi_0/dn)
  MatC& rhs = s->rhs;
  rhs = MatC::Zero(n, nm + nh);
  rhs.block(0, 0, nb, nm) = Nn.cast<cplx>();
  // incident potential per unit amplitude: phi0 = -i g/omega Z(z) e^{ik(x cos b + y sin b)},
  // Z = e^{kz} in deep water, cosh(k (z + h)) / cosh(k h) at depth h
  MatC& phi0 = s->phi0;
  phi0.resize(nb, nh);
  for (int h = 0; h < nh; h++) {
    double cb = std::cos(heading[h]), sb = std::sin(heading[h]);
    for (int i = 0; i < nb; i++) {
      const Panel& p = pb.pn[i];
      double ph = kw * ((p.c[0] - ref[0]) * cb + (p.c[1] - ref[1]) * sb), Z, Zz;
      depthFactor(kw, fd ? pb.h : 0, p.c[2], &Z, &Zz);
      cplx e = cplx(std::cos(ph), std::sin(ph)), a = cplx(0, -grav / om) * e;
      cplx f0 = a * Z;
      phi0(i, h) = f0;
      // (no Zz / Z: both underflow to 0 for a body far down)
      cplx dn = a * (cplx(0, kw * cb) * Z * p.n[0] + cplx(0, kw * sb) * Z * p.n[1] +
                     kw * Zz * p.n[2]);
      rhs(i, nm + h) = -dn;
    }
  }
}

// solves system s for the source strengths sig (all panels) and returns
// the potentials on the body panels (6 radiation modes, nh diffraction)
// (M and WS are overwritten: the LU factors, the source potential S)
MatC solvePotentials(const Freq& f, OmegaSystem* s, MatC* sig) {
  const Problem& pb = *f.pb;
  const RankineRows& rk = *f.rk;
  const std::vector<int>& rows = f.rows;
  int n = pb.nb + pb.nl, nb = pb.nb, nh = (int)f.heading->size(), nr = (int)rows.size();
  int nrb = s->nrb, nc = f.cv.nm + nh;
  bool sym = nr < n;
  if (sym) {
    *sig = groupSolve(*f.gr, s->M, s->rhs);
  } else {
    *sig = std::move(s->rhs);
    panelLuSolve(&s->M, sig);
  }
  s->M.resize(0, 0);
  // S = Sd + Si + the wave part on the body rows, in WS's storage
  s->WS.topRows(nrb) += rk.S.topRows(nrb).cast<cplx>();
  auto S = s->WS.topRows(nrb);
  MatC phi(nb, nc);
  if (!sym) {
    panelProduct(S, *sig, &phi);
  } else {
    // phi(g i) = sum_j S(i, g j) sig(j) = (S sig(g .))(i), g its own inverse
    MatC sg(n, nc);
    for (const std::vector<int>& g : f.gr->img) {
      for (int j = 0; j < n; j++) sg.row(j) = sig->row(g[j]);
      MatC pg;
      panelProduct(S, sg, &pg);
      for (int r = 0; r < nrb; r++) phi.row(g[rows[r]]) = pg.row(r);
    }
  }
  return phi;
}

// frequency w's added mass [kg], damping [kg/s] and exciting force [N/m]
// from the body potentials phi and the incident potential phi0
void integrateForces(const Freq& f, int w, const MatC& phi0, const MatC& phi) {
  const MatR& Na = *f.Na;
  const CoefView& cv = f.cv;
  int nb = f.pb->nb, nh = (int)f.heading->size(), nm = cv.nm;
  double rho = cv.rho, om = (*f.omega)[w];
  // radiation force per unit velocity: -i omega rho int phi_j n_i dS
  //   = i omega A_ij - B_ij
  MatC P = Na.transpose().cast<cplx>() * phi;
  for (int a = 0; a < nm; a++)
    for (int b = 0; b < nm; b++) {
      cv.A[nm * nm * w + nm * a + b] = -rho * P(a, b).real();
      cv.B[nm * nm * w + nm * a + b] = -rho * om * P(a, b).imag();
    }
  // exciting force: -i omega rho int (phi0 + phiD) n dS
  for (int h = 0; h < nh; h++)
    for (int a = 0; a < nm; a++) {
      cplx fk = 0, fd = 0;
      for (int i = 0; i < nb; i++) {
        fk += phi0(i, h) * Na(i, a);
        fd += phi(i, nm + h) * Na(i, a);
      }
      fk *= cplx(0, -om * rho);
      fd *= cplx(0, -om * rho);
      int o = (w * nh + h) * nm + a;
      cv.FKre[o] = fk.real();
      cv.FKim[o] = fk.imag();
      cv.Xre[o] = (fk + fd).real();
      cv.Xim[o] = (fk + fd).imag();
    }
}

// frequency w: assembly, solve, forces; false if a coefficient is not finite
bool solveOmega(const Freq& f, int w) {
  const Problem& pb = *f.pb;
  const CoefView& cv = f.cv;
  int nb = pb.nb, nh = (int)f.heading->size(), nm = cv.nm, nm2 = nm * nm;
  double om = (*f.omega)[w], K = om * om / cv.g;
  MatC sig, phi, phi0;
  {
    OmegaSystem s;
    assembleOmega(f, w, &s);
    phi = solvePotentials(f, &s, &sig);
    phi0 = std::move(s.phi0);
  }
  integrateForces(f, w, phi0, phi);
  bool ok = finiteAll(cv.A + nm2 * w, nm2) && finiteAll(cv.B + nm2 * w, nm2) &&
            finiteAll(cv.Xre + nm * w * nh, nm * nh) &&  // no headings is allowed
            finiteAll(cv.Xim + nm * w * nh, nm * nh);
  if (ok && f.field)
    (*f.field)(PanelField{&pb.pn, nb, pb.nl, w, om, K, sig.data(), phi.data(), f.body, f.out});
  return ok;
}

// finite depth: every body vertex above the seabed z = -h
bool bodyAboveSeabed(const Problem& pb, std::string* err) {
  if (!(pb.h > 0)) return true;
  for (int j = 0; j < pb.nb; j++)
    for (int v = 0; v < pb.pn[j].nv; v++)
      if (!(pb.pn[j].v[v][2] > -pb.h)) {
        char b[240];
        std::snprintf(b, sizeof b, "panel body face %d: vertex z = %g m is at or below the seabed "
                      "(depth %g m); the hull must float clear of it (raise mjbuoy.sea.depth)", j,
                      pb.pn[j].v[v][2], pb.h);
        *err = b;
        return false;
      }
  return true;
}

// whether the seabed is within kReachSize times the body's size (greenfd.h)
bool bottomNear(const Problem& pb) {
  double cx = 0, cy = 0, a = 0, r = 0;
  for (int j = 0; j < pb.nb; j++) {
    const Panel& p = pb.pn[j];
    cx += p.area * p.c[0], cy += p.area * p.c[1], a += p.area;
  }
  cx /= a, cy /= a;
  for (int j = 0; j < pb.nb; j++)
    for (int v = 0; v < pb.pn[j].nv; v++) {
      const double* q = pb.pn[j].v[v];
      double dx = q[0] - cx, dy = q[1] - cy;
      r = std::fmax(r, std::sqrt(dx * dx + dy * dy + q[2] * q[2]));
    }
  return pb.h < kReachSize * r;
}

// infinite frequency at depth h: the images beyond 1/r - 1/r' (greenfd.h),
// all at least 2 (h - draft) away: by the panel centroid
void addInfiniteImages(const Problem& pb, MatR* S, MatR* D) {
  int nb = pb.nb;
  parallelRows(nb, [&](int i) {
    const Panel& pi = pb.pn[i];
    for (int j = 0; j < nb; j++) {
      const Panel& pj = pb.pn[j];
      double G, g[3];
      greenFdInfinite(pb.h, pi.c[0] - pj.c[0], pi.c[1] - pj.c[1], pi.c[2], pj.c[2], &G, g);
      (*S)(i, j) += pj.area * G;
      (*D)(i, j) += pj.area * (g[0] * pi.n[0] + g[1] * pi.n[1] + g[2] * pi.n[2]);
    }
  });
}

// the problem of body and lid: panels, lid weights, seabed depth and
// quadrature rules; checks the frequencies [rad/s], headings [rad] and water
// a group (docs/physics.md section 13, "Interaction"): body k's panels are
// pb.bodyEnd[k - 1] .. pb.bodyEnd[k] - 1, then every body's lid panels
bool setupProblem(const std::vector<const PanelMesh*>& bodies,
                  const std::vector<const PanelMesh*>& lids, const std::vector<double>& omega,
                  const std::vector<double>& heading, const HydroCoef& out, Problem* pbp,
                  std::string* err) {
  Problem& pb = *pbp;
  int nbody = (int)bodies.size();
  for (int k = 0; k < nbody; k++) {
    size_t start = pb.pn.size();
    bool built = buildPanels(*bodies[k], false, &pb, err);
    if (!built || pb.pn.size() == start) {
      if (built) *err = "panel body: no panels";
      if (nbody > 1) *err = "group body " + std::to_string(k) + ": " + *err;
      return false;
    }
    pb.bodyEnd.push_back((int)pb.pn.size());
  }
  pb.nb = (int)pb.pn.size();
  for (int k = 0; k < nbody; k++) {
    size_t start = pb.pn.size();
    if (!buildPanels(*lids[k], true, &pb, err)) {
      if (nbody > 1) *err = "group body " + std::to_string(k) + ": " + *err;
      return false;
    }
    int nk = (int)(pb.pn.size() - start);
    std::vector<double> xy(2 * nk);
    for (int j = 0; j < nk; j++) {
      xy[2 * j] = pb.pn[start + j].c[0];
      xy[2 * j + 1] = pb.pn[start + j].c[1];
    }
    std::vector<double> w = lidWeights(*lids[k], xy);
    pb.lidw.insert(pb.lidw.end(), w.begin(), w.end());
  }
  pb.nl = (int)pb.pn.size() - pb.nb;
  for (size_t w = 0; w < omega.size(); w++)
    if (!(omega[w] > 0 && std::isfinite(omega[w])) || (w && !(omega[w] > omega[w - 1]))) {
      char b[200];
      std::snprintf(b, sizeof b, "panel omega[%d] = %g rad/s: accepted finite, > 0 and increasing", (int)w, omega[w]);
      *err = b;
      return false;
    }
  for (size_t h = 0; h < heading.size(); h++)
    if (!std::isfinite(heading[h])) {
      char b[200];
      std::snprintf(b, sizeof b, "panel heading[%d] = %g rad: accepted finite", (int)h, heading[h]);
      *err = b;
      return false;
    }
  if (!(out.rho > 0) || !(out.g > 0) || !(out.depth >= 0) || !std::isfinite(out.depth)) {
    *err = "panel: rho and g must be > 0 and depth >= 0 (0: deep water), finite";
    return false;
  }
  pb.h = out.depth;
  if (!bodyAboveSeabed(pb, err)) return false;
  int n = pb.nb + pb.nl, nb = pb.nb;
  pb.near.resize(n);
  pb.self.resize(n);
  for (int j = 0; j < n; j++) {
    panelRule(pb.pn[j], &pb.near[j]);
    if (j >= nb) duffyRule(pb.pn[j], &pb.self[j]);
  }
  return true;
}

// generalized normals of the body panels about their body's ref [m] (3 per
// body): Nn (unit), Na (times area, m^2); body k's modes are columns
// 6 k .. 6 k + 5, zero on the other bodies' panels
void bodyNormals(const Problem& pb, const double* ref, MatR* Nn, MatR* Na) {
  int nb = pb.nb, nm = 6 * (int)pb.bodyEnd.size();
  Nn->setZero(nb, nm);
  Na->setZero(nb, nm);
  for (int i = 0, k = 0; i < nb; i++) {
    while (i >= pb.bodyEnd[k]) k++;
    double gn[6];
    genNormal(pb.pn[i], ref + 3 * k, gn);
    for (int c = 0; c < 6; c++) {
      (*Nn)(i, 6 * k + c) = gn[c];
      (*Na)(i, 6 * k + c) = gn[c] * pb.pn[i].area;
    }
  }
}

// infinite-frequency added mass out->Ainf [kg]: G = 1/r - 1/r' (phi = 0 on
// z = 0), body only
bool infiniteAddedMass(const Problem& pb, const Rankine& rk, const MatR& Nn, const MatR& Na,
                       const CoefView& cv, std::string* err) {
  int nb = pb.nb, nm = cv.nm;
  double rho = cv.rho;
  MatR M = rk.Dd.leftCols(nb) - rk.Di.leftCols(nb);
  MatR S = rk.Sd.topLeftCorner(nb, nb) - rk.Si.topLeftCorner(nb, nb);
  if (pb.h > 0 && bottomNear(pb)) addInfiniteImages(pb, &S, &M);
  M.diagonal().array() -= 2 * kPi;
  MatR sig = Nn;
  panelLuSolve(&M, &sig);
  MatR phi = S * sig;
  MatR Ai = -rho * Na.transpose() * phi;
  for (int a = 0; a < nm; a++)
    for (int b = 0; b < nm; b++) cv.Ainf[nm * a + b] = Ai(a, b);
  if (!finiteAll(cv.Ainf, nm * nm)) {
    *err = "panel: non-finite infinite-frequency added mass (check the mesh for coincident panels)";
    return false;
  }
  return true;
}

// finite depth: the kernel of each frequency [rad/s] (greenfd.h); none in
// deep water; a frequency out of the seabed's reach: the deep-water
// function, a kernel with h = 0
bool depthKernels(const Problem& pb, const std::vector<double>& omega, double grav,
                  std::vector<GreenFd>* fdp, std::string* err) {
  std::vector<GreenFd>& fds = *fdp;
  fds.resize(pb.h > 0 ? omega.size() : 0);
  for (size_t w = 0; w < fds.size(); w++)
    if (omega[w] * omega[w] / grav * pb.h >= kReachKh && !bottomNear(pb)) {
      fds[w].h = 0;
    } else if (!greenFdInit(omega[w] * omega[w] / grav, pb.h, &fds[w])) {
      char b[200];
      std::snprintf(b, sizeof b, "panel: finite-depth Green function not finite at omega = %g "
                    "rad/s, depth %g m", omega[w], pb.h);
      *err = b;
      return false;
    }
  return true;
}

// the rows to solve: a mirror-symmetric mesh (about y = c, x = c or both)
// its group's (reduced systems, *gr), else all
std::vector<int> solveRows(const Problem& pb, Group* gr) {
  bool sym = gSymmetry && (*gr = symmetryGroup(pb), gr->img.size() > 1);
  if (sym) return gr->rows;
  std::vector<int> rows;
  for (int i = 0; i < pb.nb + pb.nl; i++) rows.push_back(i);
  return rows;
}

// every frequency of fq, in parallel (each with a serial fill; one
// frequency: a parallel fill): every frequency is computed by the same
// operations in the same order whatever the thread, so results do not
// depend on it; a failed allocation on a worker thread is reported, never
// an abort
bool solveFrequencies(const Freq& fq, std::string* err) {
  const std::vector<double>& omega = *fq.omega;
  int nw = (int)omega.size(), n = fq.pb->nb + fq.pb->nl;
  std::vector<char> bad(nw, 0);
  parallelRows(nw, [&](int w) {
    try {
      bad[w] = !solveOmega(fq, w);
    } catch (...) {
      bad[w] = 2;
    }
  }, 2);
  for (int w = 0; w < nw; w++)
    if (bad[w]) {
      char b[240];
      std::snprintf(b, sizeof b, bad[w] == 2 ? "panel: out of memory at omega = %g rad/s (%d unknowns); "
                    "use fewer panels (lower mjbuoy.radiation.panels or mjbuoy.radiation.refine)" : "panel: non-finite coefficients at omega = %g rad/s",
                    omega[w], n);
      *err = b;
      return false;
    }
  return true;
}

// the solve of set-up problem pb into cv: body refs (3 per body), the
// infinite-frequency added mass, then every frequency; out, field and body
// for the drift's hook (single body only)
bool solveProblem(const Problem& pb, const double* refs, const std::vector<double>& omega,
                  const std::vector<double>& heading, const CoefView& cv, HydroCoef* out,
                  const PanelFieldFn* field, const PanelMesh* body, std::string* err) {
  int nw = (int)omega.size();
  double grav = cv.g;
  PanelBlasSerial serial;
  MatR Nn, Na;
  bodyNormals(pb, refs, &Nn, &Na);
  Group gr;
  std::vector<int> rows = solveRows(pb, &gr);
  RankineRows rr;
  {
    Rankine rk;
    rankineMatrices(pb, &rk);
    if (!infiniteAddedMass(pb, rk, Nn, Na, cv, err)) return false;
    rr = rankineRows(std::move(rk), rows, pb.nb);
  }
  // the table up to the largest propagating wavenumber
  std::vector<GreenFd> fds;
  if (!depthKernels(pb, omega, grav, &fds, err)) return false;
  double kmax = omega.back() * omega.back() / grav;
  for (const GreenFd& f : fds) kmax = std::fmax(kmax, f.k0);
  std::shared_ptr<const GreenTable> tab = waveTable(pb, kmax);
  Freq fq{&pb, &rr, &Nn, &Na, tab.get(), &fds, &omega, &heading, out, nw > 1, &gr, {}, field,
          body, cv};
  fq.rows = std::move(rows);
  return solveFrequencies(fq, err);
}

}  // namespace

void panelSymmetryUse(bool on) { gSymmetry = on; }

int panelMirrors(const PanelMesh& body, const PanelMesh& lid) {
  Problem pb;
  std::string err;
  if (!buildPanels(body, false, &pb, &err)) return 0;
  pb.nb = (int)pb.pn.size();
  if (!pb.nb || !buildPanels(lid, true, &pb, &err)) return 0;
  pb.nl = (int)pb.pn.size() - pb.nb;
  return symmetryGroup(pb).planes;
}

// rates of the cost model, fitted to CPU times on the development machine
// (docs/benchmarks.md, "Radiation"): Green function integrals per second
// (the table's interpolation and the near panels' quadrature) and complex
// LU and product flops per second (OpenBLAS, AVX2), as counted below
const double kGreenRate = 2.7e6, kFlopRate = 1.1e11;

PanelCost panelCost(const PanelMesh& body, const PanelMesh& lid, int nw, int nh) {
  PanelCost c;
  Problem pb;
  std::string err;
  if (!buildPanels(body, false, &pb, &err)) return c;
  pb.nb = (int)pb.pn.size();
  if (!pb.nb || !buildPanels(lid, true, &pb, &err)) return c;
  pb.nl = (int)pb.pn.size() - pb.nb;
  c.n = pb.nb + pb.nl;
  c.ng = gSymmetry ? (int)symmetryGroup(pb).img.size() : 1;
  const double n = c.n, nr = n / c.ng, nc = 6 + nh;
  c.green = nw * n * nr;
  c.flops = nw * (c.ng * 8.0 / 3 * nr * nr * nr + 16 * n * nr * nc);
  const int nt = std::max(1, std::min(nw, panelThreads()));
  c.seconds = (c.green / kGreenRate + c.flops / kFlopRate) / nt;
  return c;
}

bool panelSolve(const PanelMesh& body, const PanelMesh& lid, const std::vector<double>& omega,
                const std::vector<double>& heading, HydroCoef* out, std::string* err,
                const PanelFieldFn* field) {
  Problem pb;
  if (!setupProblem({&body}, {&lid}, omega, heading, *out, &pb, err)) return false;
  int nh = (int)heading.size(), nw = (int)omega.size();
  out->omega = omega;
  out->heading = heading;
  out->A.assign(36 * nw, 0);
  out->B.assign(36 * nw, 0);
  out->Xre.assign(6 * nw * nh, 0);
  out->Xim.assign(6 * nw * nh, 0);
  out->FKre.assign(6 * nw * nh, 0);
  out->FKim.assign(6 * nw * nh, 0);
  CoefView cv{6, out->rho, out->g, out->ref, out->A.data(), out->B.data(), out->Ainf,
              out->Xre.data(), out->Xim.data(), out->FKre.data(), out->FKim.data()};
  return solveProblem(pb, out->ref, omega, heading, cv, out, field, &body, err);
}

bool panelSolveGroup(const std::vector<PanelMesh>& bodies, const std::vector<PanelMesh>& lids,
                     const std::vector<double>& omega, const std::vector<double>& heading,
                     PanelGroupCoef* out, std::string* err) {
  int nbody = (int)bodies.size(), nm = 6 * nbody;
  if (omega.empty()) {
    *err = "panel group: no frequencies (give at least one omega > 0)";
    return false;
  }
  if (nbody < 1 || lids.size() != bodies.size() || out->ref.size() != 3 * bodies.size()) {
    *err = "panel group: give one body mesh, one lid mesh (may be empty) and 3 ref "
           "coordinates per body";
    return false;
  }
  for (double r : out->ref)
    if (!std::isfinite(r)) {
      *err = "panel group: a body's ref is not finite";
      return false;
    }
  std::vector<const PanelMesh*> bp, lp;
  for (int k = 0; k < nbody; k++) bp.push_back(&bodies[k]), lp.push_back(&lids[k]);
  HydroCoef water;
  water.rho = out->rho, water.g = out->g, water.depth = out->depth;
  Problem pb;
  if (!setupProblem(bp, lp, omega, heading, water, &pb, err)) return false;
  int nh = (int)heading.size(), nw = (int)omega.size();
  out->omega = omega;
  out->heading = heading;
  out->A.assign(nm * nm * nw, 0);
  out->B.assign(nm * nm * nw, 0);
  out->Ainf.assign(nm * nm, 0);
  out->Xre.assign(nm * nw * nh, 0);
  out->Xim.assign(nm * nw * nh, 0);
  out->FKre.assign(nm * nw * nh, 0);
  out->FKim.assign(nm * nw * nh, 0);
  static const double origin[3] = {0, 0, 0};
  CoefView cv{nm, out->rho, out->g, origin, out->A.data(), out->B.data(), out->Ainf.data(),
              out->Xre.data(), out->Xim.data(), out->FKre.data(), out->FKim.data()};
  return solveProblem(pb, out->ref.data(), omega, heading, cv, nullptr, nullptr, nullptr, err);
}

bool panelGroupBlock(const PanelGroupCoef& g, int i, int j, HydroCoef* out) {
  int nm = g.nm(), nw = (int)g.omega.size();
  if (i < 0 || j < 0 || 6 * i >= nm || 6 * j >= nm) return false;
  out->rho = g.rho, out->g = g.g, out->depth = g.depth;
  out->omega = g.omega;
  out->A.resize(36 * nw);
  out->B.resize(36 * nw);
  for (int w = 0; w < nw; w++)
    for (int a = 0; a < 6; a++)
      for (int b = 0; b < 6; b++) {
        size_t o = (size_t)nm * nm * w + (size_t)nm * (6 * i + a) + 6 * j + b;
        out->A[36 * w + 6 * a + b] = g.A[o];
        out->B[36 * w + 6 * a + b] = g.B[o];
      }
  for (int a = 0; a < 6; a++)
    for (int b = 0; b < 6; b++) out->Ainf[6 * a + b] = g.Ainf[nm * (6 * i + a) + 6 * j + b];
  return true;
}

bool panelGroupBody(const PanelGroupCoef& g, int k, HydroCoef* out) {
  int nm = g.nm(), nw = (int)g.omega.size(), nh = (int)g.heading.size();
  if (!panelGroupBlock(g, k, k, out)) return false;
  const double* r = &g.ref[3 * k];
  for (int c = 0; c < 3; c++) out->ref[c] = r[c];
  out->heading = g.heading;
  out->Xre.resize(6 * nw * nh);
  out->Xim.resize(6 * nw * nh);
  out->FKre.resize(6 * nw * nh);
  out->FKim.resize(6 * nw * nh);
  for (int w = 0; w < nw; w++) {
    // amplitude a at the origin is a e^{i k D . r} at r: X_r = X_0 e^{-i k D . r}
    double kw = waveNumber(g.omega[w], g.g, g.depth);
    for (int h = 0; h < nh; h++) {
      double ph = -kw * (r[0] * std::cos(g.heading[h]) + r[1] * std::sin(g.heading[h]));
      cplx e(std::cos(ph), std::sin(ph));
      for (int a = 0; a < 6; a++) {
        size_t i = (size_t)(w * nh + h) * nm + 6 * k + a, o = (size_t)(w * nh + h) * 6 + a;
        cplx x = cplx(g.Xre[i], g.Xim[i]) * e, fk = cplx(g.FKre[i], g.FKim[i]) * e;
        out->Xre[o] = x.real(), out->Xim[o] = x.imag();
        out->FKre[o] = fk.real(), out->FKim[o] = fk.imag();
      }
    }
  }
  return true;
}

}  // namespace mjb
