// radiation set-up: retardation functions from B(omega), checks of a
// HydroCoef, the bodies' dof chains (docs/physics.md section 14)
#include "radiation/radiation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "radiation/radspeed.h"
#include "radiation/radtail.h"
#include "util/bodylabel.h"

namespace mjb {

namespace {

// int B cos(w t) dw over [w0, w1] with B linear from b0 to b1. Closed form
// [B sin(w t) / t + s cos(w t) / t^2] (s the slope); 4-point Gauss-Legendre
// when t (w1 - w0) is small and the closed form would cancel
double segment(double w0, double w1, double b0, double b1, double t) {
  const double h = w1 - w0, s = (b1 - b0) / h;
  if (t * h < 0.1) {
    static const double x[4] = {-0.8611363115940526, -0.3399810435848563,
                                0.3399810435848563, 0.8611363115940526};
    static const double wt[4] = {0.3478548451374538, 0.6521451548625461,
                                 0.6521451548625461, 0.3478548451374538};
    double sum = 0;
    for (int k = 0; k < 4; k++) {
      double w = w0 + 0.5 * h * (x[k] + 1);
      sum += wt[k] * (b0 + s * (w - w0)) * std::cos(w * t);
    }
    return 0.5 * h * sum;
  }
  return (b1 * std::sin(w1 * t) - b0 * std::sin(w0 * t)) / t +
         s * (std::cos(w1 * t) - std::cos(w0 * t)) / (t * t);
}

double maxAbs(const std::vector<double>& v, int i, int j) {
  double mx = 0;
  for (size_t f = 0; 36 * f < v.size(); f++) mx = std::max(mx, std::fabs(v[36 * f + 6 * i + j]));
  return mx;
}

bool finite(const double* x, size_t n) {
  for (size_t i = 0; i < n; i++) if (!std::isfinite(x[i])) return false;
  return true;
}

// positive semi-definite within round-off: Cholesky of A + eps tr(A) I
bool psd(const double A[36]) {
  double L[36] = {0}, tr = 0;
  for (int i = 0; i < 6; i++) tr += A[7 * i];
  const double eps = 1e-9 * std::max(tr, 1e-300);
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j <= i; j++) {
      double s = A[6 * i + j] + (i == j ? eps : 0);
      for (int k = 0; k < j; k++) s -= L[6 * i + k] * L[6 * j + k];
      if (i == j) {
        if (!(s > 0)) return false;
        L[6 * i + i] = std::sqrt(s);
      } else {
        L[6 * i + j] = s / L[6 * j + j];
      }
    }
  }
  return true;
}

std::string checkCoef(const HydroCoef& c) {
  char e[512];
  if (!finite(c.ref, 3)) return "mjbuoy: radiation: the reference point ref is not finite";
  if (!finite(c.Ainf, 36)) return "mjbuoy: radiation: Ainf is not finite";
  double mx = 0;
  for (double a : c.Ainf) mx = std::max(mx, std::fabs(a));
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < i; j++) {
      if (std::fabs(c.Ainf[6 * i + j] - c.Ainf[6 * j + i]) > 1e-6 * mx) {
        std::snprintf(e, sizeof(e), "mjbuoy: radiation: Ainf is not symmetric (Ainf[%d][%d] = %g, "
                      "Ainf[%d][%d] = %g); added mass is symmetric", i, j, c.Ainf[6 * i + j], j, i,
                      c.Ainf[6 * j + i]);
        return e;
      }
    }
  }
  if (!psd(c.Ainf)) {
    return "mjbuoy: radiation: Ainf is not positive semi-definite (the kinetic energy of the "
           "water it carries would be negative)";
  }
  const size_t nw = c.omega.size();
  if (c.B.size() != 36 * nw || (!c.A.empty() && c.A.size() != 36 * nw)) {
    std::snprintf(e, sizeof(e), "mjbuoy: radiation: %zu frequencies need %zu values of B (and of A, "
                  "or none); got %zu and %zu", nw, 36 * nw, c.B.size(), c.A.size());
    return e;
  }
  for (size_t f = 0; f < nw; f++) {
    if (!std::isfinite(c.omega[f]) || c.omega[f] <= 0 || (f && c.omega[f] <= c.omega[f - 1])) {
      std::snprintf(e, sizeof(e), "mjbuoy: radiation: omega[%zu] = %g; frequencies must be finite, "
                    "positive and increasing", f, c.omega[f]);
      return e;
    }
  }
  if (!finite(c.B.data(), c.B.size()) || !finite(c.A.data(), c.A.size())) {
    return "mjbuoy: radiation: A or B holds a value that is not finite";
  }
  return "";
}

}  // namespace

