// seavec: the vertex stage's surface search (Sea::solveMany) over lanes of
// 4 (AVX2 + FMA) or 8 (AVX-512F) points in lockstep, with sin and cos from
// one range reduction (sincoskern.h; libmvec's for huge phases) and
// libmvec's in the Newton steps; chosen at run time by vmath.h's level, Sea::solveMany's scalar loop
// stays the reference (tests/seavec_test.cc). Includes no inline code.
#ifndef MJBUOY_SEAVEC_H_
#define MJBUOY_SEAVEC_H_

#include "sea/wavenow.h"

namespace mjb {

// doubles of scratch per wave component the lane kernels need: phases at
// the lanes' labels and at the trial labels, sin and cos, 8 lanes
enum { kLaneTmp = 4 * 8 };

// one call of Sea::solveMany: n components (the first ng Gerstner), m
// points x, y; guesses a0, a1 become labels, z heights [m] and sc 2 per
// wave per point (point-major: sin, cos of each phase); tmp holds kLaneTmp
// per Gerstner component; fast: the Airy phases' sin and cos by
// sincoskern.h's sinCosFast where in its range (vertex integration mode)
struct LaneIn {
  const WaveNow* w;
  int n, ng, m;
  double level;
  const double *x, *y;
  double *a0, *a1, *z, *sc, *tmp;
  bool fast;
};

// the Newton steps taken in all, as Sea::solveMany (seavec_avx2.cc,
// seavec_avx512.cc: compiled for those instruction sets, called only when
// the cpu has them)
long solveLanesAvx2(const LaneIn& in);
long solveLanesAvx512(const LaneIn& in);

// one hull's vertices placed (cpuvert.cc placeVertices, in lanes: placekern.h):
// m body-frame vertices p (3 each) turned by the body's rotation R (row
// major) and shifted by t = body origin - COM [m] into rel (3 each,
// relative to the COM); X, Y = rel + com (world); the label search's
// guesses A0, A1 = X, Y + sum_s L[s] o[s] (the last steps' offsets, 2
// each, float: hull/hullstate.h HullState::off; an o[s] whose weight is 0 is not read)
struct PlaceIn {
  const double* p;
  int m;
  double R[9], t[3], com[3], L[3];
  const float* o[3];
  double *rel, *X, *Y, *A0, *A1;
};
// placed in whole chunks of lanes: returns how many (the rest: cpuvert.cc)
int placeLanesAvx2(const PlaceIn& in);
int placeLanesAvx512(const PlaceIn& in);

// after the label search (cpuvert.cc vertexOut, in lanes: placekern.h): per
// vertex of a hull its label (A0, A1) into lab (2 each), on a step's
// first call the offset label - (X, Y) into offNew (2 floats each; 0 if
// not finite), and the height above the surface h = rel z + zc - Z [m]
// (rel 3 each, relative to the COM, zc the COM's height)
struct HeightIn {
  int m;
  const double* rel;
  double zc;
  const double *X, *Y, *A0, *A1, *Z;
  int first;
  double* lab;
  float* offNew;
  double* h;
};
// done in whole chunks of lanes: returns how many (the rest: cpuvert.cc)
int heightLanesAvx2(const HeightIn& in);
int heightLanesAvx512(const HeightIn& in);

// the vertex stage's last step (cpuvert.cc packVertices, in lanes:
// placekern.h): m vertices' records for the triangle kernels (zipkern.h
// kRec doubles each, from rec): position relative to the COM (rel, 3
// each), height above the surface h, stretched height zs, label A0, A1
struct PackIn {
  int m;
  const double *rel, *h, *zs, *A0, *A1;
  double* rec;
};
// done in whole chunks of lanes: returns how many (the rest: cpuvert.cc)
int packLanesAvx2(const PackIn& in);
int packLanesAvx512(const PackIn& in);

// the vertex stage's e^L (cpuvert.cc wetVertices, in lanes: placekern.h)
// for a sea of few components: for each of m vertices (rel 3 each,
// relative to the COM; Z the surface height above them [m]) its stretched
// height zs (sea.cc stretch, with the COM height zc, the sea level and
// depth h, 0 for deep water) and per component j of n (wave numbers k
// [rad/m], sorted; perm the WaveNow index of each, null for the identity)
// and family f (1, or 2 at finite depth) e^(k zs) (e^(-k (zs + 2 h))) times
// the cos and sin of the component's phase (SC, 2 nw per vertex) into E
// (stride nw per vertex: re then im per family). Dry vertices get them
// too: nobody reads them (wetVertices). fast: e^(k zs) by expkern.h's
// expFast (vertex integration mode), else libmvec's
struct WetIn {
  int m;
  const double *rel, *Z, *SC;
  double zc, level, depth;
  int n, nw, finite, stride;
  const double* k;
  const int* perm;
  double *ZS, *E;
  bool fast;
};
// done in whole chunks of lanes: returns how many (the rest: cpuvert.cc)
int wetLanesAvx2(const WetIn& in);
int wetLanesAvx512(const WetIn& in);

}  // namespace mjb

#endif  // MJBUOY_SEAVEC_H_
