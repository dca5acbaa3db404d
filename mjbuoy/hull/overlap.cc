// overlapping closed pieces of a hull mesh (overlap.h)
#include "hull/overlap.h"

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

// 6 x signed volume of tetrahedron abcd: > 0 when d is on the side of
// plane abc its counter-clockwise normal points to
static double orient(const double* a, const double* b, const double* c, const double* d) {
  double u[3], v[3], w[3];
  for (int k = 0; k < 3; k++) {
    u[k] = b[k] - a[k];
    v[k] = c[k] - a[k];
    w[k] = d[k] - a[k];
  }
  return w[0] * (u[1] * v[2] - u[2] * v[1]) - w[1] * (u[0] * v[2] - u[2] * v[0]) +
         w[2] * (u[0] * v[1] - u[1] * v[0]);
}

// segment pq passes through the inside of triangle abc: p and q strictly on
// opposite sides of its plane and the crossing strictly inside its edges
// (every test beyond tol, a volume); a segment that only touches the
// triangle (an end on it, or through its edge or corner) does not count,
// so pieces that share a face or sit on one another do not cross
static bool crosses(const double* p, const double* q, const double* a, const double* b,
                    const double* c, double tol) {
  double sp = orient(a, b, c, p), sq = orient(a, b, c, q);
  if (!((sp > tol && sq < -tol) || (sp < -tol && sq > tol))) return false;
  double e0 = orient(p, q, a, b), e1 = orient(p, q, b, c), e2 = orient(p, q, c, a);
  return (e0 > tol && e1 > tol && e2 > tol) || (e0 < -tol && e1 < -tol && e2 < -tol);
}

// axis-aligned bounds of triangle or segment points pts[0..n) overlap box
static bool meets(const double* const* pts, int n, const std::array<double, 6>& box) {
  for (int k = 0; k < 3; k++) {
    double lo = pts[0][k], hi = pts[0][k];
    for (int i = 1; i < n; i++) {
      lo = std::min(lo, pts[i][k]);
      hi = std::max(hi, pts[i][k]);
    }
    if (hi < box[k] || lo > box[3 + k]) return false;
  }
  return true;
}

// an edge of piece fa passes through a triangle of piece fb inside the
// common box: two closed surfaces that intersect without touching only
// must have such an edge one way or the other (the intersection of two
// triangles in general position ends on an edge of one of them)
static bool edgeThrough(const Mesh& m, const std::vector<int>& fa, const std::vector<int>& fb,
                        const std::array<double, 6>& both, double tol) {
  std::vector<int> near;
  for (int f : fb) {
    const double* t[3] = {&m.v[3 * m.f[3 * f]], &m.v[3 * m.f[3 * f + 1]], &m.v[3 * m.f[3 * f + 2]]};
    if (meets(t, 3, both)) near.push_back(f);
  }
  for (int f : fa) {
    for (int e = 0; e < 3; e++) {
      int i = m.f[3 * f + e], j = m.f[3 * f + (e + 1) % 3];
      if (i > j) continue;  // each edge of a closed piece once
      const double* s[2] = {&m.v[3 * i], &m.v[3 * j]};
      if (!meets(s, 2, both)) continue;
      for (int g : near) {
        const int* t = &m.f[3 * g];
        if (crosses(s[0], s[1], &m.v[3 * t[0]], &m.v[3 * t[1]], &m.v[3 * t[2]], tol)) return true;
      }
    }
  }
  return false;
}

// faces of each piece (connected by shared vertices), pieces in the order
// of their first triangle
static std::vector<std::vector<int>> pieces(const Mesh& m) {
  const int nf = m.nf(), nv = m.nv();
  std::vector<int> par(nv);
  std::iota(par.begin(), par.end(), 0);
  for (int f = 0; f < nf; f++) {
    for (int e = 1; e < 3; e++) par[root(&par, m.f[3 * f + e])] = root(&par, m.f[3 * f]);
  }
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
  return faces;
}

