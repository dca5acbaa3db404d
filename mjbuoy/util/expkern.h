// expkern: e^x of W lanes by a reduced-cost kernel (GCC vector extensions)
// for vmath_avx2.cc and vmath_avx512.cc's vExpFast; an unnamed namespace,
// so each instruction set's file keeps its own copy. docs/physics.md
// "Vertex integration" (reduced-cost phases and exponentials)
#ifndef MJBUOY_EXPKERN_H_
#define MJBUOY_EXPKERN_H_

namespace mjb {
namespace {

// e^x within kExpFastEps relative for x in [-708, 709], measured 5.2e-11
// (SeaVec.ExpFastWithinEps); 0 below -708 (e^x < 4e-308 there), infinity
// above 709 (e^709 = 8.2e307: taken as overflow), NaN kept. x = n ln2 + r, |r| <= ln2 / 2 (ln2 in two parts,
// Cody and Waite 1980: n ln2hi exact for |n| < 2^11), e^r = 1 + r + r^2
// R(r) to r^7, near-minimax in relative error (Lawson's iteratively
// reweighted least squares, scripts/minimax_sincos.py), times 2^n built
// in the exponent bits
static const double kExpFastEps = 1e-10;

template <class V, class I>
__attribute__((always_inline)) inline V expFast(V x) {
  const double shift = 0x1.8p52;  // t - shift is x / ln2 rounded to an integer
  const double ln2hi = 0x1.62e42fefa3800p-1, ln2lo = 0x1.ef35793c7673p-45;
  const V xc = x < -708 ? V{} - 708 : (x > 709 ? V{} + 709 : x);  // (NaN passes)
  const V t = xc * 0x1.71547652b82fep0 + shift;
  const V n = t - shift;
  const V r = (xc - n * ln2hi) - n * ln2lo;
  const V p = 1 + (r + r * r * (0x1.0000003a1ae51p-1 + r * (0x1.5555544365fa9p-3 +
              r * (0x1.55548dd8679f2p-5 + r * (0x1.1112708ecdfe2p-7 +
              r * (0x1.6d8cf42556260p-10 + r * 0x1.9f08a4f98f918p-13))))));
  // t's low bits hold n (t in [2^52, 2^53): its ulp is 1); 2^n from them
  const I e = ((I)t - (I)(V{} + shift) + 1023) << 52;
  const V y = x < -708 ? V{} : p * (V)e;
  return x > 709 ? V{} + __builtin_inf() : y;
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_EXPKERN_H_