// K over n samples tapered to zero over its last quarter, then
// less c sin^2(pi t / T_m) with c such that its trapezoid sum, the
// memory's gain for a steady velocity, is B(0) = 0 (docs/physics.md
// section 14, "Steady gain")
void steadyZero(double* K, int n) {
  if (n < 3) return;
  const int n0 = (3 * (n - 1)) / 4;
  for (int k = n0 + 1; k < n; k++) K[k] *= 0.5 * (1 + std::cos(M_PI * (k - n0) / (n - 1 - n0)));
  double sk = 0, sg = 0;
  for (int k = 0; k < n; k++) {
    const double w = k == 0 || k == n - 1 ? 0.5 : 1, g = std::pow(std::sin(M_PI * k / (n - 1)), 2);
    sk += w * K[k];
    sg += w * g;
  }
  for (int k = 0; k < n; k++) K[k] -= sk / sg * std::pow(std::sin(M_PI * k / (n - 1)), 2);
}

namespace {

// the pairs (i, j) whose B_ij is not zero (within 1e-12 of the largest)
std::vector<int> memoryPairs(const HydroCoef& c) {
  double bmax = 0;
  for (double b : c.B) bmax = std::max(bmax, std::fabs(b));
  std::vector<int> pair;
  for (int i = 0; i < 6; i++)
    for (int j = 0; j < 6; j++)
      if (bmax > 0 && maxAbs(c.B, i, j) > 1e-12 * bmax) pair.push_back(6 * i + j);
  return pair;
}

// rb's retardation functions over tmem seconds, one per memoryPairs pair,
// nk samples at step hk: the timestep dt, or, when that would pass
// kMaxKernelSamples and resample is allowed (a state-space fit, whose
// modes are continuous in time, follows), kFitKernelSamples over tmem
void kernels(const HydroCoef& c, double tmem, double dt, bool resample, RadBody* rb,
             double* hk) {
  *hk = dt;
  rb->pair = memoryPairs(c);
  if (!(tmem > 0) || rb->pair.empty()) {
    rb->pair.clear();
    return;
  }
  const double nfull = std::ceil(tmem / dt) + 1;
  if (nfull > kMaxKernelSamples && resample) {
    rb->nk = kFitKernelSamples;
    *hk = tmem / (rb->nk - 1);
  } else {
    rb->nk = int(std::min<double>(nfull, kMaxKernelSamples));
  }
  rb->K.resize(rb->pair.size() * rb->nk);
  double pd[6];  // the tail's exponents, fitted once for every pair
  tailExponents(c, pd);
  for (size_t p = 0; p < rb->pair.size(); p++) {
    int i = rb->pair[p] / 6, j = rb->pair[p] % 6;
    // K is symmetric like B: the transposed pair copies
    auto q = std::find(rb->pair.begin(), rb->pair.begin() + p, 6 * j + i);
    if (q != rb->pair.begin() + p) {
      std::copy_n(rb->K.begin() + (q - rb->pair.begin()) * rb->nk, rb->nk,
                  rb->K.begin() + p * rb->nk);
    } else {
      retardationP(c, pd, i, j, *hk, rb->nk, rb->K.data() + p * rb->nk);
      steadyZero(rb->K.data() + p * rb->nk, rb->nk);
    }
  }
}

// why a convolution memory of tmem seconds at step dt cannot be had: its
// samples pass kMaxKernelSamples; the cost and the settings that fix it
std::string memoryCost(const HydroCoef& c, double tmem, double dt, const char* name,
                       const std::string& why) {
  const double n = std::ceil(tmem / dt) + 1, np = double(memoryPairs(c).size());
  char e[900];
  std::snprintf(e, sizeof e, "mjbuoy: radiation: body %s: a memory of %.4g s at "
                "opt.timestep = %.4g s is %.4g samples per pair (%d pairs: about %.4g MB of "
                "kernels and history and %.4g multiply-adds per step), above the bound of %d "
                "samples%s; raise opt.timestep, shorten mjbuoy.radiation.memory, or use "
                "mjbuoy.radiation.memorymodel statespace (which samples the kernel at a "
                "bounded rate)", name, tmem, dt, n, int(np), (2 * np + 6) * n * 8 / 1e6, n * np,
                kMaxKernelSamples, why.c_str());
  return e;
}

// the index of o's pair whose K is the same as rb's pair p (samples alike), or -1
int samePair(const RadBody& o, const RadBody& rb, size_t p) {
  const int nk = rb.nk;
  if (o.K.size() != o.pair.size() * size_t(o.nk)) return -1;  // a twin: its source is in done
  for (size_t q = 0; q < o.pair.size(); q++)
    if (o.nk == nk && std::equal(o.K.begin() + q * nk, o.K.begin() + (q + 1) * nk,
                                 rb.K.begin() + p * nk))
      return int(q);
  return -1;
}

// pair p's fit copied from an identical K fitted before: an earlier pair of rb, or a pair of a
// body in done (its modes, in o.ss order, back to poles at step dt); false if there is none
bool reuseFit(const RadBody& rb, size_t p, const std::vector<RadBody>& done, double dt,
              std::vector<KFit>* fit) {
  const int nk = rb.nk;
  bool found = false;
  for (size_t q = 0; q < p && !found; q++)
    if (std::equal(rb.K.begin() + q * nk, rb.K.begin() + (q + 1) * nk, rb.K.begin() + p * nk))
      (*fit)[p] = (*fit)[q], found = true;
  for (const RadBody& o : done) {
    if (found) break;
    if (o.ss.size() == 0) continue;
    const int q = samePair(o, rb, p);
    if (q < 0) continue;
    // o's modes of pair q, in o.ss order
    const int oi = o.pair[q] / 6, oj = o.pair[q] % 6;
    for (int r = 0; r < o.ss.size(); r++) {
      if (o.ss.i[r] != oi || o.ss.j[r] != oj) continue;
      (*fit)[p].p.push_back(std::log(o.ss.lam[r]) / dt);
      (*fit)[p].c.push_back(o.ss.c[r]);
    }
    found = true;
  }
  return found;
}

// the fit's scales of pair (i, j): sT for K (L2) and sB for B (peak)
void pairScales(const HydroCoef& c, const RadBody& rb, int i, int j, double* sT, double* sB) {
  const int nk = rb.nk;
  // the pair's scale sqrt(S_i S_j), S_d dof d's own diagonal K (L2) and
  // B (peak), but at least kFitNoise of the largest diagonal of d's kind
  // (translation or rotation, the same units): each diagonal is held to
  // its own size (a slender hull's roll damping is 1e-3 of its yaw
  // damping and decides the roll decay), a coupling to the size at which
  // B stays positive semi-definite (|B_ij| <= sqrt(B_ii B_jj)), and only a
  // diagonal that is noise (yaw of a body of revolution) to the floor
  double D[6][2] = {}, S[2][2] = {};  // [dof or kind][L2 of K, peak B]
  for (size_t q = 0; q < rb.pair.size(); q++) {
    const int d = rb.pair[q] / 6;
    if (rb.pair[q] != 7 * d) continue;
    double n2 = 0;
    for (int k = 0; k < nk; k++) n2 += rb.K[q * nk + k] * rb.K[q * nk + k];
    D[d][0] = std::sqrt(n2);
    D[d][1] = maxAbs(c.B, d, d);
    for (int e = 0; e < 2; e++) S[d / 3][e] = std::max(S[d / 3][e], D[d][e]);
  }
  double E[2][2];
  for (int e = 0; e < 2; e++) {
    E[0][e] = std::max(D[i][e], kFitNoise * S[i / 3][e]);
    E[1][e] = std::max(D[j][e], kFitNoise * S[j / 3][e]);
  }
  *sT = std::sqrt(E[0][0] * E[1][0]);
  *sB = std::sqrt(E[0][1] * E[1][1]);
}

// a fit of K_ij that missed the tolerances: kept with a warning if resampled (hk != dt) and
// within 3 times them (true), else a note that the memory is the convolution (false)
bool keepLooseFit(const KFit& fit, double hk, double dt, const char* name, int i, int j,
                  std::vector<std::string>* note, std::vector<std::string>* warn) {
  char e[512];
  if (hk != dt && !fit.p.empty() && fit.errT <= 3 * kFitTolT && fit.errF <= 3 * kFitTolF) {
    std::snprintf(e, sizeof(e), "radiation: body %s: K_%d%d(t) fitted within %.3g%% "
                  "(L2 in time) and %.3g%% (B, A), above the tolerances %g%% and %g%%; kept, "
                  "since at opt.timestep = %g s the convolution would pass %d samples (docs/"
                  "physics.md section 14, \"Small timesteps\")", name, i + 1, j + 1,
                  100 * fit.errT, 100 * fit.errF, 100 * kFitTolT, 100 * kFitTolF, dt,
                  kMaxKernelSamples);
    warn->push_back(e);
    return true;
  }
  std::snprintf(e, sizeof(e), "radiation: body %s: no fit of K_%d%d(t) by up to %d damped "
                "exponentials within %g%% (L2 in time) and %g%% (B, A at the table's "
                "frequencies); best %.3g%%, %.3g%%; its memory is the convolution (docs/physics.md "
                "section 14)", name, i + 1, j + 1, kFitMaxOrder, 100 * kFitTolT, 100 * kFitTolF,
                100 * fit.errT, 100 * fit.errF);
  note->push_back(e);
  return false;
}

// rb's memory as a state-space model (docs/physics.md section 14,
// "State-space memory"): each pair's K fitted, or copied from an identical
// K fitted before (the transposed pair, another body with the same
// coefficients). Any pair that misses the tolerance leaves rb on the
// convolution, with a note naming the body and the error. K is sampled at
// hk, the modes step at dt; a kernel resampled for the fit (hk != dt: no
// convolution to fall back on) keeps a best fit within 3 times the
// tolerances, with a warning into warn
void fitMemory(const HydroCoef& c, double hk, double dt, const std::vector<RadBody>& done,
               const char* name, RadBody* rb, std::vector<std::string>* note,
               std::vector<std::string>* warn) {
  rb->ss = SsModes();
  const int nk = rb->nk;
  std::vector<KFit> fit(rb->pair.size());
  for (size_t p = 0; p < rb->pair.size(); p++) {
    const int i = rb->pair[p] / 6, j = rb->pair[p] % 6;
    const bool found = reuseFit(*rb, p, done, dt, &fit);
    double sT = 0, sB = 0;
    pairScales(c, *rb, i, j, &sT, &sB);
    if (!found && !fitKernel(rb->K.data() + p * nk, nk, hk, c.omega, sT, sB, &fit[p])) {
      if (keepLooseFit(fit[p], hk, dt, name, i, j, note, warn)) continue;
      return;
    }
  }
  for (size_t p = 0; p < rb->pair.size(); p++)
    rb->ss.add(rb->pair[p] / 6, rb->pair[p] % 6, fit[p], dt);
}

// MuJoCo factors the dofs of a "simple" body as diagonal: J^T A J is not.
// Clear their flag and recount the runs of simple dofs (docs/physics.md
// section 14); the first call keeps the model's flags for restoreModel
void clearSimple(const mjModel* m, const std::vector<int>& dof, Radiation* r) {
  if (r->simple0.empty()) r->simple0.assign(m->dof_simplenum, m->dof_simplenum + m->nv);
  int* simple = const_cast<mjModel*>(m)->dof_simplenum;
  for (int i : dof) simple[i] = 0;
  for (int i = m->nv - 1, cnt = 0; i >= 0; i--) {
    cnt = simple[i] ? cnt + 1 : 0;
    simple[i] = cnt;
  }
}

}  // namespace

