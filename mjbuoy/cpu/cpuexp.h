// cpuexp: one vertex's e^L in lanes over its components (docs/physics.md
// "Vertex integration", waveint.h): the exponents, their exp and the
// products with the phases' sin and cos fused in one pass, the list path's
// vertexExponents, vExp / vExpFast and vertexE (cpuhull.h) with the same
// operations per component, so the same bits. Plain data and entry points
#ifndef MJBUOY_CPUEXP_H_
#define MJBUOY_CPUEXP_H_

namespace mjb {

// a sea's constants for eLanes*: k [rad/m] (n, sorted), perm (sorted index
// -> the phases' unsorted index; nullptr when the identity), nw phases,
// finite depth h [m] (a second exponent -k (z' + 2 h)), fast: vertex
// integration's exp (expkern.h expFast) instead of libmvec's (vExp's)
struct EIn {
  const double* k;
  const int* perm;
  int n, nw;
  bool finite;
  double depth;
  bool fast;
};

// e^L at stretched height zs [m] into e (per family f: Re at 2 f nw + j,
// Im at 2 f nw + nw + j) from sc, the vertex's nw phases' interleaved sin,
// cos: Re = e^a cos(theta), Im = e^a sin(theta), a = k z' and at finite
// depth -k (z' + 2 h). (cpuexp_avx2.cc, cpuexp_avx512.cc: compiled for
// those instruction sets, called only when the cpu has them)
void eLanesAvx2(const EIn& in, double zs, const double* sc, double* e);
void eLanesAvx512(const EIn& in, double zs, const double* sc, double* e);

}  // namespace mjb

#endif  // MJBUOY_CPUEXP_H_
