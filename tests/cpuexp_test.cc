// the cpu backend's fused e^L kernels (mjbuoy/cpu/cpuexp.h) against the
// list path they replace (cpuhull.h vertexExponents, vmath.h vExp /
// vExpFast, vertexE) on every vector level the cpu has, and against e^L
// in long double (waveint.h: L = k z' + i theta, at finite depth also
// -k (z' + 2 h) + i theta; docs/physics.md "Vertex integration")
#include <cfloat>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "cpu/cpuexp.h"
#include "cpu/cpuhull.h"
#include "simdlevels.h"
#include "util/vmath.h"

namespace {

using mjbt::vectorLevels;

// a sorted table of n components, k from 0.05 to 2 rad/m; perm a
// reversal of pairs (not the identity) unless ident
mjb::WaveTab table(int n, bool ident, double depth) {
  mjb::WaveTab t;
  t.n = n;
  t.finite = depth > 0;
  t.depth = depth;
  t.ident = ident;
  for (int j = 0; j < n; j++) {
    t.k.push_back(0.05 + 1.95 * j / (n - 1));
    t.perm.push_back(ident ? j : n - 1 - j);
  }
  return t;
}

// the list path's e^L of one vertex (cpuvert.cc vertexWaves on one vertex)
std::vector<double> listE(const mjb::WaveTab& t, double zs, const double* sc, bool fast) {
  const int nf = t.finite ? 2 : 1;
  std::vector<double> a(nf * t.n), e(2 * nf * t.n);
  mjb::vertexExponents(t, zs, a.data());
  (fast ? mjb::vExpFast : mjb::vExp)(nf * t.n, a.data(), a.data());
  mjb::vertexE(t, t.n, a.data(), sc, e.data());
  return e;
}

// each vector level, exact and fast exp, permuted and identity, deep and
// finite depth, 13 and 64 components (13: a tail of 5 on AVX2 and AVX-512),
// heights from the bed to 1 m above the surface: the list path's bits, and
// within 8 ulp (exact: libmvec's 4 ulp exp times one product) or 2e-10
// (fast: expkern.h's 1e-10), plus |a| eps from rounding a, of e^L in long
// double
TEST(CpuExp, FusedKernelGivesTheListsBits) {
  const int prev = mjb::simdLevel();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  long checked = 0;
  for (int level : vectorLevels("cpuexp")) {
    ASSERT_EQ(mjb::simdSet(level), level);
    const mjb::ELanesFn fn = mjb::eLanesFn();
    ASSERT_NE(fn, nullptr);
    for (int n : {13, 64}) {
      for (double depth : {0.0, 8.0}) {
        for (bool ident : {false, true}) {
          const mjb::WaveTab t = table(n, ident, depth);
          const int nf = t.finite ? 2 : 1;
          for (bool fast : {false, true}) {
            for (double zs : {0.0, -0.3, -3.7, 1.0, depth > 0 ? -depth : -30.0}) {
              std::vector<double> sc(2 * n);
              for (int i = 0; i < n; i++) {
                const double th = 3.2 * u(rng);
                sc[2 * i] = std::sin(th);
                sc[2 * i + 1] = std::cos(th);
              }
              const std::vector<double> ref = listE(t, zs, sc.data(), fast);
              // a guard past the end: the tail writes nothing beyond e's 2 nf n
              std::vector<double> e(2 * nf * n + 8, 7.5);
              fn(mjb::eIn(t, n, fast), zs, sc.data(), e.data());
              for (size_t i = 0; i < ref.size(); i++) {
                ASSERT_EQ(std::memcmp(&ref[i], &e[i], sizeof(double)), 0)
                    << mjb::simdName(level) << " n " << n << " depth " << depth << " ident "
                    << ident << " fast " << fast << " zs " << zs << " i " << i;
              }
              for (size_t i = ref.size(); i < e.size(); i++) ASSERT_EQ(e[i], 7.5);
              for (int f = 0; f < nf; f++) {
                for (int j = 0; j < n; j++) {
                  const long double kk = t.k[j], a = f == 0 ? kk * zs : -kk * (zs + 2.0L * depth);
                  const int p = t.perm[j];
                  const long double ea = std::exp(a);
                  const long double re = ea * sc[2 * p + 1], im = ea * sc[2 * p];
                  // (a's own rounding, |a| eps / 2 relative, carries into e^a)
                  const double ra =
                      (fast ? 2e-10 : 8 * DBL_EPSILON) + std::fabs(double(a)) * DBL_EPSILON;
                  const double tol = ra * double(ea);
                  EXPECT_NEAR(e[2 * f * n + j], double(re), tol);
                  EXPECT_NEAR(e[2 * f * n + n + j], double(im), tol);
                  checked++;
                }
              }
            }
          }
        }
      }
    }
  }
  mjb::simdSet(prev);
  if (checked == 0) std::printf("[cpuexp] no vector level: the list path alone runs\n");
}

// the scalar level keeps the list path: no fused kernel
TEST(CpuExp, ScalarLevelKeepsTheList) {
  const int prev = mjb::simdLevel();
  ASSERT_EQ(mjb::simdSet(mjb::kSimdScalar), mjb::kSimdScalar);
  EXPECT_EQ(mjb::eLanesFn(), nullptr);
  mjb::simdSet(prev);
}

}  // namespace
