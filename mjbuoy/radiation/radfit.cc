// radfit: damped exponentials for a retardation function by the matrix
// pencil method [Hua and Sarkar 1990] (docs/physics.md section 14,
// "State-space memory")
#include "radiation/radfit.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace mjb {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// poles z = exp(p hd) of the samples y by the matrix pencil with order m:
// the Hankel matrix's leading m right singular vectors V, eig(V1^+ V2) with
// V1, V2 its rows without the last and the first
std::vector<cplx> pencil(const MatrixXd& V, int m) {
  const int L = V.rows() - 1;
  MatrixXd V1 = V.topLeftCorner(L, m), V2 = V.block(1, 0, L, m);
  MatrixXd X = V1.colPivHouseholderQr().solve(V2);
  Eigen::EigenSolver<MatrixXd> es(X, false);
  std::vector<cplx> z;
  for (int r = 0; r < m; r++) z.push_back(es.eigenvalues()[r]);
  return z;
}

// poles p from z: stable ones (|z| < 1), one of each conjugate pair,
// not at the Nyquist frequency (z real negative)
std::vector<cplx> poles(const std::vector<cplx>& z, double hd) {
  std::vector<cplx> p;
  for (cplx q : z) {
    if (!(std::abs(q) > 1e-12) || !std::isfinite(std::abs(q))) continue;
    // an unstable pole reflected into the unit circle (same frequency)
    if (std::abs(q) >= 1) q = 1.0 / std::conj(q) * (1 - 1e-9);
    if (q.imag() < -1e-9 * std::abs(q)) continue;
    if (std::fabs(q.imag()) <= 1e-9 * std::abs(q)) {
      if (q.real() <= 0) continue;
      q = q.real();
    }
    cplx s = std::log(q) / hd;
    if (std::fabs(s.imag()) < 1e-12 / hd) s = s.real();
    p.push_back(s);
  }
  return p;
}

// real basis of the modes at t: Re e^{pt} and, for complex p, Im e^{pt}
int basis(const std::vector<cplx>& p, double t, double* row) {
  int k = 0;
  for (cplx q : p) {
    cplx e = std::exp(q * t);
    row[k++] = e.real();
    if (q.imag() != 0) row[k++] = e.imag();
  }
  return k;
}

// residues: least squares on the decimated samples with the steady gain
// g^T x = G of the full-rate trapezoid sum held exactly (eliminating the
// largest entry of g), c = a - i b for the basis (Re, Im)
bool residues(const std::vector<cplx>& p, const std::vector<double>& y, double hd, double h,
              double G, std::vector<cplx>* c) {
  const int nd = y.size();
  int nb = 0;
  for (cplx q : p) nb += q.imag() != 0 ? 2 : 1;
  if (nb == 0) return false;
  MatrixXd P(nd, nb);
  std::vector<double> row(nb);
  for (int k = 0; k < nd; k++) {
    basis(p, k * hd, row.data());
    for (int b = 0; b < nb; b++) P(k, b) = row[b];
  }
  // sum_k w_k e^{p k h} = 1 / (1 - lam) - 1/2 (infinite trapezoid sum)
  VectorXd g(nb);
  int b = 0;
  for (cplx q : p) {
    cplx s = h * (1.0 / (1.0 - std::exp(q * h)) - 0.5);
    g[b++] = s.real();
    if (q.imag() != 0) g[b++] = s.imag();
  }
  VectorXd Y = Eigen::Map<const VectorXd>(y.data(), nd), x(nb);
  int q;
  g.cwiseAbs().maxCoeff(&q);
  if (nb == 1) {
    x[0] = G / g[0];
  } else {
    // x_q = (G - g'^T x') / g_q
    MatrixXd Pr(nd, nb - 1);
    VectorXd gr(nb - 1);
    for (int k = 0, l = 0; k < nb; k++) {
      if (k == q) continue;
      Pr.col(l) = P.col(k) - P.col(q) * (g[k] / g[q]);
      gr[l++] = g[k];
    }
    VectorXd xr = Pr.colPivHouseholderQr().solve(Y - P.col(q) * (G / g[q]));
    for (int k = 0, l = 0; k < nb; k++) if (k != q) x[k] = xr[l++];
    x[q] = (G - gr.dot(xr)) / g[q];
  }
  if (!x.allFinite()) return false;
  c->clear();
  b = 0;
  for (cplx pq : p) {
    if (pq.imag() != 0) {
      c->push_back(cplx(x[b], -x[b + 1]));
      b += 2;
    } else {
      c->push_back(x[b++]);
    }
  }
  return true;
}

