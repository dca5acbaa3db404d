// panel meshes (docs/physics.md section 13)
#include "radiation/panelmesh.h"

#include <cmath>
#include <cstdio>

namespace mjb {

namespace {

const double kPi = 3.14159265358979323846;

int addVert(PanelMesh* m, double x, double y, double z) {
  m->vert.push_back(x);
  m->vert.push_back(y);
  m->vert.push_back(z);
  return (int)m->vert.size() / 3 - 1;
}

// adds the quad (a, b, c, d) (d < 0: triangle), reversed when its normal
// points against dir
void addFace(PanelMesh* m, int a, int b, int c, int d, const double* dir) {
  const double* v = m->vert.data();
  int q = d < 0 ? a : d;
  double e1[3], e2[3];
  for (int k = 0; k < 3; k++) {
    e1[k] = v[3 * c + k] - v[3 * a + k];
    e2[k] = v[3 * q + k] - v[3 * b + k];
  }
  if (d < 0)
    for (int k = 0; k < 3; k++) {
      e1[k] = v[3 * b + k] - v[3 * a + k];
      e2[k] = v[3 * c + k] - v[3 * a + k];
    }
  double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  bool flip = n[0] * dir[0] + n[1] * dir[1] + n[2] * dir[2] < 0;
  int f[4] = {a, b, c, d};
  if (flip) {
    if (d < 0) {
      f[1] = c;
      f[2] = b;
    } else {
      f[1] = d;
      f[3] = b;
    }
  }
  for (int k = 0; k < 4; k++) m->face.push_back(f[k]);
}

// waterplane disk of radius R: nr rings, na around, normals up
void diskMesh(double R, int nr, int na, PanelMesh* lid) {
  lid->vert.clear();
  lid->face.clear();
  const double up[3] = {0, 0, 1};
  int c = addVert(lid, 0, 0, 0);
  std::vector<int> ring(na), prev(na);
  for (int i = 1; i <= nr; i++) {
    double r = R * i / nr;
    for (int k = 0; k < na; k++) {
      double a = 2 * kPi * k / na;
      ring[k] = addVert(lid, r * std::cos(a), r * std::sin(a), 0);
    }
    for (int k = 0; k < na; k++) {
      int k1 = (k + 1) % na;
      if (i == 1)
        addFace(lid, c, ring[k], ring[k1], -1, up);
      else
        addFace(lid, prev[k], ring[k], ring[k1], prev[k1], up);
    }
    prev = ring;
  }
}

}  // namespace

void hemisphereMesh(double R, int nt, int na, PanelMesh* body, PanelMesh* lid) {
  body->vert.clear();
  body->face.clear();
  int pole = addVert(body, 0, 0, -R);
  std::vector<int> ring(na), prev(na);
  for (int i = 1; i <= nt; i++) {
    double t = 0.5 * kPi * i / nt;  // polar angle from the bottom
    for (int k = 0; k < na; k++) {
      double a = 2 * kPi * k / na;
      ring[k] = addVert(body, R * std::sin(t) * std::cos(a), R * std::sin(t) * std::sin(a),
                        i == nt ? 0 : -R * std::cos(t));
    }
    for (int k = 0; k < na; k++) {
      int k1 = (k + 1) % na;
      double tm = 0.5 * kPi * (i - 0.5) / nt, am = 2 * kPi * (k + 0.5) / na;
      double out[3] = {std::sin(tm) * std::cos(am), std::sin(tm) * std::sin(am), -std::cos(tm)};
      if (i == 1)
        addFace(body, pole, ring[k], ring[k1], -1, out);
      else
        addFace(body, prev[k], ring[k], ring[k1], prev[k1], out);
    }
    prev = ring;
  }
  diskMesh(R, nt / 2 > 1 ? nt / 2 : 1, na, lid);
}

void cylinderMesh(double R, double T, int nz, int nr, int na, PanelMesh* body, PanelMesh* lid) {
  body->vert.clear();
  body->face.clear();
  std::vector<int> ring(na), prev(na);
  // side, from the waterline down
  for (int i = 0; i <= nz; i++) {
    double z = -T * i / nz;
    for (int k = 0; k < na; k++) {
      double a = 2 * kPi * k / na;
      ring[k] = addVert(body, R * std::cos(a), R * std::sin(a), z);
    }
    if (i)
      for (int k = 0; k < na; k++) {
        int k1 = (k + 1) % na;
        double am = 2 * kPi * (k + 0.5) / na;
        double out[3] = {std::cos(am), std::sin(am), 0};
        addFace(body, prev[k], ring[k], ring[k1], prev[k1], out);
      }
    prev = ring;
  }
  // bottom, from the rim in
  const double down[3] = {0, 0, -1};
  for (int i = nr - 1; i >= 0; i--) {
    double r = R * i / nr;
    if (i == 0) {
      int c = addVert(body, 0, 0, -T);
      for (int k = 0; k < na; k++) addFace(body, c, prev[k], prev[(k + 1) % na], -1, down);
      break;
    }
    for (int k = 0; k < na; k++) {
      double a = 2 * kPi * k / na;
      ring[k] = addVert(body, r * std::cos(a), r * std::sin(a), -T);
    }
    for (int k = 0; k < na; k++) {
      int k1 = (k + 1) % na;
      addFace(body, prev[k], ring[k], ring[k1], prev[k1], down);
    }
    prev = ring;
  }
  diskMesh(R, nr, na, lid);
}

namespace {

// splits panel (3 or 4 points) into 4 by its edge midpoints (and centre for
// a quad), level times, appending to m
void addRefined(PanelMesh* m, const double (*p)[3], int n, int level) {
  if (level == 0) {
    int id[4] = {-1, -1, -1, -1};
    for (int k = 0; k < n; k++) id[k] = addVert(m, p[k][0], p[k][1], p[k][2]);
    for (int k = 0; k < 4; k++) m->face.push_back(id[k]);
    return;
  }
  double e[4][3], c[3] = {0, 0, 0};
  for (int k = 0; k < n; k++)
    for (int d = 0; d < 3; d++) {
      e[k][d] = 0.5 * (p[k][d] + p[(k + 1) % n][d]);
      c[d] += p[k][d] / n;
    }
  if (n == 3) {
    const double t[4][3][3] = {{{p[0][0], p[0][1], p[0][2]}, {e[0][0], e[0][1], e[0][2]}, {e[2][0], e[2][1], e[2][2]}},
                               {{e[0][0], e[0][1], e[0][2]}, {p[1][0], p[1][1], p[1][2]}, {e[1][0], e[1][1], e[1][2]}},
                               {{e[2][0], e[2][1], e[2][2]}, {e[1][0], e[1][1], e[1][2]}, {p[2][0], p[2][1], p[2][2]}},
                               {{e[0][0], e[0][1], e[0][2]}, {e[1][0], e[1][1], e[1][2]}, {e[2][0], e[2][1], e[2][2]}}};
    for (auto& q : t) addRefined(m, q, 3, level - 1);
    return;
  }
  for (int k = 0; k < 4; k++) {
    double q[4][3];
    const double* src[4] = {p[k], e[k], c, e[(k + 3) % 4]};
    for (int a = 0; a < 4; a++)
      for (int d = 0; d < 3; d++) q[a][d] = src[a][d];
    addRefined(m, q, 4, level - 1);
  }
}

// the vertices rotated by quat and raised by pos[2] (m), those within eps of z = 0 snapped
// onto it; false with a note if the pose or a vertex is not finite
bool posedVerts(const float* vert, int nvert, const double pos[3], const double quat[4],
                std::vector<double>* out, double* epsOut, std::string* note) {
  char b[240];
  // rotation of the body frame (unit quaternion w, x, y, z)
  double w = quat[0], x = quat[1], y = quat[2], z = quat[3];
  double qn = std::sqrt(w * w + x * x + y * y + z * z);
  if (!(qn > 0) || !std::isfinite(qn) || !std::isfinite(pos[2])) {
    *note = "hull panels: the pose is not finite or its quaternion is zero";
    return false;
  }
  w /= qn, x /= qn, y /= qn, z /= qn;
  const double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                       2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                       2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
  double scale = 0;
  std::vector<double>& v = *out;
  v.assign(3 * nvert, 0.0);
  for (int i = 0; i < nvert; i++) {
    for (int r = 0; r < 3; r++) {
      v[3 * i + r] = R[3 * r] * vert[3 * i] + R[3 * r + 1] * vert[3 * i + 1] + R[3 * r + 2] * vert[3 * i + 2];
      if (!std::isfinite(v[3 * i + r])) {
        std::snprintf(b, sizeof b, "hull panels: vertex %d is not finite", i);
        *note = b;
        return false;
      }
      scale = std::fmax(scale, std::fabs(v[3 * i + r]));
    }
    v[3 * i + 2] += pos[2];
  }
  double eps = 1e-9 * (1 + scale);
  for (int i = 0; i < nvert; i++)
    if (std::fabs(v[3 * i + 2]) < eps) v[3 * i + 2] = 0;
  *epsOut = eps;
  return true;
}

// clips each triangle to z <= 0 (Sutherland-Hodgman against one plane) into body, refined;
// the clipped edges on z = 0 are the waterline segments, 6 numbers each, in seg
bool clipBelow(const std::vector<double>& v, int nvert, const int* face, int nface, double eps,
               int refine, PanelMesh* body, std::vector<double>* seg, std::string* note) {
  char b[240];
  for (int f = 0; f < nface; f++) {
    const int* t = face + 3 * f;
    for (int k = 0; k < 3; k++)
      if (t[k] < 0 || t[k] >= nvert) {
        std::snprintf(b, sizeof b, "hull panels: face %d vertex index %d outside 0..%d", f, t[k], nvert - 1);
        *note = b;
        return false;
      }
    double p[4][3];
    int n = 0;
    for (int k = 0; k < 3; k++) {
      const double* a = &v[3 * t[k]];
      const double* c = &v[3 * t[(k + 1) % 3]];
      bool ain = a[2] <= 0, cin = c[2] <= 0;
      if (ain) {
        p[n][0] = a[0], p[n][1] = a[1], p[n][2] = a[2];
        n++;
      }
      if (ain != cin && a[2] != 0 && c[2] != 0) {
        double s = a[2] / (a[2] - c[2]);
        for (int d = 0; d < 2; d++) p[n][d] = a[d] + s * (c[d] - a[d]);
        p[n][2] = 0;
        n++;
      }
    }
    if (n < 3) continue;
    // waterline segments: consecutive clipped points both on z = 0
    for (int k = 0; k < n; k++) {
      const double* a = p[k];
      const double* c = p[(k + 1) % n];
      if (a[2] == 0 && c[2] == 0 && (a[0] != c[0] || a[1] != c[1]))
        seg->insert(seg->end(), {a[0], a[1], 0.0, c[0], c[1], 0.0});
    }
    double e1[3], e2[3];
    for (int d = 0; d < 3; d++) {
      e1[d] = p[1][d] - p[0][d];
      e2[d] = p[n - 1][d] - p[0][d];
    }
    double cr[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    if (std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]) < eps * eps) continue;  // sliver
    addRefined(body, p, n, refine);
  }
  return true;
}

// lid: fan of the waterline segments about the waterplane centroid; a note when there is none
void waterplaneLid(const std::vector<double>& seg, double eps, int refine, PanelMesh* lid,
                   std::string* note) {
  int ns = (int)seg.size() / 6;
  double area = 0, cx = 0, cy = 0;
  for (int s = 0; s < ns; s++) {
    const double* a = &seg[6 * s];
    double cr = a[0] * a[4] - a[3] * a[1];  // 2 x signed area of (0, a, c)
    area += 0.5 * cr;
    cx += cr * (a[0] + a[3]) / 6;
    cy += cr * (a[1] + a[4]) / 6;
  }
  if (ns < 3 || std::fabs(area) < eps * eps) {
    *note = "hull panels: no waterplane (the hull does not pierce the surface); no lid";
    return;
  }
  cx /= area, cy /= area;
  for (int s = 0; s < ns; s++) {
    const double* a = &seg[6 * s];
    double cr = (a[0] - cx) * (a[4] - cy) - (a[3] - cx) * (a[1] - cy);
    if (cr * area < -eps * eps) {
      *note = "hull panels: the waterplane is not star-shaped about its centroid (several hulls?); no lid";
      return;
    }
  }
  for (int s = 0; s < ns; s++) {
    const double* a = &seg[6 * s];
    double cr = (a[0] - cx) * (a[4] - cy) - (a[3] - cx) * (a[1] - cy);
    if (std::fabs(cr) < eps * eps) continue;
    double q[3][3] = {{cx, cy, 0}, {a[0], a[1], 0}, {a[3], a[4], 0}};
    addRefined(lid, q, 3, refine);
  }
}

}  // namespace

bool hullPanels(const float* vert, int nvert, const int* face, int nface, const double pos[3],
                const double quat[4], int refine, PanelMesh* body, PanelMesh* lid, std::string* note) {
  body->vert.clear();
  body->face.clear();
  lid->vert.clear();
  lid->face.clear();
  note->clear();
  char b[240];
  if (refine < 0 || refine > 4) {
    std::snprintf(b, sizeof b, "hull panels: refine = %d, accepted 0..4", refine);
    *note = b;
    return false;
  }
  std::vector<double> v;
  double eps = 0;
  if (!posedVerts(vert, nvert, pos, quat, &v, &eps, note)) return false;
  std::vector<double> seg;  // 6 per segment, in the triangle's order
  if (!clipBelow(v, nvert, face, nface, eps, refine, body, &seg, note)) return false;
  if (body->face.empty()) {
    *note = "hull panels: no triangle is below the mean free surface at this pose";
    return false;
  }
  waterplaneLid(seg, eps, refine, lid, note);
  return true;
}

}  // namespace mjb
