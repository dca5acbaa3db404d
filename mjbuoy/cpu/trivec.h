// trivec: the triangle stage in lanes: wholly wet triangles (hydrostatic
// integrals, the closed-form wave series of waveint.h, centroid, normal,
// water velocity and the flow extent) and the wet pieces of triangles the
// surface cuts (the same integrals per piece), over lanes of 4 (AVX2 +
// FMA) or 8 (AVX-512F); chosen at run time by vmath.h's level. cpupass.cc's
// per-triangle loop (wetTriangle, wetWaves) stays the reference
// (tests/trivec_test.cc). Plain data only: no inline code to share.
#ifndef MJBUOY_TRIVEC_H_
#define MJBUOY_TRIVEC_H_

namespace mjb {

// pass 2 in pass 1's lanes (hydro.h's viscous, drag and slamming forces
// at each wet centroid); the exponents of drag, suction and slamming must
// each be 0.5, 1 or 2 (cpupass.cc checks; others: scalar)
struct FlowIn {
  const double* tarea;               // the triangles' whole areas [m^2]
  // slamming history, swept-volume rates Q = A v, 3 per triangle [m^3/s]
  // (hydro.h sweptRate): q written on a step's first call (else null),
  // prevQ the previous step's
  float* q;
  const float* prevQ;
  double vel[6];                     // body velocity [angular; linear] at the COM
  double com[3];                     // body COM, world [m]
  // viscous: on, the flow's direction (sums: cpuhull.h passChunk)
  int visc;
  double dir[3];
  double drag[3], suction[3], vref;
  // slamming: on (history and gain and dt > 0), gain, gmax, power, the
  // hull's share and area [m^2], dt [s], the rigid group (rigid.h)
  int slam;
  double gain, gmax, pw, share, shull, dt, minv, iinv[6], gcom[3];
  // sums of one kind's lanes [force; torque about the COM]: the unit
  // viscous wrench and its first moment along dir (cpuhull.h passChunk),
  // drag, slamming
  double wv1[6], wvd[6], wd[6], ws[6];
};

// one hull's wholly wet or cut triangles for the lane kernels
struct TriIn {
  const int* idx;  // global triangle indices
  int m;           // how many
  const int* face; // 3 global vertex indices per triangle
  int v0;          // the hull's first vertex
  const double* h;     // per global vertex: height above the surface [m]
  const double *rel, *lab;  // per hull vertex: position relative to the COM,
                            // Gerstner label [m]
  const double* rec;  // per hull vertex: all of it in one record (zipkern.h kRec)
  const double *zs, *E;  // per hull vertex: stretched height [m], e^L (es nw a vertex)
  int nw, es;
  // vertex integration (mjbuoy.sea.integration = vertex): per hull vertex
  // the 4 vertex sums (cpusum.h), whose linear interpolant each piece
  // integrates instead of the series; null: the series (exact)
  const double* vs;
  // the call's wave table (WaveTab, sorted order): n components
  int n, finite;
  double depth;
  const double *k, *kdx, *kdy, *gm;
  // long-crested (WaveTab lc): every component along (ldx, ldy), of kind lgm
  int lc;
  double ldx, ldy, lgm;
  const double *wp[2], *wux[2], *wuy[2], *wz[2];
  int linear;  // linear pressure (dynamic part), else Kerner's rho g (eta - z)
  // the loose series (mjbuoy.sea.seriestol): 2 S_hull n_f n / (tol V_hull)
  // [1/m], so component j's S may omit 2^-b with 2^b >= |wp_j| sscale;
  // 0: every series to the lanes' rounding (docs/physics.md "Series
  // tolerance")
  double sscale;
  double rg, level, comz, cur[2], dir[3];
  // written per triangle done, in the hull's scratch: wet area [m^2] at
  // k - t0, centroid (relative to the COM) [m], unit normal, mean water
  // velocity [m/s] at 3 (k - t0)
  double *area, *c, *nrm, *u;
  int t0;
  // triangles left to the scalar path (a piece too coarse for the series,
  // or not finite): their indices, and how many (at most m)
  int* rest;
  int nrest;
  // set: pass 2 in the same lanes, into its sums, and no per-triangle
  // results stored; null: the results stored for pass 2 to read
  FlowIn* fl;
  // sums over the triangles done: pressure force [N] and torque [N m]
  // (to add), wet area [m^2], wet area times centroid along dir [m^3];
  // extent of their corners along dir [m]
  double f[3], t[3], wet, wdir, lo, hi;
};

// (trivec_avx2.cc, trivec_avx512.cc: compiled for those instruction sets,
// called only when the cpu has them)
// in.idx's triangles: kind 0 wholly wet; 1 cut, one corner below the
// surface (h <= 0) and two above (h > 0); 2 cut, one above and two below
void triLanesAvx2(TriIn* in, int kind);
void triLanesAvx512(TriIn* in, int kind);

}  // namespace mjb

#endif  // MJBUOY_TRIVEC_H_