bool addedMassIndefinite(const double A[36]) { return finite(A, 36) && !psd(A); }

void retardation(const HydroCoef& c, int i, int j, double dt, int n, double* K, bool tail) {
  double pd[6];
  if (tail) tailExponents(c, pd);
  retardationP(c, tail ? pd : nullptr, i, j, dt, n, K);
}

void retardationP(const HydroCoef& c, const double* pd, int i, int j, double dt, int n, double* K) {
  const int nw = c.nw();
  // beyond the last frequency B_ij(w) = B_ij(w_N) (w_N / w)^p (radtail.h)
  const double p = pd ? tailExponent(pd, i, j) : 0;
  const double bN = nw ? c.B[36 * (nw - 1) + 6 * i + j] : 0, wN = nw ? c.omega.back() : 0;
  for (int k = 0; k < n; k++) {
    const double t = k * dt;
    double w0 = 0, b0 = 0, sum = 0;  // B(0) = 0
    for (int f = 0; f < nw; f++) {
      const double w1 = c.omega[f], b1 = c.B[36 * f + 6 * i + j];
      sum += t == 0 ? 0.5 * (b0 + b1) * (w1 - w0) : segment(w0, w1, b0, b1, t);
      w0 = w1;
      b0 = b1;
    }
    K[k] = 2 / M_PI * sum + (p > 0 && bN != 0 ? tailK(bN, wN, p, t) : 0);
  }
}

