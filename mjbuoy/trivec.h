// trivec: the triangle stage's wholly wet triangles (no cut: hydrostatic
// integrals, the closed-form wave series of waveint.h, centroid, normal,
// water velocity and the flow extent) over lanes of 4 (AVX2 + FMA) or 8
// (AVX-512F) triangles; chosen at run time by vmath.h's level. cpu.cc's
// per-triangle loop (wetTriangle, wetWaves) stays the reference
// (tests/trivec_test.cc). Plain data only: no inline code to share.
#ifndef MJBUOY_TRIVEC_H_
#define MJBUOY_TRIVEC_H_

namespace mjb {

// one hull's wholly wet triangles for the lane kernels
struct TriIn {
  const int* idx;  // global triangle indices
  int m;           // how many
  const int* face; // 3 global vertex indices per triangle
  int v0;          // the hull's first vertex
  const double *rel, *h, *lab;  // per global vertex: position relative to the COM,
                                // height above the surface, Gerstner label [m]
  const double *zs, *E;  // per hull vertex: stretched height [m], e^L (es nw a vertex)
  int nw, es;
  // the call's wave table (WaveTab, sorted order): n components
  int n, finite;
  double depth;
  const double *k, *kdx, *kdy, *gm;
  const double *wp[2], *wux[2], *wuy[2], *wz[2];
  int linear;  // linear pressure (dynamic part), else Kerner's rho g (eta - z)
  double rg, level, comz, cur[2], dir[3];
  // written per triangle done: wet area, centroid (relative to the COM),
  // unit normal, mean water velocity [m/s]
  double *area, *c, *nrm, *u;
  // triangles left to the scalar path (a piece too coarse for the series,
  // or not finite): their indices, and how many
  int* rest;
  int nrest;
  // sums over the triangles done: pressure force [N] and torque [N m]
  // (to add), wet area [m^2]; extent of their corners along dir [m]
  double f[3], t[3], wet, lo, hi;
};

// (trivec_avx2.cc, trivec_avx512.cc: compiled for those instruction sets,
// called only when the cpu has them)
void triLanesAvx2(TriIn* in);
void triLanesAvx512(TriIn* in);

}  // namespace mjb

#endif  // MJBUOY_TRIVEC_H_
