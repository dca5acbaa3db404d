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

// the tail of n % 8 through a zero-padded vector
void vSinCosAvx512(int n, const double* x, double* s, double* c) {
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    __m512d v = _mm512_loadu_pd(x + i);
    __m512d vs = _ZGVeN8v_sin(v), vc = _ZGVeN8v_cos(v);
    _mm512_storeu_pd(s + i, vs);
    _mm512_storeu_pd(c + i, vc);
  }
  if (i < n) {
    double b[8] = {0, 0, 0, 0, 0, 0, 0, 0}, bs[8], bc[8];
    for (int j = i; j < n; j++) b[j - i] = x[j];
    __m512d v = _mm512_loadu_pd(b);
    _mm512_storeu_pd(bs, _ZGVeN8v_sin(v));
    _mm512_storeu_pd(bc, _ZGVeN8v_cos(v));
    for (int j = i; j < n; j++) {
      s[j] = bs[j - i];
      c[j] = bc[j - i];
    }
  }
}

void vExpAvx512(int n, const double* x, double* y) {
  int i = 0;
  for (; i + 8 <= n; i += 8) _mm512_storeu_pd(y + i, _ZGVeN8v_exp(_mm512_loadu_pd(x + i)));
  if (i < n) {
    double b[8] = {0, 0, 0, 0, 0, 0, 0, 0}, by[8];
    for (int j = i; j < n; j++) b[j - i] = x[j];
    _mm512_storeu_pd(by, _ZGVeN8v_exp(_mm512_loadu_pd(b)));
    for (int j = i; j < n; j++) y[j] = by[j - i];
  }
}

}  // namespace mjb
