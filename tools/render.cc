// render: headless pictures of an mjbuoy scene (see render.h)
#include "render.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <png.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

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

}  // namespace

struct Renderer::Impl {
  const mjbBuoy* b = nullptr;
  mjModel* m = nullptr;  // our copy, offscreen buffer resized
  RenderOptions o;
  EGLDisplay dpy = EGL_NO_DISPLAY;
  EGLContext ctx = EGL_NO_CONTEXT;
  mjvScene scn;
  mjvCamera cam;
  mjvOption opt;
  mjrContext con;
  bool made = false;
  float sea[4];
  double extent = 0;  // sea half-size [m]; 0: from the camera distance
  bool skybox = false;
  // free camera that follows the hulls
  std::vector<int> bodies;
  bool framed = false;
  double lastTime = 0;

  bool makeContext(std::string* err);
  void chooseBodies(const mjData* d);
  void frame(const mjData* d);
  void drawSky(const mjvGLCamera& c, double halfw);
  void drawSea(const mjData* d, const mjvGLCamera& c);
  void addForces(const mjData* d);
};

bool Renderer::Impl::makeContext(std::string* err) {
  dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, nullptr, nullptr)) {
    *err = "no headless EGL display (Mesa's surfaceless platform: packages libegl-mesa0 "
           "and libgl1-mesa-dri)";
    return false;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    *err = "EGL has no desktop OpenGL";
    return false;
  }
  const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                         EGL_NONE};
  EGLConfig cfg;
  EGLint n = 0;
  if (!eglChooseConfig(dpy, want, &cfg, 1, &n) || n < 1) {
    *err = "EGL display has no desktop OpenGL config";
    return false;
  }
  // MuJoCo 2.2's renderer is fixed-function: a compatibility profile
  const EGLint attr[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                         EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
  ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, attr);
  if (ctx == EGL_NO_CONTEXT) ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, nullptr);
  if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    char buf[64];
    std::snprintf(buf, sizeof(buf), " (EGL error 0x%04X)", eglGetError());
    *err = std::string("cannot create a current OpenGL context for rendering") + buf;
    return false;
  }
  return true;
}

// the bodies to frame: those mjbuoy pushes on (hull bodies, wet at the
// start) and those with a free joint; all if there are none
void Renderer::Impl::chooseBodies(const mjData* d) {
  const mjtNum* w = mjb_wrench(b, d);
  for (int i = 1; w && i < m->nbody; i++) {
    bool any = false;
    for (int k = 0; k < 6; k++) any |= w[6 * i + k] != 0;
    if (any) bodies.push_back(i);
  }
  // bodies with a free joint too: a hull above the water at t = 0 gets no force yet
  for (int j = 0; j < m->njnt; j++) {
    int bd = m->jnt_bodyid[j];
    if (m->jnt_type[j] == mjJNT_FREE && std::find(bodies.begin(), bodies.end(), bd) == bodies.end()) {
      bodies.push_back(bd);
    }
  }
  if (bodies.empty()) for (int i = 1; i < m->nbody; i++) bodies.push_back(i);
}

