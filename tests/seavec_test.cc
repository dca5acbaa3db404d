// the vertex stage's surface search in lanes (AVX2, AVX-512; seavec.h)
// against the scalar reference (Sea::solveMany's loop) and against the
// Gerstner map itself, on every instruction set this cpu has; the whole
// cpu backend on each of them repeats its bits across runs and threads
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "sea/sea.h"
#include "sea/seavec.h"
#include "simdlevels.h"
#include "util/expkern.h"
#include "util/sincoskern.h"
#include "testutil.h"
#include "util/vmath.h"

namespace mjbt {
namespace {

const double kEps = DBL_EPSILON;

// a sea of ng Gerstner and na Airy components, steepness scaled so that
// sum Q k A (the fold measure, Sea::fold) is fold
mjb::Sea makeSea(int ng, int na, double fold) {
  mjb::Sea s;
  for (int i = 0; i < ng + na; i++) {
    mjb::Wave w{};
    w.amp = 0.4 / (1 + i);
    w.len = 14.0 / (1 + 0.6 * i);
    w.dir = -70 + 37 * i;
    w.phase = 23 * i;
    w.steep = 1;
    w.kind = i < ng ? 0 : 1;
    s.waves.push_back(w);
  }
  s.level = 0.3;
  s.derive();
  const double f = s.fold();
  for (mjb::Wave& w : s.waves) w.steep = f > 0 ? w.steep * fold / f : 0;
  s.derive();
  return s;
}

// the points of a box hull's vertex grid (4 m x 1 m x 0.5 m, 9 x 5 x 3)
// under n random poses within 60 m of the origin: world x, y
void hullPoints(int n, unsigned seed, std::vector<double>* x, std::vector<double>* y) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int p = 0; p < n; p++) {
    double q[4] = {u(rng), u(rng), u(rng), u(rng)}, R[9];
    mju_normalize4(q);
    mju_quat2Mat(R, q);
    const double t[2] = {60 * u(rng), 60 * u(rng)};
    for (int i = 0; i < 9; i++) {
      for (int j = 0; j < 5; j++) {
        for (int k = 0; k < 3; k++) {
          const double v[3] = {-2 + 0.5 * i, -0.5 + 0.25 * j, -0.25 + 0.25 * k};
          x->push_back(R[0] * v[0] + R[1] * v[1] + R[2] * v[2] + t[0]);
          y->push_back(R[3] * v[0] + R[4] * v[1] + R[5] * v[2] + t[1]);
        }
      }
    }
  }
}

// one solveMany at the current simd level: labels, heights, phases, steps
struct Out {
  std::vector<double> a0, a1, z, sc;
  long nit = 0;
};
Out solveAll(const mjb::Sea& sea, double t, const std::vector<double>& x,
             const std::vector<double>& y, double guess) {
  const int n = sea.waves.size(), m = x.size();
  std::vector<mjb::WaveNow> w(n);
  sea.now(t, w.data());
  Out o;
  o.a0 = x;
  o.a1 = y;
  // guesses at the position moved by guess [m] (the label is up to
  // sum Q A from the position)
  for (int i = 0; i < m; i++) {
    o.a0[i] += guess * std::cos(0.7 * i);
    o.a1[i] += guess * std::sin(1.3 * i);
  }
  o.z.resize(m);
  o.sc.resize(2 * n * m);
  std::vector<double> tmp((2 + mjb::kLaneTmp) * n);
  o.nit = sea.solveMany(w.data(), m, x.data(), y.data(), o.a0.data(), o.a1.data(), o.z.data(),
                        o.sc.data(), tmp.data());
  return o;
}

