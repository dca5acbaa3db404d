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

// number of real basis functions of the modes p
int basisSize(const std::vector<cplx>& p) {
  int nb = 0;
  for (cplx q : p) nb += q.imag() != 0 ? 2 : 1;
  return nb;
}

// the rows of B(w) and A(w) - A_inf of the real basis (fitTransform's
// closed form, split into the parts of c = a - i b)
void freqRows(const std::vector<cplx>& p, double w, double* rb, double* ra) {
  int k = 0;
  for (cplx q : p) {
    const cplx d = q * q + w * w, b = -q / d, a = -1.0 / d;
    rb[k] = b.real();
    ra[k++] = a.real();
    if (q.imag() != 0) {
      rb[k] = b.imag();
      ra[k++] = a.imag();
    }
  }
}

// residues: weighted least squares M x = Y (rows of the decimated samples
// and of B, A - A_inf at the fit's frequencies) with the steady gain
// g^T x = G of the full-rate trapezoid sum held exactly (eliminating the
// largest entry of g), c = a - i b for the basis (Re, Im)
bool residues(const std::vector<cplx>& p, const MatrixXd& M, const VectorXd& Y, double h,
              double G, std::vector<cplx>* c) {
  const int nb = M.cols();
  if (nb == 0) return false;
  // sum_k w_k e^{p k h} = 1 / (1 - lam) - 1/2 (infinite trapezoid sum)
  VectorXd g(nb), x(nb);
  int b = 0;
  for (cplx q : p) {
    cplx s = h * (1.0 / (1.0 - std::exp(q * h)) - 0.5);
    g[b++] = s.real();
    if (q.imag() != 0) g[b++] = s.imag();
  }
  int q;
  g.cwiseAbs().maxCoeff(&q);
  if (nb == 1) {
    x[0] = G / g[0];
  } else {
    // x_q = (G - g'^T x') / g_q
    MatrixXd Pr(M.rows(), nb - 1);
    VectorXd gr(nb - 1);
    for (int k = 0, l = 0; k < nb; k++) {
      if (k == q) continue;
      Pr.col(l) = M.col(k) - M.col(q) * (g[k] / g[q]);
      gr[l++] = g[k];
    }
    VectorXd xr = Pr.colPivHouseholderQr().solve(Y - M.col(q) * (G / g[q]));
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

// the frequencies the fit is held to: the table's (but the last: B is
// cut there, and the ripple that makes in K no finite sum of exponentials
// follows) where the sampled B is at least 10% of max(its peak, sB); with
// the scale max(|B|, |A - A_inf|) of each
struct FitFreqs {
  std::vector<double> w, B, dA, sc;
};

FitFreqs fitFreqs(const double* K, int n, double h, const std::vector<double>& w, double sB) {
  std::vector<double> Bk(w.size()), Ak(w.size());
  double bmax = sB;
  for (size_t q = 0; q < w.size(); q++) {
    sampledTransform(K, n, h, w[q], &Bk[q], &Ak[q]);
    bmax = std::max(bmax, std::fabs(Bk[q]));
  }
  FitFreqs ff;
  for (size_t q = 0; q + 1 < w.size(); q++) {
    if (!(std::fabs(Bk[q]) >= 0.1 * bmax) || !(bmax > 0)) continue;
    ff.w.push_back(w[q]);
    ff.B.push_back(Bk[q]);
    ff.dA.push_back(Ak[q]);
    ff.sc.push_back(std::max(std::fabs(Bk[q]), std::fabs(Ak[q])));
  }
  return ff;
}

// the fit's errors against the samples (time, relative L2) and against
// their transform at the frequencies ff
void errors(const double* K, int n, double h, const FitFreqs& ff, double sT, KFit* f) {
  double e2 = 0, k2 = 0;
  for (int k = 0; k < n; k++) {
    cplx s = 0;
    for (size_t r = 0; r < f->p.size(); r++) s += f->c[r] * std::exp(f->p[r] * (k * h));
    e2 += (s.real() - K[k]) * (s.real() - K[k]);
    k2 += K[k] * K[k];
  }
  k2 = std::max(k2, sT * sT);
  f->errT = k2 > 0 ? std::sqrt(e2 / k2) : 0;
  double e = 0;
  for (size_t q = 0; q < ff.w.size(); q++) {
    double B, dA;
    fitTransform(*f, ff.w[q], &B, &dA);
    e = std::max(e, std::max(std::fabs(B - ff.B[q]), std::fabs(dA - ff.dA[q])) / ff.sc[q]);
  }
  f->errF = e;
}

// the fit's weighted rows for poles p, the frequency rows weighed by lf
// against the time rows: each block scaled to the error it is held to
// (errT: L2 of all n samples, s per decimated one, over kn; errF: per
// frequency over its scale, 1 / sqrt(count) so that the block's L2 is the
// rms error)
struct FitData {
  const std::vector<double>* y;
  double hd, h, G, kn;
  int s;
  const FitFreqs* ff;
};

void fitRows(const std::vector<cplx>& p, const FitData& d, double lf, MatrixXd* M, VectorXd* Y) {
  const std::vector<double>& y = *d.y;
  const FitFreqs& ff = *d.ff;
  const int nd = y.size(), nf = ff.w.size(), nb = basisSize(p);
  const int rows = nd + (lf > 0 ? 2 * nf : 0);
  M->resize(rows, nb);
  Y->resize(rows);
  std::vector<double> r1(nb), r2(nb);
  const double wt = std::sqrt(double(d.s)) / d.kn;
  for (int k = 0; k < nd; k++) {
    basis(p, k * d.hd, r1.data());
    for (int b = 0; b < nb; b++) (*M)(k, b) = wt * r1[b];
    (*Y)[k] = wt * y[k];
  }
  for (int q = 0; q < nf && lf > 0; q++) {
    const double wf = lf / (ff.sc[q] * std::sqrt(double(nf)));
    freqRows(p, ff.w[q], r1.data(), r2.data());
    for (int b = 0; b < nb; b++) {
      (*M)(nd + 2 * q, b) = wf * r1[b];
      (*M)(nd + 2 * q + 1, b) = wf * r2[b];
    }
    (*Y)[nd + 2 * q] = wf * ff.B[q];
    (*Y)[nd + 2 * q + 1] = wf * ff.dA[q];
  }
}

// the residues of poles p by the weighted rows; r: the weighted residual
bool weighted(const std::vector<cplx>& p, const FitData& d, double lf, KFit* t,
              VectorXd* r = nullptr) {
  MatrixXd M;
  VectorXd Y;
  fitRows(p, d, lf, &M, &Y);
  t->p = p;
  if (!residues(p, M, Y, d.h, d.G, &t->c)) return false;
  if (r) {
    VectorXd x(M.cols());
    for (size_t k = 0, b = 0; k < p.size(); k++) {
      x[b++] = t->c[k].real();
      if (p[k].imag() != 0) x[b++] = -t->c[k].imag();
    }
    *r = M * x - Y;
  }
  return true;
}

// poles from parameters: Re p = -exp(u) (stable), Im p = |v|
std::vector<cplx> fromParams(const std::vector<cplx>& p0, const VectorXd& x) {
  std::vector<cplx> p;
  for (size_t k = 0, b = 0; k < p0.size(); k++) {
    const double re = -std::exp(x[b++]);
    p.push_back(p0[k].imag() != 0 ? cplx(re, std::max(std::fabs(x[b++]), 1e-12)) : cplx(re));
  }
  return p;
}

// the poles of t moved to minimize the weighted residual (variable
// projection: the residues solved for at each poles; Levenberg-Marquardt
// with a forward-difference Jacobian), stable by construction
void refine(const FitData& d, double lf, KFit* t) {
  VectorXd x(basisSize(t->p));
  for (size_t k = 0, b = 0; k < t->p.size(); k++) {
    x[b++] = std::log(std::max(-t->p[k].real(), 1e-6));
    if (t->p[k].imag() != 0) x[b++] = t->p[k].imag();
  }
  const std::vector<cplx> p0 = t->p;
  KFit cur;
  VectorXd r;
  if (!weighted(fromParams(p0, x), d, lf, &cur, &r)) return;
  double mu = 1e-3, cost = r.squaredNorm();
  for (int it = 0; it < 40; it++) {
    MatrixXd J(r.size(), x.size());
    bool ok = true;
    for (int k = 0; k < x.size() && ok; k++) {
      VectorXd xk = x, rk;
      const double dx = 1e-6 * std::max(1.0, std::fabs(x[k]));
      xk[k] += dx;
      KFit tk;
      ok = weighted(fromParams(p0, xk), d, lf, &tk, &rk) && rk.size() == r.size();
      if (ok) J.col(k) = (rk - r) / dx;
    }
    if (!ok) break;
    const MatrixXd JtJ = J.transpose() * J;
    const VectorXd g = J.transpose() * r;
    bool stepped = false;
    for (int tries = 0; tries < 8 && !stepped; tries++) {
      MatrixXd Aug = JtJ;
      Aug.diagonal() += mu * (JtJ.diagonal().array() + 1e-12).matrix();
      const VectorXd dx = -Aug.ldlt().solve(g);
      KFit tn;
      VectorXd rn;
      if (dx.allFinite() && weighted(fromParams(p0, x + dx), d, lf, &tn, &rn) &&
          rn.squaredNorm() < cost) {
        x += dx;
        r = rn;
        cost = rn.squaredNorm();
        cur = tn;
        mu = std::max(mu / 3, 1e-9);
        stepped = true;
      } else {
        mu *= 4;
      }
    }
    if (!stepped) break;
  }
  *t = cur;
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
  const FitFreqs ff = fitFreqs(K, n, h, w, sB);
  double k2 = 0;
  for (int k = 0; k < n; k++) k2 += K[k] * K[k];
  const double kn = std::max(std::sqrt(k2), sT);
  if (!(kn > 0)) return false;
  const FitData d = {&y, hd, h, G, kn, s, &ff};
  const int mmax = std::min<int>(kFitMaxOrder, std::min<int>(V.cols(), L - 1));
  auto keep = [&](const KFit& t) {
    const bool ok = t.errT <= kFitTolT && t.errF <= kFitTolF;
    if (ok || std::max(t.errT / kFitTolT, t.errF / kFitTolF) <
                  std::max(f->errT / kFitTolT, f->errF / kFitTolF))
      *f = t;
    return ok;
  };
  // the residues of the pencil's poles of each order: by the samples'
  // least squares (lf = 0), then, at no order meeting both, with the
  // frequency domain's rows increasingly held
  std::vector<std::vector<cplx>> pm;  // the pencil's poles of each order
  for (int m = 1; m <= mmax; m++) pm.push_back(poles(pencil(V, m), hd));
  for (double lf : {0.0, 0.3, 1.0, 3.0, 10.0}) {
    for (const std::vector<cplx>& p : pm) {
      KFit t;
      if (p.empty() || !weighted(p, d, lf, &t)) continue;
      errors(K, n, h, ff, sT, &t);
      if (std::isfinite(t.errT) && std::isfinite(t.errF) && keep(t)) return true;
    }
  }
  // no order met both: the pencil's poles of each order moved to the
  // weighted least squares of time and frequency rows
  for (const std::vector<cplx>& p : pm) {
    if (p.empty()) continue;
    for (double lf : {1.0, 3.0}) {
      KFit t;
      if (!weighted(p, d, lf, &t)) continue;
      refine(d, lf, &t);
      errors(K, n, h, ff, sT, &t);
      if (std::isfinite(t.errT) && std::isfinite(t.errF) && keep(t)) return true;
    }
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
