// vmath kernels for AVX-512 (this file is compiled with -mavx512f -mfma; it
// includes no header with inline functions other files could share, so no
// AVX code leaks into the scalar path)
#include <immintrin.h>

#include "vmath.h"

// glibc libmvec, 8 doubles per call (x86_64 vector ABI, ISA "e" = AVX-512)
extern "C" __m512d _ZGVeN8v_sin(__m512d);
extern "C" __m512d _ZGVeN8v_cos(__m512d);
extern "C" __m512d _ZGVeN8v_exp(__m512d);

namespace mjb {

// the tail of n % 8 through masked loads and stores (no stack buffer: an
// over-aligned one breaks under AddressSanitizer's fake stack)
void vSinCosAvx512(int n, const double* x, double* s, double* c) {
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    __m512d v = _mm512_loadu_pd(x + i);
    __m512d vs = _ZGVeN8v_sin(v), vc = _ZGVeN8v_cos(v);
    _mm512_storeu_pd(s + i, vs);
    _mm512_storeu_pd(c + i, vc);
  }
  if (i < n) {
    const __mmask8 m = __mmask8((1u << (n - i)) - 1);
    __m512d v = _mm512_maskz_loadu_pd(m, x + i);
    __m512d vs = _ZGVeN8v_sin(v), vc = _ZGVeN8v_cos(v);
    _mm512_mask_storeu_pd(s + i, m, vs);
    _mm512_mask_storeu_pd(c + i, m, vc);
  }
}

void vExpAvx512(int n, const double* x, double* y) {
  int i = 0;
  for (; i + 8 <= n; i += 8) _mm512_storeu_pd(y + i, _ZGVeN8v_exp(_mm512_loadu_pd(x + i)));
  if (i < n) {
    const __mmask8 m = __mmask8((1u << (n - i)) - 1);
    _mm512_mask_storeu_pd(y + i, m, _ZGVeN8v_exp(_mm512_maskz_loadu_pd(m, x + i)));
  }
}

}  // namespace mjb
