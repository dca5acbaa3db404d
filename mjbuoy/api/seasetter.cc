// seasetter: replace the sea of an attached model between steps
// (mjb_setSea); validation builds strings only when it fails
#include "api/seasetter.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "sea/spectra.h"

namespace mjb {

static int fail(char* error, int error_sz, const char* fmt, ...)
    __attribute__((format(printf, 3, 4)));

static int fail(char* error, int error_sz, const char* fmt, ...) {
  if (error && error_sz > 0) {
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(error, error_sz, fmt, ap);
    va_end(ap);
  }
  return 0;
}

static int checkWaves(const mjbSea& sea, char* error, int error_sz) {
  if (sea.nwave < 0 || (sea.nwave > 0 && !sea.wave)) {
    return fail(error, error_sz, "mjb_setSea: nwave = %d with wave %s; give nwave >= 0 and "
                "nwave x 5 values", sea.nwave, sea.wave ? "set" : "NULL");
  }
  static const char* kName[5] = {"amplitude", "wavelength", "direction", "phase", "steepness"};
  static const char* kRange[5] = {">= 0 [m]", "> 0 [m]", "finite [deg]", "finite [deg]",
                                  ">= 0 and <= 1"};
  double fold = 0;
  for (int i = 0; i < sea.nwave; i++) {
    const double* v = sea.wave + 5 * i;
    bool ok[5] = {v[0] >= 0 && std::isfinite(v[0]), v[1] > 0 && std::isfinite(v[1]),
                  std::isfinite(v[2]), std::isfinite(v[3]), v[4] >= 0 && v[4] <= 1};
    for (int j = 0; j < 5; j++) {
      if (!ok[j]) {
        return fail(error, error_sz, "mjb_setSea: wave %d %s = %.10g is out of range: it "
                    "must be %s", i, kName[j], v[j], kRange[j]);
      }
    }
    fold += v[4] * (2 * M_PI / v[1]) * v[0];
  }
  if (!(fold < 1)) {
    return fail(error, error_sz, "mjb_setSea: the waves fold: sum of steepness * k * amplitude "
                "= %.10g must be < 1 (k = 2 pi / wavelength); lower steepness or amplitude", fold);
  }
  return 1;
}

static int checkWind(const mjbWind& w, char* error, int error_sz) {
  if (!(w.speed >= 0 && w.speed <= 100)) {
    return fail(error, error_sz, "mjb_setSea: wind speed = %.10g is out of range: it must be "
                ">= 0 and <= 100 [m/s]", w.speed);
  }
  if (!std::isfinite(w.dir)) {
    return fail(error, error_sz, "mjb_setSea: wind dir = %.10g is not finite [deg]", w.dir);
  }
  if (w.gust != mjbGUST_NONE && w.gust != mjbGUST_FROYA) {
    return fail(error, error_sz, "mjb_setSea: wind gust = %d is not a gust spectrum; accepted: "
                "mjbGUST_NONE (0), mjbGUST_FROYA (1)", w.gust);
  }
  if (w.gust != mjbGUST_NONE && (w.ngust < 1 || w.ngust > 1024)) {
    return fail(error, error_sz, "mjb_setSea: wind ngust = %d is out of range: it must be >= 1 "
                "and <= 1024", w.ngust);
  }
  return 1;
}

int setSea(Buoy* b, const mjbSea& sea, char* error, int error_sz) {
  if (!std::isfinite(sea.current[0]) || !std::isfinite(sea.current[1])) {
    return fail(error, error_sz, "mjb_setSea: current = %.10g %.10g is not finite [m/s]",
                sea.current[0], sea.current[1]);
  }
  if (!checkWaves(sea, error, error_sz) || !checkWind(sea.wind, error, error_sz)) return 0;
  if (sea.nspectrum < 0 || (sea.nspectrum > 0 && !sea.spectrum)) {
    return fail(error, error_sz, "mjb_setSea: nspectrum = %d with spectrum %s", sea.nspectrum,
                sea.spectrum ? "set" : "NULL");
  }
  long total = sea.nwave;
  Sea& s = b->cfg.sea;
  for (int i = 0; i < sea.nspectrum; i++) {
    char where[48];
    std::snprintf(where, sizeof(where), "mjb_setSea: spectrum %d ", i);
    std::string e = specCheck(sea.spectrum[i], where);
    if (!e.empty()) return fail(error, error_sz, "%s", e.c_str());
    total += sea.spectrum[i].n;
  }
  if (total > long(b->wcap)) {
    return fail(error, error_sz, "mjb_setSea: %ld wave components exceed the %zu reserved at "
                "attach; raise <numeric name=\"mjbuoy.sea.capacity\"> in the model", total,
                b->wcap);
  }
  // rewrite in place: resize within the reserved capacity allocates nothing
  s.waves.resize(total);
  for (int i = 0; i < sea.nwave; i++) {
    const double* v = sea.wave + 5 * i;
    s.waves[i] = Wave{v[0], v[1], v[2], v[3], v[4], 0, 0, 0, 0, 0};
  }
  long at = sea.nwave;
  for (int i = 0; i < sea.nspectrum; i++) {
    specExpand(sea.spectrum[i], s.g, s.depth, s.waves.data() + at);
    at += sea.spectrum[i].n;
  }
  s.derive();
  diffSea(s, &b->diff);  // each component's row in the diffraction tables
  s.current[0] = sea.current[0];
  s.current[1] = sea.current[1];
  Wind& w = b->wind;
  w.par.w = sea.wind;
  w.par.on = w.par.on || sea.wind.speed > 0;
  windGusts(&w);
  return 1;
}

}  // namespace mjb
