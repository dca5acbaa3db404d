// trisort: a hull's triangles sorted by how the surface cuts them, for the
// lane kernels of trivec.h (cpupass.cc passLanes). The vector sorts gather
// three heights per triangle in lanes and append each lane's triangle to
// its kind's list in order (AVX-512F compress stores; AVX2 a permutation
// per mask from a table), so the lists are the scalar rule's, in the same
// (ascending) order, and results keep their bits
// (tests/trivec_test.cc TriVec.SortsByKindAsTheScalarRule).
#ifndef MJBUOY_TRISORT_H_
#define MJBUOY_TRISORT_H_

namespace mjb {

// triangle kinds by their corners' heights h above the surface [m]
enum {
  kKindWet = 0,    // every corner at or below (h <= 0)
  kKindOneBelow,   // one corner at or below, two above (h > 0)
  kKindOneAbove,   // two at or below, one above
  kKindOther,      // none of these nor dry: a height not finite (scalar path)
  kNKind,
  kKindDry = -1    // every corner at or above (h >= 0): no wet part
};

// the triangles [t0, t0 + nt) of face (3 global vertex indices each),
// heights h per global vertex: list[c] gets those of kind c in ascending
// order, n[c] how many. Each list needs room for nt ints
struct TriSort {
  const int* face;
  const double* h;
  int t0, nt;
  int* list[kNKind];
  int n[kNKind];
};

// the scalar rule, and the tail of the vector sorts (trisort.cc)
int triKind(double h0, double h1, double h2);
void sortKinds(TriSort* in, int k0);  // triangles [k0, t0 + nt) appended

// (trisort_avx2.cc, trisort_avx512.cc: compiled for those instruction
// sets, called only when the cpu has them)
void sortKindsAvx2(TriSort* in);
void sortKindsAvx512(TriSort* in);

}  // namespace mjb

#endif  // MJBUOY_TRISORT_H_