double memoryLength(const HydroCoef& c) {
  if (c.nw() == 0) return 0;
  // K is band-limited to the last frequency: a grid of a quarter of its
  // half period resolves the envelope
  const double dc = std::min(M_PI / (4 * c.omega.back()), 0.05);
  const int n = int(kMaxMemory / dc) + 1;
  std::vector<double> K(n);
  double peak = 0, bmax = 0;
  int last = 0;
  for (int i = 0; i < 6; i++) for (int j = 0; j < 6; j++) bmax = std::max(bmax, maxAbs(c.B, i, j));
  std::vector<std::vector<double>> all;
  double pd[6];  // the tail's exponents, fitted once for every pair
  tailExponents(c, pd);
  for (int i = 0; i < 6; i++) {
    for (int j = i; j < 6; j++) {
      if (maxAbs(c.B, i, j) <= 1e-12 * bmax) continue;
      retardationP(c, pd, i, j, dc, n, K.data());
      all.push_back(K);
      for (double k : K) peak = std::max(peak, std::fabs(k));
    }
  }
  for (const auto& k : all) {
    for (int s = n - 1; s > last; s--) {
      if (std::fabs(k[s]) > 0.01 * peak) {
        last = s;
        break;
      }
    }
  }
  return peak > 0 ? std::min(kMaxMemory, (last + 1) * dc) : 0;
}

