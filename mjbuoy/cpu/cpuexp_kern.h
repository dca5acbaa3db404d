// cpuexp_kern: cpuexp.h's e^L over the components in lanes of W (GCC
// vector extensions), included by one file per instruction set with its
// libmvec exp (X::exp, vExp's)
#ifndef MJBUOY_CPUEXP_KERN_H_
#define MJBUOY_CPUEXP_KERN_H_

#include "cpu/cpuexp.h"
#include "util/expkern.h"
#include "util/zipkern.h"

namespace mjb {
namespace {

template <int W>
struct ELanes {
  typedef double V __attribute__((vector_size(8 * W)));
  typedef long I __attribute__((vector_size(8 * W)));
};

// sin (s) and cos (c) of sorted components [j, j + m) from the interleaved
// unsorted sc: through perm, or (perm null, a whole group) two loads split
// into even and odd lanes. A tail's (m < W) other lanes are zero, not read
template <int W>
__attribute__((always_inline)) inline void ePhases(const int* perm, const double* sc, int j,
                                                   int m, typename ELanes<W>::V* s,
                                                   typename ELanes<W>::V* c) {
  typedef typename ELanes<W>::V V;
  if (!perm && m == W) {  // (zipkern.h: shuffles GCC and clang both take)
    *s = unzip<V, W, 2, 0>(sc + 2 * j);
    *c = unzip<V, W, 2, 1>(sc + 2 * j);
    return;
  }
  V vs = {}, vc = {};
  for (int l = 0; l < m; l++) {
    const int i = perm ? perm[j + l] : j + l;
    vs[l] = sc[2 * i];
    vc[l] = sc[2 * i + 1];
  }
  *s = vs;
  *c = vc;
}

// components [j, j + m) of both families (m <= W): a = k z' (family 0),
// -k (z' + 2 h) (family 1, zd = z' + 2 h), e^a, then Re = e^a cos, Im =
// e^a sin, each the list path's single product; only m lanes stored
template <int W, class X, bool kFast>
__attribute__((always_inline)) inline void eGroup(const EIn& in, double zs, double zd,
                                                  const double* sc, double* e, int j, int m) {
  typedef typename ELanes<W>::V V;
  typedef typename ELanes<W>::I I;
  V k = {}, s, c;
  if (m == W) {
    __builtin_memcpy(&k, in.k + j, sizeof k);
  } else {
    for (int l = 0; l < m; l++) k[l] = in.k[j + l];
  }
  ePhases<W>(in.perm, sc, j, m, &s, &c);
  const int nf = in.finite ? 2 : 1;
  for (int f = 0; f < nf; f++) {
    const V a = f == 0 ? k * zs : -k * zd;
    const V ex = kFast ? expFast<V, I>(a) : X::exp(a);
    const V re = ex * c, im = ex * s;
    double* er = e + 2 * f * in.nw + j;
    double* ei = er + in.nw;
    if (m == W) {
      __builtin_memcpy(er, &re, sizeof re);
      __builtin_memcpy(ei, &im, sizeof im);
    } else {
      for (int l = 0; l < m; l++) {
        er[l] = re[l];
        ei[l] = im[l];
      }
    }
  }
}

// one vertex's e^L (cpuexp.h): whole groups of W components, then the tail
template <int W, class X, bool kFast>
static void eLanesAt(const EIn& in, double zs, const double* sc, double* e) {
  const double zd = zs + 2 * in.depth;  // (the list's z' + 2 h, one rounding)
  const int nb = in.n - in.n % W;
  for (int j = 0; j < nb; j += W) eGroup<W, X, kFast>(in, zs, zd, sc, e, j, W);
  if (nb < in.n) eGroup<W, X, kFast>(in, zs, zd, sc, e, nb, in.n - nb);
}

template <int W, class X>
static void eLanes(const EIn& in, double zs, const double* sc, double* e) {
  if (in.fast) {
    eLanesAt<W, X, true>(in, zs, sc, e);
  } else {
    eLanesAt<W, X, false>(in, zs, sc, e);
  }
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_CPUEXP_KERN_H_
