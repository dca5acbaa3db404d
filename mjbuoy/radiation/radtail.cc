// radtail: B beyond the table as a power law, and its part of K(t)
// (radtail.h; docs/physics.md section 14, "High-frequency tail")
#include "radiation/radtail.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace mjb {

using cd = std::complex<double>;

// (2/pi) PV int_0^wN B_dd(v) / (v^2 - w^2) dv of the table's B (linear
// between its frequencies, from 0 at 0): per segment B = a + s v, whose
// partial fractions al / (v - w) + be / (v + w) integrate to logarithms;
// at a table frequency the two ln|v - w| = ln 0 of the adjacent segments
// cancel (B is continuous there) and are left out
static double hilbertTable(const HydroCoef& c, int d, double w) {
  double w0 = 0, b0 = 0, sum = 0;
  for (int f = 0; f < c.nw(); f++) {
    const double w1 = c.omega[f], b1 = c.B[36 * f + 7 * d];
    const double s = (b1 - b0) / (w1 - w0), a = b0 - s * w0;
    const double al = (a + s * w) / (2 * w), be = (s * w - a) / (2 * w);
    const double e1 = std::fabs(w1 - w), e0 = std::fabs(w0 - w), tiny = 1e-12 * w;
    sum += (e1 > tiny ? al * std::log(e1) : 0) - (e0 > tiny ? al * std::log(e0) : 0) +
           be * std::log((w1 + w) / (w0 + w));
    w0 = w1, b0 = b1;
  }
  return 2 / M_PI * sum;
}

// (2/pi) int_wN^inf bN (wN/v)^p / (v^2 - w^2) dv for r = w / wN < 1:
// (2/pi) (bN / wN) sum_k r^2k / (p + 2k + 1)
static double hilbertTail(double bN, double wN, double p, double r) {
  double sum = 0, rk = 1;
  for (int k = 0; k < 2000 && rk > 1e-14; k++, rk *= r * r) sum += rk / (p + 2 * k + 1);
  return 2 / M_PI * bN / wN * sum;
}

void tailExponents(const HydroCoef& c, double p[6]) {
  const int nw = c.nw(), m = 3;
  for (int d = 0; d < 6; d++) {
    p[d] = 0;
    if (nw < m) continue;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    bool pos = true;
    for (int f = nw - m; f < nw; f++) {
      const double b = c.B[36 * f + 7 * d];
      if (!(b > 0)) pos = false;
      if (!pos) break;
      const double x = std::log(c.omega[f]), y = std::log(b);
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    if (!pos) continue;
    const double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
    p[d] = std::clamp(-slope, kTailPMin, kTailPMax);
    if (c.A.size() != 36 * size_t(nw)) continue;
    // with A(w) known: the p whose tail makes Kramers-Kronig hold best,
    // A(w) - A_inf - H_table(w) = H_tail(w) in least squares over the
    // frequencies up to 0.9 w_N (H_tail falls monotonically with p, so the
    // misfit has one minimum in [kTailPMin, kTailPMax]: golden section)
    const double wN = c.omega[nw - 1], bN = c.B[36 * (nw - 1) + 7 * d];
    std::vector<double> r, D;
    for (int f = 0; f < nw - 1 && c.omega[f] <= 0.9 * wN; f++) {
      r.push_back(c.omega[f] / wN);
      D.push_back(c.A[36 * f + 7 * d] - c.Ainf[7 * d] - hilbertTable(c, d, c.omega[f]));
    }
    if (r.empty()) continue;
    auto misfit = [&](double q) {
      double e = 0;
      for (size_t k = 0; k < r.size(); k++) e += std::pow(D[k] - hilbertTail(bN, wN, q, r[k]), 2);
      return e;
    };
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double lo = kTailPMin, hi = kTailPMax, x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = misfit(x1), f2 = misfit(x2);
    for (int it = 0; it < 40; it++) {
      if (f1 < f2) {
        hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = misfit(x1);
      } else {
        lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = misfit(x2);
      }
    }
    p[d] = 0.5 * (lo + hi);
  }
}

double tailExponent(const double p[6], int i, int j) {
  return p[i] > 0 && p[j] > 0 ? 0.5 * (p[i] + p[j]) : 0;
}

// E_p(z), Re z >= 0, z != 0, by Legendre's continued fraction of the
// incomplete gamma function, E_p(z) = z^(p-1) Gamma(1-p, z) (Abramowitz
// and Stegun 6.5.31, 5.1.22), evaluated from the front by the modified
// Lentz method: on z = -i x it converges for every x > 0, in about
// 130 / x terms (7 at x = 50), so it is used from x = 0.5 up
static cd expintCF(double p, cd z) {
  const double tiny = 1e-300;
  cd b = z + p, cc = 1 / tiny, dd = 1.0 / b, h = dd;
  for (int i = 1; i < 2000; i++) {
    const double an = -i * (p - 1 + i);
    b += 2.0;
    dd = an * dd + b;
    if (std::abs(dd) < tiny) dd = tiny;
    cc = b + an / cc;
    if (std::abs(cc) < tiny) cc = tiny;
    dd = 1.0 / dd;
    const cd del = cc * dd;
    h *= del;
    if (std::abs(del - 1.0) < 1e-14) break;
  }
  return h * std::exp(-z);
}

// E_p(-i x) for small x: the path u = 1 + i s (the integrand decays in
// the first quadrant), i e^{ix} int_0^inf (1 + i s)^-p e^{-x s} ds, with
// s = e^v and the trapezoid rule in v: the integrand is analytic for
// |Im v| < pi/2, so the error falls as e^(-pi^2 / h); it decays at least
// as e^v below and e^{-(p-1) v} above. At h = 0.25 it agrees with the
// continued fraction to 1e-10 for x in [0.05, 5], p in [2, 8]
static cd expintPath(double p, double x) {
  const double h = 0.25;
  cd sum = 0;
  for (int k = -120; k <= 120; k++) {
    const double s = std::exp(k * h);
    sum += std::pow(cd(1, s), -p) * (std::exp(-x * s) * s);
  }
  return cd(0, 1) * std::exp(cd(0, x)) * (h * sum);
}

void expintImag(double p, double x, double* re, double* im) {
  cd e = x == 0 ? cd(1 / (p - 1), 0) : x < 0.5 ? expintPath(p, x) : expintCF(p, cd(0, -x));
  *re = e.real();
  *im = e.imag();
}

double tailK(double bN, double wN, double p, double t) {
  double re, im;
  expintImag(p, wN * t, &re, &im);
  return 2 / M_PI * bN * wN * re;
}

}  // namespace mjb
