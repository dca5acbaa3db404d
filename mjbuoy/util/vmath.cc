// vmath: run-time choice of the vector level, and the scalar reference
#include "util/vmath.h"

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace mjb {

// the best level the cpu has (AVX-512F with its FMA, or AVX2 with FMA)
static int cpuLevel() {
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f")) return kSimdAvx512;
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return kSimdAvx2;
  return kSimdScalar;
}

// the cpu's level capped by MJBUOY_SIMD
static int envLevel() {
  int l = cpuLevel();
  const char* e = std::getenv("MJBUOY_SIMD");
  if (e && !std::strcmp(e, "scalar")) l = kSimdScalar;
  if (e && !std::strcmp(e, "avx2") && l > kSimdAvx2) l = kSimdAvx2;
  return l;
}

static std::atomic<int> glevel{-1};

int simdLevel() {
  int l = glevel.load(std::memory_order_relaxed);
  if (l < 0) {
    l = envLevel();
    glevel.store(l, std::memory_order_relaxed);
  }
  return l;
}

int simdSet(int level) {
  int c = cpuLevel(), l = level < c ? level : c;
  if (l < 0) l = 0;
  glevel.store(l, std::memory_order_relaxed);
  return l;
}

const char* simdName(int level) {
  return level == kSimdAvx512 ? "avx512" : level == kSimdAvx2 ? "avx2" : "scalar";
}

void vSinCos(int n, const double* x, double* s, double* c) {
  switch (simdLevel()) {
    case kSimdAvx512: vSinCosAvx512(n, x, s, c); return;
    case kSimdAvx2: vSinCosAvx2(n, x, s, c); return;
  }
  for (int i = 0; i < n; i++) {
    double v = x[i];
    s[i] = std::sin(v);
    c[i] = std::cos(v);
  }
}

void vExp(int n, const double* x, double* y) {
  switch (simdLevel()) {
    case kSimdAvx512: vExpAvx512(n, x, y); return;
    case kSimdAvx2: vExpAvx2(n, x, y); return;
  }
  for (int i = 0; i < n; i++) y[i] = std::exp(x[i]);
}

void vExpFast(int n, const double* x, double* y) {
  switch (simdLevel()) {
    case kSimdAvx512: vExpFastAvx512(n, x, y); return;
    case kSimdAvx2: vExpFastAvx2(n, x, y); return;
  }
  for (int i = 0; i < n; i++) y[i] = std::exp(x[i]);
}

double vDot(int n, const double* a, const double* b) {
  switch (simdLevel()) {
    case kSimdAvx512: return vDotAvx512(n, a, b);
    case kSimdAvx2: return vDotAvx2(n, a, b);
  }
  // four running sums: one add's latency bounds a single sum
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    s0 += a[i] * b[i];
    s1 += a[i + 1] * b[i + 1];
    s2 += a[i + 2] * b[i + 2];
    s3 += a[i + 3] * b[i + 3];
  }
  for (; i < n; i++) s0 += a[i] * b[i];
  return (s0 + s1) + (s2 + s3);
}

}  // namespace mjb
