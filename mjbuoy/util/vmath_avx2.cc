// vmath kernels for AVX2 (this file is compiled with -mavx2 -mfma; it
// includes no header with inline functions other files could share, so no
// AVX code leaks into the scalar path)
#include <immintrin.h>

#include "util/expkern.h"
#include "util/vmath.h"

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

void vExpFastAvx2(int n, const double* x, double* y) {
  typedef double V __attribute__((vector_size(32)));
  typedef long I __attribute__((vector_size(32)));
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    _mm256_storeu_pd(y + i, (__m256d)expFast<V, I>((V)_mm256_loadu_pd(x + i)));
  }
  if (i < n) {
    const __m256i m = tailMask(n - i);
    _mm256_maskstore_pd(y + i, m, (__m256d)expFast<V, I>((V)_mm256_maskload_pd(x + i, m)));
  }
}

// four FMA chains of 4 lanes (the FMA's latency times its throughput),
// the tail masked into the first; the lanes summed in a fixed order
double vDotAvx2(int n, const double* a, const double* b) {
  __m256d s0 = _mm256_setzero_pd(), s1 = s0, s2 = s0, s3 = s0;
  int i = 0;
  for (; i + 16 <= n; i += 16) {
    s0 = _mm256_fmadd_pd(_mm256_loadu_pd(a + i), _mm256_loadu_pd(b + i), s0);
    s1 = _mm256_fmadd_pd(_mm256_loadu_pd(a + i + 4), _mm256_loadu_pd(b + i + 4), s1);
    s2 = _mm256_fmadd_pd(_mm256_loadu_pd(a + i + 8), _mm256_loadu_pd(b + i + 8), s2);
    s3 = _mm256_fmadd_pd(_mm256_loadu_pd(a + i + 12), _mm256_loadu_pd(b + i + 12), s3);
  }
  for (; i + 4 <= n; i += 4) {
    s0 = _mm256_fmadd_pd(_mm256_loadu_pd(a + i), _mm256_loadu_pd(b + i), s0);
  }
  if (i < n) {
    const __m256i m = tailMask(n - i);
    s0 = _mm256_fmadd_pd(_mm256_maskload_pd(a + i, m), _mm256_maskload_pd(b + i, m), s0);
  }
  const __m256d s = _mm256_add_pd(_mm256_add_pd(s0, s1), _mm256_add_pd(s2, s3));
  const __m128d h = _mm_add_pd(_mm256_castpd256_pd128(s), _mm256_extractf128_pd(s, 1));
  return _mm_cvtsd_f64(_mm_add_sd(h, _mm_unpackhi_pd(h, h)));
}

}  // namespace mjb
