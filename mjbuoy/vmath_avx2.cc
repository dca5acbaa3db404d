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

// the tail of n % 4 through a zero-padded vector
void vSinCosAvx2(int n, const double* x, double* s, double* c) {
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    __m256d v = _mm256_loadu_pd(x + i);
    __m256d vs = _ZGVdN4v_sin(v), vc = _ZGVdN4v_cos(v);
    _mm256_storeu_pd(s + i, vs);
    _mm256_storeu_pd(c + i, vc);
  }
  if (i < n) {
    double b[4] = {0, 0, 0, 0}, bs[4], bc[4];
    for (int j = i; j < n; j++) b[j - i] = x[j];
    __m256d v = _mm256_loadu_pd(b);
    _mm256_storeu_pd(bs, _ZGVdN4v_sin(v));
    _mm256_storeu_pd(bc, _ZGVdN4v_cos(v));
    for (int j = i; j < n; j++) {
      s[j] = bs[j - i];
      c[j] = bc[j - i];
    }
  }
}

void vExpAvx2(int n, const double* x, double* y) {
  int i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(y + i, _ZGVdN4v_exp(_mm256_loadu_pd(x + i)));
  if (i < n) {
    double b[4] = {0, 0, 0, 0}, by[4];
    for (int j = i; j < n; j++) b[j - i] = x[j];
    _mm256_storeu_pd(by, _ZGVdN4v_exp(_mm256_loadu_pd(b)));
    for (int j = i; j < n; j++) y[j] = by[j - i];
  }
}

}  // namespace mjb
