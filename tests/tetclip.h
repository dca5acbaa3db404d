// independent submerged volume: signed tetrahedra (origin + each face)
// clipped against the plane z = level. Shares no code with mjbuoy.
#ifndef MJBUOY_TESTS_TETCLIP_H_
#define MJBUOY_TESTS_TETCLIP_H_

#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <mujoco/mujoco.h>

namespace mjbt {

using Eigen::Vector3d;

struct VolumeMoment {
  double vol = 0;                       // [m^3]
  Vector3d mom = Vector3d::Zero();      // integral of r dV [m^4]
  Vector3d centroid() const { return mom / vol; }
};

// unsigned tet (a, b, c, d) counted with sign s
inline void addTet(const Vector3d& a, const Vector3d& b, const Vector3d& c,
                   const Vector3d& d, double s, VolumeMoment* vm) {
  double v = std::fabs((b - a).dot((c - a).cross(d - a))) / 6 * s;
  vm->vol += v;
  vm->mom += v * (a + b + c + d) / 4;
}

// part of tet p[4] (signed volume sign s) below z = level
inline void clipTet(const Vector3d p[4], double s, double level, VolumeMoment* vm) {
  int below[4], above[4], nb = 0, na = 0;
  for (int i = 0; i < 4; i++) {
    if (p[i].z() <= level) below[nb++] = i; else above[na++] = i;
  }
  auto cut = [&](int i, int j) {  // point on edge ij at z = level
    double t = (level - p[i].z()) / (p[j].z() - p[i].z());
    return Vector3d(p[i] + t * (p[j] - p[i]));
  };
  if (nb == 4) {
    addTet(p[0], p[1], p[2], p[3], s, vm);
  } else if (nb == 1) {
    int a = below[0];
    addTet(p[a], cut(a, above[0]), cut(a, above[1]), cut(a, above[2]), s, vm);
  } else if (nb == 3) {
    // whole minus the small tet above
    int a = above[0];
    addTet(p[0], p[1], p[2], p[3], s, vm);
    addTet(p[a], cut(a, below[0]), cut(a, below[1]), cut(a, below[2]), -s, vm);
  } else if (nb == 2) {
    // prism a, ac, ad / b, bc, bd split into three tets
    int a = below[0], b = below[1], c = above[0], d = above[1];
    Vector3d ac = cut(a, c), ad = cut(a, d), bc = cut(b, c), bd = cut(b, d);
    addTet(p[a], ac, ad, bd, s, vm);
    addTet(p[a], ac, bc, bd, s, vm);
    addTet(p[a], p[b], bc, bd, s, vm);
  }
}

// volume and first moment of the closed mesh (vertices v, faces f) below z = level
inline VolumeMoment submerged(const std::vector<Vector3d>& v, const std::vector<int>& f,
                              double level) {
  VolumeMoment vm;
  Vector3d o = Vector3d::Zero();
  for (size_t k = 0; k + 2 < f.size(); k += 3) {
    Vector3d p[4] = {o, v[f[k]], v[f[k + 1]], v[f[k + 2]]};
    double sv = (p[1] - o).dot((p[2] - o).cross(p[3] - o));
    if (sv == 0) continue;
    clipTet(p, sv > 0 ? 1 : -1, level, &vm);
  }
  return vm;
}

// the hull geom's vertices in world coordinates, from MuJoCo's own data
inline std::vector<Vector3d> worldVerts(const mjModel* m, const mjData* d, int g) {
  int id = m->geom_dataid[g];
  std::vector<Vector3d> out;
  Vector3d x(d->geom_xpos[3 * g], d->geom_xpos[3 * g + 1], d->geom_xpos[3 * g + 2]);
  Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> R(d->geom_xmat + 9 * g);
  for (int i = 0; i < m->mesh_vertnum[id]; i++) {
    const float* p = m->mesh_vert + 3 * (m->mesh_vertadr[id] + i);
    out.push_back(x + R * Vector3d(p[0], p[1], p[2]));
  }
  return out;
}

inline std::vector<int> faces(const mjModel* m, int g) {
  int id = m->geom_dataid[g];
  return std::vector<int>(m->mesh_face + 3 * m->mesh_faceadr[id],
                          m->mesh_face + 3 * (m->mesh_faceadr[id] + m->mesh_facenum[id]));
}

}  // namespace mjbt

#endif  // MJBUOY_TESTS_TETCLIP_H_
