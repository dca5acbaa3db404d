// waveint's series for AVX2 + FMA, 4 components at once (compiled with
// -mavx2 -mfma; called only when the cpu has them, vmath.cc)
#include "sea/waveint_kern.h"

namespace mjb {
void seriesAvx2(const KernIn& in, int j0, int j1, double out[7]) {
  seriesRange<4>(in, j0, j1, out);
}
}  // namespace mjb