// Both paths run Newton to |F| <= 1e-12 m on F(a) = a - sum Q A D
// sin(theta(a)) - x (sea.cc), whose Jacobian J = I - sum Q k A cos D D^T has
// |J^-1| <= 1 / (1 - sum Q k A): each label is within 1e-12 / (1 - fold) of
// the root, so the two within tolA = 2e-12 / (1 - fold), plus the round-off
// of a label itself where a search stops for lack of progress (16 ulp of
// |a|). A height z = level + sum A cos(theta) moves by sum A k tolA with
// the labels; each cosine is within 4 ulp (libmvec, glibc manual "Errors in
// Math Functions"; the lanes' own, sincoskern.h, within 3) plus 1 ulp for
// glibc's scalar one, of a phase rounded
// to about 4 ulp of |theta|: A (5 eps + 4 eps |theta|) per component
// far [m] moves the points along x
void checkSea(const mjb::Sea& sea, double guess, const char* what, double far = 0) {
  const double t = 3.7;
  std::vector<double> x, y;
  hullPoints(7, 11, &x, &y);  // 945 points: lanes of 4 and 8 with a tail
  for (double& v : x) v += far;
  const int n = sea.waves.size(), m = x.size();
  std::vector<mjb::WaveNow> w(n);
  sea.now(t, w.data());
  const int prev = mjb::simdLevel();
  mjb::simdSet(mjb::kSimdScalar);
  const Out ref = solveAll(sea, t, x, y, guess);
  const double fold = sea.fold();
  double sumAk = 0;
  for (const mjb::Wave& wv : sea.waves) sumAk += std::fabs(wv.amp) * wv.k;
  const double tolA = 2e-12 / (1 - fold);
  for (int level : vectorLevels("seavec")) {
    mjb::simdSet(level);
    const Out o = solveAll(sea, t, x, y, guess);
    double worstA = 0, worstZ = 0, worstF = 0;
    for (int i = 0; i < m; i++) {
      const double ta = tolA + 16 * kEps * (std::fabs(x[i]) + std::fabs(y[i]) + 1);
      EXPECT_NEAR(o.a0[i], ref.a0[i], ta) << what << " " << mjb::simdName(level) << " " << i;
      EXPECT_NEAR(o.a1[i], ref.a1[i], ta) << what << " " << mjb::simdName(level) << " " << i;
      // the Gerstner map in long double at the lanes' label: x within the
      // solver's tolerance, and the height its sum, as sea.h defines it
      // (phases after Newton steps come from the guess's by angle
      // addition: each step adds a few ulp, k2 per unit k after up to 8)
      const double k2 = 32 * kEps * (std::fabs(o.a0[i]) + std::fabs(o.a1[i]) + 1);
      long double f0 = o.a0[i] - (long double)x[i], f1 = o.a1[i] - (long double)y[i];
      long double zr = sea.level, tz = 0;
      for (int j = 0; j < n; j++) {
        const bool ger = j < sea.ng;
        const long double px = ger ? o.a0[i] : x[i], py = ger ? o.a1[i] : y[i];
        const long double th = w[j].k * (w[j].dx * px + w[j].dy * py) - w[j].wt + w[j].ph;
        if (ger) {
          f0 -= (long double)w[j].qx * sinl(th);
          f1 -= (long double)w[j].qy * sinl(th);
        }
        // the phase's terms' size: each of its 5 roundings within half an
        // ulp of it, so theta within 4 eps M
        const double M = w[j].k * (std::fabs(w[j].dx * (double)px) + std::fabs(w[j].dy * (double)py)) +
                         std::fabs(w[j].wt) + std::fabs(w[j].ph);
        const double ts = (5 + 4 * M) * kEps;
        zr += w[j].amp * cosl(th);
        tz += std::fabs(w[j].amp) * ts;
        // the phases handed on (velocity, pressure) are those of the label
        EXPECT_NEAR(o.sc[2 * n * i + 2 * j], (double)sinl(th), ts + k2 * std::fabs(w[j].k));
        EXPECT_NEAR(o.sc[2 * n * i + 2 * j + 1], (double)cosl(th), ts + k2 * std::fabs(w[j].k));
      }
      const double F = std::sqrt((double)(f0 * f0 + f1 * f1));
      EXPECT_LE(F, 1e-12 + 16 * kEps * (std::fabs(x[i]) + std::fabs(y[i]) + 1)) << what << " " << i;
      EXPECT_NEAR(o.z[i], (double)zr, tz) << what << " " << mjb::simdName(level) << " " << i;
      EXPECT_NEAR(o.z[i], ref.z[i], sumAk * tolA + 2 * tz) << what << " " << i;
      worstA = std::fmax(worstA, std::fmax(std::fabs(o.a0[i] - ref.a0[i]),
                                           std::fabs(o.a1[i] - ref.a1[i])));
      worstZ = std::fmax(worstZ, std::fabs(o.z[i] - ref.z[i]));
      worstF = std::fmax(worstF, F);
    }
    // the same steps: counts differ only where a residual lands within
    // round-off of the stopping test
    EXPECT_NEAR(o.nit, ref.nit, 0.01 * ref.nit + 1) << what << " " << mjb::simdName(level);
    // repeated: the same bits
    const Out again = solveAll(sea, t, x, y, guess);
    EXPECT_TRUE(again.a0 == o.a0 && again.a1 == o.a1 && again.z == o.z && again.sc == o.sc)
        << what << " " << mjb::simdName(level);
    std::printf("[seavec] %s %s: labels within %.2g m of scalar (bound %.2g), heights %.2g m, "
                "|F| <= %.2g m; Newton steps %ld (scalar %ld) for %d points\n",
                what, mjb::simdName(level), worstA, tolA, worstZ, worstF, o.nit, ref.nit, m);
  }
  mjb::simdSet(prev);
}

