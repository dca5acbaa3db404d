// trisort over 8 triangles at a time, AVX2 (compiled with -mavx2; called
// only when the cpu has it, vmath.cc). AVX2 has no compress store: each
// kind's lanes are moved to the front by a permutation looked up by their
// mask, and all 8 stored, the count advancing by the mask's bits (what
// lies past it is overwritten by the next store or never read)
// GCC 12 takes the headers' undefined pass-through operands (gathers,
// shifts, extracts) for uninitialised variables: a false warning
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>

#include <array>
#include <cstdint>

#include "cpu/trisort.h"

namespace mjb {
namespace {

// per 8-lane mask, the lanes set in ascending order then the rest, one
// byte each (the rest's order does not matter)
constexpr std::array<uint64_t, 256> packTable() {
  std::array<uint64_t, 256> t{};
  for (int m = 0; m < 256; m++) {
    uint64_t v = 0;
    int n = 0;
    for (int i = 0; i < 8; i++) {
      if (m >> i & 1) v |= uint64_t(i) << (8 * n++);
    }
    t[m] = v;
  }
  return t;
}
constexpr std::array<uint64_t, 256> kPack = packTable();

// the masks of 4 doubles as 4 bits
unsigned bits(__m256d x) { return unsigned(_mm256_movemask_pd(x)); }

// per corner of triangles in lanes: heights h <= 0 (le), > 0 (gt), >= 0
// (ge) as 8-bit lane masks; idx the corner's global vertex indices
void corner(const double* h, __m256i idx, unsigned* le, unsigned* gt, unsigned* ge) {
  const __m256d z = _mm256_setzero_pd();
  const __m256d a = _mm256_i32gather_pd(h, _mm256_castsi256_si128(idx), 8);
  const __m256d b = _mm256_i32gather_pd(h, _mm256_extracti128_si256(idx, 1), 8);
  // (ordered compares: a NaN height is in none of the three)
  *le = bits(_mm256_cmp_pd(a, z, _CMP_LE_OQ)) | bits(_mm256_cmp_pd(b, z, _CMP_LE_OQ)) << 4;
  *gt = bits(_mm256_cmp_pd(a, z, _CMP_GT_OQ)) | bits(_mm256_cmp_pd(b, z, _CMP_GT_OQ)) << 4;
  *ge = bits(_mm256_cmp_pd(a, z, _CMP_GE_OQ)) | bits(_mm256_cmp_pd(b, z, _CMP_GE_OQ)) << 4;
}

}  // namespace

void sortKindsAvx2(TriSort* in) {
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i tri3 = _mm256_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21);
  // per corner c and load l: all ones in lanes j whose 3 j + c is in load l
  __m256i from[3][3];
  for (int c = 0; c < 3; c++) {
    for (int l = 0; l < 3; l++) {
      alignas(32) int m[8];
      for (int j = 0; j < 8; j++) m[j] = (3 * j + c) >> 3 == l ? -1 : 0;
      from[c][l] = _mm256_load_si256((const __m256i*)m);
    }
  }
  const int end = in->t0 + in->nt;
  int k = in->t0;
  // (counts and lists in locals: a store through a list may alias in->n)
  int n[kNKind] = {in->n[0], in->n[1], in->n[2], in->n[3]};
  int* const list[kNKind] = {in->list[0], in->list[1], in->list[2], in->list[3]};
  // full groups only: a store of 8 at a list's count n <= k - t0 ends
  // within its nt ints
  for (; k + 8 <= end; k += 8) {
    const __m256i kv = _mm256_add_epi32(_mm256_set1_epi32(k), lane);
    // the 8 triangles' 24 corner indices, loaded whole and split by corner:
    // corner c of triangle j is f[3 j + c], in load 3 j + c >> 3 at lane
    // 3 j + c & 7; each load permuted to those lanes, then blended
    const int* f = in->face + 3 * k;
    const __m256i ld[3] = {_mm256_loadu_si256((const __m256i*)f),
                           _mm256_loadu_si256((const __m256i*)(f + 8)),
                           _mm256_loadu_si256((const __m256i*)(f + 16))};
    unsigned le[3], gt[3], ge[3];
    for (int c = 0; c < 3; c++) {
      const __m256i p = _mm256_add_epi32(tri3, _mm256_set1_epi32(c));  // permutes use p & 7
      __m256i idx = _mm256_permutevar8x32_epi32(ld[0], p);
      idx = _mm256_blendv_epi8(idx, _mm256_permutevar8x32_epi32(ld[1], p), from[c][1]);
      idx = _mm256_blendv_epi8(idx, _mm256_permutevar8x32_epi32(ld[2], p), from[c][2]);
      corner(in->h, idx, &le[c], &gt[c], &ge[c]);
    }
    // triKind's rule on masks, as trisort_avx512.cc
    const unsigned dry = ge[0] & ge[1] & ge[2];
    const unsigned fin = (le[0] | gt[0]) & (le[1] | gt[1]) & (le[2] | gt[2]);
    const unsigned all = le[0] & le[1] & le[2];
    const unsigned odd = le[0] ^ le[1] ^ le[2];
    const unsigned two = ((le[0] & le[1]) | (le[1] & le[2]) | (le[0] & le[2])) & ~all;
    unsigned m[kNKind];
    m[kKindWet] = all & ~dry;
    m[kKindOneBelow] = fin & ~dry & odd & ~all;
    m[kKindOneAbove] = fin & ~dry & two;
    m[kKindOther] = 0xffu & ~dry & ~m[0] & ~m[1] & ~m[2];
    for (int c = 0; c < kNKind; c++) {
      const __m256i perm = _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i*)&kPack[m[c]]));
      _mm256_storeu_si256((__m256i*)(list[c] + n[c]), _mm256_permutevar8x32_epi32(kv, perm));
      n[c] += __builtin_popcount(m[c]);
    }
  }
  for (int c = 0; c < kNKind; c++) in->n[c] = n[c];
  sortKinds(in, k);
}

}  // namespace mjb
