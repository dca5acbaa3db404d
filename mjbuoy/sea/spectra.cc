// spectra: Pierson-Moskowitz, JONSWAP and tabulated spectra, directional
// spreading, and their expansion into linear components (docs/physics.md,
// "Irregular seas and wind")
#include "sea/spectra.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sea/seacheck.h"

namespace mjb {

static const double kDeg = M_PI / 180;

uint64_t Rng::next() {
  // SplitMix64: Steele, Lea, Flood, "Fast splittable pseudorandom number
  // generators", OOPSLA 2014
  uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double Rng::uniform() { return double(next() >> 11) * 0x1.0p-53; }

void pmFromWind(double u10, double g, double* hs, double* tp) {
  // Pierson and Moskowitz 1964: Hs = 0.21 U19.5^2 / g, omega_p = 0.877 g / U19.5
  double u = kU195 * u10;
  *hs = 0.21 * u * u / g;
  *tp = 2 * M_PI * u / (0.877 * g);
}

void specPeak(const mjbSpectrum& s, double g, double* wp, double* hs) {
  double h = s.hs, tp = s.tp;
  if (s.type == mjbSPEC_PM && s.wind > 0) pmFromWind(s.wind, g, &h, &tp);
  if (s.type == mjbSPEC_TABLE) h = tp = 0;
  *wp = tp > 0 ? 2 * M_PI / tp : 0;
  *hs = h;
}

double specDensity(const mjbSpectrum& s, double w, double g) {
  if (s.type == mjbSPEC_TABLE) {
    const double* t = s.table;
    int n = s.ntable;
    if (!(w >= t[0]) || w > t[2 * (n - 1)]) return 0;
    int lo = 0, hi = n - 1;  // t[2 lo] <= w <= t[2 hi]
    while (hi - lo > 1) {
      int mid = (lo + hi) / 2;
      (t[2 * mid] <= w ? lo : hi) = mid;
    }
    double f = (w - t[2 * lo]) / (t[2 * hi] - t[2 * lo]);
    return t[2 * lo + 1] + f * (t[2 * hi + 1] - t[2 * lo + 1]);
  }
  if (!(w > 0)) return 0;
  double wp, hs;
  specPeak(s, g, &wp, &hs);
  // Pierson-Moskowitz in Hs and wp (DNV-RP-C205 eq. 3.5.5.1)
  double r = wp / w, r4 = r * r * r * r;
  double pm = 5.0 / 16 * hs * hs * r4 / w * std::exp(-1.25 * r4);
  if (s.type == mjbSPEC_PM) return pm;
  // JONSWAP (Hasselmann et al. 1973) with A_g = 1 - 0.287 ln gamma
  // (DNV-RP-C205 eq. 3.5.5.4)
  double sg = w <= wp ? 0.07 : 0.09, d = (w - wp) / (sg * wp);
  return (1 - 0.287 * std::log(s.gamma)) * pm * std::pow(s.gamma, std::exp(-0.5 * d * d));
}

void specRange(const mjbSpectrum& s, double g, double* wmin, double* wmax) {
  if (s.wmin > 0 || s.wmax > 0) {
    *wmin = s.wmin;
    *wmax = s.wmax;
  } else if (s.type == mjbSPEC_TABLE) {
    *wmin = s.table[0];
    *wmax = s.table[2 * (s.ntable - 1)];
  } else {
    // 0.5 wp to 4 wp holds all but 0.5% of a PM spectrum's energy
    // (integral of S_PM above w: m0 (1 - exp(-1.25 (wp / w)^4)))
    double wp, hs;
    specPeak(s, g, &wp, &hs);
    *wmin = 0.5 * wp;
    *wmax = 4 * wp;
  }
}

static const double kMaxHs = 50, kMaxSteep = 1.0 / 7;

static std::string fmt(double v) {
  std::ostringstream o;
  o.precision(10);
  o << v;
  return o.str();
}

static std::string bad(const std::string& where, const char* field, double v,
                       const char* range) {
  return where + field + " = " + fmt(v) + " is out of range: it must be " + range;
}

// the sea a valid spectrum's components make (specExpand's range and
// trapezoids): m0 [m^2], the peak frequency [rad/s]
static void specMoment(const mjbSpectrum& s, double g, double* m0, double* wpk);

// the bounds of the sea a spectrum makes, whatever its type (a table's
// included): Hs = 4 sqrt(m0) within the hs range, the significant
// steepness Hs / Lp (Lp = 2 pi g / wp^2, deep water) below the breaking
// limit 1/7 of a single Stokes wave (Michell 1893), and the shortest
// component (at wmax) no shorter than the shortest listed wave, 5 cm: a
// shorter one is capillary, not gravity, and its cost per step grows as
// (triangle size / wavelength)^2 (docs/robustness.md, "cost cliffs")
template <class Where>
static std::string seaCheck(const mjbSpectrum& s, double g, Where W) {
  double m0, wp, wmin, wmax;
  specMoment(s, g, &m0, &wp);
  specRange(s, g, &wmin, &wmax);
  double hs = 4 * std::sqrt(m0);
  if (!(hs <= kMaxHs)) {
    return W() + "makes a sea of Hs = 4 sqrt(m0) = " + fmt(hs) + " m, out of range: it must be "
           "<= " + fmt(kMaxHs) + " m (the highest seas measured are about 20 m); lower " +
           (s.type == mjbSPEC_TABLE ? "the table's S values" : "hs");
  }
  double lmin = 2 * M_PI * g / (wmax * wmax);
  if (!(lmin >= kWaveRange[1].lo)) {
    return W() + "has components as short as " + fmt(lmin) + " m (omega = " + fmt(wmax) +
           " rad/s), below the 0.05 m of the shortest wave mjbuoy models (shorter waves are "
           "capillary, and their cost per step explodes: docs/robustness.md); raise tp, or give "
           "a range whose wmax is <= " + fmt(std::sqrt(2 * M_PI * g / kWaveRange[1].lo)) + " rad/s";
  }
  double lp = wp > 0 ? 2 * M_PI * g / (wp * wp) : INFINITY, steep = hs / lp;
  if (!(steep <= kMaxSteep)) {
    return W() + "makes a sea of Hs / Lp = " + fmt(steep) + " (Hs " + fmt(hs) +
           " m, peak wavelength " + fmt(lp) + " m), steeper than the breaking limit 1/7; "
           "lower hs (or S) or raise tp (a longer peak period)";
  }
  return "";
}

std::string specCheck(const mjbSpectrum& s, double g, const char* where) {
  // strings are built on the error paths only: mjb_setSea allocates nothing
  auto W = [&] { return std::string(where); };
  if (s.type < mjbSPEC_PM || s.type > mjbSPEC_TABLE) {
    return W() + "type = " + std::to_string(s.type) + " is not a spectrum; accepted: pm, jonswap, table";
  }
  if (s.type != mjbSPEC_TABLE) {
    bool wind = s.type == mjbSPEC_PM && s.wind != 0;
    if (wind && !(s.wind > 0 && s.wind <= 100)) return bad(W(), "wind", s.wind, "> 0 and <= 100 [m/s]");
    if (!wind && !(s.hs > 0 && s.hs <= 50)) return bad(W(), "hs", s.hs, "> 0 and <= 50 [m]");
    if (!wind && !(s.tp > 0 && s.tp <= 100)) return bad(W(), "tp", s.tp, "> 0 and <= 100 [s]");
  }
  if (s.type == mjbSPEC_JONSWAP && !(s.gamma >= 1 && s.gamma <= 10)) {
    return bad(W(), "gamma", s.gamma, ">= 1 and <= 10 [dimensionless]");
  }
  if (s.type == mjbSPEC_TABLE) {
    if (!s.table || s.ntable < 2) {
      return W() + "table has " + std::to_string(s.ntable) +
             " pair(s); give at least 2 pairs of omega [rad/s] and S [m^2 s/rad]";
    }
    for (int i = 0; i < s.ntable; i++) {
      double om = s.table[2 * i], sv = s.table[2 * i + 1];
      std::string at = "table pair " + std::to_string(i + 1);
      if (!(om > 0) || !std::isfinite(om) || (i && !(om > s.table[2 * i - 2]))) {
        return W() + at + " omega = " + fmt(om) +
               " is out of range: omegas must be finite, > 0 and rising [rad/s]";
      }
      if (!(sv >= 0) || !std::isfinite(sv)) {
        return W() + at + " S = " + fmt(sv) + " is out of range: it must be finite and >= 0 [m^2 s/rad]";
      }
    }
  }
  if (!(s.dir >= -kDirRange.hi && s.dir <= kDirRange.hi)) {
    return bad(W(), "direction", s.dir, ">= -360 and <= 360 [deg]");
  }
  if (!(s.spread >= 0 && s.spread <= 1000)) {
    return bad(W(), "spreading", s.spread, ">= 0 and <= 1000 [dimensionless; 0 = long-crested]");
  }
  if (s.n < 1 || s.n > 4096) {
    return W() + "components = " + std::to_string(s.n) + " is out of range: it must be >= 1 and <= 4096";
  }
  if (s.wmin != 0 || s.wmax != 0) {
    if (!(s.wmin > 0 && s.wmax > s.wmin && std::isfinite(s.wmax))) {
      return W() + "range = " + fmt(s.wmin) + " " + fmt(s.wmax) +
             " is out of range: it must be 0 < wmin < wmax, finite [rad/s] (or 0 0 for the default)";
    }
  }
  return seaCheck(s, g, W);
}

// the spreading function's inverse distribution: the direction offset
// [rad] below which a fraction u of cos^2s(x / 2) on [-pi, pi] lies,
// from its cumulative integral tabulated on kGrid intervals (trapezoids)
static const int kGrid = 2048;
static void spreadTable(double s, double* cdf) {
  double h = 2 * M_PI / kGrid, prev = 0;
  cdf[0] = 0;
  for (int i = 1; i <= kGrid; i++) {
    double x = -M_PI + i * h;
    double c = std::cos(0.5 * x);
    double f = c > 0 ? std::exp(2 * s * std::log(c)) : 0;
    cdf[i] = cdf[i - 1] + 0.5 * h * (prev + f);
    prev = f;
  }
}

static double spreadSample(const double* cdf, double u) {
  double t = u * cdf[kGrid];
  int lo = 0, hi = kGrid;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    (cdf[mid] <= t ? lo : hi) = mid;
  }
  double d = cdf[hi] - cdf[lo], f = d > 0 ? (t - cdf[lo]) / d : 0.5;
  return -M_PI + (lo + f) * 2 * M_PI / kGrid;
}

double waveNumber(double w, double g, double depth) {
  double k = w * w / g;  // deep water
  if (!(depth > 0)) return k;
  // Newton on F(k) = g k tanh(k h) - w^2, from the deep-water value (F is
  // convex and increasing, so it converges from above)
  k = std::fmax(k, w / std::sqrt(g * depth));
  for (int i = 0; i < 100; i++) {
    double th = std::tanh(k * depth);
    double f = g * k * th - w * w;
    double df = g * th + g * k * depth * (1 - th * th);
    double dk = f / df;
    k -= dk;
    if (std::fabs(dk) <= 1e-15 * k) break;
  }
  return k;
}

// the frequency where the tabulated cumulative energy F (kCdf intervals of
// width h from w0) reaches e, linear within an interval
static const int kCdf = 4096;
static double invert(const double* F, double w0, double h, double e) {
  int lo = 0, hi = kCdf;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    (F[mid] <= e ? lo : hi) = mid;
  }
  double d = F[hi] - F[lo], f = d > 0 ? (e - F[lo]) / d : 0.5;
  return w0 + (lo + std::min(1.0, std::max(0.0, f))) * h;
}