// free camera: look at the middle of the bodies from the south, 25 degrees
// above the horizon, far enough for all to fit; follows them smoothly
void Renderer::Impl::frame(const mjData* d) {
  if (bodies.empty()) chooseBodies(d);
  if (bodies.empty()) return;
  // body bounding radii from their geoms
  std::vector<double> rad(bodies.size(), 0.1);
  for (int g = 0; g < m->ngeom; g++) {
    for (size_t k = 0; k < bodies.size(); k++) {
      if (m->geom_bodyid[g] != bodies[k]) continue;
      const mjtNum* gp = d->geom_xpos + 3 * g;
      const mjtNum* bp = d->xpos + 3 * bodies[k];
      double dd = std::sqrt((gp[0] - bp[0]) * (gp[0] - bp[0]) + (gp[1] - bp[1]) * (gp[1] - bp[1]) +
                            (gp[2] - bp[2]) * (gp[2] - bp[2]));
      rad[k] = std::max(rad[k], dd + m->geom_rbound[g]);
    }
  }
  V3 lo = v3(1e300, 1e300, 1e300), hi = v3(-1e300, -1e300, -1e300);
  for (size_t k = 0; k < bodies.size(); k++) {
    const mjtNum* p = d->xpos + 3 * bodies[k];
    lo = v3(std::min(lo.x, p[0] - rad[k]), std::min(lo.y, p[1] - rad[k]), std::min(lo.z, p[2]));
    hi = v3(std::max(hi.x, p[0] + rad[k]), std::max(hi.y, p[1] + rad[k]), std::max(hi.z, p[2]));
  }
  V3 c = 0.5 * (lo + hi);
  const double az = 90 * M_PI / 180, el = -25 * M_PI / 180;
  V3 F = v3(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  V3 R = unit(cross(F, v3(0, 0, 1)));
  V3 U = cross(R, F);
  double tv = std::tan(0.5 * m->vis.global.fovy * M_PI / 180);
  double th = tv * o.width / o.height;
  double need = 1;
  for (size_t k = 0; k < bodies.size(); k++) {
    const mjtNum* p = d->xpos + 3 * bodies[k];
    V3 q = v3(p[0], p[1], p[2]) - c;
    double r = dot(q, R), u = dot(q, U), f = dot(q, F);
    need = std::max(need, (std::fabs(r) + rad[k]) / th - f);
    need = std::max(need, (std::fabs(u) + rad[k]) / tv - f);
  }
  need *= 1.1;
  double t = d->time;
  double a = framed ? 1 - std::exp(-std::max(0.0, t - lastTime) / 1.5) : 1;
  lastTime = t;
  framed = true;
  cam.type = mjCAMERA_FREE;
  cam.azimuth = 90;
  cam.elevation = -25;
  cam.lookat[0] += a * (c.x - cam.lookat[0]);
  cam.lookat[1] += a * (c.y - cam.lookat[1]);
  cam.lookat[2] += a * (c.z - cam.lookat[2]);
  cam.distance += a * (need - cam.distance);
}

// a vertical gradient where MuJoCo drew nothing (depth still cleared)
void Renderer::Impl::drawSky(const mjvGLCamera& c, double halfw) {
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

// the sea: a square grid around the point of interest, spacing growing
// geometrically outwards, heights from the exact surface, shaded on the CPU
// (sun, sky reflection by a Fresnel term, highlight), faded into the sky
// colour at its edge
void Renderer::Impl::drawSea(const mjData* d, const mjvGLCamera& c) {
  V3 eye = v3(c.pos[0], c.pos[1], c.pos[2]);
  double cx = cam.lookat[0], cy = cam.lookat[1], dist = cam.distance;
  if (cam.type == mjCAMERA_FIXED) {
    // where the view axis meets the mean surface (or a point ahead)
    V3 F = v3(c.forward[0], c.forward[1], c.forward[2]);
    double h = eye.z - mjb_seaHeight(b, eye.x, eye.y, d->time);
    double s = F.z < -0.05 ? std::min(h / -F.z, 200.0) : 20.0;
    cx = eye.x + s * F.x;
    cy = eye.y + s * F.y;
    dist = std::max(5.0, std::sqrt((eye.x - cx) * (eye.x - cx) + (eye.y - cy) * (eye.y - cy) +
                                   h * h));
  }
  double R = extent > 0 ? extent : std::max(60.0, 6 * dist);
  double ds0 = std::max(0.05, dist / 80);
  // axis samples: 0, +-ds0, ... growing by 3% a step up to R
  std::vector<double> ax{0};
  for (double s = 0, step = ds0; s < R; step *= 1.03) {
    s = std::min(R, s + step);
    ax.push_back(s);
  }
  int half = (int)ax.size() - 1;
  std::vector<double> u(2 * half + 1);
  for (int i = 0; i <= half; i++) {
    u[half + i] = ax[i];
    u[half - i] = -ax[i];
  }
  // snap the centre so that the near grid does not swim with the camera
  cx = std::round(cx / ds0) * ds0;
  cy = std::round(cy / ds0) * ds0;
  int n = (int)u.size();
  std::vector<float> z(n * n);
  for (int j = 0; j < n; j++) {
    for (int i = 0; i < n; i++) z[j * n + i] = mjb_seaHeight(b, cx + u[i], cy + u[j], d->time);
  }
  // the sea's own sun: low (30 degrees) ahead and to the left of the view,
  // so that slopes shade and the far water glitters; a light from straight
  // above (the usual MJCF light) would leave the sea flat
  V3 fw = unit(v3(c.forward[0], c.forward[1], 0));
  if (dot(fw, fw) < 0.5) fw = v3(0, 1, 0);
  V3 lf = cross(v3(0, 0, 1), fw);
  V3 sun = unit(std::cos(M_PI / 6) * unit(fw + 0.6 * lf) + v3(0, 0, std::sin(M_PI / 6)));
  std::vector<float> col(4 * n * n);
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
      float* o4 = &col[4 * (j * n + i)];
      for (int k = 0; k < 3; k++) {
        double w = sea[k] * (0.25 + 1.1 * ndl);
        w = w + fres * (kSky[k] - w) + spec;
        o4[k] = w + fog * (kSky[k] - w);
      }
      double alpha = sea[3] + (1 - sea[3]) * std::min(1.0, 2 * fres);
      o4[3] = alpha + fog * (1 - alpha);
    }
  }
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  for (int j = 0; j + 1 < n; j++) {
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i < n; i++) {
      for (int jj = j + 1; jj >= j; jj--) {
        glColor4fv(&col[4 * (jj * n + i)]);
        glVertex3d(cx + u[i], cy + u[jj], z[jj * n + i]);
      }
    }
    glEnd();
  }
}

