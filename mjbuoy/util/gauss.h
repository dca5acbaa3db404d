// Gauss-Legendre rules on [-1, 1] (computed once, Newton on P_n)
#ifndef MJBUOY_GAUSS_H_
#define MJBUOY_GAUSS_H_

namespace mjb {

struct GaussRule {
  int n;
  double x[32];
  double w[32];
};

// n in 1..32; thread-safe (built on first use)
const GaussRule& gaussRule(int n);

}  // namespace mjb

#endif  // MJBUOY_GAUSS_H_