// bounding box (min xyz, max xyz) of faces fs; closed gets whether every
// undirected edge is used by exactly two of them
static std::array<double, 6> pieceBox(const Mesh& m, const std::vector<int>& fs, bool* closed) {
  std::map<std::pair<int, int>, int> use;
  std::array<double, 6> box = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
  for (int f : fs) {
    for (int e = 0; e < 3; e++) {
      int a = m.f[3 * f + e], b = m.f[3 * f + (e + 1) % 3];
      use[{std::min(a, b), std::max(a, b)}]++;
      for (int j = 0; j < 3; j++) {
        box[j] = std::min(box[j], m.v[3 * a + j]);
        box[3 + j] = std::max(box[3 + j], m.v[3 * a + j]);
      }
    }
  }
  *closed = true;
  for (const auto& kv : use) *closed = *closed && kv.second == 2;
  return box;
}

// a point of faces fa (vertex or triangle centroid) strictly inside the
// closed piece fb of bounding box bb
static bool pointInside(const Mesh& m, const std::vector<int>& fa, const std::vector<int>& fb,
                        const std::array<double, 6>& bb) {
  auto in = [&](const double* p) {
    for (int k = 0; k < 3; k++) {
      if (p[k] <= bb[k] || p[k] >= bb[3 + k]) return false;
    }
    return std::fabs(winding(m, fb, p)) > 0.75;
  };
  for (int f : fa) {
    const int* t = &m.f[3 * f];
    double c[3];
    for (int k = 0; k < 3; k++) c[k] = (m.v[3 * t[0] + k] + m.v[3 * t[1] + k] + m.v[3 * t[2] + k]) / 3;
    if (in(c) || in(&m.v[3 * t[0]]) || in(&m.v[3 * t[1]]) || in(&m.v[3 * t[2]])) return true;
  }
  return false;
}

// closed pieces fa and fb (boxes ba, bb) share volume: one has a point
// inside the other (nested, or poking in), or their surfaces pass through
// one another (crossing: no vertex of either need be inside the other)
static bool shareVolume(const Mesh& m, const std::vector<int>& fa, const std::vector<int>& fb,
                        const std::array<double, 6>& ba, const std::array<double, 6>& bb,
                        double tol) {
  std::array<double, 6> both;
  for (int k = 0; k < 3; k++) {
    both[k] = std::max(ba[k], bb[k]);
    both[3 + k] = std::min(ba[3 + k], bb[3 + k]);
    if (both[3 + k] <= both[k]) return false;  // apart, or touching at most
  }
  return pointInside(m, fa, fb, bb) || pointInside(m, fb, fa, ba) ||
         edgeThrough(m, fa, fb, both, tol) || edgeThrough(m, fb, fa, both, tol);
}

std::vector<std::pair<int, int>> overlappingPieces(const Mesh& m, std::vector<int>* ntri) {
  std::vector<std::vector<int>> faces = pieces(m);
  const int np = faces.size();
  ntri->assign(np, 0);
  std::vector<std::pair<int, int>> out;
  std::vector<std::array<double, 6>> box(np);
  std::vector<char> closed(np);
  // size: the largest extent of the mesh, for the touching tolerance
  double size = 0;
  for (int i = 0; i < np; i++) {
    bool c;
    (*ntri)[i] = faces[i].size();
    box[i] = pieceBox(m, faces[i], &c);
    closed[i] = c;
    for (int k = 0; k < 3; k++) size = std::max(size, box[i][3 + k] - box[i][k]);
  }
  // volume below which an orientation test counts as touching: 1e-9 of
  // the cube of the largest piece's size
  const double tol = 1e-9 * size * size * size;
  for (int i = 0; i < np; i++) {
    for (int j = i + 1; j < np; j++) {
      if (closed[i] && closed[j] && shareVolume(m, faces[i], faces[j], box[i], box[j], tol)) {
        out.push_back({i + 1, j + 1});
      }
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
