// irregular seas: spectra, their expansion, statistics of the surface
// (docs/physics.md, "Irregular seas and wind")
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "sea/spectra.h"
#include "testutil.h"

namespace {

using mjb::Wave;

const double kG = 9.81;

// JONSWAP written out from DNV-RP-C205 (2010) eqs. 3.5.5.1 and 3.5.5.4,
// independently of spectra.cc: S_PM(w) = 5/16 Hs^2 wp^4 w^-5
// exp(-5/4 (wp/w)^4), S_J = (1 - 0.287 ln gamma) S_PM gamma^exp(-(w -
// wp)^2 / (2 sigma^2 wp^2)), sigma 0.07 / 0.09 below / above wp
double jonswap(double w, double hs, double tp, double gamma) {
  double wp = 2 * M_PI / tp;
  double pm = 5.0 / 16 * hs * hs * std::pow(wp, 4) * std::pow(w, -5) *
              std::exp(-1.25 * std::pow(wp / w, 4));
  double sg = w <= wp ? 0.07 : 0.09;
  return (1 - 0.287 * std::log(gamma)) * pm *
         std::pow(gamma, std::exp(-(w - wp) * (w - wp) / (2 * sg * sg * wp * wp)));
}

std::vector<Wave> expand(const mjbSpectrum& s, double depth = 0) {
  std::vector<Wave> w(s.n);
  mjb::specExpand(s, kG, depth, w.data());
  return w;
}

// eta at the origin every dt for T seconds, by the direct sum
std::vector<double> record(const std::vector<Wave>& w, double T, double dt) {
  std::vector<double> r(size_t(T / dt));
  for (size_t i = 0; i < r.size(); i++) r[i] = mjb::etaSum(w.data(), w.size(), 0, 0, i * dt);
  return r;
}

double hsOf(const std::vector<double>& r) {
  double m = 0, v = 0;
  for (double x : r) m += x;
  m /= r.size();
  for (double x : r) v += (x - m) * (x - m);
  return 4 * std::sqrt(v / r.size());
}

// Welch's estimate (Welch 1967) of the one-sided spectrum [m^2 s/rad] at
// the frequencies w: Hann segments of L samples, 50% overlap; returns the
// number of segments in k. Direct DFT at each w (no FFT needed here).
std::vector<double> welch(const std::vector<double>& r, double dt, int L,
                          const std::vector<double>& w, int* k) {
  std::vector<double> win(L), out(w.size(), 0);
  double u = 0;
  for (int n = 0; n < L; n++) {
    win[n] = 0.5 - 0.5 * std::cos(2 * M_PI * n / L);
    u += win[n] * win[n];
  }
  *k = 0;
  for (size_t s0 = 0; s0 + L <= r.size(); s0 += L / 2, ++*k) {
    for (size_t j = 0; j < w.size(); j++) {
      std::complex<double> X = 0, e = 1, step = std::polar(1.0, -w[j] * dt);
      for (int n = 0; n < L; n++, e *= step) X += r[s0 + n] * win[n] * e;
      out[j] += 2 * dt * std::norm(X) / (2 * M_PI * u);
    }
  }
  for (double& x : out) x /= *k;
  return out;
}

// chi-square quantile p with nu degrees of freedom (Wilson and Hilferty
// 1931); z the standard normal quantile of p
double chi2(double nu, double z) {
  double a = 2 / (9 * nu);
  return nu * std::pow(1 - a + z * std::sqrt(a), 3);
}

// the peak frequency of a Welch estimate S on the grid om: S smoothed by a
// running mean over +-2 bins (the width of about one component bin, so
// the peak is the spectrum's, not one component's), then a parabola
// through the highest smoothed value and its neighbours
double peakOf(const std::vector<double>& om, const std::vector<double>& S) {
  std::vector<double> sm(S.size(), 0);
  for (size_t j = 2; j + 2 < S.size(); j++) {
    for (int i = -2; i <= 2; i++) sm[j] += S[j + i] / 5;
  }
  size_t ip = 3;
  for (size_t j = 3; j + 3 < S.size(); j++) if (sm[j] > sm[ip]) ip = j;
  double a = sm[ip - 1], b = sm[ip], c = sm[ip + 1], h = om[1] - om[0];
  return om[ip] + 0.5 * h * (a - c) / (a - 2 * b + c);
}

mjbSpectrum jonswap64(unsigned long long seed) {
  mjbSpectrum s;
  mjb_defaultSpectrum(&s);
  s.type = mjbSPEC_JONSWAP;
  s.hs = 2;
  s.tp = 8;
  s.gamma = 3.3;
  s.n = 64;
  s.seed = seed;
  return s;
}

TEST(Spectra, DensityIsJonswapOfDnv) {
  mjbSpectrum s = jonswap64(1);
  for (double w : {0.4, 0.7, 2 * M_PI / 8, 0.9, 1.5, 3.0}) {
    EXPECT_NEAR(mjb::specDensity(s, w, kG), jonswap(w, 2, 8, 3.3), 1e-12) << w;
  }
  // gamma = 1 is Pierson-Moskowitz, whose m0 = Hs^2 / 16 (DNV-RP-C205 3.5.5)
  s.gamma = 1;
  double m0 = 0, h = 1e-4;
  for (double w = 0.05; w < 40; w += h) m0 += mjb::specDensity(s, w, kG) * h;
  EXPECT_NEAR(4 * std::sqrt(m0), 2.0, 2e-3);
}

// an hour of eta at one point: Hs = 4 std(eta), Tp from Welch's peak
// (target: the spectrum's own Hs, Tp; the default range 0.5-4 wp holds
// 99.9% of this JONSWAP's m0, so Hs of the range is 1.9992 m)
TEST(Spectra, HourRecordReproducesHsTpAndSpectrum) {
  const double dt = 0.5, T = 3600;
  mjbSpectrum s = jonswap64(7);
  std::vector<Wave> w = expand(s);
  std::vector<double> r = record(w, T, dt);
  double hs = hsOf(r);
  EXPECT_NEAR(hs, 2.0, 0.03 * 2.0);
  std::vector<double> om;
  for (double x = 0.35; x < 3.2; x += 2 * M_PI / 512) om.push_back(x);
  int k;
  std::vector<double> S = welch(r, dt, 1024, om, &k);
  double tp = 2 * M_PI / peakOf(om, S);
  EXPECT_NEAR(tp, 8.0, 0.05 * 8.0);
  std::printf("[spectra] JONSWAP Hs 2 m Tp 8 s, 64 components, 1 h: Hs %.4f m, Tp %.3f s, "
              "%d Welch segments\n", hs, tp, k);
  // the spectrum in bands holding whole component bins: the bins are the
  // equal-energy quantiles of the analytic S over 0.5-4 wp (recomputed
  // here from the formula), joined until a band is 0.1 rad/s wide (eight
  // Welch bins: wider than the Hann window's leakage); where the band
  // holds energy, Welch's integral over it against the analytic one
  // within chi-square bounds of nu = 2 k M / 1.06 degrees of freedom (M
  // Welch bins in the band; Hann, 50% overlap: Welch 1967) at 99.9%
  const double wp = 2 * M_PI / 8, w0 = 0.5 * wp, w1 = 4 * wp, hh = (w1 - w0) / 100000;
  std::vector<double> F(100001, 0);
  for (int i = 1; i <= 100000; i++) {
    F[i] = F[i - 1] + 0.5 * hh * (jonswap(w0 + (i - 1) * hh, 2, 8, 3.3) +
                                  jonswap(w0 + i * hh, 2, 8, 3.3));
  }
  auto edge = [&](double q) {  // frequency of the energy quantile q
    size_t i = std::lower_bound(F.begin(), F.end(), q * F.back()) - F.begin();
    return w0 + i * hh;
  };
  const double dom = 2 * M_PI / 512;
  int bad = 0, nb = 0;
  double a = edge(0);
  for (int j = 1; j <= 64; j++) {
    double b = edge(j / 64.0);
    if (b - a < 0.1 && j < 64) continue;
    double est = 0, ref = 0;
    int M = 0;
    for (size_t i = 0; i < om.size(); i++) {
      if (om[i] < a || om[i] >= b) continue;
      est += S[i] * dom;
      M++;
    }
    for (double x = a; x < b; x += 1e-4) ref += jonswap(x + 5e-5, 2, 8, 3.3) * 1e-4;
    a = b;
    if (ref < 0.02 * F.back() || M < 4) continue;
    double nu = 2.0 * k * M / 1.06;
    double lo = chi2(nu, -3.29) / nu, hi = chi2(nu, 3.29) / nu;
    nb++;
    if (est / ref < lo || est / ref > hi) bad++;
    std::printf("[spectra] band to %.3f rad/s (%d Welch bins): Welch / S = %.3f (bounds %.3f %.3f)\n",
                b, M, est / ref, lo, hi);
  }
  EXPECT_GE(nb, 5);
  EXPECT_EQ(bad, 0);
}

// cos^2s((b - b0) / 2): E[cos(b - b0)] = s / (s + 1), E[cos 2(b - b0)] =
// s (s - 1) / ((s + 1)(s + 2)) (Longuet-Higgins et al. 1963; from the
// ratio of integrals of cos^n: I(n + 2) / I(n) = (n + 1) / (n + 2))
TEST(Spectra, DirectionalSpreadMatchesItsParameter) {
  for (double sp : {2.0, 10.0, 40.0}) {
    mjbSpectrum s = jonswap64(3);
    s.n = 1024;
    s.dir = 30;
    s.spread = sp;
    std::vector<Wave> w = expand(s);
    const double m1 = sp / (sp + 1), m2 = sp * (sp - 1) / ((sp + 1) * (sp + 2));
    // the directions of the components: stratified, so their moments hold
    // to the stratum width (1/n in probability)
    double c1 = 0, c2 = 0, s1 = 0;
    for (const Wave& x : w) {
      double d = (x.dir - 30) * M_PI / 180;
      c1 += std::cos(d) / s.n;
      c2 += std::cos(2 * d) / s.n;
      s1 += std::sin(d) / s.n;
    }
    EXPECT_NEAR(c1, m1, 2e-3) << sp;
    EXPECT_NEAR(c2, m2, 2e-3) << sp;
    EXPECT_NEAR(s1, 0, 2e-3) << sp;
    // the energy's directional moments: directions fall on frequencies at
    // random, so within 4 standard errors of that weighting, sigma^2 =
    // var(cos) sum A^4 / (sum A^2)^2, var(cos) = (1 + m2) / 2 - m1^2
    double e = 0, e2 = 0, k1 = 0;
    for (const Wave& x : w) {
      double a2 = x.amp * x.amp;
      e += a2;
      e2 += a2 * a2;
      k1 += a2 * std::cos((x.dir - 30) * M_PI / 180);
    }
    double se = std::sqrt(((1 + m2) / 2 - m1 * m1) * e2) / e;
    EXPECT_NEAR(k1 / e, m1, 4 * se) << sp;
    std::printf("[spectra] s = %g: mean cos %.4f (analytic %.4f), energy-weighted %.4f "
                "(+- %.4f), mean cos 2 %.4f (%.4f)\n", sp, c1, m1, k1 / e, se, c2, m2);
  }
}

TEST(Spectra, SeedsAreReproducibleAndDistinct) {
  std::vector<Wave> a = expand(jonswap64(11)), b = expand(jonswap64(11)),
                    c = expand(jonswap64(12));
  for (size_t i = 0; i < a.size(); i++) {
    EXPECT_EQ(std::memcmp(&a[i].omega, &b[i].omega, 8), 0);
    EXPECT_EQ(std::memcmp(&a[i].ph, &b[i].ph, 8), 0);
    EXPECT_EQ(std::memcmp(&a[i].amp, &b[i].amp, 8), 0);
  }
  int same = 0;
  for (size_t i = 0; i < a.size(); i++) same += a[i].ph == c[i].ph || a[i].omega == c[i].omega;
  EXPECT_EQ(same, 0);
  // SplitMix64's first output for seed 0 is 0xe220a8397b1dcdaf (Vigna's
  // reference implementation, prng.di.unimi.it): the stream is the
  // specified one, on every platform
  mjb::Rng r(0);
  EXPECT_EQ(r.next(), 0xe220a8397b1dcdafULL);
}

// a sea whose frequencies are multiples of one dw repeats every 2 pi / dw
// (the autocorrelation returns to 1 there); this sea must not repeat
// within an hour: the envelope of its autocorrelation function R(tau) =
// sum A^2 / 2 cos(omega tau) / m0 (Rice 1944) stays small from 10 peak
// periods to 3600 s, and the record's autocorrelation at 2 pi / dw of the
// mean bin width dw is small
TEST(Spectra, NoRepetitionWithinAnHour) {
  mjbSpectrum s = jonswap64(5);
  std::vector<Wave> w = expand(s);
  double wmin, wmax, m0 = 0;
  mjb::specRange(s, kG, &wmin, &wmax);
  for (const Wave& x : w) m0 += x.amp * x.amp;
  auto envelope = [&](const std::vector<Wave>& x, double tau) {
    double c = 0, sn = 0;
    for (const Wave& y : x) {
      c += y.amp * y.amp * std::cos(y.omega * tau);
      sn += y.amp * y.amp * std::sin(y.omega * tau);
    }
    return std::hypot(c, sn) / m0;
  };
  double worst = 0, at = 0;
  for (double tau = 80; tau <= 3600; tau += 0.25) {
    double e = envelope(w, tau);
    if (e > worst) worst = e, at = tau;
  }
  const double dw = (wmax - wmin) / s.n, tau = 2 * M_PI / dw;
  const int lag = int(std::ceil(tau / 0.5));
  const double dt = tau / lag;  // the lag falls on a sample
  auto corr = [&](const std::vector<Wave>& x) {
    std::vector<double> r = record(x, 3600 + tau, dt);
    int n = r.size() - lag;
    double c = 0, v = 0;
    for (int i = 0; i < n; i++) {
      c += r[i] * r[i + lag];
      v += r[i] * r[i];
    }
    return c / v;
  };
  double rr = corr(w);
  // the same components moved to the nearest multiple of dw: it repeats
  std::vector<Wave> grid = w;
  for (Wave& x : grid) x.omega = dw * std::round(x.omega / dw);
  double rg = corr(grid);
  std::printf("[spectra] autocorrelation envelope from 80 s to 1 h at most %.3f (at %.1f s); "
              "record at 2 pi / dw = %.1f s: %.3f (on multiples of dw: %.3f)\n",
              worst, at, tau, rr, rg);
  // N = 64 equal components at random frequencies: the envelope at one
  // lag is Rayleigh with scale 1 / sqrt(2 N) = 0.088, and its largest of
  // the ~1400 independent lags of an hour (bandwidth 2.4 rad/s) about
  // 0.088 sqrt(2 ln 1400) = 0.34; 0.45 is exceeded with probability 3e-3
  EXPECT_LT(worst, 0.45);
  EXPECT_LT(std::fabs(rr), 0.3);
  EXPECT_GT(rg, 0.99);
  EXPECT_GT(envelope(grid, tau), 0.99);
}

// Pierson and Moskowitz 1964 from the wind: U10 = 15 m/s, U19.5 = 1.026
// U10 = 15.39 m/s: Hs = 0.21 U19.5^2 / g = 5.071 m, wp = 0.877 g / U19.5 =
// 0.5590 rad/s, Tp = 11.24 s
TEST(Spectra, PiersonMoskowitzFromWind) {
  double hs, tp;
  mjb::pmFromWind(15, kG, &hs, &tp);
  EXPECT_NEAR(hs, 5.071, 0.001);
  EXPECT_NEAR(tp, 11.24, 0.01);
  mjbSpectrum s;
  mjb_defaultSpectrum(&s);
  s.type = mjbSPEC_PM;
  s.wind = 15;
  s.n = 128;
  s.seed = 9;
  std::vector<Wave> w = expand(s);
  const double dt = 0.5;
  std::vector<double> r = record(w, 3600, dt);
  EXPECT_NEAR(hsOf(r), 5.071, 0.03 * 5.071);
  std::vector<double> om;
  for (double x = 0.25; x < 2.0; x += 2 * M_PI / 512) om.push_back(x);
  int k;
  std::vector<double> S = welch(r, dt, 1024, om, &k);
  double tpm = 2 * M_PI / peakOf(om, S);
  EXPECT_NEAR(tpm, 11.24, 0.05 * 11.24);
  std::printf("[spectra] PM from U10 15 m/s: Hs %.3f m (5.071), Tp %.2f s (11.24)\n", hsOf(r), tpm);
}

// a tabulated triangle S = 0, 2, 0 m^2 s/rad at 0.5, 1, 1.5 rad/s: m0 =
// 1/2 base height = 0.5 * 1 * 2 = 1 m^2, Hs = 4 m; half its energy lies
// below 1 rad/s, so (equal-energy bins) half the components do
TEST(Spectra, TableSpectrum) {
  const double tab[6] = {0.5, 0, 1.0, 2, 1.5, 0};
  mjbSpectrum s;
  mjb_defaultSpectrum(&s);
  s.type = mjbSPEC_TABLE;
  s.table = tab;
  s.ntable = 3;
  s.n = 128;
  EXPECT_EQ(mjb::specCheck(s, 9.81, ""), "");
  EXPECT_DOUBLE_EQ(mjb::specDensity(s, 0.75, kG), 1.0);
  std::vector<Wave> w = expand(s);
  double m0 = 0;
  int below = 0;
  for (const Wave& x : w) {
    m0 += x.amp * x.amp / 2;
    below += x.omega < 1.0;
    EXPECT_GE(x.omega, 0.5);
    EXPECT_LE(x.omega, 1.5);
  }
  EXPECT_NEAR(m0, 1.0, 1e-4);
  EXPECT_EQ(below, 64);
  std::vector<double> r = record(w, 3600, 0.5);
  EXPECT_NEAR(hsOf(r), 4.0, 0.03 * 4.0);
}

// the finite-depth dispersion relation w^2 = g k tanh(k h)
TEST(Spectra, WaveNumberSolvesDispersion) {
  for (double h : {2.0, 10.0, 100.0}) {
    double k = mjb::waveNumber(0.8, kG, h);
    EXPECT_NEAR(kG * k * std::tanh(k * h), 0.64, 1e-12) << h;
  }
  EXPECT_DOUBLE_EQ(mjb::waveNumber(0.8, kG, 0), 0.64 / kG);
}

}  // namespace
