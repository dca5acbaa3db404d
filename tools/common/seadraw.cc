// seadraw: sky, sea, wet hull parts and force arrows (see seadraw.h)
#include "seadraw.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "api/config.h"
#include "hull/hull.h"

namespace mjbsim {
namespace {

struct V3 {
  double x = 0, y = 0, z = 0;
};
V3 v3(double x, double y, double z) { V3 v; v.x = x; v.y = y; v.z = z; return v; }
V3 operator-(V3 a, V3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
V3 operator+(V3 a, V3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
V3 operator*(double s, V3 a) { return v3(s * a.x, s * a.y, s * a.z); }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) {
  return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
V3 unit(V3 a) {
  double n = std::sqrt(dot(a, a));
  return n > 0 ? (1 / n) * a : a;
}
double clamp01(double x) { return x < 0 ? 0 : x > 1 ? 1 : x; }
double smooth(double a, double b, double x) {
  double t = clamp01((x - a) / (b - a));
  return t * t * (3 - 2 * t);
}

const float kSky[3] = {0.80f, 0.87f, 0.93f};     // at the horizon
const float kZenith[3] = {0.36f, 0.56f, 0.82f};  // 45 degrees up and above
const float kSea[4] = {0.06f, 0.34f, 0.44f, 0.70f};

// the factor g > 1 with 1 + g + ... + g^(half - 1) = ratio: the grid's
// spacing grows by g a step to cover ratio first spacings in half steps
// (uniform, g = 1, when half steps are enough); by bisection
double growth(double ratio, int half) {
  if (ratio <= half) return 1;
  double lo = 1, hi = 2;
  auto sum = [&](double g) { return (std::pow(g, half) - 1) / (g - 1); };
  while (sum(hi) < ratio) hi *= 2;
  for (int it = 0; it < 60; it++) {
    double mid = 0.5 * (lo + hi);
    (sum(mid) < ratio ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace

const float kWetRgba[4] = {0.85f, 0.10f, 0.75f, 1};

bool SeaPainter::init(mjModel* m, const mjbBuoy* b, std::string* err) {
  m_ = m;
  b_ = b;
  std::memcpy(sea_, kSea, sizeof(kSea));
  for (int i = 0; i < m->nnumeric; i++) {
    const char* name = m->names + m->name_numericadr[i];
    const mjtNum* v = m->numeric_data + m->numeric_adr[i];
    int sz = m->numeric_size[i];
    if (!std::strcmp(name, "mjbuoy-sim.sea.rgba")) {
      if (sz != 4) {
        *err = "<numeric name=\"mjbuoy-sim.sea.rgba\"> needs 4 values (r g b a in [0, 1])";
        return false;
      }
      for (int k = 0; k < 4; k++) sea_[k] = (float)std::fmin(1.0, std::fmax(0.0, v[k]));
    } else if (!std::strcmp(name, "mjbuoy-sim.sea.extent")) {
      if (sz != 1 || !(v[0] > 0)) {
        *err = "<numeric name=\"mjbuoy-sim.sea.extent\"> needs 1 positive value (m)";
        return false;
      }
      extent_ = v[0];
    }
  }
  for (int t = 0; t < m->ntex; t++) skybox_ |= m->tex_type[t] == mjTEXTURE_SKYBOX;
  // the far plane must reach the sea's edge
  double far = std::max(400.0, 3 * extent_);
  if (m->stat.extent > 0) m->vis.map.zfar = std::max((double)m->vis.map.zfar, far / m->stat.extent);

  // the hull meshes the physics uses (mjb_attach has validated the entries)
  mjb::Config cfg;
  std::string e = mjb::parseConfig(m, &cfg);
  if (!e.empty()) {
    *err = e;
    return false;
  }
  // the surface stays within level -+ the sum of the amplitudes
  level_ = cfg.sea.level;
  amp_ = 0;
  for (const mjb::Wave& w : cfg.sea.waves) amp_ += std::fabs(w.amp);
  size_t nv = 0;
  for (int g : cfg.geom) {
    std::vector<std::string> warn;
    mjb::Mesh mesh = mjb::hullMesh(m, g, &warn);
    hulls_.push_back(Hull{m->geom_bodyid[g], mesh.v, mesh.f});
    nv = std::max(nv, mesh.v.size() / 3);
  }
  pose_.assign(12 * hulls_.size(), 0);
  world_.resize(3 * nv);
  height_.resize(nv);
  return true;
}

void SeaPainter::capture(const mjData* d) {
  time_ = d->time;
  for (size_t h = 0; h < hulls_.size(); h++) {
    int bd = hulls_[h].body;
    std::memcpy(&pose_[12 * h], d->xpos + 3 * bd, 3 * sizeof(double));
    std::memcpy(&pose_[12 * h + 3], d->xmat + 9 * bd, 9 * sizeof(double));
  }
}

void SeaPainter::draw(const mjvScene& scn, const mjvCamera& cam, mjrRect vp, bool wet) {
  mjvGLCamera c = mjv_averageCamera(scn.camera, scn.camera + 1);
  double halfw = 0.5 * (double)vp.width / vp.height * (c.frustum_top - c.frustum_bottom);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glViewport(vp.left, vp.bottom, vp.width, vp.height);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_CULL_FACE);
  glDisable(GL_FOG);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glFrustum(c.frustum_center - halfw, c.frustum_center + halfw, c.frustum_bottom, c.frustum_top,
            c.frustum_near, c.frustum_far);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  {
    V3 F = unit(v3(c.forward[0], c.forward[1], c.forward[2]));
    V3 U = unit(v3(c.up[0], c.up[1], c.up[2]));
    V3 S = unit(cross(F, U));
    U = cross(S, F);
    double M[16] = {S.x, U.x, -F.x, 0, S.y, U.y, -F.y, 0, S.z, U.z, -F.z, 0, 0, 0, 0, 1};
    glMultMatrixd(M);
    glTranslated(-c.pos[0], -c.pos[1], -c.pos[2]);
  }
  if (!skybox_) drawSky(c, halfw);
  if (wet) drawWet();
  drawSea(c, cam, halfw);
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  glPopMatrix();
  glPopAttrib();
}

// a vertical gradient where MuJoCo drew nothing (depth still cleared)
void SeaPainter::drawSky(const mjvGLCamera& c, double halfw) {
  V3 F = unit(v3(c.forward[0], c.forward[1], c.forward[2]));
  V3 U = unit(v3(c.up[0], c.up[1], c.up[2]));
  V3 R = cross(F, U);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  const int nb = 48;
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= nb; i++) {
    double y = -1 + 2.0 * i / nb;
    for (int sx = -1; sx <= 1; sx += 2) {
      double xr = c.frustum_center + sx * halfw;
      double yu = c.frustum_bottom + 0.5 * (y + 1) * (c.frustum_top - c.frustum_bottom);
      V3 dir = unit(c.frustum_near * F + xr * R + yu * U);
      double e = clamp01(std::asin(std::max(-1.0, std::min(1.0, dir.z))) / (M_PI / 4));
      e = std::sqrt(e);
      glColor4f(kSky[0] + e * (kZenith[0] - kSky[0]), kSky[1] + e * (kZenith[1] - kSky[1]),
                kSky[2] + e * (kZenith[2] - kSky[2]), 1);
      glVertex3f(sx, y, 1);
    }
  }
  glEnd();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  glPopMatrix();
}

// the wet part of every hull: each triangle cut by the plane through the
// surface heights at its vertices (the same linear cut of the vertex
// heights that the pressure integration uses), the part below drawn in
// kWetRgba, shaded by a light from above, pulled towards the camera in
// depth so it wins over MuJoCo's drawing of the same surface
void SeaPainter::drawWet() {
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_TRUE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-2, -8);
  const V3 light = unit(v3(0.3, -0.5, 1));
  for (size_t h = 0; h < hulls_.size(); h++) {
    const Hull& hl = hulls_[h];
    const double* p = &pose_[12 * h];
    const double* R = p + 3;
    int nv = (int)hl.v.size() / 3;
    for (int i = 0; i < nv; i++) {
      const double* q = &hl.v[3 * i];
      double* w = &world_[3 * i];
      for (int k = 0; k < 3; k++) w[k] = p[k] + R[3 * k] * q[0] + R[3 * k + 1] * q[1] + R[3 * k + 2] * q[2];
      height_[i] = w[2] - mjb_seaHeight(b_, w[0], w[1], time_);
    }
    glBegin(GL_TRIANGLES);
    for (size_t t = 0; t + 2 < hl.f.size(); t += 3) {
      const int* f = &hl.f[t];
      double hv[3] = {height_[f[0]], height_[f[1]], height_[f[2]]};
      if (hv[0] >= 0 && hv[1] >= 0 && hv[2] >= 0) continue;
      V3 a[3];
      for (int k = 0; k < 3; k++) a[k] = v3(world_[3 * f[k]], world_[3 * f[k] + 1], world_[3 * f[k] + 2]);
      double s = 0.45 + 0.55 * std::fabs(dot(unit(cross(a[1] - a[0], a[2] - a[0])), light));
      glColor4f(s * kWetRgba[0], s * kWetRgba[1], s * kWetRgba[2], 1);
      // the wet polygon: vertices below, and the crossings of the edges
      V3 poly[4];
      int n = 0;
      for (int k = 0; k < 3; k++) {
        int k1 = (k + 1) % 3;
        if (hv[k] < 0) poly[n++] = a[k];
        if ((hv[k] < 0) != (hv[k1] < 0)) {
          double u = hv[k] / (hv[k] - hv[k1]);
          poly[n++] = a[k] + u * (a[k1] - a[k]);
        }
      }
      for (int k = 1; k + 1 < n; k++) {
        for (const V3& v : {poly[0], poly[k], poly[k + 1]}) glVertex3d(v.x, v.y, v.z);
      }
    }
    glEnd();
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
}

// the sea: a square grid around the point of interest, spacing growing
// geometrically outwards, heights from the exact surface, shaded on the CPU
// (sun, sky reflection by a Fresnel term, highlight), faded into the sky
// colour at its edge
// vis_: 1 for the grid vertices (cx + u_[i], cy + u_[j]) whose heights
// between level_ -+ amp_ project into the view (5% margin), dilated by two
// cells; the cost of the sea's heights is then the visible part's
void SeaPainter::markVisible(const mjvGLCamera& c, double halfw, double cx, double cy, int n) {
  V3 eye = v3(c.pos[0], c.pos[1], c.pos[2]);
  V3 F = unit(v3(c.forward[0], c.forward[1], c.forward[2]));
  V3 U = unit(v3(c.up[0], c.up[1], c.up[2]));
  V3 S = unit(cross(F, U));
  U = cross(S, F);
  const double nr = c.frustum_near, m = 0.05 * (c.frustum_top - c.frustum_bottom);
  const double xlo = c.frustum_center - halfw - m, xhi = c.frustum_center + halfw + m;
  const double ylo = c.frustum_bottom - m, yhi = c.frustum_top + m;
  std::vector<char> seen((size_t)n * n, 0);
  for (int j = 0; j < n; j++) {
    for (int i = 0; i < n; i++) {
      bool in = false;
      for (double h : {level_ - amp_, level_ + amp_}) {
        V3 d = v3(cx + u_[i], cy + u_[j], h) - eye;
        double f = dot(d, F);
        if (f <= nr) continue;
        double x = nr * dot(d, S) / f, y = nr * dot(d, U) / f;
        in = in || (x >= xlo && x <= xhi && y >= ylo && y <= yhi);
      }
      // a column seen edge-on: its ends above and below the view
      if (!in) {
        V3 d0 = v3(cx + u_[i], cy + u_[j], level_ - amp_) - eye;
        V3 d1 = v3(cx + u_[i], cy + u_[j], level_ + amp_) - eye;
        double f0 = dot(d0, F), f1 = dot(d1, F);
        if (f0 > nr && f1 > nr) {
          double x = nr * dot(d0, S) / f0;
          double y0 = nr * dot(d0, U) / f0, y1 = nr * dot(d1, U) / f1;
          in = x >= xlo && x <= xhi && y0 < ylo && y1 > yhi;
        }
      }
      seen[(size_t)j * n + i] = in;
    }
  }
  vis_.assign((size_t)n * n, 0);
  const int r = 2;
  for (int j = 0; j < n; j++) {
    for (int i = 0; i < n; i++) {
      if (!seen[(size_t)j * n + i]) continue;
      for (int jj = std::max(0, j - r); jj <= std::min(n - 1, j + r); jj++) {
        for (int ii = std::max(0, i - r); ii <= std::min(n - 1, i + r); ii++) {
          vis_[(size_t)jj * n + ii] = 1;
        }
      }
    }
  }
}

void SeaPainter::drawSea(const mjvGLCamera& c, const mjvCamera& cam, double halfw) {
  V3 eye = v3(c.pos[0], c.pos[1], c.pos[2]);
  double cx = cam.lookat[0], cy = cam.lookat[1], dist = cam.distance;
  if (cam.type == mjCAMERA_FIXED) {
    // where the view axis meets the mean surface (or a point ahead)
    V3 F = v3(c.forward[0], c.forward[1], c.forward[2]);
    double h = eye.z - mjb_seaHeight(b_, eye.x, eye.y, time_);
    double s = F.z < -0.05 ? std::min(h / -F.z, 200.0) : 20.0;
    cx = eye.x + s * F.x;
    cy = eye.y + s * F.y;
    dist = std::max(5.0, std::sqrt((eye.x - cx) * (eye.x - cx) + (eye.y - cy) * (eye.y - cy) +
                                   h * h));
  }
  double R = extent_ > 0 ? extent_ : std::max(60.0, 6 * dist);
  double ds0 = std::max(0.05, dist / 80);
  // a level-of-detail grid of a fixed (2 kHalf + 1)^2 vertices: spacing ds0
  // at the centre, growing by a factor g a step out to R, so that its cost
  // (components x vertices, once a frame) depends neither on the pixels nor
  // on the distance
  const int half = kHalf, n = 2 * half + 1;
  const double g = growth(R / ds0, half);
  u_.resize(n);
  u_[half] = 0;
  for (int i = 1; i <= half; i++) {
    double step = ds0 * std::pow(g, i - 1);
    u_[half + i] = i == half ? R : u_[half + i - 1] + step;
    u_[half - i] = -u_[half + i];
  }
  const std::vector<double>& u = u_;
  // snap the centre so that the near grid does not swim with the camera
  cx = std::round(cx / ds0) * ds0;
  cy = std::round(cy / ds0) * ds0;
  z_.resize((size_t)n * n);
  col_.resize((size_t)4 * n * n);
  std::vector<float>& z = z_;
  // heights where the picture needs them: vertices whose column of possible
  // surface heights meets the view, and two cells around them (triangles
  // across the view's edge); the rest, unseen, lie at the mean level
  markVisible(c, halfw, cx, cy, n);
  for (int j = 0; j < n; j++) {
    for (int i = 0; i < n; i++) {
      z[j * n + i] = vis_[j * n + i] ? mjb_seaHeight(b_, cx + u[i], cy + u[j], time_) : level_;
    }
  }
  // the sea's own sun: low (30 degrees) ahead and to the left of the view,
  // so that slopes shade and the far water glitters; a light from straight
  // above (the usual MJCF light) would leave the sea flat
  V3 fw = unit(v3(c.forward[0], c.forward[1], 0));
  if (dot(fw, fw) < 0.5) fw = v3(0, 1, 0);
  V3 lf = cross(v3(0, 0, 1), fw);
  V3 sun = unit(std::cos(M_PI / 6) * unit(fw + 0.6 * lf) + v3(0, 0, std::sin(M_PI / 6)));
  for (int j = 0; j < n; j++) {
    for (int i = 0; i < n; i++) {
      int i0 = std::max(0, i - 1), i1 = std::min(n - 1, i + 1);
      int j0 = std::max(0, j - 1), j1 = std::min(n - 1, j + 1);
      double dzx = (z[j * n + i1] - z[j * n + i0]) / (u[i1] - u[i0]);
      double dzy = (z[j1 * n + i] - z[j0 * n + i]) / (u[j1] - u[j0]);
      V3 nrm = unit(v3(-dzx, -dzy, 1));
      V3 p = v3(cx + u[i], cy + u[j], z[j * n + i]);
      V3 view = unit(eye - p);
      double ndl = std::max(0.0, dot(nrm, sun));
      double ndv = std::max(0.0, dot(nrm, view));
      double fres = 0.04 + 0.96 * std::pow(1 - ndv, 5);
      V3 hv = unit(sun + view);
      double spec = 0.35 * std::pow(std::max(0.0, dot(nrm, hv)), 120);
      double r = std::sqrt(u[i] * u[i] + u[j] * u[j]);
      double fog = smooth(0.45 * R, 0.95 * R, r);
      float* o4 = &col_[4 * (j * n + i)];
      for (int k = 0; k < 3; k++) {
        double w = sea_[k] * (0.25 + 1.1 * ndl);
        w = w + fres * (kSky[k] - w) + spec;
        o4[k] = w + fog * (kSky[k] - w);
      }
      double alpha = sea_[3] + (1 - sea_[3]) * std::min(1.0, 2 * fres);
      o4[3] = alpha + fog * (1 - alpha);
    }
  }
  // one vertex array, drawn as strips through an index list built once
  xyz_.resize((size_t)3 * n * n);
  for (int j = 0; j < n; j++) {
    for (int i = 0; i < n; i++) {
      float* p = &xyz_[3 * (j * n + i)];
      p[0] = (float)(cx + u[i]);
      p[1] = (float)(cy + u[j]);
      p[2] = z[j * n + i];
    }
  }
  if (strip_.size() != (size_t)2 * n * (n - 1)) {
    strip_.resize((size_t)2 * n * (n - 1));
    for (int j = 0; j + 1 < n; j++) {
      for (int i = 0; i < n; i++) {
        strip_[2 * (j * n + i)] = (j + 1) * n + i;
        strip_[2 * (j * n + i) + 1] = j * n + i;
      }
    }
  }
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, xyz_.data());
  glColorPointer(4, GL_FLOAT, 0, col_.data());
  for (int j = 0; j + 1 < n; j++) {
    glDrawElements(GL_TRIANGLE_STRIP, 2 * n, GL_UNSIGNED_INT, &strip_[(size_t)2 * j * n]);
  }
  glPopClientAttrib();
}

void addForceArrows(const mjModel* m, const mjbBuoy* b, const mjData* d, mjvScene* scn) {
  const mjtNum* w = mjb_wrench(b, d);
  if (!w) return;
  for (int i = 1; i < m->nbody; i++) {
    const mjtNum* f = w + 6 * i;
    double fn = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    if (fn == 0 || scn->ngeom >= scn->maxgeom) continue;
    double r = 0.1;
    for (int g = 0; g < m->ngeom; g++) {
      if (m->geom_bodyid[g] == i) r = std::max(r, m->geom_rbound[g]);
    }
    double mg = std::max(1e-9, m->body_subtreemass[i] * std::fabs(m->opt.gravity[2]));
    double len = 1.6 * std::min(4.0, fn / mg) * r;
    const mjtNum* p = d->xipos + 3 * i;
    mjvGeom* g = scn->geoms + scn->ngeom++;
    const float rgba[4] = {0.95f, 0.15f, 0.1f, 1};
    mjv_initGeom(g, mjGEOM_ARROW, nullptr, nullptr, nullptr, rgba);
    mjv_makeConnector(g, mjGEOM_ARROW, 0.06 * r, p[0], p[1], p[2], p[0] + len * f[0] / fn,
                      p[1] + len * f[1] / fn, p[2] + len * f[2] / fn);
    g->category = mjCAT_DECOR;
  }
}

// the seabed under the lines (or 100 m around the origin without lines):
// a sand-coloured slab at the bed's height with a grid of dark lines at a
// round spacing, about ten across
static void addSeabed(const mjbBuoy* b, double lo[2], double hi[2], mjvScene* scn) {
  mjtNum z;
  if (!mjb_seabed(b, &z)) return;
  if (!(hi[0] >= lo[0])) lo[0] = lo[1] = -100, hi[0] = hi[1] = 100;
  const double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
  const double half = std::max(20.0, 0.6 * std::max(hi[0] - lo[0], hi[1] - lo[1]));
  const double step = std::pow(10.0, std::floor(std::log10(half / 5)));
  const double th = 0.01 * half;  // the slab's thickness, below the bed
  if (scn->ngeom >= scn->maxgeom) return;
  mjvGeom* g = scn->geoms + scn->ngeom++;
  const float sand[4] = {0.55f, 0.5f, 0.38f, 1};
  const mjtNum size[3] = {half, half, th}, pos[3] = {cx, cy, z - th};
  mjv_initGeom(g, mjGEOM_BOX, size, pos, nullptr, sand);
  g->category = mjCAT_DECOR;
  const float grid[4] = {0.35f, 0.32f, 0.25f, 1};
  const int n = int(std::floor(half / step));
  for (int i = -n; i <= n; i++) {
    for (int ax = 0; ax < 2 && scn->ngeom < scn->maxgeom; ax++) {
      const double u = (ax ? cy : cx) + i * step;
      mjtNum a[3], c[3];
      a[ax] = c[ax] = u;
      a[1 - ax] = (ax ? cx : cy) - half;
      c[1 - ax] = (ax ? cx : cy) + half;
      a[2] = c[2] = z + 1e-3 * half;
      mjvGeom* l = scn->geoms + scn->ngeom++;
      mjv_initGeom(l, mjGEOM_LINE, nullptr, nullptr, nullptr, grid);
      mjv_makeConnector(l, mjGEOM_LINE, 2, a[0], a[1], a[2], c[0], c[1], c[2]);
      l->category = mjCAT_DECOR;
    }
  }
}

void addLines(const mjbBuoy* b, const mjData* d, mjvScene* scn) {
  const int kMaxNodes = 1001;  // segments are at most 1000 (docs/mooring.md)
  static thread_local std::vector<mjtNum> p(3 * kMaxNodes);
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (int i = 0; i < mjb_lineCount(b); i++) {
    const int n = std::min(mjb_lineNodes(b, d, i, p.data(), kMaxNodes), kMaxNodes);
    double len = 0;
    for (int j = 1; j < n; j++) len += mju_dist3(&p[3 * j], &p[3 * j - 3]);
    const double r = std::max(0.05, 1e-3 * len);
    for (int j = 0; j < n; j++) {
      for (int k = 0; k < 2; k++) {
        lo[k] = std::min(lo[k], double(p[3 * j + k]));
        hi[k] = std::max(hi[k], double(p[3 * j + k]));
      }
    }
    for (int j = 1; j < n && scn->ngeom < scn->maxgeom; j++) {
      const mjtNum* a = &p[3 * j - 3];
      const mjtNum* c = &p[3 * j];
      mjvGeom* g = scn->geoms + scn->ngeom++;
      const float rgba[4] = {0.15f, 0.15f, 0.17f, 1};
      mjv_initGeom(g, mjGEOM_CAPSULE, nullptr, nullptr, nullptr, rgba);
      mjv_makeConnector(g, mjGEOM_CAPSULE, r, a[0], a[1], a[2], c[0], c[1], c[2]);
      g->category = mjCAT_DECOR;
    }
  }
  addSeabed(b, lo, hi, scn);
}

// the bodies to frame: those mjbuoy pushes on (hull bodies, wet at the
// start) and those with a free joint; all if there are none
void HullFramer::choose(const mjModel* m, const mjbBuoy* b, const mjData* d) {
  const mjtNum* w = mjb_wrench(b, d);
  for (int i = 1; w && i < m->nbody; i++) {
    bool any = false;
    for (int k = 0; k < 6; k++) any |= w[6 * i + k] != 0;
    if (any) bodies_.push_back(i);
  }
  // bodies with a free joint too: a hull above the water at t = 0 gets no force yet
  for (int j = 0; j < m->njnt; j++) {
    int bd = m->jnt_bodyid[j];
    if (m->jnt_type[j] == mjJNT_FREE &&
        std::find(bodies_.begin(), bodies_.end(), bd) == bodies_.end()) {
      bodies_.push_back(bd);
    }
  }
  if (bodies_.empty()) for (int i = 1; i < m->nbody; i++) bodies_.push_back(i);
}

// look at the middle of the bodies from the south, 25 degrees above the
// horizon, far enough for all to fit; follows them smoothly
void HullFramer::update(const mjModel* m, const mjbBuoy* b, const mjData* d, double aspect,
                        mjvCamera* cam) {
  if (bodies_.empty()) choose(m, b, d);
  if (bodies_.empty()) return;
  // body bounding radii from their geoms
  std::vector<double> rad(bodies_.size(), 0.1);
  for (int g = 0; g < m->ngeom; g++) {
    for (size_t k = 0; k < bodies_.size(); k++) {
      if (m->geom_bodyid[g] != bodies_[k]) continue;
      const mjtNum* gp = d->geom_xpos + 3 * g;
      const mjtNum* bp = d->xpos + 3 * bodies_[k];
      double dd = std::sqrt((gp[0] - bp[0]) * (gp[0] - bp[0]) + (gp[1] - bp[1]) * (gp[1] - bp[1]) +
                            (gp[2] - bp[2]) * (gp[2] - bp[2]));
      rad[k] = std::max(rad[k], dd + m->geom_rbound[g]);
    }
  }
  V3 lo = v3(1e300, 1e300, 1e300), hi = v3(-1e300, -1e300, -1e300);
  for (size_t k = 0; k < bodies_.size(); k++) {
    const mjtNum* p = d->xpos + 3 * bodies_[k];
    lo = v3(std::min(lo.x, p[0] - rad[k]), std::min(lo.y, p[1] - rad[k]), std::min(lo.z, p[2]));
    hi = v3(std::max(hi.x, p[0] + rad[k]), std::max(hi.y, p[1] + rad[k]), std::max(hi.z, p[2]));
  }
  V3 c = 0.5 * (lo + hi);
  const double az = 90 * M_PI / 180, el = -25 * M_PI / 180;
  V3 F = v3(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  V3 R = unit(cross(F, v3(0, 0, 1)));
  V3 U = cross(R, F);
  double tv = std::tan(0.5 * m->vis.global.fovy * M_PI / 180);
  double th = tv * aspect;
  double need = 1;
  for (size_t k = 0; k < bodies_.size(); k++) {
    const mjtNum* p = d->xpos + 3 * bodies_[k];
    V3 q = v3(p[0], p[1], p[2]) - c;
    double r = dot(q, R), u = dot(q, U), f = dot(q, F);
    need = std::max(need, (std::fabs(r) + rad[k]) / th - f);
    need = std::max(need, (std::fabs(u) + rad[k]) / tv - f);
  }
  need *= 1.1;
  double t = d->time;
  double a = framed_ ? 1 - std::exp(-std::max(0.0, t - lastTime_) / 1.5) : 1;
  lastTime_ = t;
  framed_ = true;
  cam->type = mjCAMERA_FREE;
  cam->azimuth = 90;
  cam->elevation = -25;
  cam->lookat[0] += a * (c.x - cam->lookat[0]);
  cam->lookat[1] += a * (c.y - cam->lookat[1]);
  cam->lookat[2] += a * (c.z - cam->lookat[2]);
  cam->distance += a * (need - cam->distance);
}

}  // namespace mjbsim
