// vmath: sin, cos and exp over arrays, vectorised with glibc's libmvec
// (AVX2 or AVX-512, chosen at run time from cpuid) or scalar glibc
//
// libmvec's documented maximum error is 4 ulp per function (glibc manual,
// "Errors in Math Functions"), glibc's scalar sin, cos and exp are within 1
// ulp; results are the same bits on every run and thread count of one
// machine. The environment variable MJBUOY_SIMD=scalar|avx2|avx512 caps
// the level (read once, at the first use); simdSet overrides it (tests).
#ifndef MJBUOY_VMATH_H_
#define MJBUOY_VMATH_H_

namespace mjb {

enum { kSimdScalar = 0, kSimdAvx2 = 1, kSimdAvx512 = 2 };

// the level in use
int simdLevel();
// use level at most (capped by what the cpu has); returns the level set
int simdSet(int level);
// the name of a level: "scalar", "avx2", "avx512"
const char* simdName(int level);

// s[i] = sin x[i], c[i] = cos x[i] for i < n (c may alias x)
void vSinCos(int n, const double* x, double* s, double* c);
// y[i] = exp x[i] for i < n (y may alias x)
void vExp(int n, const double* x, double* y);
// y[i] = e^x[i] for i < n within expkern.h's kExpFastEps (1e-10) relative
// (y may alias x): the vertex integration mode's e^(k z') (docs/physics.md
// "Vertex integration"); 0 below x = -708, infinity above 709; glibc's exp
// on the scalar level
void vExpFast(int n, const double* x, double* y);
// sum a[i] b[i] for i < n: partial sums (4 scalars; 4 vectors of 4 with
// AVX2, of 8 with AVX-512) added in a fixed order, so each level repeats
// its bits; levels differ by round-off (the order of the sums, FMA), each
// within n eps sum |a b| of the exact sum
double vDot(int n, const double* a, const double* b);

// per-level kernels (vmath_avx2.cc, vmath_avx512.cc: compiled for those
// instruction sets, called only when the cpu has them)
void vSinCosAvx2(int n, const double* x, double* s, double* c);
void vExpAvx2(int n, const double* x, double* y);
void vExpFastAvx2(int n, const double* x, double* y);
double vDotAvx2(int n, const double* a, const double* b);
void vSinCosAvx512(int n, const double* x, double* s, double* c);
void vExpAvx512(int n, const double* x, double* y);
void vExpFastAvx512(int n, const double* x, double* y);
double vDotAvx512(int n, const double* a, const double* b);

}  // namespace mjb

#endif  // MJBUOY_VMATH_H_
