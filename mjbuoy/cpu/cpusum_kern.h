// cpusum_kern: cpusum.h's sums over the components in lanes of W (GCC
// vector extensions), included by one file per instruction set
#ifndef MJBUOY_CPUSUM_KERN_H_
#define MJBUOY_CPUSUM_KERN_H_

#include "cpu/cpusum.h"

namespace mjb {
namespace {

template <int W>
struct SLanes {
  typedef double V __attribute__((vector_size(8 * W)));
};

template <int W>
static void sumLanes(const SumIn& in) {
  typedef typename SLanes<W>::V V;
  auto ld = [](const double* p) {
    V v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
  };
  // two accumulators a quantity: the adds' latency hidden behind the next
  V a[2][4] = {};
  double s[4] = {0, 0, 0, 0};
  const int nb = in.n - in.n % W;
  for (int f = 0; f < in.nf; f++) {
    const double *er = in.e + 2 * f * in.nw, *ei = er + in.nw;
    const double *wp = in.wp[f], *wx = in.wux[f], *wy = in.wuy[f], *wz = in.wz[f];
    int j = 0;
    for (; j < nb; j += W) {
      V* b = a[(j / W) & 1];
      const V r = ld(er + j), i = ld(ei + j);
      b[0] += ld(wp + j) * r;
      b[1] += ld(wx + j) * r;
      b[2] += ld(wy + j) * r;
      b[3] += ld(wz + j) * i;
    }
    for (; j < in.n; j++) {
      s[0] += wp[j] * er[j];
      s[1] += wx[j] * er[j];
      s[2] += wy[j] * er[j];
      s[3] += wz[j] * ei[j];
    }
  }
  for (int q = 0; q < 4; q++) {
    const V v = a[0][q] + a[1][q];
    double t = s[q];
    for (int l = 0; l < W; l++) t += v[l];
    in.out[q] = t;
  }
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_CPUSUM_KERN_H_
