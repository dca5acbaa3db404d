// hull meshes: mesh geoms as compiled, primitives tessellated
#include "hull/hull.h"
#include "hull/overlap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <tuple>

namespace mjb {

static void addTri(Mesh* m, int a, int b, int c) {
  m->f.insert(m->f.end(), {a, b, c});
}

static int addVert(Mesh* m, double x, double y, double z) {
  m->v.insert(m->v.end(), {x, y, z});
  return m->nv() - 1;
}

// box of half sizes s: each face a grid of kBoxDiv^2 squares
static Mesh box(const double s[3]) {
  Mesh m;
  const int n = kBoxDiv;
  for (int ax = 0; ax < 3; ax++) {
    for (int sg = -1; sg <= 1; sg += 2) {
      // face normal along sg * e_ax; u, v span it so that u x v = normal
      int u = (ax + 1) % 3, w = (ax + 2) % 3;
      if (sg < 0) std::swap(u, w);
      int base = m.nv();
      for (int i = 0; i <= n; i++) {
        for (int j = 0; j <= n; j++) {
          double p[3];
          p[ax] = sg * s[ax];
          p[u] = s[u] * (2.0 * i / n - 1);
          p[w] = s[w] * (2.0 * j / n - 1);
          addVert(&m, p[0], p[1], p[2]);
        }
      }
      for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++) {
          int a = base + i * (n + 1) + j, b = a + (n + 1);
          addTri(&m, a, b, b + 1);
          addTri(&m, a, b + 1, a + 1);
        }
      }
    }
  }
  return m;
}

// surface of revolution about z through the given (r, z) profile, from the
// bottom pole (r = 0) to the top pole (r = 0); kRound segments around
static Mesh revolve(const std::vector<double>& r, const std::vector<double>& z) {
  Mesh m;
  const int nr = r.size(), nseg = kRound;
  int bot = addVert(&m, 0, 0, z[0]);
  std::vector<int> ring(nr, -1);
  for (int i = 1; i < nr - 1; i++) {
    ring[i] = m.nv();
    for (int k = 0; k < nseg; k++) {
      double a = 2 * M_PI * k / nseg;
      addVert(&m, r[i] * std::cos(a), r[i] * std::sin(a), z[i]);
    }
  }
  int top = addVert(&m, 0, 0, z[nr - 1]);
  for (int k = 0; k < nseg; k++) {
    int k1 = (k + 1) % nseg;
    addTri(&m, bot, ring[1] + k1, ring[1] + k);
    addTri(&m, top, ring[nr - 2] + k, ring[nr - 2] + k1);
    for (int i = 1; i < nr - 2; i++) {
      int a = ring[i] + k, b = ring[i] + k1, c = ring[i + 1] + k1, d = ring[i + 1] + k;
      addTri(&m, a, b, c);
      addTri(&m, a, c, d);
    }
  }
  return m;
}

static double volume(const Mesh& m) {
  return topology(m).volume;
}

// scale x, y (and z if all3) so the enclosed volume becomes vexact
static void fitVolume(Mesh* m, double vexact, bool all3) {
  double ratio = vexact / volume(*m);
  double s = all3 ? std::cbrt(ratio) : std::sqrt(ratio);
  for (int i = 0; i < m->nv(); i++) {
    m->v[3 * i] *= s;
    m->v[3 * i + 1] *= s;
    if (all3) m->v[3 * i + 2] *= s;
  }
}

