// the vertex sums over 4 lanes (AVX2 + FMA; compiled with -mavx2 -mfma;
// called only when the cpu has them, vmath.cc)
#include "cpu/cpusum_kern.h"

namespace mjb {
void sumLanesAvx2(const SumIn& in) { sumLanes<4>(in); }
}  // namespace mjb