namespace {

// the pairs i <= j whose B_ij is not zero, each with its scale and its K
// over n samples at step dc, and cos(w_f k dc) for the table's frequencies
struct PairKernels {
  std::vector<int> pair;
  std::vector<double> scale, K, cosw;
  int n = 0;
  double dc = 0;
};

// pk for c over tmax s. The grid is an eighth of the last frequency's half
// period (at most 25 ms): the trapezoid transform of the samples aliases B
// from about 16 w_N - w, where the tail has fallen by (1/15)^p
void pairKernels(const HydroCoef& c, double tmax, PairKernels* pk) {
  pk->dc = std::min(M_PI / (8 * c.omega.back()), 0.025);
  pk->n = int(std::ceil(tmax / pk->dc)) + 1;
  double S[6], kind[2] = {0, 0};  // scale of each dof: peak |B_dd|, floored as the fit's
  for (int d = 0; d < 6; d++) kind[d / 3] = std::max(kind[d / 3], S[d] = maxAbs(c.B, d, d));
  for (int d = 0; d < 6; d++) S[d] = std::max(S[d], kFitNoise * kind[d / 3]);
  double pd[6];
  tailExponents(c, pd);
  for (int p : memoryPairs(c)) {
    const int i = p / 6, j = p % 6;
    if (j < i) continue;  // K is symmetric
    const double sc = std::sqrt(S[i] * S[j]);
    pk->pair.push_back(p);
    pk->scale.push_back(sc > 0 ? sc : maxAbs(c.B, i, j));
    pk->K.resize(pk->K.size() + pk->n);
    retardationP(c, pd, i, j, pk->dc, pk->n, pk->K.data() + pk->K.size() - pk->n);
  }
  pk->cosw.resize(size_t(c.nw()) * pk->n);
  for (int f = 0; f < c.nw(); f++)
    for (int k = 0; k < pk->n; k++)
      pk->cosw[size_t(f) * pk->n + k] = std::cos(c.omega[f] * k * pk->dc);
}

// the worst |B_T(w) - B(w)| / scale over pk's pairs and c's frequencies,
// B_T = h sum w_k K_k cos(w t_k) of K cut at tmem, tapered and zero-gain
// (steadyZero); *pair its 6 i + j
double transformError(const HydroCoef& c, const PairKernels& pk, double tmem, int* pair) {
  const int m = std::min(pk.n, int(std::lround(tmem / pk.dc)) + 1);
  std::vector<double> K(m);
  double worst = 0;
  *pair = -1;
  for (size_t q = 0; q < pk.pair.size(); q++) {
    std::copy_n(pk.K.begin() + q * pk.n, m, K.begin());
    steadyZero(K.data(), m);
    for (int f = 0; f < c.nw(); f++) {
      const double* cw = pk.cosw.data() + size_t(f) * pk.n;
      double s = 0.5 * (K[0] * cw[0] + K[m - 1] * cw[m - 1]);
      for (int k = 1; k < m - 1; k++) s += K[k] * cw[k];
      const double e = std::fabs(pk.dc * s - c.B[36 * f + pk.pair[q]]) / pk.scale[q];
      if (e > worst) worst = e, *pair = pk.pair[q];
    }
  }
  return worst;
}

}  // namespace