Mesh tessellate(int type, const double size[3]) {
  std::vector<double> r, z;
  Mesh m;
  switch (type) {
    case mjGEOM_BOX:
      return box(size);
    case mjGEOM_SPHERE:
    case mjGEOM_ELLIPSOID: {
      for (int i = 0; i <= kSphereRings; i++) {
        double th = M_PI * i / kSphereRings;
        r.push_back(std::sin(th));
        z.push_back(-std::cos(th));
      }
      m = revolve(r, z);
      fitVolume(&m, 4 * M_PI / 3, true);  // unit sphere
      double s[3] = {size[0], size[0], size[0]};
      if (type == mjGEOM_ELLIPSOID) std::memcpy(s, size, sizeof(s));
      for (int i = 0; i < m.nv(); i++) {
        for (int j = 0; j < 3; j++) m.v[3 * i + j] *= s[j];
      }
      return m;
    }
    case mjGEOM_CYLINDER: {
      // size: radius, half length; flat caps are fans from the axis
      double R = size[0], h = size[1];
      r.push_back(0); z.push_back(-h);
      for (int i = 0; i <= kCylDiv; i++) {
        r.push_back(R);
        z.push_back(-h + 2 * h * i / kCylDiv);
      }
      r.push_back(0); z.push_back(h);
      m = revolve(r, z);
      fitVolume(&m, M_PI * R * R * 2 * h, false);
      return m;
    }
    case mjGEOM_CAPSULE: {
      double R = size[0], h = size[1];
      const int nc = kSphereRings / 2;
      for (int i = 0; i <= nc; i++) {  // bottom cap, pole to equator
        double th = 0.5 * M_PI * i / nc;
        r.push_back(R * std::sin(th));
        z.push_back(-h - R * std::cos(th));
      }
      for (int i = 1; i <= kCylDiv; i++) {
        r.push_back(R);
        z.push_back(-h + 2 * h * i / kCylDiv);
      }
      for (int i = 1; i <= nc; i++) {  // top cap, equator to pole
        double th = 0.5 * M_PI * (nc - i) / nc;
        r.push_back(R * std::sin(th));
        z.push_back(h + R * std::cos(th));
      }
      m = revolve(r, z);
      fitVolume(&m, M_PI * R * R * (2 * h + 4 * R / 3), false);
      return m;
    }
  }
  return m;
}

// index of the first vertex at the same position as each vertex
static std::vector<int> weldIndex(const Mesh& m, int* nunique) {
  std::map<std::tuple<double, double, double>, int> weld;
  std::vector<int> id(m.nv());
  for (int i = 0; i < m.nv(); i++) {
    auto key = std::make_tuple(m.v[3 * i], m.v[3 * i + 1], m.v[3 * i + 2]);
    id[i] = weld.emplace(key, (int)weld.size()).first->second;
  }
  *nunique = weld.size();
  return id;
}

// merge vertices at identical positions: MuJoCo 2.2 gives every OBJ face
// corner its own vertex, which would triple the per-vertex work
static Mesh weld(const Mesh& m) {
  int nu;
  std::vector<int> id = weldIndex(m, &nu);
  Mesh out;
  out.v.resize(3 * nu);
  for (int i = 0; i < m.nv(); i++) {
    for (int j = 0; j < 3; j++) out.v[3 * id[i] + j] = m.v[3 * i + j];
  }
  for (int i : m.f) out.f.push_back(id[i]);
  return out;
}

Topology topology(const Mesh& m) {
  int nu;
  std::vector<int> id = weldIndex(m, &nu);
  // directed edge counts: a closed, consistently wound mesh uses every
  // edge once in each direction
  std::map<std::pair<int, int>, int> dir;
  Topology t = {0, 0, 0};
  for (int f = 0; f < m.nf(); f++) {
    const int* v = &m.f[3 * f];
    const double* a = &m.v[3 * v[0]];
    const double* b = &m.v[3 * v[1]];
    const double* c = &m.v[3 * v[2]];
    // divergence theorem: V = sum a . (b x c) / 6
    t.volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                 a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
    for (int e = 0; e < 3; e++) {
      int p = id[v[e]], q = id[v[(e + 1) % 3]];
      if (p != q) dir[{p, q}]++;
    }
  }
  for (const auto& [e, n] : dir) {
    auto back = dir.find({e.second, e.first});
    int nb = back == dir.end() ? 0 : back->second;
    if (n > 1) t.nonmanifold++;
    if (nb == 0) {
      t.boundary++;
    } else if (n != nb && e.first < e.second) {
      t.nonmanifold++;
    }
  }
  return t;
}

// twice the area of triangle f, and its longest edge squared
static double area2(const Mesh& m, int f, double* lmax2) {
  const double* p[3];
  for (int e = 0; e < 3; e++) p[e] = &m.v[3 * m.f[3 * f + e]];
  double u[3], w[3], l2 = 0;
  for (int e = 0; e < 3; e++) {
    double s = 0;
    for (int j = 0; j < 3; j++) {
      double d = p[(e + 1) % 3][j] - p[e][j];
      s += d * d;
    }
    l2 = std::max(l2, s);
  }
  for (int j = 0; j < 3; j++) {
    u[j] = p[1][j] - p[0][j];
    w[j] = p[2][j] - p[0][j];
  }
  double c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  *lmax2 = l2;
  return std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}

