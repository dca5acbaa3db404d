// Gauss-Legendre rules (Golub & Welsch would do too; Newton on the
// Legendre recurrence is enough for n <= 32)
#include "util/gauss.h"

#include <cmath>

namespace mjb {

namespace {

GaussRule makeRule(int n) {
  GaussRule g;
  g.n = n;
  for (int i = 0; i < n; i++) {
    double x = std::cos(3.14159265358979323846 * (i + 0.75) / (n + 0.5));
    double dp = 1;
    for (int it = 0; it < 100; it++) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; k++) {
        double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1;
      dp = n * (x * p1 - p0) / (x * x - 1);
      double dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-16) break;
    }
    g.x[i] = x;
    g.w[i] = 2 / ((1 - x * x) * dp * dp);
  }
  return g;
}

struct Rules {
  GaussRule r[33];
  Rules() {
    for (int n = 1; n <= 32; n++) r[n] = makeRule(n);
  }
};

}  // namespace

const GaussRule& gaussRule(int n) {
  static const Rules rules;
  return rules.r[n < 1 ? 1 : (n > 32 ? 32 : n)];
}

}  // namespace mjb
