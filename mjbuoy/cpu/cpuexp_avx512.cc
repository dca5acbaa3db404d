// one vertex's e^L over 8 lanes (AVX-512F + FMA; compiled with -mavx512f -mfma;
// called only when the cpu has them, vmath.cc)
#include <immintrin.h>

#include "cpu/cpuexp_kern.h"

// glibc libmvec, 8 doubles per call (x86_64 vector ABI, ISA "e" = AVX-512)
extern "C" __m512d _ZGVeN8v_exp(__m512d);

namespace mjb {
namespace {
struct Exp8 {
  typedef ELanes<8>::V V;
  static V exp(V x) { return (V)_ZGVeN8v_exp((__m512d)x); }  // vExpAvx512's
};
}  // namespace

void eLanesAvx512(const EIn& in, double zs, const double* sc, double* e) {
  eLanes<8, Exp8>(in, zs, sc, e);
}
}  // namespace mjb
