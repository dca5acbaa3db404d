// wave drift in the time domain (driftstep.h, docs/physics.md section 18)
#include "radiation/driftstep.h"

#include <cmath>
#include <complex>

namespace mjb {

std::string setDrift(int body, const DriftTable& dt, const double ref[3], const double com[3],
                     Diffraction* df) {
  for (DiffBody& b : df->db) {
    if (b.body != body) continue;
    const size_t n = 3 * (size_t)b.c.nw() * b.c.nh();
    if (dt.far.size() != n || dt.fk.size() != n)
      return "mjbuoy: drift: the drift table needs 3 values per frequency and heading of the "
             "diffraction table";
    // the step's pressure integration and diffraction phase give dt.fk itself
    b.Tfar = dt.far;
    std::vector<double> T(n);
    for (size_t i = 0; i < n; i++) T[i] = dt.far[i] - dt.fk[i];
    // Mz about the COM: Mz(ref) - (com - ref) x F
    const double dx = com[0] - ref[0], dy = com[1] - ref[1];
    for (std::vector<double>* t : {&T, &b.Tfar})
      for (size_t i = 0; i < n; i += 3) {
        (*t)[i + 2] -= dx * (*t)[i + 1] - dy * (*t)[i];
        for (int k = 0; k < 3; k++)
          if (!std::isfinite((*t)[i + k])) return "mjbuoy: drift: the drift table is not finite";
      }
    // an identical hull's table, if any, else its own
    for (const DiffBody& o : df->db)
      if (o.body != body && b.T.share(o.T, T)) return "";
    b.T = std::move(T);
    return "";
  }
  return "mjbuoy: drift: the body has no diffraction table (turn mjbuoy.radiation.diffraction "
         "on)";
}

void driftAt(const DiffBody& b, int iw, double tw, double beta, double T[3]) {
  T[0] = T[1] = T[2] = 0;
  if (b.T.empty()) return;
  // as diffAt: below the table, row 0 weighted omega / omega_0
  TableWeights w;
  tableWeights(b.c.nh(), iw, tw, beta, &w);
  driftBlend(b, w, T);
}

void driftFinish(const DiffBody& b, const DriftSum& s, double r, double F[6]) {
  if (b.T.empty()) return;
  // quadratic in the amplitudes, so the start-up ramp enters squared (sea.h)
  const double r2 = r * r;
  F[0] += r2 * (s.P[0] * std::conj(s.Q)).real();
  F[1] += r2 * (s.P[1] * std::conj(s.Q)).real();
  F[5] += r2 * (s.P[2] * std::conj(s.Q)).real();
}

}  // namespace mjb