static void flip(Mesh* m, int f) {
  std::swap(m->f[3 * f + 1], m->f[3 * f + 2]);
}

// triangles of each undirected edge (lo, hi), with +1 when a triangle runs
// lo -> hi and -1 when it runs hi -> lo
typedef std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> EdgeMap;

static EdgeMap edges(const Mesh& m) {
  EdgeMap e;
  for (int f = 0; f < m.nf(); f++) {
    for (int k = 0; k < 3; k++) {
      int p = m.f[3 * f + k], q = m.f[3 * f + (k + 1) % 3];
      if (p < q) e[{p, q}].push_back({f, 1});
      else e[{q, p}].push_back({f, -1});
    }
  }
  return e;
}

static void dropRepeats(Mesh* m, Repair* r) {
  // duplicates (any order or winding) and triangles with a repeated vertex
  // go first: a copy doubles (same winding) or cancels (opposite winding)
  // the pressure on its patch, and breaks the edge topology below
  std::map<std::array<int, 3>, int> seen;
  Mesh out;
  out.v = m->v;
  for (int f = 0; f < m->nf(); f++) {
    std::array<int, 3> k = {m->f[3 * f], m->f[3 * f + 1], m->f[3 * f + 2]};
    std::array<int, 3> s = k;
    std::sort(s.begin(), s.end());
    if (s[0] == s[1] || s[1] == s[2]) {
      r->degenerate++;
      continue;
    }
    if (!seen.emplace(s, f).second) {
      r->duplicate++;
      continue;
    }
    out.f.insert(out.f.end(), k.begin(), k.end());
  }
  *m = out;
}

// pieces: each triangle's connected piece; returns their count
static int orient(Mesh* m, const std::vector<char>& zero, std::vector<int>* pieces, Repair* r) {
  // orientation: neighbours across a two-triangle edge must run it in
  // opposite directions. Breadth-first over each connected piece, par[f]
  // says whether f disagrees with the piece's first triangle; the minority
  // is re-wound (ties keep the first triangle's winding)
  EdgeMap em = edges(*m);
  const int nf = m->nf();
  std::vector<int>& piece = *pieces;
  piece.assign(nf, -1);
  std::vector<int> par(nf, 0);
  std::vector<std::vector<int>> adj(nf);
  std::vector<std::vector<int>> same(nf);  // 1 when the pair runs the edge the same way
  for (const auto& [e, t] : em) {
    if (t.size() != 2) continue;
    adj[t[0].first].push_back(t[1].first);
    adj[t[1].first].push_back(t[0].first);
    int sm = t[0].second == t[1].second;
    same[t[0].first].push_back(sm);
    same[t[1].first].push_back(sm);
  }
  int np = 0;
  for (int f0 = 0; f0 < nf; f0++) {
    if (piece[f0] >= 0) continue;
    std::vector<int> q = {f0};
    piece[f0] = np;
    for (size_t i = 0; i < q.size(); i++) {
      int f = q[i];
      for (size_t j = 0; j < adj[f].size(); j++) {
        int g = adj[f][j];
        if (piece[g] >= 0) continue;
        piece[g] = np;
        par[g] = par[f] ^ same[f][j];
        q.push_back(g);
      }
    }
    int n[2] = {0, 0};
    for (int f : q) n[par[f]] += !zero[f];
    int bad = n[1] > n[0] ? 0 : 1;
    for (int f : q) {
      if (par[f] != bad) continue;
      flip(m, f);
      r->rewound += !zero[f];
    }
    np++;
  }
  return np;
}

static void closePieces(Mesh* m, const std::vector<int>& piece, int np, Repair* r) {
  const int nf = m->nf();
  // holes, non-manifold edges, and pieces that are closed but inside out
  EdgeMap em = edges(*m);
  std::vector<char> open(np, 0);
  for (const auto& [e, t] : em) {
    if (t.size() == 1) {
      r->boundary++;
      open[piece[t[0].first]] = 1;
    } else if (t.size() > 2 || t[0].second == t[1].second) {
      r->nonmanifold++;
      for (const auto& ft : t) open[piece[ft.first]] = 1;
    }
  }
  std::vector<double> vol(np, 0);
  for (int f = 0; f < nf; f++) {
    const double* a = &m->v[3 * m->f[3 * f]];
    const double* b = &m->v[3 * m->f[3 * f + 1]];
    const double* c = &m->v[3 * m->f[3 * f + 2]];
    vol[piece[f]] += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                      a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  }
  for (int p = 0; p < np; p++) {
    if (open[p] || !(vol[p] < 0)) continue;
    r->inverted++;
    r->invvol += vol[p];
    for (int f = 0; f < nf; f++) if (piece[f] == p) flip(m, f);
  }
}