// the trapezoid transform of the samples: B and A - A_inf at w
void sampledTransform(const double* K, int n, double h, double w, double* B, double* dA) {
  double sc = 0, ss = 0;
  for (int k = 0; k < n; k++) {
    const double wk = k == 0 || k == n - 1 ? 0.5 : 1;
    sc += wk * K[k] * std::cos(w * k * h);
    ss += wk * K[k] * std::sin(w * k * h);
  }
  *B = h * sc;
  *dA = -h * ss / w;
}

// the fit's errors against the samples (time, relative L2) and against
// their transform at the frequencies where B is significant
void errors(const double* K, int n, double h, const std::vector<double>& w,
            const std::vector<double>& Bk, const std::vector<double>& Ak, double sT, double sB,
            KFit* f) {
  double e2 = 0, k2 = 0;
  for (int k = 0; k < n; k++) {
    cplx s = 0;
    for (size_t r = 0; r < f->p.size(); r++) s += f->c[r] * std::exp(f->p[r] * (k * h));
    e2 += (s.real() - K[k]) * (s.real() - K[k]);
    k2 += K[k] * K[k];
  }
  k2 = std::max(k2, sT * sT);
  f->errT = k2 > 0 ? std::sqrt(e2 / k2) : 0;
  double bmax = sB, e = 0;
  for (double b : Bk) bmax = std::max(bmax, std::fabs(b));
  // the table's last frequency is left out: B is cut there, and the
  // ripple that makes in K no finite sum of exponentials follows
  for (size_t q = 0; q + 1 < w.size(); q++) {
    if (std::fabs(Bk[q]) < 0.1 * bmax) continue;
    double B, dA;
    fitTransform(*f, w[q], &B, &dA);
    const double sc = std::max(std::fabs(Bk[q]), std::fabs(Ak[q]));
    e = std::max(e, std::max(std::fabs(B - Bk[q]), std::fabs(dA - Ak[q])) / sc);
  }
  f->errF = e;
}

}  // namespace

void fitTransform(const KFit& f, double w, double* B, double* dA) {
  // int_0^inf e^{pt} cos(wt) dt = -p / (p^2 + w^2), sin: w / (p^2 + w^2)
  cplx b = 0, a = 0;
  for (size_t r = 0; r < f.p.size(); r++) {
    const cplx d = f.p[r] * f.p[r] + w * w;
    b += f.c[r] * (-f.p[r]) / d;
    a += f.c[r] / d;
  }
  *B = b.real();
  *dA = -a.real();
}

bool fitKernel(const double* K, int n, double h, const std::vector<double>& w, double sT,
               double sB, KFit* f) {
  *f = KFit();
  f->errT = f->errF = INFINITY;
  if (n < 4) return false;
  // decimated samples: at most ~300, at least 4 per period of the highest
  // frequency where the table allows
  const int s = std::max(1, (n + 299) / 300);
  std::vector<double> y;
  for (int k = 0; k < n; k += s) y.push_back(K[k]);
  const int nd = y.size(), L = nd / 2;
  const double hd = s * h;
  double G = 0;
  for (int k = 0; k < n; k++) G += (k == 0 || k == n - 1 ? 0.5 : 1) * K[k];
  G *= h;
  MatrixXd H(nd - L, L + 1);
  for (int r = 0; r < nd - L; r++) for (int c = 0; c <= L; c++) H(r, c) = y[r + c];
  Eigen::BDCSVD<MatrixXd> svd(H, Eigen::ComputeThinV);
  MatrixXd V = svd.matrixV();
  std::vector<double> Bk(w.size()), Ak(w.size());
  for (size_t q = 0; q < w.size(); q++) sampledTransform(K, n, h, w[q], &Bk[q], &Ak[q]);
  const int mmax = std::min<int>(kFitMaxOrder, std::min<int>(V.cols(), L - 1));
  for (int m = 1; m <= mmax; m++) {
    KFit t;
    t.p = poles(pencil(V, m), hd);
    if (t.p.empty() || !residues(t.p, y, hd, h, G, &t.c)) continue;
    errors(K, n, h, w, Bk, Ak, sT, sB, &t);
    if (!std::isfinite(t.errT) || !std::isfinite(t.errF)) continue;
    const bool ok = t.errT <= kFitTolT && t.errF <= kFitTolF;
    if (ok || std::max(t.errT / kFitTolT, t.errF / kFitTolF) <
                  std::max(f->errT / kFitTolT, f->errF / kFitTolF)) {
      *f = t;
    }
    if (ok) return true;
  }
  return false;
}

void SsModes::add(int i0, int j0, const KFit& f, double h) {
  for (size_t r = 0; r < f.p.size(); r++) {
    i.push_back(i0);
    j.push_back(j0);
    lam.push_back(std::exp(f.p[r] * h));
    c.push_back(f.c[r]);
    p.push_back(f.p[r]);
  }
}

}  // namespace mjb
