// sincoskern: sin and cos of W phases sharing one range reduction (GCC
// vector extensions), for seavec_kern.h; an unnamed namespace, so each
// instruction set's file keeps its own copy. docs/physics.md, "Phases'
// sine and cosine in lanes"
#ifndef MJBUOY_SINCOSKERN_H_
#define MJBUOY_SINCOSKERN_H_

namespace mjb {
namespace {

// pi/2 = kP1 + kP2 + kP3, the first two of 32 significant bits (n kP1 and
// n kP2 exact for |n| < 2^21), Cody and Waite 1980
static const double kP1 = 0x1.921fb544p+0, kP2 = 0x1.0b4611a6p-34;
static const double kP3 = 0x1.3198a2e037073p-69;

// sin and cos of x in the lanes: x = n pi/2 + r, |r| <= pi/4 (plus
// rounding), then the Taylor series of sin r to r^17 and cos r to r^16
// (the first terms left out below 2^-60 of the result) and the quadrant
// n mod 4. Within 3 ulp (of the result, or of 2^-53 below 1/2) for |x| <
// 2^20 pi/2, measured 2.0 (SeaVec.SinCosLanesWithinThreeUlp); false (nothing written) when a lane
// is beyond that or not finite: the caller uses libmvec then
//
// sinCosInRange is the same without the check, for callers that have
// bounded |x| < 2^20 (so |n| < 2^20 too) for all lanes beforehand
template <class V, class I>
__attribute__((always_inline)) inline void sinCosInRange(V x, V* s, V* c) {
  const double shift = 0x1.8p52;  // t - shift is x 2/pi rounded to an integer
  const V t = x * 0x1.45f306dc9c883p-1 + shift;
  const V n = t - shift;
  const V r = ((x - n * kP1) - n * kP2) - n * kP3;
  const V r2 = r * r;
  const V ps = r2 * (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040 + r2 * (1.0 / 362880 +
               r2 * (-1.0 / 39916800 + r2 * (1.0 / 6227020800 + r2 * (-1.0 / 1307674368000 +
               r2 * (1.0 / 355687428096000))))))));
  const V pc = r2 * r2 * (1.0 / 24 + r2 * (-1.0 / 720 + r2 * (1.0 / 40320 +
               r2 * (-1.0 / 3628800 + r2 * (1.0 / 479001600 + r2 * (-1.0 / 87178291200 +
               r2 * (1.0 / 20922789888000)))))));
  const V sr = r + r * ps, cr = (1 - 0.5 * r2) + pc;
  // t's low mantissa bits are n mod 4 (t in [2^52, 2^53): its ulp is 1)
  const I q = (I)t;
  const I odd = (q & 1) != 0, sneg = (q & 2) != 0, cneg = ((q + 1) & 2) != 0;
  const V sv = odd ? cr : sr, cv = odd ? sr : cr;
  *s = sneg ? -sv : sv;
  *c = cneg ? -cv : cv;
}

template <class V, class I>
__attribute__((always_inline)) inline bool sinCosLanes(V x, V* s, V* c) {
  const double shift = 0x1.8p52;
  const V n = (x * 0x1.45f306dc9c883p-1 + shift) - shift;
  const V an = n < 0 ? -n : n;
  bool ok = true;
  for (int l = 0; l < int(sizeof(V) / sizeof(double)); l++) ok &= an[l] < 0x1p20;
  if (!ok) return false;  // also NaN and infinity
  sinCosInRange<V, I>(x, s, c);
  return true;
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_SINCOSKERN_H_
