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
  // two accumulators a quantity, in registers (an array indexed by the
  // loop counter would live on the stack): the adds' latency hidden
  V p0 = {}, x0 = {}, y0 = {}, z0 = {}, p1 = {}, x1 = {}, y1 = {}, z1 = {};
  double s[4] = {0, 0, 0, 0};
  const int nb = in.n - in.n % W, nb2 = in.n - in.n % (2 * W);
  for (int f = 0; f < in.nf; f++) {
    const double *er = in.e + 2 * f * in.nw, *ei = er + in.nw;
    const double *wp = in.wp[f], *wx = in.wux[f], *wy = in.wuy[f], *wz = in.wz[f];
    int j = 0;
    for (; j < nb2; j += 2 * W) {
      const V r0 = ld(er + j), i0 = ld(ei + j), r1 = ld(er + j + W), i1 = ld(ei + j + W);
      p0 += ld(wp + j) * r0;
      x0 += ld(wx + j) * r0;
      y0 += ld(wy + j) * r0;
      z0 += ld(wz + j) * i0;
      p1 += ld(wp + j + W) * r1;
      x1 += ld(wx + j + W) * r1;
      y1 += ld(wy + j + W) * r1;
      z1 += ld(wz + j + W) * i1;
    }
    for (; j < nb; j += W) {
      const V r0 = ld(er + j), i0 = ld(ei + j);
      p0 += ld(wp + j) * r0;
      x0 += ld(wx + j) * r0;
      y0 += ld(wy + j) * r0;
      z0 += ld(wz + j) * i0;
    }
    for (; j < in.n; j++) {
      s[0] += wp[j] * er[j];
      s[1] += wx[j] * er[j];
      s[2] += wy[j] * er[j];
      s[3] += wz[j] * ei[j];
    }
  }
  const V v[4] = {p0 + p1, x0 + x1, y0 + y1, z0 + z1};
  for (int q = 0; q < 4; q++) {
    double t = s[q];
    for (int l = 0; l < W; l++) t += v[q][l];
    in.out[q] = t;
  }
}

}  // namespace
}  // namespace mjb

#endif  // MJBUOY_CPUSUM_KERN_H_