double memoryLengthByTransform(const HydroCoef& c, double* worst, int* pair) {
  if (worst) *worst = 0;
  if (pair) *pair = -1;
  double t = memoryLength(c);
  if (!(t > 0)) return t;
  // the shortest of t g^k whose K reproduces B (docs/physics.md section 14,
  // "Memory length"); a kernel that decays later than the cap keeps its decay length
  const double top = std::max(t, kAutoMemoryMax);
  PairKernels pk;
  pairKernels(c, top, &pk);
  int pr = -1;
  double e = transformError(c, pk, t, &pr);
  while (e > kMemoryTol && t < top) {
    t = std::min(t * kMemoryGrowth, top);
    e = transformError(c, pk, t, &pr);
  }
  if (worst) *worst = e;
  if (pair) *pair = pr;
  return t;
}

// what a body's memory (K and its fit) depends on: the memory length
// asked (0: automatic, from B), the step, the frequencies and B
static std::vector<double> memoryKey(const HydroCoef& c, double tmem, double dt) {
  std::vector<double> k = {tmem, dt, double(c.omega.size())};
  k.insert(k.end(), c.omega.begin(), c.omega.end());
  k.insert(k.end(), c.B.begin(), c.B.end());
  return k;
}

// whether two memory keys agree: the same memory length, step and
// frequencies, and B within 1e-9 of its largest entry. Identical hulls at
// different places get B different in the last bits (their panel meshes
// are built from world positions), far below what the fit resolves
static bool sameMemory(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.size() < 3) return false;
  const size_t nb = 3 + size_t(a[2]);
  if (!std::equal(a.begin(), a.begin() + nb, b.begin())) return false;
  double bmax = 0, dmax = 0;
  for (size_t q = nb; q < a.size(); q++) {
    bmax = std::max(bmax, std::fabs(a[q]));
    dmax = std::max(dmax, std::fabs(a[q] - b[q]));
  }
  return dmax <= 1e-9 * bmax;
}

// rb's memory copied from a body set before with the same key (a fleet of
// one hull: K and the fit within round-off of its own, without their 0.1 s
// per body); quiet: no note is due for a fit that fell back to the
// convolution, else such a twin is not copied, so the note names each body
static bool copyMemory(const std::vector<RadBody>& done, bool quiet, RadBody* rb) {
  for (const RadBody& o : done) {
    if (!sameMemory(o.key, rb->key) || (o.nk && !quiet && o.ss.size() == 0)) continue;
    rb->pair = o.pair;
    rb->Kr = o.Kr;
    rb->nk = o.nk;
    rb->ss = o.ss;
    return true;
  }
  return false;
}

// why body cannot take radiation (its id, its joints, c, the memory length tmem in s, a step
// other than r's), else "" with the nearest body at or above it that has dofs in *mover
static std::string radBodyError(const mjModel* m, int body, const HydroCoef& c, double tmem,
                                const Radiation& r, int* mover) {
  char e[512];
  if (body <= 0 || body >= m->nbody) {
    std::snprintf(e, sizeof(e), "mjbuoy: radiation: body id %d out of range [1, %d]", body,
                  m->nbody - 1);
    return e;
  }
  char who[128];
  const char* name = bodyLabel(m, body, who, sizeof who);
  *mover = body;
  while (*mover && !m->body_dofnum[*mover]) *mover = m->body_parentid[*mover];
  if (!*mover) {
    std::snprintf(e, sizeof(e), "mjbuoy: radiation: body %s has no joint between it and the "
                  "world; added mass needs a body free to move", name);
    return e;
  }
  std::string ce = checkCoef(c);
  if (!ce.empty()) return ce + " (body " + name + ")";
  const double dt = m->opt.timestep;
  if (!std::isfinite(tmem) || tmem > kMaxMemory) {
    std::snprintf(e, sizeof(e), "mjbuoy: radiation: memory length %g s for body %s is out of "
                  "range; give (0, %g] s, 0 for automatic or < 0 for none", tmem, name, kMaxMemory);
    return e;
  }
  if (!r.rb.empty() && r.dt != dt) {
    return "mjbuoy: radiation: opt.timestep changed since the first body was set";
  }
  return "";
}