// one arrow per body that mjbuoy pushes on: from the centre of mass along
// the force; its own weight is as long as the body's bounding radius
void Renderer::Impl::addForces(const mjData* d) {
  const mjtNum* w = mjb_wrench(b, d);
  if (!w) return;
  for (int i = 1; i < m->nbody; i++) {
    const mjtNum* f = w + 6 * i;
    double fn = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    if (fn == 0 || scn.ngeom >= scn.maxgeom) continue;
    double r = 0.1;
    for (int g = 0; g < m->ngeom; g++) {
      if (m->geom_bodyid[g] == i) r = std::max(r, m->geom_rbound[g]);
    }
    double mg = std::max(1e-9, m->body_subtreemass[i] * std::fabs(m->opt.gravity[2]));
    double len = 1.6 * std::min(4.0, fn / mg) * r;
    const mjtNum* p = d->xipos + 3 * i;
    mjvGeom* g = scn.geoms + scn.ngeom++;
    const float rgba[4] = {0.95f, 0.15f, 0.1f, 1};
    mjv_initGeom(g, mjGEOM_ARROW, nullptr, nullptr, nullptr, rgba);
    mjv_makeConnector(g, mjGEOM_ARROW, 0.06 * r, p[0], p[1], p[2], p[0] + len * f[0] / fn,
                      p[1] + len * f[1] / fn, p[2] + len * f[2] / fn);
    g->category = mjCAT_DECOR;
  }
}