// the lanes' sine and cosine (sincoskern.h: Cody-Waite reduction by pi/2
// in three parts, Taylor series on [-pi/4, pi/4]) against long double's
// sinl and cosl: within 3 ulp of the result (or of 2^-53 where it is below
// 1/2, the size of r's own rounding; r's rounding, 1/2 ulp, and the
// series' rounding, at most 2 ulp, measured 2.0) for phases up to 2^20 pi/2, both
// signs, next to multiples of pi/2 and far from them; refused (false)
// beyond, for infinity and NaN. Compiled here without AVX and FMA, two
// lanes, so each product and sum rounds apart: the bound holds without the
// FMAs the vector builds may contract to
TEST(SeaVec, SinCosLanesWithinThreeUlp) {
  typedef double V __attribute__((vector_size(16)));
  typedef long I __attribute__((vector_size(16)));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> xs;
  for (int i = 0; i < 200000; i++) xs.push_back(u(rng) * std::pow(10.0, 6 * std::fabs(u(rng))));
  const long double hp = 1.570796326794896619231321691639751442L;
  for (long m : {1L, 2L, 3L, 4L, 5L, 100L, 1001L, 65536L, 1000003L}) {
    for (double d : {0.0, 1e-12, -1e-9, 1e-6, 0.3, -0.78, 0.785}) {
      xs.push_back(double(m * hp) + d);
      xs.push_back(-double(m * hp) + d);
    }
  }
  auto ulp = [](double v) {
    const double a = std::fmax(std::fabs(v), 0.5);
    return std::nextafter(a, INFINITY) - a;
  };
  double worst = 0;
  int n = 0;
  for (size_t i = 0; i + 1 < xs.size(); i += 2) {
    const V x = {xs[i], xs[i + 1]};
    V s, c;
    const bool inr = std::fabs(x[0]) < 1.6e6 && std::fabs(x[1]) < 1.6e6;
    const bool got = mjb::sinCosLanes<V, I>(x, &s, &c);
    if (!inr) continue;
    ASSERT_TRUE(got) << x[0] << " " << x[1];
    for (int l = 0; l < 2; l++) {
      const double rs = double(sinl((long double)x[l])), rc = double(cosl((long double)x[l]));
      worst = std::fmax(worst, std::fabs(s[l] - rs) / ulp(rs));
      worst = std::fmax(worst, std::fabs(c[l] - rc) / ulp(rc));
      EXPECT_LE(std::fabs(s[l] - rs), 3 * ulp(rs)) << x[l];
      EXPECT_LE(std::fabs(c[l] - rc), 3 * ulp(rc)) << x[l];
      n++;
    }
  }
  std::printf("[seavec] sinCosLanes: %d phases, worst %.2f ulp\n", n, worst);
  V s, c;
  EXPECT_FALSE((mjb::sinCosLanes<V, I>(V{1, 1.7e6}, &s, &c)));
  EXPECT_FALSE((mjb::sinCosLanes<V, I>(V{1, INFINITY}, &s, &c)));
  EXPECT_FALSE((mjb::sinCosLanes<V, I>(V{NAN, 1}, &s, &c)));
}

