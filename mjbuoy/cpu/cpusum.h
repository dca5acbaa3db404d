// cpusum: the vertex sums of mjbuoy.sea.integration = vertex (docs/physics.md
// "Vertex integration"): at each wet vertex, and each dry one a cut
// triangle may reach, the components' weighted e^L summed once into the
// four quantities the lanes integrate (dynamic pressure over rho g, water
// velocity x, y, z), so a piece's integrals cost the same for any count of
// components. Plain data and entry points only
#ifndef MJBUOY_CPUSUM_H_
#define MJBUOY_CPUSUM_H_

namespace mjb {

struct HullCall;
struct HullScr;

// one vertex's sums: e = its e^L (waveint.h layout: per family f, Re at
// 2 f nw + j, Im at 2 f nw + nw + j, sorted order), n components, nf
// families, the weights of TriIn (trivec.h); out[4] = sum_f sum_j (wp
// Re, wux Re, wuy Re, wz Im)
struct SumIn {
  const double* e;
  int nw, n, nf;
  const double *wp[2], *wux[2], *wuy[2], *wz[2];
  double* out;
};

// (cpusum_avx2.cc, cpusum_avx512.cc: compiled for those instruction sets)
void sumLanesAvx2(const SumIn& in);
void sumLanesAvx512(const SumIn& in);

// the vertex sums of vertices [q0, q1) of c's hull into hs.VS (4 each),
// after the vertex stage of the whole hull: wet ones (h <= 0) from the
// vertex stage's e^L; dry ones with a wet neighbour (the dry corners of
// cut triangles) from e^L at their unclipped stretched height (the linear
// z' of the triangle through its cut points: docs/physics.md "Vertex
// integration"), up to k z' = kRMax for the largest k (waveker.h); the
// other dry ones NaN, which sends a cut triangle reaching one to the exact
// scalar path
void vertexSums(const HullCall& c, const HullScr& hs, int q0, int q1);

}  // namespace mjb

#endif  // MJBUOY_CPUSUM_H_
