// spectra: irregular seas as sums of linear (Airy) components drawn from a
// wave spectrum (docs/physics.md, "Irregular seas and wind")
#ifndef MJBUOY_SPECTRA_H_
#define MJBUOY_SPECTRA_H_

#include <cstdint>
#include <string>
#include <vector>

#include "mjbuoy.h"
#include "sea/sea.h"

namespace mjb {

// SplitMix64 (Steele, Lea and Flood 2014): integer arithmetic only, so a
// seed gives the same stream on every platform and compiler
struct Rng {
  uint64_t s;
  explicit Rng(uint64_t seed) : s(seed) {}
  uint64_t next();
  double uniform();  // [0, 1), 53 random bits
};

// spectral density S(w) [m^2 s/rad] of a spectrum at w [rad/s]; the peak
// frequency wp [rad/s] and Hs [m] it was built from (table: 0)
double specDensity(const mjbSpectrum& s, double w, double g);
void specPeak(const mjbSpectrum& s, double g, double* wp, double* hs);

// the frequency range the components cover [rad/s]
void specRange(const mjbSpectrum& s, double g, double* wmin, double* wmax);

// "" or an error naming where + the field, its value and accepted range;
// then the sea it makes (g [m/s^2]): Hs, steepness and shortest component
// bounded (spectra.cc seaCheck). The one validator of a spectrum, for
// MJCF and mjb_setSea alike
std::string specCheck(const mjbSpectrum& s, double g, const char* where);

// the spectrum's n components into out[0, n): random frequency inside each
// of n equal bins, amplitude from the bin's energy, random phase and a
// direction drawn from the spreading function; kind 1 (Airy), Q = 0.
// depth 0: deep water. Allocates nothing.
void specExpand(const mjbSpectrum& s, double g, double depth, Wave* out);

// wave number k [rad/m] of frequency w [rad/s]: w^2 = g k tanh(k h)
double waveNumber(double w, double g, double depth);

// linear surface elevation eta - level [m] of components w at (x, y, t):
// the direct sum of A cos(k D.x - omega t + phi)
double etaSum(const Wave* w, int n, double x, double y, double t);

// Pierson-Moskowitz from the wind speed at 10 m [m/s]: Hs [m], Tp [s]
void pmFromWind(double u10, double g, double* hs, double* tp);

// U19.5 / U10 used by pmFromWind (docs/physics.md)
const double kU195 = 1.026;

}  // namespace mjb

#endif  // MJBUOY_SPECTRA_H_
