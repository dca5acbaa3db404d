// trisort: the scalar rule of a triangle's kind (trisort.h)
#include "cpu/trisort.h"

namespace mjb {

int triKind(double h0, double h1, double h2) {
  if (h0 >= 0 && h1 >= 0 && h2 >= 0) return kKindDry;
  const int up = (h0 > 0) + (h1 > 0) + (h2 > 0), down = (h0 <= 0) + (h1 <= 0) + (h2 <= 0);
  if (down == 3) return kKindWet;
  if (down == 1 && up == 2) return kKindOneBelow;
  if (down == 2 && up == 1) return kKindOneAbove;
  return kKindOther;
}

void sortKinds(TriSort* in, int k0) {
  for (int k = k0; k < in->t0 + in->nt; k++) {
    const int* f = in->face + 3 * k;
    const int c = triKind(in->h[f[0]], in->h[f[1]], in->h[f[2]]);
    if (c != kKindDry) in->list[c][in->n[c]++] = k;
  }
}

}  // namespace mjb