// the vertex integration mode's sine and cosine (sincoskern.h sinCosFast:
// two-part Cody-Waite reduction, near-minimax polynomials) against long
// double's sinl and cosl: within its stated kSinCosFastEps absolute over
// its whole range |x| < 2^19 (the bound airyPhaseBound checks), both
// signs: random phases of every size, next to multiples of pi/2 (the
// quadrant boundaries, where r is near 0 and near +-pi/4) up to the
// largest below 2^19, and the range's edges. Two lanes without FMA here,
// as SinCosLanesWithinThreeUlp; the vector levels through solveMany below
TEST(SeaVec, SinCosFastWithinEps) {
  typedef double V __attribute__((vector_size(16)));
  typedef long I __attribute__((vector_size(16)));
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> xs;
  const double top = std::nextafter(0x1p19, 0);
  for (int i = 0; i < 400000; i++) xs.push_back(u(rng) * std::pow(2.0, 19 * std::fabs(u(rng))));
  const long double hp = 1.570796326794896619231321691639751442L;
  const long mmax = long(0x1p19 / hp);  // the last multiple of pi/2 below 2^19
  for (long m : {0L, 1L, 2L, 3L, 4L, 5L, 7L, 100L, 1001L, 65536L, 200003L, mmax - 1, mmax}) {
    for (double d : {0.0, 1e-12, -1e-9, 1e-6, 0.3, -0.78, 0.785, -0.7853981, 0.7853982}) {
      const double x = double(m * hp) + d;
      if (std::fabs(x) < 0x1p19) xs.push_back(x), xs.push_back(-x);
    }
  }
  for (double x : {top, -top, top - 0.5, -(top - 0.5), 0.0, -0.0, 1e-300, -5e-324}) xs.push_back(x);
  if (xs.size() % 2) xs.push_back(1);
  double worst = 0;
  for (size_t i = 0; i < xs.size(); i += 2) {
    const V x = {xs[i], xs[i + 1]};
    V s, c;
    mjb::sinCosFast<V, I>(x, &s, &c);
    for (int l = 0; l < 2; l++) {
      const long double rs = sinl((long double)x[l]), rc = cosl((long double)x[l]);
      const double es = double(std::fabs(s[l] - rs)), ec = double(std::fabs(c[l] - rc));
      worst = std::fmax(worst, std::fmax(es, ec));
      EXPECT_LE(es, mjb::kSinCosFastEps) << x[l];
      EXPECT_LE(ec, mjb::kSinCosFastEps) << x[l];
    }
  }
  std::printf("[seavec] sinCosFast: %zu phases, worst %.3g (eps %.3g)\n", xs.size(), worst,
              mjb::kSinCosFastEps);
}

