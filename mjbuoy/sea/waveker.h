// waveker: the plain-data interface of waveint's series kernels, one per
// instruction set (waveint_kern.h); no includes, no inline functions, so a
// file compiled for AVX shares no code with the scalar path
#ifndef MJBUOY_WAVEKER_H_
#define MJBUOY_WAVEKER_H_

namespace mjb {

// series about corner 0 is used while max |u_c| <= kRMax (its terms peak
// at e^r, so at most e^4 of round-off is lost); kNMax terms always suffice
static const double kRMax = 4;
static const int kNMax = 64;

// the data of one piece of one exponent family, for the kernels: corner 0
// (whose e^L0 is known) and corners 1, 2 as differences from it
struct KernIn {
  const double *k, *kdx, *kdy, *gm;      // WaveTab's arrays
  const double *wp, *wux, *wuy, *wz;     // the family's weights
  const double *e0r, *e0i;               // e^L0 per component
  double dz[2];      // stretched height z' of corners 1, 2 minus corner 0 [m]
  double dp[2][2];   // their horizontal position minus corner 0's [m]
  double dl[2][2];   // their Gerstner label minus corner 0's [m]
  double sgn;        // +1: exponent k z'; -1: -k (z' + 2 h)
  double rho;        // |u_c| <= k rho for every component
  int mom;           // 0: only S (velocity, pressure force), T_c left at 0
};

// out += sums over components j in [j0, j1) of w Re(e^L0 S) (pressure),
// w Re(e^L0 T_c) for c = 0, 1, 2, wux Re(e^L0 S), wuy Re(..), wz Im(..)
// (7 values; times 2 area they are the integrals); every component in the
// range must have k rho <= kRMax. By level: glibc-free arithmetic only, so
// levels differ by FMA contraction, summation order, terms past the
// scalar's count (two chunks share one) and, on the vector levels, T_2 by
// the sum rule T_0 + T_1 + T_2 = S (serieskern.h) and the series cut at
// 2^-kSeriesBitsV instead of 2^-54
void seriesSums(const KernIn& in, int j0, int j1, double out[7]);
void seriesScalar(const KernIn& in, int j0, int j1, double out[7]);
void seriesAvx2(const KernIn& in, int j0, int j1, double out[7]);
void seriesAvx512(const KernIn& in, int j0, int j1, double out[7]);

// the number of series terms for radius r <= kRMax: the first term left
// out is below 2^-54 of the leading one (docs/physics.md, "Cost")
int seriesTerms(double r);
// the largest radius N terms serve, for N <= kNMax (rising with N)
extern const double* kSeriesR;
// the vector lanes' series stop where the first term left out is below
// 2^-kSeriesBitsV of the leading one, the lanes' own rounding level (a
// triangle's integrals already differ from the scalar path's by about 64
// e^4 eps, 1e-12, trivec_kern.h): 2 to 4 terms fewer than the scalar
// reference's 2^-54 (docs/physics.md, "Dynamic part in closed form")
static const int kSeriesBitsV = 40;
// the largest radius N terms serve in the vector lanes (kSeriesR's kind)
extern const double* kSeriesRv;
// the loose series of mjbuoy.sea.seriestol (docs/physics.md "Series
// tolerance"): for bits b in [1, kSeriesBitsV), kSeriesRb + b (kNMax + 1)
// holds the largest radius N terms serve when the whole omitted tail of S,
// sum_(m>=N) (m+1) r^m / (m+2)!, must stay at or below 2^-b
extern const double* kSeriesRb;
// 1/(m+2)! and 1/(m+3)! for m < kNMax
extern const double* kInvF2;
extern const double* kInvF3;

}  // namespace mjb

#endif  // MJBUOY_WAVEKER_H_
