// mjbuoy-hullgen: write a closed Wigley hull triangle mesh as Wavefront OBJ
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cliopt.h"
#include "outfile.h"
#include "mjbuoy_version.h"

// hull dimensions [m]: length, beam, draft, freeboard
struct Dims {
  double L = 4, B = 0.5, T = 0.25, F = 0.15;
};

struct Mesh {
  std::vector<double> v;  // vertices, 3 per vertex [m]
  std::vector<int> f;     // faces, 3 vertex indices each, counter-clockwise from outside
  int nv() const { return v.size() / 3; }
  int nf() const { return f.size() / 3; }
};

// triangles the construction below emits for an nx x nz grid
static long count(long nx, long nz) { return 4 * nx * nz + 2 * nx - 2; }

// grid with the triangle count closest to n, nx / nz in [2, 5]; ties keep the smallest nz
static void pickGrid(long n, int* nx, int* nz) {
  long best = -1;
  for (long z = 1; count(2 * z, z) <= n + best || best < 0; z++) {
    for (long x = 2 * z; x <= 5 * z; x++) {
      long e = std::labs(count(x, z) - n);
      if (best < 0 || e < best) {
        best = e;
        *nx = x;
        *nz = z;
      }
    }
  }
}

// half-breadth [m] at x, z: parabolic below the waterline, vertical sides above
static double halfBreadth(const Dims& d, double x, double z) {
  double u = 2 * x / d.L, w = z < 0 ? z / d.T : 0;
  return 0.5 * d.B * (1 - u * u) * (1 - w * w);
}

static int addVert(Mesh* m, double x, double y, double z) {
  m->v.insert(m->v.end(), {x, y, z});
  return m->nv() - 1;
}

static void addTri(Mesh* m, int a, int b, int c) {
  m->f.insert(m->f.end(), {a, b, c});
}

// vertices on the centre plane y = 0 are shared by both sides
static bool onCentre(const Mesh& m, int a) { return m.v[3 * a + 1] == 0; }

// quad q0 q1 q2 q3 (counter-clockwise), split along q0-q2, or q1-q3 when
// flip (mirror symmetry fore and aft); collapses to a triangle when two
// neighbours coincide; the diagonal avoids a triangle lying in y = 0, which
// port and starboard would both emit
static void addQuad(Mesh* m, int q0, int q1, int q2, int q3, bool flip) {
  int q[4] = {q0, q1, q2, q3}, u[4], n = 0;
  for (int k = 0; k < 4; k++) {
    if (q[k] != q[(k + 3) % 4]) u[n++] = q[k];
  }
  if (n == 3) return addTri(m, u[0], u[1], u[2]);
  if (n < 3) return;
  auto flat = [&](int a, int b, int c) {
    return onCentre(*m, a) && onCentre(*m, b) && onCentre(*m, c);
  };
  if (flip ? !(flat(u[0], u[1], u[3]) || flat(u[1], u[2], u[3]))
           : flat(u[0], u[1], u[2]) || flat(u[0], u[2], u[3])) {
    addTri(m, u[0], u[1], u[3]);
    addTri(m, u[1], u[2], u[3]);
  } else {
    addTri(m, u[0], u[1], u[2]);
    addTri(m, u[0], u[2], u[3]);
  }
}

// closed Wigley hull: two sides on an nx x nz grid of stations and levels,
// shared stems and keel, flat deck at z = F
static Mesh wigley(const Dims& d, int nx, int nz) {
  Mesh m;
  auto xs = [&](int i) { return d.L * (double(i) / nx - 0.5); };
  auto zs = [&](int j) { return -d.T + (d.T + d.F) * j / nz; };
  std::vector<int> keel(nx + 1), bow(nz + 1), stern(nz + 1);
  for (int i = 0; i <= nx; i++) keel[i] = addVert(&m, xs(i), 0, -d.T);
  stern[0] = keel[0];
  bow[0] = keel[nx];
  for (int j = 1; j <= nz; j++) {
    stern[j] = addVert(&m, xs(0), 0, zs(j));
    bow[j] = addVert(&m, xs(nx), 0, zs(j));
  }
  // side grids: s = 0 port (y > 0), s = 1 starboard (y < 0)
  std::vector<int> side[2];
  for (int s = 0; s < 2; s++) {
    side[s].resize((nx + 1) * (nz + 1));
    for (int i = 0; i <= nx; i++) {
      for (int j = 0; j <= nz; j++) {
        int& id = side[s][i * (nz + 1) + j];
        if (j == 0) id = keel[i];
        else if (i == 0) id = stern[j];
        else if (i == nx) id = bow[j];
        else id = addVert(&m, xs(i), (s ? -1 : 1) * halfBreadth(d, xs(i), zs(j)), zs(j));
      }
    }
  }
  auto at = [&](int s, int i, int j) { return side[s][i * (nz + 1) + j]; };
  for (int i = 0; i < nx; i++) {
    bool fore = 2 * i >= nx;  // mirrored diagonals in the fore half
    for (int j = 0; j < nz; j++) {
      int a[2], b[2], c[2], e[2];
      for (int s = 0; s < 2; s++) {
        a[s] = at(s, i, j), b[s] = at(s, i + 1, j);
        c[s] = at(s, i + 1, j + 1), e[s] = at(s, i, j + 1);
      }
      addQuad(&m, a[0], e[0], c[0], b[0], fore);  // port: normal +y
      addQuad(&m, a[1], b[1], c[1], e[1], fore);  // starboard: normal -y
    }
  }
  // deck: starboard to port, normal +z; the end quads collapse at the stems
  for (int i = 0; i < nx; i++) {
    addQuad(&m, at(1, i, nz), at(1, i + 1, nz), at(0, i + 1, nz), at(0, i, nz), 2 * i >= nx);
  }
  return m;
}