static void dropZero(Mesh* m, const std::vector<char>& zero, Repair* r) {
  const int nf = m->nf();
  // zero-area triangles carry no pressure
  Mesh out;
  out.v = m->v;
  for (int f = 0; f < nf; f++) {
    if (zero[f]) {
      r->degenerate++;
      continue;
    }
    out.f.insert(out.f.end(), m->f.begin() + 3 * f, m->f.begin() + 3 * f + 3);
  }
  *m = out;
}

Repair repair(Mesh* m) {
  Repair r;
  dropRepeats(m, &r);
  // zero area: height below 1e-6 of the longest edge, i.e. collinear to
  // within float precision. Kept through the topology (a sliver closing a
  // T-junction keeps the edges paired) and dropped at the end
  const int nf = m->nf();
  std::vector<char> zero(nf);
  for (int f = 0; f < nf; f++) {
    double l2, a2 = area2(*m, f, &l2);
    zero[f] = !(a2 > 1e-6 * l2);
  }
  std::vector<int> piece;
  const int np = orient(m, zero, &piece, &r);
  closePieces(m, piece, np, &r);
  dropZero(m, zero, &r);
  return r;
}

static std::string count(int n, const char* what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

static std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof(b), "%.3g", x);
  return b;
}

// a time step the heave cannot follow. Undamped heave of a wall-sided hull
// (mjbuoy adds no added mass): omega^2 = rho g A_wp / m. MuJoCo's
// semi-implicit Euler is unstable for omega dt > 2 (dt > T / pi) and
// inaccurate well before; warn above T / 10. A_wp is bounded by the hull's
// area projected on its body's xy plane, so the estimate of T is short (the
// warning errs on the safe side), and one hull of several on a body sees
// only its own share
static void stepCheck(const mjModel* m, int g, const Mesh& mesh, std::vector<std::string>* warn) {
  double a = 0;
  for (int f = 0; f < mesh.nf(); f++) {
    const double* p = &mesh.v[3 * mesh.f[3 * f]];
    const double* q = &mesh.v[3 * mesh.f[3 * f + 1]];
    const double* r = &mesh.v[3 * mesh.f[3 * f + 2]];
    double cz = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    if (cz < 0) a -= 0.5 * cz;  // downward-facing: the wetted bottom
  }
  double rho = 1000;
  int i = mj_name2id(m, mjOBJ_NUMERIC, "mjbuoy.sea.density");
  if (i >= 0 && m->numeric_size[i] == 1) rho = m->numeric_data[m->numeric_adr[i]];
  double mass = m->body_subtreemass[m->body_weldid[m->geom_bodyid[g]]];
  double G = -m->opt.gravity[2], dt = m->opt.timestep;
  if (!(a > 0) || !(mass > 0) || !(G > 0)) return;
  double T = 2 * M_PI * std::sqrt(mass / (rho * G * a));
  if (!(dt > T / 10)) return;
  warn->push_back("<option timestep=\"" + num(dt) + "\"> is too long for hull geom \"" +
                  (m->names + m->name_geomadr[g]) + "\": its heave period 2 pi sqrt(m / (rho g "
                  "A_wp)) is about " + num(T) + " s (m " + num(mass) + " kg, A_wp up to " +
                  num(a) + " m^2); a step above T/10 is inaccurate and above T/pi unstable "
                  "(the motion gains energy every step); use timestep <= " + num(T / 20));
}

