// overlapping closed pieces of a hull mesh (overlap.h)
#include "overlap.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <array>
#include <numeric>

namespace mjb {

static int root(std::vector<int>* p, int i) {
  while ((*p)[i] != i) i = (*p)[i] = (*p)[(*p)[i]];
  return i;
}

// solid angle of triangle abc seen from the origin (Van Oosterom and
// Strackee, IEEE Trans. Biomed. Eng. 30(2), 1983), signed by its winding
static double solid(const double* a, const double* b, const double* c) {
  double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  double lc = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
               a[2] * (b[0] * c[1] - b[1] * c[0]);
  double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  double bc = b[0] * c[0] + b[1] * c[1] + b[2] * c[2];
  double ca = c[0] * a[0] + c[1] * a[1] + c[2] * a[2];
  return 2 * std::atan2(det, la * lb * lc + ab * lc + bc * la + ca * lb);
}

// generalized winding number of piece faces fs about point p: 1 inside a
// closed outward piece, 0 outside
static double winding(const Mesh& m, const std::vector<int>& fs, const double* p) {
  double s = 0;
  for (int f : fs) {
    double q[3][3];
    for (int e = 0; e < 3; e++) {
      for (int j = 0; j < 3; j++) q[e][j] = m.v[3 * m.f[3 * f + e] + j] - p[j];
    }
    s += solid(q[0], q[1], q[2]);
  }
  return s / (4 * M_PI);
}

std::vector<std::pair<int, int>> overlappingPieces(const Mesh& m, std::vector<int>* ntri) {
  const int nf = m.nf(), nv = m.nv();
  std::vector<int> par(nv);
  std::iota(par.begin(), par.end(), 0);
  for (int f = 0; f < nf; f++) {
    for (int e = 1; e < 3; e++) par[root(&par, m.f[3 * f + e])] = root(&par, m.f[3 * f]);
  }
  // pieces in the order of their first triangle
  std::map<int, int> id;
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < nf; f++) {
    int r = root(&par, m.f[3 * f]);
    auto it = id.find(r);
    if (it == id.end()) {
      it = id.emplace(r, int(faces.size())).first;
      faces.emplace_back();
    }
    faces[it->second].push_back(f);
  }
  const int np = faces.size();
  ntri->assign(np, 0);
  for (int i = 0; i < np; i++) (*ntri)[i] = faces[i].size();
  std::vector<std::pair<int, int>> out;
  if (np < 2) return out;
  // closed: every undirected edge used by exactly two of the piece's faces
  std::vector<char> closed(np, 1);
  std::vector<std::array<double, 6>> box(np);
  for (int i = 0; i < np; i++) {
    std::map<std::pair<int, int>, int> use;
    box[i] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (int f : faces[i]) {
      for (int e = 0; e < 3; e++) {
        int a = m.f[3 * f + e], b = m.f[3 * f + (e + 1) % 3];
        use[{std::min(a, b), std::max(a, b)}]++;
        for (int j = 0; j < 3; j++) {
          box[i][j] = std::min(box[i][j], m.v[3 * a + j]);
          box[i][3 + j] = std::max(box[i][3 + j], m.v[3 * a + j]);
        }
      }
    }
    for (const auto& kv : use) closed[i] = closed[i] && kv.second == 2;
  }
  auto inBox = [&](int j, const double* p) {
    for (int k = 0; k < 3; k++) {
      if (p[k] <= box[j][k] || p[k] >= box[j][3 + k]) return false;
    }
    return true;
  };
  // a point of piece i (vertex or triangle centroid) inside piece j
  auto inside = [&](int i, int j) {
    for (int f : faces[i]) {
      const int* t = &m.f[3 * f];
      double c[3];
      for (int k = 0; k < 3; k++) {
        c[k] = (m.v[3 * t[0] + k] + m.v[3 * t[1] + k] + m.v[3 * t[2] + k]) / 3;
      }
      if (inBox(j, c) && std::fabs(winding(m, faces[j], c)) > 0.75) return true;
      for (int e = 0; e < 3; e++) {
        const double* p = &m.v[3 * t[e]];
        if (inBox(j, p) && std::fabs(winding(m, faces[j], p)) > 0.75) return true;
      }
    }
    return false;
  };
  for (int i = 0; i < np; i++) {
    for (int j = i + 1; j < np; j++) {
      if (!closed[i] || !closed[j]) continue;
      bool apart = false;
      for (int k = 0; k < 3; k++) {
        apart = apart || box[i][3 + k] <= box[j][k] || box[j][3 + k] <= box[i][k];
      }
      if (!apart && (inside(i, j) || inside(j, i))) out.push_back({i + 1, j + 1});
    }
  }
  return out;
}

void checkOverlap(const Mesh& mesh, const std::string& gname, std::vector<std::string>* warn) {
  std::vector<int> nt;
  auto ov = overlappingPieces(mesh, &nt);
  for (size_t k = 0; k < ov.size() && k < 5; k++) {
    int a = ov[k].first, b = ov[k].second;
    warn->push_back("hull geom \"" + gname + "\": closed pieces " + std::to_string(a) + " (" +
                    std::to_string(nt[a - 1]) + " triangles) and " + std::to_string(b) + " (" +
                    std::to_string(nt[b - 1]) + " triangles) of its mesh overlap: the pressure "
                    "counts their shared volume twice (too much buoyancy); merge them with a "
                    "boolean union, or make them separate geoms that do not overlap");
  }
  if (ov.size() > 5) {
    warn->push_back("hull geom \"" + gname + "\": " + std::to_string(ov.size() - 5) +
                    " more overlapping pairs of closed pieces");
  }
}

}  // namespace mjb
