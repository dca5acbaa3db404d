// the vertex sums over 8 lanes (AVX-512F; compiled with -mavx512f;
// called only when the cpu has them, vmath.cc)
#include "cpu/cpusum_kern.h"

namespace mjb {
void sumLanesAvx512(const SumIn& in) { sumLanes<8>(in); }
}  // namespace mjb
