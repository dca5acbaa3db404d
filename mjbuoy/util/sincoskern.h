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

// sinCosFast: the vertex integration mode's sin and cos of the vertex
// phases (docs/physics.md "Vertex integration", "Reduced-cost phases and
// exponentials"): within kSinCosFastEps absolute for |x| < 2^19 (the
// caller's bound, airyPhaseBound), measured 9.5e-11
// (SeaVec.SinCosFastWithinEps). Two-part Cody-Waite reduction (pi/2 = kP1
// + kP2f + 3.5e-27, so r errs by n 3.5e-27 < 2e-21 for |x| < 2^19, plus
// r's rounding) and near-minimax polynomials on |r| <= pi/4 (Lawson's iteratively
// reweighted least squares, scripts/minimax_sincos.py): sin r = r + r^3
// P(r^2) to r^9 (2.3e-12), cos r = 1 - r^2/2 + r^4 Q(r^2) to r^8 (9.5e-11);
// 7 coefficients instead of sinCosInRange's 15
static const double kSinCosFastEps = 1e-10;
static const double kP2f = 0x1.0b4611a626331p-34;  // pi/2 - kP1 rounded

template <class V, class I>
__attribute__((always_inline)) inline void sinCosFast(V x, V* s, V* c) {
  const double shift = 0x1.8p52;
  const V t = x * 0x1.45f306dc9c883p-1 + shift;
  const V n = t - shift;
  const V r = (x - n * kP1) - n * kP2f;
  const V r2 = r * r;
  const V ps = r2 * (-0x1.555555480c182p-3 + r2 * (0x1.111106204561cp-7 +
               r2 * (-0x1.a00e0e2311590p-13 + r2 * 0x1.6c8987f116800p-19)));
  const V pc = r2 * r2 * (0x1.55554ab402bb2p-5 + r2 * (-0x1.6c0c8bb90566cp-10 +
               r2 * 0x1.9a0259abf4ca0p-16));
  const V sr = r + r * ps, cr = (1 - 0.5 * r2) + pc;
  const I q = (I)t;  // n mod 4, as sinCosInRange
  const I odd = (q & 1) != 0;
  const V sv = odd ? cr : sr, cv = odd ? sr : cr;
  // the signs by bit 1 of n and of n + 1 moved to the sign bit (an xor,
  // not a compare and a blend: the same values)
  *s = (V)((I)sv ^ ((q & 2) << 62));
  *c = (V)((I)cv ^ (((q + 1) & 2) << 62));
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