std::unique_ptr<Renderer> Renderer::create(const mjModel* m0, const mjbBuoy* b,
                                           const RenderOptions& o, std::string* err) {
  if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192) {
    *err = "picture size must be between 16 and 8192 pixels a side";
    return nullptr;
  }
  Impl* p = new Impl;
  std::unique_ptr<Renderer> r(new Renderer(p));
  p->b = b;
  p->o = o;
  p->m = mj_copyModel(nullptr, m0);
  mjModel* m = p->m;
  // MuJoCo 2.2 sizes the offscreen buffer from these at mjr_makeContext
  m->vis.global.offwidth = o.width;
  m->vis.global.offheight = o.height;
  std::memcpy(p->sea, kSea, sizeof(kSea));
  for (int i = 0; i < m->nnumeric; i++) {
    const char* name = m->names + m->name_numericadr[i];
    const mjtNum* v = m->numeric_data + m->numeric_adr[i];
    int sz = m->numeric_size[i];
    if (!std::strcmp(name, "mjbuoy-sim.sea.rgba")) {
      if (sz != 4) {
        *err = "<numeric name=\"mjbuoy-sim.sea.rgba\"> needs 4 values (r g b a in [0, 1])";
        return nullptr;
      }
      for (int k = 0; k < 4; k++) p->sea[k] = (float)std::fmin(1.0, std::fmax(0.0, v[k]));
    } else if (!std::strcmp(name, "mjbuoy-sim.sea.extent")) {
      if (sz != 1 || !(v[0] > 0)) {
        *err = "<numeric name=\"mjbuoy-sim.sea.extent\"> needs 1 positive value (m)";
        return nullptr;
      }
      p->extent = v[0];
    }
  }
  for (int t = 0; t < m->ntex; t++) p->skybox |= m->tex_type[t] == mjTEXTURE_SKYBOX;

  mjv_defaultCamera(&p->cam);
  mjv_defaultOption(&p->opt);
  mjv_defaultScene(&p->scn);
  mjr_defaultContext(&p->con);
  if (!o.camera.empty()) {
    int id = mj_name2id(m, mjOBJ_CAMERA, o.camera.c_str());
    if (id < 0) {
      std::string names;
      for (int c = 0; c < m->ncam; c++) {
        names += std::string(names.empty() ? "" : ", ") + (m->names + m->name_camadr[c]);
      }
      *err = "no camera named \"" + o.camera + "\" in the model (" +
             (names.empty() ? std::string("it has none") : "it has: " + names) +
             "); leave --camera out for a free camera that follows the hulls";
      return nullptr;
    }
    p->cam.type = mjCAMERA_FIXED;
    p->cam.fixedcamid = id;
  }
  // the far plane must reach the sea's edge
  double far = std::max(400.0, 3 * p->extent);
  if (m->stat.extent > 0) m->vis.map.zfar = std::max((double)m->vis.map.zfar, far / m->stat.extent);

  if (!p->makeContext(err)) return nullptr;
  mjv_makeScene(m, &p->scn, m->ngeom + m->nbody + 2000);
  mjr_makeContext(m, &p->con, mjFONTSCALE_100);
  p->made = true;
  if (p->con.offWidth < o.width || p->con.offHeight < o.height) {
    *err = "the offscreen buffer is " + std::to_string(p->con.offWidth) + "x" +
           std::to_string(p->con.offHeight) + ", smaller than the request";
    return nullptr;
  }
  mjr_setBuffer(mjFB_OFFSCREEN, &p->con);
  if (p->con.currentBuffer != mjFB_OFFSCREEN) {
    *err = "MuJoCo's offscreen framebuffer is not available on this OpenGL context";
    return nullptr;
  }
  return r;
}