// Sea::solveMany's fast mode (vertex integration) on every vector level:
// each Airy component's sin and cos within kSinCosFastEps of sinl and cosl
// of the long double phase, plus the phase's own rounding (checkSea's ts);
// the height within sum A (eps + ts); the Gerstner labels and their
// phases as the exact mode's (the fast kernel serves only the Airy
// groups). Phases near the origin and 5e4 m out (up to 8e4 rad: bounded
// below 2^19, the fast kernel's range), 5e5 m (beyond: the exact kernels)
void checkFast(const mjb::Sea& sea, double far, const char* what) {
  const double t = 3.7;
  std::vector<double> x, y;
  hullPoints(7, 13, &x, &y);
  for (double& v : x) v += far;
  const int n = sea.waves.size(), m = x.size();
  std::vector<mjb::WaveNow> w(n);
  sea.now(t, w.data());
  std::vector<double> tmp((2 + mjb::kLaneTmp) * n);
  const int prev = mjb::simdLevel();
  for (int level : vectorLevels("seavec")) {
    mjb::simdSet(level);
    Out ex, o;
    for (Out* p : {&ex, &o}) {
      p->a0 = x;
      p->a1 = y;
      p->z.resize(m);
      p->sc.resize(2 * n * m);
      p->nit = sea.solveMany(w.data(), m, x.data(), y.data(), p->a0.data(), p->a1.data(),
                             p->z.data(), p->sc.data(), tmp.data(), p == &o);
    }
    double worst = 0;
    for (int i = 0; i < m; i++) {
      ASSERT_EQ(o.a0[i], ex.a0[i]) << what;
      ASSERT_EQ(o.a1[i], ex.a1[i]) << what;
      long double zr = sea.level;
      double tz = 0;
      for (int j = 0; j < n; j++) {
        const bool ger = j < sea.ng;
        const long double px = ger ? o.a0[i] : x[i], py = ger ? o.a1[i] : y[i];
        const long double th = w[j].k * (w[j].dx * px + w[j].dy * py) - w[j].wt + w[j].ph;
        const double M = w[j].k * (std::fabs(w[j].dx * (double)px) +
                                   std::fabs(w[j].dy * (double)py)) +
                         std::fabs(w[j].wt) + std::fabs(w[j].ph);
        const double ts = (5 + 4 * M) * kEps + mjb::kSinCosFastEps;
        zr += w[j].amp * cosl(th);
        tz += std::fabs(w[j].amp) * ts;
        const double es = std::fabs(o.sc[2 * n * i + 2 * j] - (double)sinl(th));
        const double ec = std::fabs(o.sc[2 * n * i + 2 * j + 1] - (double)cosl(th));
        if (ger) {
          EXPECT_EQ(o.sc[2 * n * i + 2 * j], ex.sc[2 * n * i + 2 * j]) << what;
          EXPECT_EQ(o.sc[2 * n * i + 2 * j + 1], ex.sc[2 * n * i + 2 * j + 1]) << what;
          continue;
        }
        EXPECT_LE(es, ts) << what << " " << mjb::simdName(level) << " " << i << " " << j;
        EXPECT_LE(ec, ts) << what << " " << mjb::simdName(level) << " " << i << " " << j;
        worst = std::fmax(worst, std::fmax(es, ec));
      }
      EXPECT_NEAR(o.z[i], (double)zr, tz) << what << " " << mjb::simdName(level) << " " << i;
    }
    std::printf("[seavec] fast %s %s: Airy sin, cos within %.3g of long double (eps %.3g)\n",
                what, mjb::simdName(level), worst, mjb::kSinCosFastEps);
  }
  mjb::simdSet(prev);
}

TEST(SeaVec, FastPhasesWithinEpsOnEveryLevel) {
  checkFast(makeSea(0, 5, 0.0), 0, "airy");
  checkFast(makeSea(0, 5, 0.0), 5e4, "airy 5e4");
  checkFast(makeSea(0, 5, 0.0), 5e5, "airy 5e5");
  checkFast(makeSea(2, 3, 0.35), 0, "gerstner and airy");
}

