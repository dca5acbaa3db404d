// seacheck: ranges of waves, current and wind, one validator each
#include "sea/seacheck.h"

#include <cmath>
#include <cstring>
#include <sstream>

namespace mjb {

static std::string num(double v) {
  std::ostringstream o;
  o.precision(10);
  o << v;
  return o.str();
}

static bool inside(double v, const Range& r) { return v >= r.lo && v <= r.hi; }

static std::string outside(const char* where, const char* name, double v, const Range& r) {
  return std::string(where) + name + " = " + num(v) + " is out of range: it must be finite, >= " +
         num(r.lo) + " and <= " + num(r.hi) + " [" + r.unit + "]";
}

std::string waveCheck(const double* v, int nv, const char* where) {
  for (int j = 0; j < nv && j < 5; j++) {
    if (!inside(v[j], kWaveRange[j])) return outside(where, kWaveRange[j].name, v[j], kWaveRange[j]);
  }
  return "";
}

void waveSums(double amp, double len, double steep, double* sum, double* fold) {
  *sum += amp;
  *fold += steep * (2 * M_PI / len) * amp;
}

std::string wavesCheck(double sum, double fold, const char* where, const char* amps,
                       const char* steeps) {
  if (!(sum <= kMaxAmpSum)) {
    return std::string(where) + "the waves' amplitudes add up to " + num(sum) + " m, above " +
           num(kMaxAmpSum) + " m (twice the amplitude of the highest ocean waves measured, "
           "about 15 m); lower the amplitudes of " + amps;
  }
  if (!(fold < 1)) {
    return std::string(where) + "the waves fold: sum over " + steeps +
           " of steepness * k * amplitude = " + num(fold) +
           " must be < 1 (k = 2 pi / wavelength); lower steepness or amplitude";
  }
  return "";
}

std::string currentCheck(const double c[2], const char* where) {
  for (int j = 0; j < 2; j++) {
    if (!inside(c[j], kCurrentRange)) {
      return outside(where, j ? "current y" : "current x", c[j], kCurrentRange);
    }
  }
  return "";
}

std::string rampCheck(double ramp, const char* where) {
  return inside(ramp, kRampRange) ? "" : outside(where, "ramp", ramp, kRampRange);
}

std::string integrationCheck(const char* text, const char* where, int* mode) {
  if (!std::strcmp(text, "exact")) {
    *mode = kIntegrateExact;
  } else if (!std::strcmp(text, "vertex")) {
    *mode = kIntegrateVertex;
  } else {
    return std::string(where) + " = \"" + text + "\" is not an integration mode; give \"exact\" "
           "(each component in closed form, the default) or \"vertex\" (the components summed "
           "at the vertices, cpu backend; docs/physics.md \"Vertex integration\")";
  }
  return "";
}

std::string windCheck(const mjbWind& w, const char* where) {
  if (!inside(w.speed, kWindSpeedRange)) return outside(where, "wind speed", w.speed, kWindSpeedRange);
  if (!inside(w.dir, kDirRange)) return outside(where, "wind direction", w.dir, kDirRange);
  if (w.gust != mjbGUST_NONE && w.gust != mjbGUST_FROYA) {
    return std::string(where) + "wind gust = " + std::to_string(w.gust) +
           " is not a gust spectrum; accepted: none (mjbGUST_NONE, 0), froya (mjbGUST_FROYA, 1)";
  }
  if (w.gust != mjbGUST_NONE && (w.ngust < 1 || w.ngust > kMaxGust)) {
    return std::string(where) + "wind gust components = " + std::to_string(w.ngust) +
           " is out of range: it must be >= 1 and <= " + std::to_string(kMaxGust);
  }
  return "";
}

}  // namespace mjb
