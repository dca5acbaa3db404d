// the triangle stage over 8 lanes, AVX-512F (compiled with -mavx512f
// -mfma; called only when the cpu has them, vmath.cc)
#include <immintrin.h>

#include "cpu/trivec_kern.h"

namespace mjb {
namespace {
struct Ops8 {
  typedef TLanes<8>::V V;
  // (the masked form: GCC 12 warns of _mm512_sqrt_pd's undefined pass-through)
  static V sqrt(V x) { return (V)_mm512_mask_sqrt_pd((__m512d)x, 0xff, (__m512d)x); }
};
}  // namespace

void triLanesAvx512(TriIn* in, int kind) {
  if (kind == 0) triLanes<8, Ops8, 0>(in);
  if (kind == 1) triLanes<8, Ops8, 1>(in);
  if (kind == 2) triLanes<8, Ops8, 2>(in);
}
}  // namespace mjb