// vmath.h's vExpFast (expkern.h: 2^n times a near-minimax polynomial) on
// every vector level against long double's expl: within kExpFastEps
// relative over its range [-708, 709]: random arguments over all of it and
// densely over [-40, 4] (the vertices' k z'), next to the reduction's
// boundaries (n ln2 + ln2 / 2, where r changes sign) and at the range's
// edges; 0 below, infinity above, NaN kept; a count of 11 (a tail past the
// lanes). Input aliased to the output as well
TEST(SeaVec, ExpFastWithinEps) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> xs;
  for (int i = 0; i < 100000; i++) xs.push_back(-708 + 1417 * u(rng));
  for (int i = 0; i < 100000; i++) xs.push_back(-40 + 44 * u(rng));
  const long double ln2 = 0.693147180559945309417232121458176568L;
  for (int m = -1021; m <= 1022; m += 7) {
    for (double d : {-1e-9, 0.0, 1e-9}) xs.push_back(double((m + 0.5L) * ln2) + d);
  }
  for (double x : {-708.0, 709.0, 0.0, -0.0, 1e-300, -1e-17, 4.0, -40.0}) xs.push_back(x);
  const int prev = mjb::simdLevel();
  for (int level : vectorLevels("seavec")) {
    mjb::simdSet(level);
    std::vector<double> y(xs.size());
    mjb::vExpFast(xs.size(), xs.data(), y.data());
    double worst = 0;
    for (size_t i = 0; i < xs.size(); i++) {
      const double e = double(std::fabs(y[i] / expl((long double)xs[i]) - 1));
      worst = std::fmax(worst, e);
      EXPECT_LE(e, mjb::kExpFastEps) << xs[i] << " " << mjb::simdName(level);
    }
    std::vector<double> z = {-709, -1e4, 709.5, 1e4, INFINITY, -INFINITY, NAN, 1, -1, 2, 3};
    mjb::vExpFast(z.size(), z.data(), z.data());
    EXPECT_EQ(z[0], 0);
    EXPECT_EQ(z[1], 0);
    EXPECT_EQ(z[2], INFINITY);
    EXPECT_EQ(z[3], INFINITY);
    EXPECT_EQ(z[4], INFINITY);
    EXPECT_EQ(z[5], 0);
    EXPECT_TRUE(std::isnan(z[6]));
    for (int i = 7; i < 11; i++) {
      const double x = i == 7 ? 1 : i == 8 ? -1 : i - 7;
      EXPECT_NEAR(z[i], std::exp(x), mjb::kExpFastEps * std::exp(x)) << i;
    }
    std::printf("[seavec] vExpFast %s: %zu arguments, worst %.3g relative (eps %.3g)\n",
                mjb::simdName(level), xs.size(), worst, mjb::kExpFastEps);
  }
  mjb::simdSet(prev);
}

TEST(SeaVec, LanesMatchTheScalarSearch) {
  // two Gerstner and two Airy components, fold 0.35, guesses at the
  // position moved by 3 mm; five Gerstner (the scalar path's general loop)
  // and one Airy, fold 0.9, guesses moved by 0.4 m: large first steps
  // (phases moved directly, not by angle addition); one Gerstner (the
  // scalar path's unrolled loop); Airy alone (no search)
  checkSea(makeSea(2, 2, 0.35), 3e-3, "warm");
  checkSea(makeSea(5, 1, 0.9), 0.4, "steep");
  checkSea(makeSea(1, 0, 0.5), 0.05, "one");
  checkSea(makeSea(0, 3, 0.0), 0.0, "airy");
  // five Airy components (k 0.45 to 1.53 rad/m; whole lane groups and a
  // rest) far out: phases 2e4 to 8e4 (bounded below 2^19 beforehand: the
  // lanes' range check skipped), 2e5 to 8e5 (the bound above 2^19:
  // checked per lane) and 1e6 to 5e6 (beyond the lanes' 2^20 pi/2 for the
  // short components: libmvec's)
  checkSea(makeSea(0, 5, 0.0), 0.0, "airy 5e4", 5e4);
  checkSea(makeSea(0, 5, 0.0), 0.0, "airy 5e5", 5e5);
  checkSea(makeSea(0, 5, 0.0), 0.0, "airy 3e6", 3e6);
}

