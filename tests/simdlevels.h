// test helper: the vector levels (mjbuoy/util/vmath.h) this cpu has, for tests
// that check each vector path against the scalar one (seavec_test.cc,
// trivec_test.cc)
#ifndef MJBUOY_TESTS_SIMDLEVELS_H_
#define MJBUOY_TESTS_SIMDLEVELS_H_

#include <cstdio>
#include <vector>

#include "util/vmath.h"

namespace mjbt {

// the levels above scalar that this cpu has; a missing one is printed,
// prefixed by tag, as not checked with the reason
inline std::vector<int> vectorLevels(const char* tag) {
  const int prev = mjb::simdLevel(), best = mjb::simdSet(mjb::kSimdAvx512);
  mjb::simdSet(prev);
  std::vector<int> l;
  for (int level = mjb::kSimdAvx2; level <= mjb::kSimdAvx512; level++) {
    if (level <= best) {
      l.push_back(level);
    } else {
      std::printf("[%s] %s path not checked: this cpu lacks %s\n", tag, mjb::simdName(level),
                  level == mjb::kSimdAvx2 ? "AVX2 with FMA" : "AVX-512F");
    }
  }
  return l;
}

}  // namespace mjbt

#endif  // MJBUOY_TESTS_SIMDLEVELS_H_
