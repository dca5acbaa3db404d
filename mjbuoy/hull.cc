// hull meshes: mesh geoms as compiled, primitives tessellated
#include "hull.h"

#include <cmath>
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
    Topology t = topology(local);
    if (t.boundary || t.nonmanifold) {
      warn->push_back("hull geom \"" + gname + "\": mesh is not closed (" +
                      std::to_string(t.boundary) + " boundary edges, " +
                      std::to_string(t.nonmanifold) +
                      " non-manifold or inconsistently wound edges); buoyancy is exact "
                      "only for closed, outward-oriented meshes");
    }
    if (t.volume < 0) {
      warn->push_back("hull geom \"" + gname + "\": normals look inverted (enclosed "
                      "volume " + std::to_string(t.volume) +
                      " m^3 < 0); fix the face winding to counter-clockwise seen from outside");
    }
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
  return out;
}

}  // namespace mjb
