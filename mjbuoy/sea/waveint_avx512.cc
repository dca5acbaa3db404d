// waveint's series for AVX-512F, 8 components at once (compiled with
// -mavx512f -mfma; called only when the cpu has them, vmath.cc)
#include "sea/waveint_kern.h"

namespace mjb {
void seriesAvx512(const KernIn& in, int j0, int j1, double out[7]) {
  seriesRange<8>(in, j0, j1, out);
}
}  // namespace mjb
