// radss: per-step states of the state-space radiation memory
// (docs/physics.md section 14, "State-space memory"); no allocation
#include <cstring>

#include "radiation/radfit.h"

namespace mjb {

void ssRestart(const SsModes& sm, SsState s, const double nu[6]) {
  for (int r = 0; r < sm.size(); r++) {
    s.X[r] = 0;
    s.pw[r] = 1;
  }
  std::memcpy(s.first, nu, 6 * sizeof(double));
  std::memcpy(s.last, nu, 6 * sizeof(double));
}

// X <- lam X + nu_j(t_{n-1}): the sum over the samples before the new one
void ssNew(const SsModes& sm, SsState s, const double nu[6], const cplx* lam) {
  if (!lam) lam = sm.lam.data();
  for (int r = 0; r < sm.size(); r++) {
    s.X[r] = lam[r] * s.X[r] + s.last[sm.j[r]];
    cplx q = s.pw[r] * lam[r];
    // the first sample's half weight has decayed: exact zeros, no denormals
    s.pw[r] = std::norm(q) < 1e-200 ? cplx(0) : q;
  }
  std::memcpy(s.last, nu, 6 * sizeof(double));
}

void ssSame(SsState s, const double nu[6], bool first) {
  std::memcpy(s.last, nu, 6 * sizeof(double));
  if (first) std::memcpy(s.first, nu, 6 * sizeof(double));
}

// trapezoid weights: 1/2 for the newest and the first sample, 1 between
void ssForce(const SsModes& sm, SsState s, double h, double f[6], const cplx* lam) {
  if (!lam) lam = sm.lam.data();
  std::memset(f, 0, 6 * sizeof(double));
  for (int r = 0; r < sm.size(); r++) {
    const int j = sm.j[r];
    cplx v = lam[r] * s.X[r] + 0.5 * (s.last[j] - s.pw[r] * s.first[j]);
    f[sm.i[r]] -= h * (sm.c[r] * v).real();
  }
}

}  // namespace mjb