static void specMoment(const mjbSpectrum& s, double g, double* m0, double* wpk) {
  double wmin, wmax;
  specRange(s, g, &wmin, &wmax);
  const double h = (wmax - wmin) / kCdf;
  double prev = specDensity(s, wmin, g), sum = 0, top = prev;
  *wpk = wmin;
  for (int j = 1; j <= kCdf; j++) {
    double w = wmin + j * h, cur = specDensity(s, w, g);
    sum += 0.5 * h * (prev + cur);
    if (cur > top) top = cur, *wpk = w;
    prev = cur;
  }
  *m0 = sum;
}

void specExpand(const mjbSpectrum& s, double g, double depth, Wave* out) {
  double wmin, wmax;
  specRange(s, g, &wmin, &wmax);
  double cdf[kGrid + 1];
  if (s.spread > 0) spreadTable(s.spread, cdf);
  Rng r(s.seed);
  // directions by stratified sampling: component i takes stratum perm[i]
  // of n equal-probability strata of the spreading function, so every sea
  // holds the spreading's distribution to 1/n; perm is shuffled first
  // (Fisher-Yates from the top, index floor(u (j + 1)))
  int perm[4096];
  for (int i = 0; i < s.n; i++) perm[i] = i;
  for (int j = s.n - 1; j > 0; j--) {
    int k = std::min(j, int(r.uniform() * (j + 1)));
    std::swap(perm[j], perm[k]);
  }
  // equal-energy bins: the cumulative energy F(w) on kCdf intervals
  // (trapezoids); bin i holds the energies m0 [i, i + 1) / n, so A =
  // sqrt(2 S dw) = sqrt(2 m0 / n) for every component, and the bins are
  // narrow where S is large (a well resolved peak)
  double F[kCdf + 1];
  const double h = (wmax - wmin) / kCdf;
  F[0] = 0;
  double prev = specDensity(s, wmin, g);
  for (int j = 1; j <= kCdf; j++) {
    double cur = specDensity(s, wmin + j * h, g);
    F[j] = F[j - 1] + 0.5 * h * (prev + cur);
    prev = cur;
  }
  const double m0 = F[kCdf];
  for (int i = 0; i < s.n; i++) {
    // then three draws per component, always in this order: the frequency
    // in its bin (as an energy quantile, so it falls where S is), the
    // phase, the direction in its stratum (all drawn even when
    // long-crested, so the phases of a seed do not depend on the spreading)
    double q = (i + r.uniform()) / s.n;
    double w = m0 > 0 ? invert(F, wmin, h, q * m0) : wmin + q * (wmax - wmin);
    double ph = 2 * M_PI * r.uniform();
    double ud = (perm[i] + r.uniform()) / s.n;
    double b = s.dir * kDeg + (s.spread > 0 ? spreadSample(cdf, ud) : 0);
    double e = m0 / s.n;
    double k = waveNumber(w, g, depth);
    Wave& o = out[i];
    o = Wave{};
    o.amp = std::sqrt(2 * std::fmax(e, 0.0));
    o.len = 2 * M_PI / k;
    o.dir = b / kDeg;
    o.phase = ph / kDeg;
    o.steep = 0;
    o.k = k;
    o.omega = w;
    o.dx = std::cos(b);
    o.dy = std::sin(b);
    o.ph = ph;
    o.kind = 1;
  }
}

double etaSum(const Wave* w, int n, double x, double y, double t) {
  double z = 0;
  for (int i = 0; i < n; i++) {
    z += w[i].amp * std::cos(w[i].k * (w[i].dx * x + w[i].dy * y) - w[i].omega * t + w[i].ph);
  }
  return z;
}

static void defaults(mjbSpectrum* s) {
  *s = mjbSpectrum{};
  s->type = mjbSPEC_JONSWAP;
  s->hs = 1;
  s->tp = 8;
  s->gamma = 3.3;
  s->n = 64;
  s->seed = 1;
}

}  // namespace mjb

void mjb_defaultSpectrum(mjbSpectrum* s) {
  if (s) mjb::defaults(s);
}
