// forward-speed terms of the radiation memory (radspeed.h, docs/physics.md
// section 14, "Forward speed")
#include "radiation/radspeed.h"

#include <algorithm>
#include <cmath>

#include "radiation/radiation.h"
#include "radiation/radtail.h"

namespace mjb {

void speedKernels(const HydroCoef& c, double tmem, double dt, std::vector<double>* L, int* n) {
  L->clear();
  *n = 0;
  double bmax = 0;
  for (double b : c.B) bmax = std::max(bmax, std::fabs(b));
  bool any = false;
  for (int d = 1; d <= 2; d++)
    for (int w = 0; w < c.nw(); w++) any = any || std::fabs(c.B[36 * w + 7 * d]) > 1e-12 * bmax;
  if (!any || !(tmem > 0) || !(dt > 0)) return;
  *n = int(std::min<double>(std::ceil(tmem / dt) + 1, kMaxKernelSamples));
  L->assign(2 * size_t(*n), 0);
  double pd[6];
  tailExponents(c, pd);
  std::vector<double> K(*n);
  for (int j = 0; j < 2; j++) {
    retardationP(c, pd, j + 1, j + 1, dt, *n, K.data());
    steadyZero(K.data(), *n);
    // L(t) = int_0^t K by the trapezoid rule: L(T_m) is then the memory's
    // steady gain, 0 to round-off (docs/physics.md section 14, "Steady gain")
    double* l = L->data() + size_t(j) * *n;
    for (int k = 1; k < *n; k++) l[k] = l[k - 1] + 0.5 * dt * (K[k - 1] + K[k]);
  }
}

double speedConv(const std::vector<double>& L, int n, int j, const double* ring, int nh,
                 int head, int count, double dt) {
  const int N = std::min(count, n);
  if (N < 2) return 0;
  const double* l = L.data() + size_t(j) * n;
  double s = 0;
  for (int k = 0; k < N; k++) {
    const double w = k == 0 || k == N - 1 ? 0.5 : 1;
    s += w * l[k] * ring[(head - k + nh) % nh];
  }
  return dt * s;
}

void speedSs(const SsModes& sm, SsState s, double h, double out[2], const cplx* lam) {
  if (!lam) lam = sm.lam.data();
  out[0] = out[1] = 0;
  for (int r = 0; r < sm.size(); r++) {
    const int j = sm.j[r];
    if (sm.i[r] != j || j < 1 || j > 2) continue;
    const cplx l = lam[r];
    // L_k = h sum_m w_m K_m (trapezoid to k) = G - h Re sum c lam^k (1 + lam) / (2 (1 - lam)),
    // G = h Re sum c (1 / (1 - lam) - 1/2) the fit's trapezoid steady gain
    const cplx d = sm.c[r] * (0.5 * h) * (1.0 + l) / (l - 1.0);
    const cplx v = l * s.X[r] + 0.5 * (s.last[j] - s.pw[r] * s.first[j]);
    out[j - 1] += h * (d * v).real();
  }
}

}  // namespace mjb
