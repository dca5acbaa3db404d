// vmath kernels for AVX-512 (this file is compiled with -mavx512f -mfma; it
// includes no header with inline functions other files could share, so no
// AVX code leaks into the scalar path)
#include <immintrin.h>

#include "util/expkern.h"
#include "util/vmath.h"

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

void vExpFastAvx512(int n, const double* x, double* y) {
  typedef double V __attribute__((vector_size(64)));
  typedef long I __attribute__((vector_size(64)));
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    _mm512_storeu_pd(y + i, (__m512d)expFast<V, I>((V)_mm512_loadu_pd(x + i)));
  }
  if (i < n) {
    const __mmask8 m = __mmask8((1u << (n - i)) - 1);
    _mm512_mask_storeu_pd(y + i, m, (__m512d)expFast<V, I>((V)_mm512_maskz_loadu_pd(m, x + i)));
  }
}

// four FMA chains of 8 lanes, the tail masked into the first; the lanes
// summed in a fixed order
double vDotAvx512(int n, const double* a, const double* b) {
  __m512d s0 = _mm512_setzero_pd(), s1 = s0, s2 = s0, s3 = s0;
  int i = 0;
  for (; i + 32 <= n; i += 32) {
    s0 = _mm512_fmadd_pd(_mm512_loadu_pd(a + i), _mm512_loadu_pd(b + i), s0);
    s1 = _mm512_fmadd_pd(_mm512_loadu_pd(a + i + 8), _mm512_loadu_pd(b + i + 8), s1);
    s2 = _mm512_fmadd_pd(_mm512_loadu_pd(a + i + 16), _mm512_loadu_pd(b + i + 16), s2);
    s3 = _mm512_fmadd_pd(_mm512_loadu_pd(a + i + 24), _mm512_loadu_pd(b + i + 24), s3);
  }
  for (; i + 8 <= n; i += 8) {
    s0 = _mm512_fmadd_pd(_mm512_loadu_pd(a + i), _mm512_loadu_pd(b + i), s0);
  }
  if (i < n) {
    const __mmask8 m = __mmask8((1u << (n - i)) - 1);
    s0 = _mm512_fmadd_pd(_mm512_maskz_loadu_pd(m, a + i), _mm512_maskz_loadu_pd(m, b + i), s0);
  }
  double l[8];  // unaligned store: _mm512_reduce_add_pd trips GCC 12's -Wuninitialized
  _mm512_storeu_pd(l, _mm512_add_pd(_mm512_add_pd(s0, s1), _mm512_add_pd(s2, s3)));
  return ((l[0] + l[1]) + (l[2] + l[3])) + ((l[4] + l[5]) + (l[6] + l[7]));
}

}  // namespace mjb