// the vertex stage's e^L in lanes (seavec.h WetIn, for seas of few
// components) gives the list path's bits (cpuvert.cc wetVertices): the
// stretched height bit for bit that of sea.cc's stretch and each e^L the
// level's vExp of the same argument times the same cos and sin. 4000
// vertices of random heights, with surfaces above and below them, one
// at the surface, a NaN surface and a NaN height, and at finite depth
// surfaces at and below the bed (stretch's branches and glibc's fmin and
// fmax at NaN); three components in permuted order (perm), deep water and
// 4 m; with libmvec's exp (vExp) and the vertex mode's (fast: vExpFast)
TEST(SeaVec, WetVerticesInLanesGiveTheListsBits) {
  const int prev = mjb::simdLevel();
  const int m = 4000, n = 3, nw = 3;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> rel(3 * m), Z(m), SC(2 * nw * m);
  const double zc = -0.2, level = 0.1;
  for (int q = 0; q < m; q++) {
    for (int j = 0; j < 3; j++) rel[3 * q + j] = u(rng);
    Z[q] = level + 0.5 * u(rng);
    for (int j = 0; j < 2 * nw; j++) SC[2 * nw * q + j] = u(rng);
  }
  // edge cases: at the surface, NaN surface, surface at and below the bed
  rel[3 * 0 + 2] = 0, Z[0] = zc;           // z - eta = (0 + zc - level) - (zc - level) = 0
  Z[1] = std::nan("");
  Z[2] = level - 4, Z[3] = level - 5;      // depth + eta = 0, < 0 at 4 m
  rel[3 * 4 + 2] = std::nan("");
  const double k[n] = {0.2, 0.7, 1.9};
  const int perm[n] = {2, 0, 1};
  const std::vector<int> lvs = vectorLevels("seavec");
  for (double depth : {0.0, 4.0}) {
    const bool finite = depth > 0;
    const int stride = finite ? 4 : 2;
    for (int lf = 0; lf < 2 * int(lvs.size()); lf++) {
      // each level with libmvec's exp and with the vertex mode's (fast)
      const int level_ = lvs[lf / 2];
      const bool fast = lf % 2;
      mjb::simdSet(level_);
      std::vector<double> ZS(m, 7), E(stride * nw * m, 7);
      mjb::WetIn in{m, rel.data(), Z.data(), SC.data(), zc, level, depth, n, nw, finite, stride,
                    k, perm, ZS.data(), E.data(), fast};
      const int done = level_ == mjb::kSimdAvx512 ? mjb::wetLanesAvx512(in) : mjb::wetLanesAvx2(in);
      ASSERT_EQ(done, m - m % (level_ == mjb::kSimdAvx512 ? 8 : 4));
      long bad = 0;
      for (int q = 0; q < done; q++) {
        const double zs = mjb::stretch(depth, rel[3 * q + 2] + zc - level, Z[q] - level);
        bad += std::memcmp(&zs, &ZS[q], sizeof zs) != 0;
        for (int f = 0; f < (finite ? 2 : 1); f++) {
          double arg[n], a[n];
          for (int j = 0; j < n; j++) arg[j] = f == 0 ? k[j] * zs : -k[j] * (zs + 2 * depth);
          (fast ? mjb::vExpFast : mjb::vExp)(n, arg, a);
          for (int j = 0; j < n; j++) {
            const double er = a[j] * SC[2 * nw * q + 2 * perm[j] + 1];
            const double ei = a[j] * SC[2 * nw * q + 2 * perm[j]];
            const double* e = &E[stride * nw * q + 2 * f * nw];
            bad += std::memcmp(&er, &e[j], sizeof er) != 0;
            bad += std::memcmp(&ei, &e[nw + j], sizeof ei) != 0;
          }
        }
      }
      EXPECT_EQ(bad, 0) << mjb::simdName(level_) << ", depth " << depth << ", fast " << fast;
      // the cases were hit: at the surface 0; deep, a NaN surface gives
      // fmin(NaN, 0) = 0; at 4 m the bed and a NaN height give -depth
      EXPECT_EQ(ZS[0], 0);
      if (!finite) {
        EXPECT_EQ(ZS[1], 0);
      } else {
        EXPECT_EQ(ZS[2], -depth);
        EXPECT_EQ(ZS[3], -depth);
        EXPECT_EQ(ZS[4], -depth);
      }
    }
  }
  mjb::simdSet(prev);
}

