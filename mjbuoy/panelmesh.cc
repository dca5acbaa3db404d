// panel meshes (docs/physics.md section 13)
#include "panelmesh.h"

#include <cmath>

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

}  // namespace mjb
