// wind: the wind field at 10 m, its mean and its gusts from the Froya
// spectrum (docs/physics.md, "Irregular seas and wind")
#include "sea/wind.h"

#include <cmath>

#include "sea/spectra.h"

namespace mjb {

double froya(double u0, double f) {
  // Froya spectrum at z = 10 m (Andersen and Lovseth 1992; API RP 2A-WSD
  // 2.3.2c; DNV-RP-C205 eq. 2.16): S(f) = 320 (U0/10)^2 / (1 + ft^n)^(5/3n),
  // ft = 172 f (U0/10)^-0.75, n = 0.468, S in m^2/s^2 per Hz
  if (!(f > 0) || !(u0 > 0)) return 0;
  const double n = 0.468;
  double u = u0 / 10, ft = 172 * f * std::pow(u, -0.75);
  return 320 * u * u / std::pow(1 + std::pow(ft, n), 5 / (3 * n));
}

// gusts between kF0 and kF1 [Hz] (periods of 2000 s to 2 s) in bins of
// equal width in log f: the spectrum's energy sits at low frequencies
static const double kF0 = 5e-4, kF1 = 0.5;

void windGusts(WindField* w) {
  const mjbWind& p = w->par.w;
  w->gust.clear();  // keeps capacity
  if (p.gust != mjbGUST_FROYA || !(p.speed > 0)) return;
  Rng r(p.seed);
  const int n = p.ngust, sub = 16;
  const double l0 = std::log(kF0), dl = (std::log(kF1) - l0) / n;
  for (int i = 0; i < n; i++) {
    // draws as in specExpand: frequency in the bin, then phase
    double f = std::exp(l0 + (i + r.uniform()) * dl);
    double ph = 2 * M_PI * r.uniform();
    // the bin's variance, Simpson in log f: integral S(f) f dlog f
    double h = dl / sub, e = 0;
    for (int j = 0; j <= sub; j++) {
      double c = j == 0 || j == sub ? 1 : (j % 2 ? 4 : 2);
      double fj = std::exp(l0 + i * dl + j * h);
      e += c * froya(p.speed, fj) * fj;
    }
    w->gust.push_back(Gust{std::sqrt(2 * e * h / 3), f, ph});
  }
}

double windSpeed(const WindField& w, double t) {
  double u = w.par.w.speed;
  for (const Gust& g : w.gust) u += g.a * std::cos(2 * M_PI * g.f * t + g.ph);
  return u;
}

}  // namespace mjb