// a Wigley hull and a box on a sea of three Gerstner and one Airy
// component (fold 0.27)
std::string scene(int threads) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
    << "/meshes/wigley_576.obj\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"h*\"/>"
    << "<numeric name=\"mjbuoy.wave.a\" data=\"0.4 10 20 0 0.6\"/>"
    << "<numeric name=\"mjbuoy.wave.b\" data=\"0.15 6 -50 40 0.5\"/>"
    << "<numeric name=\"mjbuoy.wave.c\" data=\"0.05 3 100 70 0.4\"/>"
    << "<numeric name=\"mjbuoy.airy.d\" data=\"0.1 8 -120 10\"/>"
    << "<numeric name=\"mjbuoy.threads\" data=\"" << threads << "\"/></custom><worldbody>"
    << "<body pos=\"0 0 0.03\" euler=\"3 -2 30\"><freejoint/><inertial pos=\"0 0 -0.08\" "
    << "mass=\"176.2\" diaginertia=\"6.02 237.28 238.6\"/><geom name=\"h0\" type=\"mesh\" "
    << "mesh=\"w\" contype=\"0\" conaffinity=\"0\"/></body>"
    << "<body pos=\"-6 2 0\"><freejoint/><geom name=\"h1\" type=\"box\" size=\"1.5 0.6 0.3\" "
    << "mass=\"600\"/></body></worldbody></mujoco>";
  return s.str();
}

std::vector<double> run(const Scene& s, int steps) {
  mj_resetData(s.m, s.d);
  std::vector<double> out;
  for (int i = 0; i < steps; i++) {
    mj_step(s.m, s.d);
    out.insert(out.end(), s.d->qpos, s.d->qpos + s.m->nq);
    const mjtNum* w = mjb_wrench(s.b, s.d);
    out.insert(out.end(), w, w + 6 * s.m->nbody);
  }
  return out;
}

TEST(SeaVec, CpuBackendRepeatsItsBitsOnEachPath) {
  Scene one(scene(1)), two(scene(2));
  ASSERT_TRUE(one.ok() && two.ok()) << one.err << two.err;
  const int prev = mjb::simdLevel();
  std::vector<int> levels = vectorLevels("seavec");
  levels.insert(levels.begin(), mjb::kSimdScalar);
  std::vector<double> w0;
  for (int level : levels) {
    mjb::simdSet(level);
    const std::vector<double> ref = run(one, 60);
    EXPECT_EQ(run(one, 60), ref) << mjb::simdName(level);
    EXPECT_EQ(run(two, 60), ref) << mjb::simdName(level);
    // the wrench at the first state: labels within 1.4e-12 m (fold 0.27) of
    // the scalar path's move the hydrostatic force by rho g S_wet 1e-12 N
    // against 1e3 N (tests/guess_test.cc's argument): 1e-9 of its size
    mj_resetData(one.m, one.d);
    mj_forward(one.m, one.d);
    const mjtNum* w = mjb_wrench(one.b, one.d);
    std::vector<double> wv(w, w + 6 * one.m->nbody);
    if (level == mjb::kSimdScalar) {
      w0 = wv;
    } else {
      double big = 0, diff = 0;
      for (size_t i = 0; i < wv.size(); i++) {
        big = std::fmax(big, std::fabs(w0[i]));
        diff = std::fmax(diff, std::fabs(wv[i] - w0[i]));
      }
      EXPECT_GT(big, 100);
      EXPECT_LE(diff, 1e-9 * big) << mjb::simdName(level);
      std::printf("[seavec] %s: wrench within %.3g of scalar (relative)\n", mjb::simdName(level),
                  diff / big);
    }
  }
  mjb::simdSet(prev);
}

}  // namespace
}  // namespace mjbt
