// seasetter: replace the sea of an attached model between steps
// (mjb_setSea); validation builds strings only when it fails
#include "api/seasetter.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "sea/seacheck.h"
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
  // the ranges of mjbuoy.wave.<label> (sea/seacheck.h), one wave at a time
  for (int i = 0; i < sea.nwave; i++) {
    char where[48];
    std::snprintf(where, sizeof(where), "mjb_setSea: wave %d ", i);
    std::string e = waveCheck(sea.wave + 5 * i, 5, where);
    if (!e.empty()) return fail(error, error_sz, "%s", e.c_str());
  }
  // and together, as the model's
  double sum = 0, fold = 0;
  for (int i = 0; i < sea.nwave; i++) {
    const double* v = sea.wave + 5 * i;
    waveSums(v[0], v[1], v[4], &sum, &fold);
  }
  std::string e = wavesCheck(sum, fold, "mjb_setSea: ", "sea->wave", "sea->wave");
  if (!e.empty()) return fail(error, error_sz, "%s", e.c_str());
  return 1;
}

int setSea(Buoy* b, const mjbSea& sea, char* error, int error_sz) {
  std::string e = currentCheck(sea.current, "mjb_setSea: ");
  if (e.empty()) e = windCheck(sea.wind, "mjb_setSea: ");
  // a finite negative ramp keeps the model's; NaN and -inf are refused
  const bool keepRamp = sea.ramp < 0 && std::isfinite(sea.ramp);
  if (e.empty() && !keepRamp) e = rampCheck(sea.ramp, "mjb_setSea: ");
  if (!e.empty()) return fail(error, error_sz, "%s", e.c_str());
  if (!checkWaves(sea, error, error_sz)) return 0;
  if (sea.nspectrum < 0 || (sea.nspectrum > 0 && !sea.spectrum)) {
    return fail(error, error_sz, "mjb_setSea: nspectrum = %d with spectrum %s", sea.nspectrum,
                sea.spectrum ? "set" : "NULL");
  }
  long total = sea.nwave;
  Sea& s = b->cfg.sea;
  for (int i = 0; i < sea.nspectrum; i++) {
    char where[48];
    std::snprintf(where, sizeof(where), "mjb_setSea: spectrum %d ", i);
    e = specCheck(sea.spectrum[i], s.g, where);
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
  if (sea.ramp >= 0) s.ramp = sea.ramp;
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
