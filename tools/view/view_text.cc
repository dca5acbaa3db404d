// view_text: mjbuoy-view's overlay text and actuator keys (see viewtext.h)
#include "viewtext.h"

#include <cmath>
#include <cstdio>

#include "api/config.h"

namespace mjbview {
namespace {

// "JONSWAP Hs 0.5 m Tp 4 s" and the like, one spectrum
std::string spectrumName(const mjbSpectrum& s) {
  char buf[96];
  if (s.type == mjbSPEC_TABLE) return "tabulated spectrum";
  const char* name = s.type == mjbSPEC_PM ? "PM" : "JONSWAP";
  if (s.type == mjbSPEC_PM && s.wind > 0) {
    std::snprintf(buf, sizeof(buf), "PM of %g m/s wind", s.wind);
  } else {
    std::snprintf(buf, sizeof(buf), "%s Hs %g m Tp %g s", name, s.hs, s.tp);
  }
  return buf;
}

}  // namespace

std::string describeSea(const mjModel* m) {
  mjb::Config c;
  if (!mjb::parseConfig(m, &c).empty()) return "?";
  char buf[256];
  if (c.sea.waves.empty()) {
    std::snprintf(buf, sizeof(buf), "calm, level %g m", c.sea.level);
    return buf;
  }
  double amax = 0, lmin = 1e300, lmax = 0;
  size_t ngerstner = 0;  // the rest are linear (Airy) components, e.g. of spectra
  for (const mjb::Wave& w : c.sea.waves) {
    amax = std::fmax(amax, w.amp);
    lmin = std::fmin(lmin, w.len);
    lmax = std::fmax(lmax, w.len);
    ngerstner += w.kind == 0;
  }
  const size_t n = c.sea.waves.size(), nlinear = n - ngerstner;
  std::string kinds = !nlinear ? "Gerstner" : !ngerstner ? "linear" :
                      std::to_string(ngerstner) + " Gerstner, " + std::to_string(nlinear) +
                      " linear";
  if (nlinear && ngerstner) kinds = "(" + kinds + ")";
  std::snprintf(buf, sizeof(buf), "%zu %s wave component%s", n, kinds.c_str(), n > 1 ? "s" : "");
  std::string s = buf;
  for (size_t i = 0; i < c.spec.size(); i++) {
    s += (i ? ", " : " (") + spectrumName(c.spec[i]) + (i + 1 == c.spec.size() ? ")" : "");
  }
  std::snprintf(buf, sizeof(buf), ", A <= %.3g m, lambda %.3g-%.3g m", amax, lmin, lmax);
  s += buf;
  if (c.sea.current[0] != 0 || c.sea.current[1] != 0) {
    std::snprintf(buf, sizeof(buf), ", current %g %g m/s", c.sea.current[0], c.sea.current[1]);
    s += buf;
  }
  return s;
}

std::string describeWind(const mjModel* m) {
  mjb::Config c;
  if (!mjb::parseConfig(m, &c).empty()) return "?";
  if (!c.wind.on) return "none";
  char buf[160];
  std::snprintf(buf, sizeof(buf), "%g m/s at 10 m towards %g deg%s", c.wind.w.speed, c.wind.w.dir,
                c.wind.w.gust == mjbGUST_FROYA ? ", Froya gusts" : ", steady");
  return buf;
}

double nudgeCtrl(const mjModel* m, int a, double ctrl, int dir) {
  if (a < 0 || a >= m->nu) return ctrl;
  if (!m->actuator_ctrllimited[a]) return ctrl + dir * kFreeStep;
  const double lo = m->actuator_ctrlrange[2 * a], hi = m->actuator_ctrlrange[2 * a + 1];
  return std::fmin(hi, std::fmax(lo, ctrl + dir * (hi - lo) / 20));
}

std::string describeCtrl(const mjModel* m, int a, double ctrl) {
  if (a < 0 || a >= m->nu) return "none";
  const char* name = mj_id2name(m, mjOBJ_ACTUATOR, a);
  std::string n = name ? name : "actuator " + std::to_string(a);
  char buf[160];
  if (m->actuator_ctrllimited[a]) {
    std::snprintf(buf, sizeof(buf), "%s = %.4g in [%g, %g]", n.c_str(), ctrl,
                  m->actuator_ctrlrange[2 * a], m->actuator_ctrlrange[2 * a + 1]);
  } else {
    std::snprintf(buf, sizeof(buf), "%s = %.4g", n.c_str(), ctrl);
  }
  return buf;
}

}  // namespace mjbview