Renderer::~Renderer() {
  if (p_->made) {
    eglMakeCurrent(p_->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, p_->ctx);
    mjr_freeContext(&p_->con);
    mjv_freeScene(&p_->scn);
  }
  if (p_->ctx != EGL_NO_CONTEXT) {
    eglMakeCurrent(p_->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(p_->dpy, p_->ctx);
  }
  if (p_->m) mj_deleteModel(p_->m);
  delete p_;
}

std::string Renderer::describeCamera() const {
  char buf[256];
  const mjvCamera& c = p_->cam;
  if (c.type == mjCAMERA_FIXED) {
    std::snprintf(buf, sizeof(buf), "camera \"%s\" (model camera), fovy %g deg",
                  p_->o.camera.c_str(), p_->m->cam_fovy[c.fixedcamid]);
  } else {
    std::snprintf(buf, sizeof(buf),
                  "free camera: lookat %.4f %.4f %.4f distance %.4f azimuth %g elevation %g "
                  "fovy %g deg",
                  c.lookat[0], c.lookat[1], c.lookat[2], c.distance, c.azimuth, c.elevation,
                  p_->m->vis.global.fovy);
  }
  return buf;
}

int Renderer::width() const { return p_->o.width; }
int Renderer::height() const { return p_->o.height; }

bool Renderer::render(const mjData* d0, std::vector<unsigned char>* rgb, std::string* err) {
  Impl& p = *p_;
  // the gl backend's GlCurrent gives the context back, but be sure
  if (eglGetCurrentContext() != p.ctx &&
      !eglMakeCurrent(p.dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, p.ctx)) {
    *err = "cannot make the rendering context current";
    return false;
  }
  mjData* d = const_cast<mjData*>(d0);  // mjv_updateScene reads only
  if (p.o.camera.empty()) p.frame(d);
  mjv_updateScene(p.m, d, &p.opt, nullptr, &p.cam, mjCAT_ALL, &p.scn);
  if (p.o.showForces) p.addForces(d);
  mjrRect vp = {0, 0, p.o.width, p.o.height};
  mjr_setBuffer(mjFB_OFFSCREEN, &p.con);
  mjr_render(vp, &p.scn, &p.con);

  // sky and sea into the same framebuffer with MuJoCo's projection
  mjvGLCamera c = mjv_averageCamera(p.scn.camera, p.scn.camera + 1);
  double halfw = 0.5 * (double)vp.width / vp.height * (c.frustum_top - c.frustum_bottom);
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glViewport(0, 0, vp.width, vp.height);
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
  glLoadIdentity();
  glFrustum(c.frustum_center - halfw, c.frustum_center + halfw, c.frustum_bottom, c.frustum_top,
            c.frustum_near, c.frustum_far);
  glMatrixMode(GL_MODELVIEW);
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
  if (!p.skybox) p.drawSky(c, halfw);
  p.drawSea(d, c);
  glPopAttrib();

  rgb->resize((size_t)3 * vp.width * vp.height);
  mjr_readPixels(rgb->data(), nullptr, vp, &p.con);
  GLenum e = glGetError();
  if (e != GL_NO_ERROR) {
    char buf[64];
    std::snprintf(buf, sizeof(buf), "OpenGL error 0x%04X while rendering", e);
    *err = buf;
    return false;
  }
  return true;
}

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}

std::string findProgram(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream ss(path ? path : "");
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    if (dir.empty()) dir = ".";
    std::string f = dir + "/" + name;
    struct stat st;
    if (!stat(f.c_str(), &st) && S_ISREG(st.st_mode) && !access(f.c_str(), X_OK)) return dir;
  }
  return "";
}

VideoWriter::~VideoWriter() {
  std::string e;
  if (pipe_) close(&e);
}

