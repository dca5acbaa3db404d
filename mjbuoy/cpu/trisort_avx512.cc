// trisort over 16 triangles at a time, AVX-512F (compiled with -mavx512f;
// called only when the cpu has it, vmath.cc)
// GCC 12 takes the headers' undefined pass-through operands (gathers,
// shifts, extracts) for uninitialised variables: a false warning
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>

#include "cpu/trisort.h"

namespace mjb {
namespace {

// per corner c of triangles in lanes: heights h <= 0 (le), > 0 (gt), >= 0
// (ge) as lane masks; idx the corner's global vertex indices
void corner(const double* h, __m512i idx, __mmask16* le, __mmask16* gt, __mmask16* ge) {
  const __m512d z = _mm512_setzero_pd();
  const __m512d a = _mm512_i32gather_pd(_mm512_castsi512_si256(idx), h, 8);
  const __m512d b = _mm512_i32gather_pd(_mm512_extracti64x4_epi64(idx, 1), h, 8);
  // (ordered compares: a NaN height is in none of the three)
  *le = __mmask16(_mm512_cmp_pd_mask(a, z, _CMP_LE_OQ) | _mm512_cmp_pd_mask(b, z, _CMP_LE_OQ) << 8);
  *gt = __mmask16(_mm512_cmp_pd_mask(a, z, _CMP_GT_OQ) | _mm512_cmp_pd_mask(b, z, _CMP_GT_OQ) << 8);
  *ge = __mmask16(_mm512_cmp_pd_mask(a, z, _CMP_GE_OQ) | _mm512_cmp_pd_mask(b, z, _CMP_GE_OQ) << 8);
}

}  // namespace

void sortKindsAvx512(TriSort* in) {
  const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const __m512i tri3 = _mm512_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21, 24, 27, 30, 33, 36, 39, 42, 45);
  // lanes j whose corner c, at 3 j + c, lies in the last 32 (>= 32)
  unsigned hiMask[3];
  for (int c = 0; c < 3; c++) {
    hiMask[c] = 0;
    for (int j = 0; j < 16; j++) hiMask[c] |= unsigned(3 * j + c >= 32) << j;
  }
  const int end = in->t0 + in->nt;
  int k = in->t0;
  // (counts and lists in locals: a store through a list may alias in->n)
  int n[kNKind] = {in->n[0], in->n[1], in->n[2], in->n[3]};
  int* const list[kNKind] = {in->list[0], in->list[1], in->list[2], in->list[3]};
  // full groups only: a store of 16 at a list's count n <= k - t0 ends
  // within its nt ints
  for (; k + 16 <= end; k += 16) {
    const __m512i kv = _mm512_add_epi32(_mm512_set1_epi32(k), lane);
    // the 16 triangles' 48 corner indices, loaded whole and split by
    // corner (two-source permutes: a gather is slow on Zen 4)
    const int* f = in->face + 3 * k;
    const __m512i a = _mm512_loadu_si512(f), b = _mm512_loadu_si512(f + 16),
                  c2 = _mm512_loadu_si512(f + 32);
    unsigned le[3], gt[3], ge[3];
    for (int c = 0; c < 3; c++) {
      // corner c of triangle j is f[3 j + c]: lanes 0..15 of a|b (index
      // < 32), then of b|c2 for the rest (index - 16)
      const __m512i ab = _mm512_permutex2var_epi32(a, _mm512_add_epi32(tri3, _mm512_set1_epi32(c)), b);
      const __m512i bc = _mm512_permutex2var_epi32(b, _mm512_add_epi32(tri3, _mm512_set1_epi32(c - 16)), c2);
      const __m512i idx = _mm512_mask_blend_epi32(__mmask16(hiMask[c]), ab, bc);
      __mmask16 l, g, e;
      corner(in->h, idx, &l, &g, &e);
      le[c] = l, gt[c] = g, ge[c] = e;
    }
    // triKind's rule on masks: each finite height is in le or gt, so with
    // all three finite "one le" is down 1 up 2 and "two le" down 2 up 1
    const unsigned dry = ge[0] & ge[1] & ge[2];
    const unsigned fin = (le[0] | gt[0]) & (le[1] | gt[1]) & (le[2] | gt[2]);
    const unsigned all = le[0] & le[1] & le[2];
    const unsigned odd = le[0] ^ le[1] ^ le[2];  // one or three
    const unsigned two = ((le[0] & le[1]) | (le[1] & le[2]) | (le[0] & le[2])) & ~all;
    unsigned m[kNKind];
    m[kKindWet] = all & ~dry;  // (all heights 0 is dry)
    m[kKindOneBelow] = fin & ~dry & odd & ~all;
    m[kKindOneAbove] = fin & ~dry & two;
    m[kKindOther] = 0xffffu & ~dry & ~m[0] & ~m[1] & ~m[2];
    // compressed in a register and stored whole (a compress straight to
    // memory is microcoded and slow on AMD Zen 4); the count advances by
    // the mask's bits, so what lies past it is overwritten or never read
    for (int c = 0; c < kNKind; c++) {
      _mm512_storeu_si512(list[c] + n[c], _mm512_maskz_compress_epi32(__mmask16(m[c]), kv));
      n[c] += __builtin_popcount(m[c]);
    }
  }
  for (int c = 0; c < kNKind; c++) in->n[c] = n[c];
  sortKinds(in, k);
}

}  // namespace mjb
