// one vertex's e^L over 4 lanes (AVX2 + FMA; compiled with -mavx2 -mfma;
// called only when the cpu has them, vmath.cc)
#include <immintrin.h>

#include "cpu/cpuexp_kern.h"

// glibc libmvec, 4 doubles per call (x86_64 vector ABI, ISA "d" = AVX2)
extern "C" __m256d _ZGVdN4v_exp(__m256d);

namespace mjb {
namespace {
struct Exp4 {
  typedef ELanes<4>::V V;
  static V exp(V x) { return (V)_ZGVdN4v_exp((__m256d)x); }  // vExpAvx2's
};
}  // namespace

void eLanesAvx2(const EIn& in, double zs, const double* sc, double* e) {
  eLanes<4, Exp4>(in, zs, sc, e);
}
}  // namespace mjb
