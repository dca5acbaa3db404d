// zipkern: W lanes from and to arrays of small vectors stored one after
// another (3 doubles a vertex or triangle, 2 floats an offset), by
// two-source shuffles instead of a load or store per lane (GCC vector
// extensions; V of W doubles, I its integer lanes). Included by the lane
// kernels (placekern.h, trivec_kern.h); everything here is static.
#ifndef MJBUOY_ZIPKERN_H_
#define MJBUOY_ZIPKERN_H_

namespace mjb {
namespace {

template <class V>
static inline V zload(const double* p) {
  V v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}

// component j of the W vectors of N doubles each stored one after another
// from p (N = 2 or 3): the lanes' elements N l + j lie in N loads of W
template <class V, class I, int W, int N>
static inline V unzip(const double* p, int j) {
  const V a = zload<V>(p), b = zload<V>(p + W);
  const V c = N == 3 ? zload<V>(p + 2 * W) : a;
  I m1, m2;
  for (int l = 0; l < W; l++) {
    const int e = N * l + j;
    m1[l] = e < 2 * W ? e : 0;
    m2[l] = e < 2 * W ? l : W + e - 2 * W;
  }
  return __builtin_shuffle(__builtin_shuffle(a, b, m1), c, m2);
}

// the W 3-vectors (x[l], y[l], z[l]) stored one after another from p
template <class V, class I, int W>
static inline void zip3(double* p, V x, V y, V z) {
  for (int q = 0; q < 3; q++) {
    I m1, m2;
    for (int l = 0; l < W; l++) {
      const int e = q * W + l, v = e / 3, c = e % 3;
      m1[l] = c == 0 ? v : c == 1 ? W + v : 0;
      m2[l] = c == 2 ? W + v : l;
    }
    const V o = __builtin_shuffle(__builtin_shuffle(x, y, m1), z, m2);
    __builtin_memcpy(p + q * W, &o, sizeof o);
  }
}

// the W pairs (x[l], y[l]) stored one after another from p
template <class V, class I, int W>
static inline void zip2(double* p, V x, V y) {
  for (int q = 0; q < 2; q++) {
    I m;
    for (int l = 0; l < W; l++) {
      const int e = q * W + l;
      m[l] = e % 2 == 0 ? e / 2 : W + e / 2;
    }
    const V o = __builtin_shuffle(x, y, m);
    __builtin_memcpy(p + q * W, &o, sizeof o);
  }
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_ZIPKERN_H_
