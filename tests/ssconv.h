// test helper: a body's state-space radiation memory against the trapezoid
// convolution of its sampled K (docs/physics.md section 14, "State-space
// memory"; radfit_test.cc, radfit_models_test.cc)
#ifndef MJBUOY_TESTS_SSCONV_H_
#define MJBUOY_TESTS_SSCONV_H_

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "radiation/radfit.h"
#include "radiation/radiation.h"

namespace mjbt {

// trapezoid convolution of K (nk samples at h, the first nu at index 0,
// the body at rest before it) with nu up to index n: -h sum_k w_k K_k
// nu_{n-k}, w = 1/2 at both ends (the convolution of radstep.cc, memory())
inline double convolve(const double* K, int nk, const std::vector<double>& nu, int n,
                       double h) {
  const int N = std::min(n + 1, nk);
  if (N < 2) return 0;
  double s = 0;
  for (int k = 0; k < N; k++) s += (k == 0 || k == N - 1 ? 0.5 : 1) * K[k] * nu[n - k];
  return -h * s;
}

// a smooth random velocity: white noise through two first-order lags of
// time constant tau [s], scaled to unit RMS
inline std::vector<double> randomVelocity(int n, double h, double tau, unsigned seed) {
  std::mt19937 g(seed);
  std::normal_distribution<double> N(0, 1);
  std::vector<double> v(n);
  double a = 0, b = 0, s2 = 0, q = h / tau;
  for (int k = 0; k < n; k++) {
    a += q * (N(g) - a);
    b += q * (a - b);
    v[k] = b;
    s2 += b * b;
  }
  for (double& x : v) x /= std::sqrt(s2 / n);
  return v;
}

// rb's memory force over ns steps h of a random velocity in all six dofs
// (randomVelocity, tau 0.3 s, dof j from seed + j) from its state-space
// modes (radfit.h) and from the convolution of its sampled K (the
// reference), summed over the steps per dof: e2 the squared difference,
// f2 the squared convolution force
inline void ssAgainstConvolution(const mjb::RadBody& rb, double h, int ns, unsigned seed,
                                 double e2[6], double f2[6]) {
  std::vector<std::vector<double>> v(6);
  for (int j = 0; j < 6; j++) v[j] = randomVelocity(ns, h, 0.3, seed + j);
  std::vector<mjb::cplx> X(rb.ss.size()), pw(rb.ss.size());
  double first[6], last[6], nu[6], F[6];
  mjb::SsState st{X.data(), pw.data(), first, last};
  for (int i = 0; i < 6; i++) e2[i] = f2[i] = 0;
  for (int k = 0; k < ns; k++) {
    for (int j = 0; j < 6; j++) nu[j] = v[j][k];
    if (k == 0) mjb::ssRestart(rb.ss, st, nu);
    else mjb::ssNew(rb.ss, st, nu);
    mjb::ssForce(rb.ss, st, h, F);
    double Fc[6] = {0};
    for (size_t q = 0; q < rb.pair.size(); q++) {
      const double* K = rb.K.data() + q * rb.nk;
      Fc[rb.pair[q] / 6] += convolve(K, rb.nk, v[rb.pair[q] % 6], k, h);
    }
    for (int i = 0; i < 6; i++) {
      e2[i] += (F[i] - Fc[i]) * (F[i] - Fc[i]);
      f2[i] += Fc[i] * Fc[i];
    }
  }
}

// the scale of dof i's squared force sums f2: the largest of its kind
// (translation or rotation)
inline double kindScale(const double f2[6], int i) {
  double sc = 0;
  for (int k = 3 * (i / 3); k < 3 * (i / 3) + 3; k++) sc = std::max(sc, f2[k]);
  return sc;
}

}  // namespace mjbt

#endif  // MJBUOY_TESTS_SSCONV_H_