bool VideoWriter::open(const std::string& path, const std::string& name, int w, int h,
                       double fps, std::string* err) {
  std::string dir = findProgram("ffmpeg");
  if (dir.empty()) {
    *err = "--render needs the ffmpeg program, which is not on PATH; install the Debian "
           "package ffmpeg (apt-get install ffmpeg)";
    return false;
  }
  path_ = path;
  name_ = name;
  width_ = w;
  height_ = h;
  const char* td = std::getenv("TMPDIR");
  std::string tmpl = std::string(td && *td ? td : "/tmp") + "/mjbuoy-ffmpeg-XXXXXX";
  std::vector<char> buf(tmpl.begin(), tmpl.end());
  buf.push_back(0);
  int fd = mkstemp(buf.data());
  if (fd < 0) {
    *err = "cannot create a temporary file for ffmpeg's log in " + tmpl.substr(0, tmpl.rfind('/')) +
           ": " + std::strerror(errno);
    return false;
  }
  ::close(fd);
  log_ = buf.data();
  char sz[64], rate[32];
  std::snprintf(sz, sizeof(sz), "%dx%d", w, h);
  std::snprintf(rate, sizeof(rate), "%.6g", fps);
  // H.264 needs even sizes: pad by one pixel if odd; -f mp4: the container
  // does not depend on the (temporary) file's name
  std::string cmd = shellQuote(dir + "/ffmpeg") +
                    " -nostdin -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgb24 -s " +
                    sz + " -r " + rate + " -i - -vf " +
                    shellQuote("vflip,pad=ceil(iw/2)*2:ceil(ih/2)*2") +
                    " -c:v libx264 -preset veryfast -crf 20 -pix_fmt yuv420p -movflags +faststart "
                    "-f mp4 " + shellQuote(path) + " 2>" + shellQuote(log_);
  pipe_ = popen(cmd.c_str(), "w");
  if (!pipe_) {
    *err = "cannot start ffmpeg: " + std::string(std::strerror(errno));
    std::remove(log_.c_str());
    log_.clear();
    return false;
  }
  return true;
}

// the last lines of ffmpeg's log (its own reason for failing)
static std::string readLog(const std::string& f) {
  std::ifstream in(f);
  std::vector<std::string> lines;
  std::string l;
  while (std::getline(in, l)) {
    if (!l.empty()) lines.push_back(l);
  }
  std::string s;
  size_t from = lines.size() > 4 ? lines.size() - 4 : 0;
  for (size_t i = from; i < lines.size(); i++) s += (s.empty() ? "" : " | ") + lines[i];
  return s;
}

bool VideoWriter::write(const std::vector<unsigned char>& rgb, std::string* err) {
  if (!pipe_) {
    *err = "video is not open";
    return false;
  }
  if (std::fwrite(rgb.data(), 1, rgb.size(), pipe_) != rgb.size() || std::fflush(pipe_) != 0) {
    std::string e;
    close(&e);
    *err = "ffmpeg stopped taking frames after " + std::to_string(frames_) + " while writing " +
           name_ + (e.empty() ? "" : "; " + e);
    return false;
  }
  frames_++;
  return true;
}

bool VideoWriter::close(std::string* err) {
  if (!pipe_) return true;
  std::fflush(pipe_);  // an EPIPE here shows in ffmpeg's status below
  int st = pclose(pipe_);
  pipe_ = nullptr;
  std::string log = readLog(log_);
  std::remove(log_.c_str());
  log_.clear();
  if (st == -1 || !WIFEXITED(st) || WEXITSTATUS(st) != 0) {
    char how[64] = "";
    if (st != -1 && WIFEXITED(st)) std::snprintf(how, sizeof(how), " (exit status %d)", WEXITSTATUS(st));
    if (st != -1 && WIFSIGNALED(st)) std::snprintf(how, sizeof(how), " (signal %d)", WTERMSIG(st));
    *err = "ffmpeg failed writing " + name_ + how +
           (log.empty() ? std::string(" and gave no reason") : ": " + log);
    return false;
  }
  return true;
}

bool writePng(FILE* f, const std::string& name, const std::vector<unsigned char>& rgb, int w,
              int h, std::string* err) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    *err = "libpng failed writing " + name;
    return false;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, w, h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = h - 1; y >= 0; y--) {
    png_write_row(png, const_cast<png_bytep>(rgb.data() + (size_t)3 * w * y));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  if (std::ferror(f)) {
    *err = "cannot write " + name + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

}  // namespace mjbsim
