// the triangle stage over 4 lanes, AVX2 + FMA (compiled with -mavx2
// -mfma; called only when the cpu has them, vmath.cc)
#include <immintrin.h>

#include "cpu/trivec_kern.h"

namespace mjb {
namespace {
struct Ops4 {
  typedef TLanes<4>::V V;
  static V sqrt(V x) { return (V)_mm256_sqrt_pd((__m256d)x); }
};
}  // namespace

void triLanesAvx2(TriIn* in, int kind) {
  if (kind == 0) triLanes<4, Ops4, 0>(in);
  if (kind == 1) triLanes<4, Ops4, 1>(in);
  if (kind == 2) triLanes<4, Ops4, 2>(in);
}
}  // namespace mjb
