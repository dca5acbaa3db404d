// radfit: the radiation memory as a state-space model (docs/physics.md
// section 14, "State-space memory"): each retardation function K_ij(t) fitted
// by a few damped complex exponentials, and their per-step states
#ifndef MJBUOY_RADFIT_H_
#define MJBUOY_RADFIT_H_

#include <complex>
#include <string>
#include <vector>

namespace mjb {

using cplx = std::complex<double>;

// K(t) ~ sum_r Re(c_r exp(p_r t)), Re p_r < 0
struct KFit {
  std::vector<cplx> p, c;  // poles [1/s] (Im >= 0: one of each conjugate pair), residues
  double errT = 0;         // ||fit - K||_2 / ||K||_2 over the samples
  double errF = 0;         // worst error of B, A - A_inf rebuilt from the fit (see fitKernel)
};

// tolerances of fitKernel (docs/physics.md section 14)
const double kFitTolT = 0.02, kFitTolF = 0.03;
const int kFitMaxOrder = 20;  // real exponentials (a complex pair counts 2)
// a diagonal K below this fraction of the largest of its kind (translation
// or rotation) is fitted to that floor, not to its own size (radiation.cc;
// the yaw of the test hemisphere, 2.6e-4 of its roll, is panel noise; the
// roll of the 64-triangle Wigley, 1.3e-3 of its yaw, is not)
const double kFitNoise = 3e-3;

// fit n samples K[k] = K(k h) (n >= 4): matrix pencil on samples decimated
// to at most ~300, residues by least squares with the trapezoid steady gain
// h sum w_k K_k held, order the smallest meeting kFitTolT and kFitTolF;
// failing that, residues with rows of B and A - A_inf added, then the
// pencil's poles moved (stable) to that least squares (Perez and Fossen
// 2008; docs/physics.md section 14).
// errT is the L2 error over the samples relative to max(||K||_2, sT); errF
// the largest error of B and of A - A_inf at the frequencies w (but the
// last) where the sampled K's B is at least 10% of max(its peak, sB),
// relative to max(|B|, |A - A_inf|) there. sT, sB: a coupling pair's scale
// (0 for its own), so that a pair that is noise next to the diagonal is
// not held to its own size. true when one order met both; f holds the
// best found either way
bool fitKernel(const double* K, int n, double h, const std::vector<double>& w, double sT,
               double sB, KFit* f);

// B(w) = int_0^inf K cos(w t) dt and A(w) - A_inf = -(1/w) int_0^inf K sin(w t) dt
// of a fit, in closed form
void fitTransform(const KFit& f, double w, double* B, double* dA);

// a body's memory as modes: force row i, velocity dof j, lam = exp(p h), c;
// p the continuous poles [1/s], for another step h (a changed timestep)
struct SsModes {
  std::vector<int> i, j;
  std::vector<cplx> lam, c, p;
  int size() const { return int(i.size()); }
  void add(int i0, int j0, const KFit& f, double h);
};

// per-mode states of one body: X = sum_k lam^k nu_j(t_{n-1-k}) over the
// samples before the newest, pw = lam^(samples - 1); and the first and
// newest velocity samples
struct SsState {
  cplx* X;
  cplx* pw;
  double* first;  // 6
  double* last;   // 6
};

// the memory's step clock (radstep.cc): restart (first sample nu), new step
// (commits the newest sample, then nu is the newest), same time (nu
// replaces the newest); then f = the trapezoid convolution of the fitted K
// with the samples: -h Re sum c (lam X + nu_n / 2 - pw nu_first / 2).
// lam: the modes' exp(p h) at the step h in force (nullptr: sm.lam)
void ssRestart(const SsModes& sm, SsState s, const double nu[6]);
void ssNew(const SsModes& sm, SsState s, const double nu[6], const cplx* lam = nullptr);
void ssSame(SsState s, const double nu[6], bool first);
void ssForce(const SsModes& sm, SsState s, double h, double f[6], const cplx* lam = nullptr);

}  // namespace mjb

#endif  // MJBUOY_RADFIT_H_
