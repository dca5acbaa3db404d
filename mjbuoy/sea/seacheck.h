// seacheck: the one validator of each kind of sea input, shared by every
// entry: the MJCF parser (api/config.cc, api/seaconfig.cc; the tools'
// --set and --spectrum edit the MJCF) and mjb_setSea (api/seasetter.cc).
// Spectra have theirs in spectra.h (specCheck). Messages are built on the
// error paths only: mjb_setSea allocates nothing (docs/robustness.md)
#ifndef MJBUOY_SEACHECK_H_
#define MJBUOY_SEACHECK_H_

#include <string>

#include "mjbuoy.h"
#include "sea/sea.h"

namespace mjb {

// accepted range of one value [lo, hi]
struct Range {
  const char* name;
  double lo, hi;
  const char* unit;
};

// a listed wave's values: amplitude, wavelength, direction, phase,
// steepness (docs/mjcf.md justifies each bound). The shortest wavelength,
// 5 cm, is the shortest wave gravity governs (capillary below about
// 1.7 cm) and bounds the cost of a component (docs/robustness.md)
inline constexpr Range kWaveRange[5] = {
    {"amplitude", 0, 30, "m"},
    {"wavelength", 0.05, 1e6, "m"},
    {"direction", -360, 360, "deg"},
    {"phase", -360, 360, "deg"},
    {"steepness", 0, 1, "dimensionless"},
};
// sum of the listed amplitudes: the highest crest, level + sum A, stays
// about twice the highest ocean wave measured (amplitude about 15 m) [m]
inline constexpr double kMaxAmpSum = 30;
// current along x and y [m/s]; wind speed at 10 m [m/s]; directions [deg]
inline constexpr Range kCurrentRange = {"current", -50, 50, "m/s"};
inline constexpr Range kWindSpeedRange = {"speed", 0, 100, "m/s"};
inline constexpr Range kDirRange = {"direction", -360, 360, "deg"};
// the start-up ramp T [s] (Sea::ramp): up to an hour, beyond the few
// periods of the longest swell (about 25 s) any run needs
inline constexpr Range kRampRange = {"ramp", 0, 3600, "s"};
// gust components
inline constexpr int kMaxGust = 1024;

// one listed wave, nv values (4: an Airy component, no steepness);
// "" or where + the value's name, the value and its accepted range
std::string waveCheck(const double* v, int nv, const char* where);

// the listed waves together: the sum of their amplitudes sum A [m] and
// the fold sum Q k A < 1 (k = 2 pi / wavelength) of each wave added up by
// waveSums; the messages name them as amps (all listed waves) and steeps
// (those with a steepness)
void waveSums(double amp, double len, double steep, double* sum, double* fold);
std::string wavesCheck(double sum, double fold, const char* where, const char* amps,
                       const char* steeps);

// a uniform current [m/s]
std::string currentCheck(const double c[2], const char* where);

// the start-up ramp time [s]
std::string rampCheck(double ramp, const char* where);

// the cpu lanes' integration mode (Sea::integration) named text: "exact"
// or "vertex" into *mode; "" or where + the value and the accepted ones
std::string integrationCheck(const char* text, const char* where, int* mode);

// mean wind and gusts (speed, direction, gust spectrum, gust count)
std::string windCheck(const mjbWind& w, const char* where);

}  // namespace mjb

#endif  // MJBUOY_SEACHECK_H_
