// panelcoarse: quadric simplification of a hull for the panel solver
// (panelcoarse.h; docs/physics.md section 13, "Coarsened hulls")
#include "radiation/panelcoarse.h"

#include <algorithm>
#include <array>
#include <queue>
#include <cmath>
#include <cstdio>

#include <meshoptimizer.h>

#include "radiation/panelmesh.h"

namespace mjb {

// area vector and centroid z of each triangle of each panel (a quad is
// the triangles 012 and 023), to f(a, zc)
template <class F>
static void eachTriangle(const PanelMesh& p, F f) {
  for (int i = 0; i < p.nface(); i++) {
    const int* q = &p.face[4 * i];
    for (int t = 0; t < (q[3] < 0 ? 1 : 2); t++) {
      const double* a = &p.vert[3 * q[0]];
      const double* b = &p.vert[3 * q[1 + t]];
      const double* c = &p.vert[3 * q[2 + t]];
      double u[3], v[3];
      for (int k = 0; k < 3; k++) u[k] = b[k] - a[k], v[k] = c[k] - a[k];
      double n[3] = {0.5 * (u[1] * v[2] - u[2] * v[1]), 0.5 * (u[2] * v[0] - u[0] * v[2]),
                     0.5 * (u[0] * v[1] - u[1] * v[0])};
      f(n, (a[2] + b[2] + c[2]) / 3);
    }
  }
}

double panelVolume(const PanelMesh& body) {
  // V = int z n_z dS over the closed wet surface; z = 0 on the waterplane
  double v = 0;
  eachTriangle(body, [&](const double* n, double zc) { v += n[2] * zc; });
  return v;
}

double panelWaterplane(const PanelMesh& body) {
  double a = 0;
  eachTriangle(body, [&](const double* n, double) { a -= n[2]; });
  return a;
}

static int countPanels(const PanelMesh& body, const PanelMesh& lid, bool countLid) {
  return body.nface() + (countLid ? lid.nface() : 0);
}

// the hull's triangles welded: positions rounded to 1e-6 of the extent
// (a mesh file's per-face copies of a vertex, or nearly equal ones, become
// one), so that the simplifier sees one connected surface
static void weldedTriangles(const float* vert, int nvert, const int* face, int nface,
                            std::vector<float>* pv, std::vector<unsigned>* idx) {
  float ext = 0;
  for (int i = 0; i < 3 * nvert; i++) ext = std::max(ext, std::fabs(vert[i]));
  const double h = 1e-6 * (ext > 0 ? ext : 1);
  std::vector<float> q(3 * nvert);
  for (size_t i = 0; i < q.size(); i++) q[i] = float(std::round(vert[i] / h) * h);
  std::vector<unsigned> in(face, face + 3 * nface), remap(nvert);
  size_t nv = meshopt_generateVertexRemap(remap.data(), in.data(), in.size(), q.data(), nvert,
                                          3 * sizeof(float));
  idx->resize(in.size());
  pv->resize(3 * nv);
  meshopt_remapIndexBuffer(idx->data(), in.data(), in.size(), remap.data());
  meshopt_remapVertexBuffer(pv->data(), q.data(), nvert, 3 * sizeof(float), remap.data());
}

// share of the target triangle count the quadric collapse keeps; the
// rest comes from bisecting the longest edges, which bounds the panels'
// length where the collapse left long slivers on flat parts (the panel
// solution needs resolution where the geometry needs none)
// (0.7: the Wigley hull's pitch damping within 5% of the full mesh's,
// 4 to 13% low with the collapse alone; docs/physics.md section 13)
const double kShapeShare = 0.7;

// triangles tri (n, indices into pv) as a soup (9 floats each), the
// longest edge of the triangle with the longest edge halved until there
// are target of them; a hanging node is harmless to constant panels
static void bisectLongest(const std::vector<float>& pv, const unsigned* tri, size_t n, int target,
                          std::vector<float>* soup) {
  std::vector<std::array<float, 9>> t(n);
  for (size_t i = 0; i < n; i++)
    for (int k = 0; k < 3; k++)
      for (int d = 0; d < 3; d++) t[i][3 * k + d] = pv[3 * tri[3 * i + k] + d];
  // (squared longest edge, its first vertex) of a triangle
  auto longest = [](const std::array<float, 9>& a, int* e) {
    float best = -1;
    for (int k = 0; k < 3; k++) {
      int j = (k + 1) % 3;
      float s = 0;
      for (int d = 0; d < 3; d++) s += (a[3 * j + d] - a[3 * k + d]) * (a[3 * j + d] - a[3 * k + d]);
      if (s > best) best = s, *e = k;
    }
    return best;
  };
  std::priority_queue<std::pair<float, size_t>> q;
  int e = 0;
  for (size_t i = 0; i < n; i++) q.push({longest(t[i], &e), i});
  while ((int)t.size() < target && !q.empty()) {
    size_t i = q.top().second;
    q.pop();
    std::array<float, 9> a = t[i], b = t[i];
    longest(a, &e);
    int j = (e + 1) % 3;
    for (int d = 0; d < 3; d++) {
      float m = 0.5f * (a[3 * e + d] + a[3 * j + d]);
      a[3 * j + d] = m;  // (v_e, m, v_o)
      b[3 * e + d] = m;  // (m, v_j, v_o)
    }
    t[i] = a;
    t.push_back(b);
    q.push({longest(t[i], &e), i});
    q.push({longest(t.back(), &e), t.size() - 1});
  }
  soup->clear();
  for (const auto& a : t) soup->insert(soup->end(), a.begin(), a.end());
}

bool coarsenPanels(const float* vert, int nvert, const int* face, int nface, const double pos[3],
                   const double quat[4], int refine, bool countLid, int budget, PanelMesh* body,
                   PanelMesh* lid, std::string* note, CoarseInfo* info) {
  *info = CoarseInfo();
  info->panels0 = countPanels(*body, *lid, countLid);
  info->vol0 = panelVolume(*body);
  info->awp0 = panelWaterplane(*body);
  // the whole hull is simplified (its waterline, a crease between a
  // hull's bottom and its sides in many meshes, is kept as a feature), and
  // cut at the sea as before: the dry part spends some of the triangles
  std::string nt;
  std::vector<float> pv;
  std::vector<unsigned> idx;
  weldedTriangles(vert, nvert, face, nface, &pv, &idx);
  size_t nv = pv.size() / 3, ni = idx.size();
  std::vector<unsigned> out(ni);
  // first guess: triangles in proportion to the budget; then scaled by the
  // panels' over- or undershoot (the cut, refine and the lid add panels)
  int ntri = int(ni / 3);
  info->tri0 = ntri;
  int target = std::max(8, int(0.95 * ntri * budget / std::max(1, info->panels0)));
  PanelMesh b, l;
  std::vector<float> soup;
  std::vector<int> sf;
  bool found = false;
  for (int it = 0; it < 10; it++) {
    float err = 0;
    // quadric collapse to a share of the target (target error 1: the
    // whole extent, i.e. the triangle count decides), then the longest
    // edges bisected up to the target
    // (at most the mesh's own count: meshopt_simplify requires it)
    size_t tq = std::min(ni / 3, std::max(size_t(4), size_t(kShapeShare * target)));
    size_t n = meshopt_simplify(out.data(), idx.data(), ni, pv.data(), nv, 3 * sizeof(float),
                                3 * tq, 1.0f, 0, &err);
    bisectLongest(pv, out.data(), n / 3, target, &soup);
    sf.resize(soup.size() / 3);
    for (size_t i = 0; i < sf.size(); i++) sf[i] = int(i);
    if (!hullPanels(soup.data(), int(sf.size()), sf.data(), int(sf.size() / 3), pos, quat, refine,
                    &b, &l, &nt)) {
      break;
    }
    int np = countPanels(b, l, countLid);
    if (np <= budget && np > info->panels) {
      // the finest within the budget so far
      found = true;
      *body = b;
      *lid = l;
      *note = nt;
      info->panels = np;
      info->tri = int(sf.size() / 3);
      info->vol = panelVolume(b);
      info->awp = panelWaterplane(b);
      info->err = err;
    }
    if (np <= budget && np >= 0.97 * budget) break;
    // the panels grow about in proportion to the triangles
    int next = std::max(8, int((np <= budget ? 0.995 : 0.98) * target * budget / np));
    if (next == target) break;
    target = next;
  }
  if (found) return true;
  char s[200];
  std::snprintf(s, sizeof s, "the hull's %d triangles could not be simplified to %d wet "
                "panels or fewer (%d triangles at the last try)", ntri, budget, target);
  *note = s;
  return false;
}

}  // namespace mjb