// rb's memory of tmem s (0: automatic) at step dt (s) computed anew: kernels, the state-space
// fit, the reversed kernels of the convolution; "" or why it cannot be had
static std::string newMemory(const HydroCoef& c, double tmem, double dt, const char* name,
                             Radiation* r, RadBody* rb) {
  if (tmem == 0) tmem = memoryLength(c);
  // a convolution memory is bounded in samples (docs/physics.md section
  // 14, "Small timesteps"): refused with its cost beyond
  if (r->conv && tmem > 0 && std::ceil(tmem / dt) + 1 > kMaxKernelSamples &&
      !memoryPairs(c).empty())
    return memoryCost(c, tmem, dt, name, "");
  double hk = dt;
  kernels(c, tmem, dt, !r->conv, rb, &hk);
  // a fallback to the exact convolution costs time, not accuracy: it is
  // noted (a warning) only when the state-space model was asked for
  std::vector<std::string> quiet;
  if (rb->nk && !r->conv)
    fitMemory(c, hk, dt, r->rb, name, rb, r->ssAsked ? &r->note : &quiet, &r->note);
  // a kernel resampled for the fit cannot serve the convolution
  if (hk != dt && rb->ss.size() == 0) {
    const std::vector<std::string>& fn = quiet.empty() ? r->note : quiet;
    return memoryCost(c, tmem, dt, name, ", and its state-space fit failed" +
                      (fn.empty() ? std::string() : " (" + fn.back() + ")"));
  }
  // the convolution runs forward over the history (radstep.cc, radMemory)
  auto kr = std::make_shared<std::vector<double>>(rb->K.size());
  for (size_t p = 0; p < rb->pair.size(); p++)
    std::reverse_copy(rb->K.begin() + p * rb->nk, rb->K.begin() + (p + 1) * rb->nk,
                      kr->begin() + p * rb->nk);
  rb->Kr = std::move(kr);
  return "";
}

// rb in r, in place of the body's earlier entry; then the mode offsets and the sizes that
// stepping needs (dofs, history samples, modes)
static void placeBody(RadBody&& rb, Radiation* r) {
  const int body = rb.body;
  auto it = std::find_if(r->rb.begin(), r->rb.end(), [&](const RadBody& x) { return x.body == body; });
  if (it != r->rb.end()) {
    *it = std::move(rb);
  } else {
    r->rb.push_back(std::move(rb));
  }
  r->maxdof = 0;
  r->nh = 1;
  r->nsh = 1;
  r->nmode = 0;
  for (RadBody& x : r->rb) {
    x.soff = r->nmode;
    r->nmode += x.ss.size();
    r->maxdof = std::max(r->maxdof, int(x.dof.size()));
    // the history ring serves the convolution; a state-space body needs
    // only its first and newest samples (the clock counts to 2)
    r->nh = std::max(r->nh, x.ss.size() ? std::min(x.nk, 2) : x.nk);
    // the speed terms' ring serves the convolution only (radstep.cc speedForce)
    r->nsh = std::max(r->nsh, x.ss.size() ? 1 : x.nls);
  }
}

std::string setRadiation(const mjModel* m, int body, const HydroCoef& c, double tmem,
                         Radiation* r) {
  int mover = 0;
  std::string err = radBodyError(m, body, c, tmem, *r, &mover);
  if (!err.empty()) return err;
  char who[128];
  const char* name = bodyLabel(m, body, who, sizeof who);
  const double dt = m->opt.timestep;
  r->dt = dt;

  RadBody rb;
  rb.body = body;
  std::copy(c.ref, c.ref + 3, rb.ref);
  std::copy(c.Ainf, c.Ainf + 36, rb.A);
  std::copy(r->roll, r->roll + 2, rb.roll);
  for (int i = m->body_dofadr[mover] + m->body_dofnum[mover] - 1; i >= 0; i = m->dof_parentid[i]) {
    rb.dof.push_back(i);
  }
  rb.key = memoryKey(c, tmem, dt);
  if (!copyMemory(r->rb, r->conv || !r->ssAsked, &rb)) {
    err = newMemory(c, tmem, dt, name, r, &rb);
    if (!err.empty()) return err;
  }
  // forward speed: a memory-carrying body slender along x (or any, speed 2),
  // at any speed (0 at rest)
  const bool slender = c.Ainf[0] <= kSlenderA11 * c.Ainf[7];
  if ((r->speed == 2 || (r->speed == 1 && slender)) && tmem >= 0)
    speedKernels(c, tmem == 0 ? memoryLength(c) : tmem, dt, &rb.Ls, &rb.nls);
  clearSimple(m, rb.dof, r);
  placeBody(std::move(rb), r);
  return "";
}

