// the interior lid's damping weight (panellid.h)
#include "radiation/panellid.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace mjb {

namespace {

// horizontal distance from p to the segment a b [m]
double segDist(const double* p, const double* a, const double* b) {
  double ex = b[0] - a[0], ey = b[1] - a[1], l2 = ex * ex + ey * ey;
  double t = l2 > 0 ? ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / l2 : 0;
  t = std::min(1.0, std::max(0.0, t));
  return std::hypot(p[0] - a[0] - t * ex, p[1] - a[1] - t * ey);
}

}  // namespace

std::vector<double> lidWeights(const PanelMesh& lid, const std::vector<double>& xy) {
  const int nf = lid.nface();
  std::vector<double> w(nf, 1.0);
  if (nf == 0) return {};
  // waterline edges: used by one face only (vertex pairs, unordered)
  std::map<std::pair<int, int>, int> uses;
  for (int f = 0; f < nf; f++) {
    const int* v = &lid.face[4 * f];
    const int nv = v[3] < 0 ? 3 : 4;
    for (int k = 0; k < nv; k++) {
      int a = v[k], b = v[(k + 1) % nv];
      uses[{std::min(a, b), std::max(a, b)}]++;
    }
  }
  double dmax = 0;
  for (int f = 0; f < nf; f++) {
    double d = 1e300;
    for (const auto& e : uses) {
      if (e.second != 1) continue;
      d = std::min(d, segDist(&xy[2 * f], &lid.vert[3 * e.first.first], &lid.vert[3 * e.first.second]));
    }
    w[f] = d < 1e300 ? d : 0;
    dmax = std::max(dmax, w[f]);
  }
  for (double& x : w) x = dmax > 0 ? x / dmax : 1.0;
  return w;
}

}  // namespace mjb