std::string sizeError(const mjModel* m, int g) {
  static const char* kName[] = {"x half-size", "y half-size", "z half-size"};
  int t = m->geom_type[g], n = 0;
  const char* const* what = kName;
  static const char* kRound[] = {"radius", "half-length"};
  static const char* kEll[] = {"x radius", "y radius", "z radius"};
  if (t == mjGEOM_BOX) n = 3;
  if (t == mjGEOM_SPHERE) { n = 1; what = kRound; }
  if (t == mjGEOM_CYLINDER || t == mjGEOM_CAPSULE) { n = 2; what = kRound; }
  if (t == mjGEOM_ELLIPSOID) { n = 3; what = kEll; }
  static const char* kType[] = {"plane", "hfield", "sphere", "capsule", "ellipsoid",
                                "cylinder", "box", "mesh"};
  for (int j = 0; j < n; j++) {
    double v = m->geom_size[3 * g + j];
    if (v >= kMinSize) continue;
    char b[512];
    std::snprintf(b, sizeof(b),
                  "mjbuoy: hull geom \"%s\" (%s) is too small: its %s is %g m, below the "
                  "minimum %g m for a hull (below 0.1 mm surface tension, not buoyancy, "
                  "carries a body); give it a size of at least %g m",
                  m->names + m->name_geomadr[g], kType[t], what[j], v, kMinSize, kMinSize);
    return b;
  }
  return "";
}

Mesh hullMesh(const mjModel* m, int g, std::vector<std::string>* warn) {
  Mesh local;
  std::string gname = m->names + m->name_geomadr[g];
  if (m->geom_type[g] == mjGEOM_MESH) {
    // mesh_vert is already re-centred by the compiler; geom_pos/quat place it
    int id = m->geom_dataid[g];
    int v0 = m->mesh_vertadr[id], nv = m->mesh_vertnum[id];
    int f0 = m->mesh_faceadr[id], nf = m->mesh_facenum[id];
    for (int i = 0; i < nv; i++) {
      const float* p = m->mesh_vert + 3 * (v0 + i);
      addVert(&local, p[0], p[1], p[2]);
    }
    for (int i = 0; i < nf; i++) {
      const int* f = m->mesh_face + 3 * (f0 + i);
      addTri(&local, f[0], f[1], f[2]);
    }
    local = weld(local);
    Repair r = repair(&local);
    std::string pre = "hull geom \"" + gname + "\": ";
    if (r.duplicate) {
      warn->push_back(pre + count(r.duplicate, "duplicate triangle") +
                      " (the same three vertices as another) dropped: a copy would double, "
                      "or with opposite winding cancel, the pressure on its patch");
    }
    if (r.degenerate) {
      warn->push_back(pre + count(r.degenerate, "zero-area triangle") +
                      " dropped (they carry no pressure)");
    }
    if (r.rewound) {
      warn->push_back(pre + count(r.rewound, "triangle") + " wound against " +
                      (r.rewound == 1 ? "its" : "their") + " neighbours (mixed winding), "
                      "re-wound to match them; fix the mesh so every face is counter-clockwise "
                      "seen from outside");
    }
    if (r.inverted) {
      warn->push_back(pre + "normals look inverted (enclosed volume " + num(r.invvol) +
                      " m^3 < 0), turned outward; fix the face winding to counter-clockwise "
                      "seen from outside");
    }
    if (r.boundary || r.nonmanifold) {
      warn->push_back(pre + "mesh is not closed (" + count(r.boundary, "boundary edge") +
                      ", " + count(r.nonmanifold, "non-manifold edge") +
                      "); the pressure on the faces that are there still acts, so buoyancy "
                      "stays exact while the holes are dry and misses the pressure on any "
                      "missing surface under water");
    }
    checkOverlap(local, gname, warn);
  } else {
    double s[3] = {m->geom_size[3 * g], m->geom_size[3 * g + 1], m->geom_size[3 * g + 2]};
    local = tessellate(m->geom_type[g], s);
  }
  // geom frame -> body frame
  Mesh out;
  out.f = local.f;
  out.v.resize(local.v.size());
  const mjtNum* gp = m->geom_pos + 3 * g;
  const mjtNum* gq = m->geom_quat + 4 * g;
  for (int i = 0; i < local.nv(); i++) {
    mjtNum p[3] = {local.v[3 * i], local.v[3 * i + 1], local.v[3 * i + 2]}, r[3];
    mju_rotVecQuat(r, p, gq);
    for (int j = 0; j < 3; j++) out.v[3 * i + j] = r[j] + gp[j];
  }
  stepCheck(m, g, out, warn);
  return out;
}

}  // namespace mjb
