// vmath kernels for AVX2 (this file is compiled with -mavx2 -mfma; it
// includes no header with inline functions other files could share, so no
// AVX code leaks into the scalar path)
#include <immintrin.h>

#include "vmath.h"

// glibc libmvec, 4 doubles per call (x86_64 vector ABI, ISA "d" = AVX2)
extern "C" __m256d _ZGVdN4v_sin(__m256d);
extern "C" __m256d _ZGVdN4v_cos(__m256d);
extern "C" __m256d _ZGVdN4v_exp(__m256d);

namespace mjb {

// the tail of n % 4 through masked loads and stores (no stack buffer: an
// over-aligned one breaks under AddressSanitizer's fake stack)
static __m256i tailMask(int r) {
  return _mm256_set_epi64x(r > 3 ? -1 : 0, r > 2 ? -1 : 0, r > 1 ? -1 : 0, r > 0 ? -1 : 0);
}

void vSinCosAvx2(int n, const double* x, double* s, double* c) {
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    __m256d v = _mm256_loadu_pd(x + i);
    __m256d vs = _ZGVdN4v_sin(v), vc = _ZGVdN4v_cos(v);
    _mm256_storeu_pd(s + i, vs);
    _mm256_storeu_pd(c + i, vc);
  }
  if (i < n) {
    const __m256i m = tailMask(n - i);
    __m256d v = _mm256_maskload_pd(x + i, m);
    __m256d vs = _ZGVdN4v_sin(v), vc = _ZGVdN4v_cos(v);
    _mm256_maskstore_pd(s + i, m, vs);
    _mm256_maskstore_pd(c + i, m, vc);
  }
}

void vExpAvx2(int n, const double* x, double* y) {
  int i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(y + i, _ZGVdN4v_exp(_mm256_loadu_pd(x + i)));
  if (i < n) {
    const __m256i m = tailMask(n - i);
    _mm256_maskstore_pd(y + i, m, _ZGVdN4v_exp(_mm256_maskload_pd(x + i, m)));
  }
}

}  // namespace mjb