// enclosed volume [m^3] by the divergence theorem, sum a . (b x c) / 6
static double volume(const Mesh& m) {
  double v = 0;
  for (int k = 0; k < m.nf(); k++) {
    const double* a = &m.v[3 * m.f[3 * k]];
    const double* b = &m.v[3 * m.f[3 * k + 1]];
    const double* c = &m.v[3 * m.f[3 * k + 2]];
    v += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return v / 6;
}

// volume below z = 0 [m^3]: divergence theorem with the field (0, 0, z),
// which makes the cut face at z = 0 contribute nothing; each face is
// clipped to z <= 0 and adds (signed xy area) * (mean z)
static double volumeBelow(const Mesh& m) {
  double v = 0;
  for (int k = 0; k < m.nf(); k++) {
    std::vector<const double*> p;
    for (int e = 0; e < 3; e++) p.push_back(&m.v[3 * m.f[3 * k + e]]);
    std::vector<std::array<double, 3>> poly;
    for (int e = 0; e < 3; e++) {
      const double *a = p[e], *b = p[(e + 1) % 3];
      if (a[2] <= 0) poly.push_back({a[0], a[1], a[2]});
      if ((a[2] < 0) != (b[2] < 0) && a[2] != 0 && b[2] != 0) {
        double t = a[2] / (a[2] - b[2]);
        poly.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), 0});
      }
    }
    for (size_t i = 1; i + 1 < poly.size(); i++) {
      const auto &a = poly[0], &b = poly[i], &c = poly[i + 1];
      double axy = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
      v += axy * (a[2] + b[2] + c[2]) / 3;
    }
  }
  return v;
}

static bool writeObj(const Mesh& m, const Dims& d, int nx, int nz, FILE* out) {
  std::fprintf(out, "# Wigley hull by mjbuoy-hullgen: L %g B %g T %g F %g m, nx %d nz %d, "
               "%d vertices, %d triangles\n", d.L, d.B, d.T, d.F, nx, nz, m.nv(), m.nf());
  for (int i = 0; i < m.nv(); i++) {
    std::fprintf(out, "v %.9g %.9g %.9g\n", m.v[3 * i], m.v[3 * i + 1], m.v[3 * i + 2]);
  }
  for (int k = 0; k < m.nf(); k++) {
    std::fprintf(out, "f %d %d %d\n", m.f[3 * k] + 1, m.f[3 * k + 1] + 1, m.f[3 * k + 2] + 1);
  }
  return std::fflush(out) == 0 && !std::ferror(out);
}

int main(int argc, char** argv) {
  CLI::App app{"Write a closed Wigley hull triangle mesh (z up, x along the length, origin "
               "at midships on the design waterline) as Wavefront OBJ."};
  app.set_version_flag("--version", std::string("mjbuoy-hullgen ") + MJBUOY_VERSION_STRING);
  Dims d;
  long n = 576;
  std::string file;
  bool print = false;
  using mjbtool::Finite;
  const double big = mjbtool::kInf;
  app.add_option("--triangles", n, "target triangle count")->check(Finite(10, 1e8));
  app.add_option("--length", d.L, "length L [m]")->check(Finite(0, big, true));
  app.add_option("--beam", d.B, "beam B [m]")->check(Finite(0, big, true));
  app.add_option("--draft", d.T, "design draft T [m]")->check(Finite(0, big, true));
  app.add_option("--freeboard", d.F, "freeboard F [m]")->check(Finite(0, big, true));
  app.add_option("-o,--output", file, "OBJ file to write, replaced only when complete "
                 "(default: stdout)");
  app.add_flag("--print", print, "print grid, triangle count and volumes to stderr");
  {
    int rc = mjbtool::parseArgs(app, argc, argv, 1);  // docs: invalid input exits 1
    if (rc >= 0) return rc;
  }

  int nx = 0, nz = 0;
  pickGrid(n, &nx, &nz);
  Mesh m = wigley(d, nx, nz);
  if (m.nf() != count(nx, nz)) {
    std::fprintf(stderr, "mjbuoy-hullgen: internal error: %d triangles, expected %ld\n",
                 m.nf(), count(nx, nz));
    return 1;
  }
  mjbtool::OutFile of;
  std::string e;
  if (!file.empty() && !of.open(file, "-o", &e)) {
    std::fprintf(stderr, "mjbuoy-hullgen: %s\n", e.c_str());
    return 1;
  }
  bool ok = writeObj(m, d, nx, nz, file.empty() ? stdout : of.file());
  if (!ok || (!file.empty() && !of.commit(&e))) {
    if (e.empty()) e = std::string("write failed on ") + (file.empty() ? "stdout" : file.c_str());
    std::fprintf(stderr, "mjbuoy-hullgen: %s\n", e.c_str());
    return 1;
  }
  if (print) {
    std::fprintf(stderr, "nx %d nz %d: %d vertices, %d triangles (target %ld)\n", nx, nz,
                 m.nv(), m.nf(), n);
    std::fprintf(stderr, "enclosed volume %.9g m^3\n", volume(m));
    std::fprintf(stderr, "volume below the design waterline: mesh %.9g m^3, analytic "
                 "4/9 L B T %.9g m^3\n", volumeBelow(m), 4.0 / 9 * d.L * d.B * d.T);
  }
  return 0;
}