void restoreModel(const mjModel* m, const Radiation& r) {
  if (r.simple0.empty()) return;
  std::copy(r.simple0.begin(), r.simple0.end(), const_cast<mjModel*>(m)->dof_simplenum);
}

void radMakeState(const Radiation& r, RadState* s) {
  s->hist.assign(6 * r.rb.size() * r.nh, 0);
  s->fmem.assign(6 * r.rb.size(), 0);
  s->shist.assign(2 * r.rb.size() * r.nsh, 0);
  s->jac.assign(6 * r.maxdof, 0);
  s->ajac.assign(6 * r.maxdof, 0);
  s->told.assign(r.rb.size(), 0);
  s->ssX.assign(r.nmode, 0);
  s->ssPw.assign(r.nmode, 0);
  s->ssLam.assign(r.nmode, 0);
  s->ssDt = 0;
  s->ssNu.assign(12 * r.rb.size(), 0);
  s->imm.assign(r.rb.size(), 1.0);
  s->sstep.assign(2 * r.rb.size(), 1.0);
  s->mdiag.assign(r.rb.size(), NAN);
  s->poff.assign(r.rb.size() + 1, 0);
  for (size_t ib = 0; ib < r.rb.size(); ib++) {
    s->poff[ib + 1] = s->poff[ib] + int(r.rb[ib].pair.size());
  }
  s->pre.assign(3 * s->poff.back(), 0);
  s->chist.assign(r.cp.empty() ? 0 : 6 * r.rb.size() * r.nch, 0);
  s->fcp.assign(6 * r.cp.size(), 0);
  radRestart(s);
}

void radRestart(RadState* s) {
  std::fill(s->fmem.begin(), s->fmem.end(), 0.0);
  std::fill(s->told.begin(), s->told.end(), 0);
  std::fill(s->imm.begin(), s->imm.end(), 1.0);
  std::fill(s->sstep.begin(), s->sstep.end(), 1.0);
  s->head = s->count = 0;
  s->shead = s->scount = 0;
  s->chead = s->ccount = 0;
  std::fill(s->fcp.begin(), s->fcp.end(), 0.0);
  s->dtTold = false;
  s->key = -1;
  s->tcur = 0;
  s->mstamp = -1;
}

std::string setCouple(int i, int j, const HydroCoef& c, double tmem, double dt, Radiation* r) {
  if (i < 0 || j < 0 || i >= int(r->rb.size()) || j >= int(r->rb.size()) || i == j)
    return "radiation coupling: bodies " + std::to_string(i) + " and " + std::to_string(j) +
           " are not two radiating bodies";
  RadCouple x;
  x.i = i, x.j = j;
  std::copy(c.Ainf, c.Ainf + 36, x.A);
  if (tmem == 0) tmem = memoryLength(c);
  const double nfull = std::ceil(tmem / dt) + 1;
  if (!(nfull <= kMaxKernelSamples))
    return "radiation coupling: a memory of " + std::to_string(tmem) + " s is more than " +
           std::to_string(kMaxKernelSamples) + " samples of the timestep; set "
           "mjbuoy.radiation.memory shorter or the timestep longer";
  x.nk = std::max(2, int(nfull));
  double big = 0;
  for (double b : c.B) big = std::max(big, std::fabs(b));
  for (int p = 0; p < 36; p++) {
    double m = 0;
    for (int w = 0; w < c.nw(); w++) m = std::max(m, std::fabs(c.B[36 * w + p]));
    if (!(m > 1e-6 * big)) continue;  // a block entry the symmetry makes zero
    x.pair.push_back(p);
    x.K.resize(x.pair.size() * x.nk);
    double* K = x.K.data() + (x.pair.size() - 1) * x.nk;
    retardationP(c, nullptr, p / 6, p % 6, dt, x.nk, K);
    steadyZero(K, x.nk);
    for (int k = 0; k < x.nk; k++)
      if (!std::isfinite(K[k])) return "radiation coupling: its memory kernel is not finite";
    std::reverse(K, K + x.nk);  // oldest sample's weight first, as the step reads it
  }
  r->nch = std::max(r->nch, x.nk);
  r->cp.push_back(std::move(x));
  return "";
}

}  // namespace mjb
