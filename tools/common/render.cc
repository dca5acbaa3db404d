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

#include "seadraw.h"

namespace mjbsim {

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
  SeaPainter sea;      // sky, sea and wet hull parts (seadraw.h)
  HullFramer framer;   // free camera that follows the hulls

  bool makeContext(std::string* err);
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
  if (!p->sea.init(m, b, err)) return nullptr;

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
  if (p.o.camera.empty()) p.framer.update(p.m, p.b, d, (double)p.o.width / p.o.height, &p.cam);
  mjv_updateScene(p.m, d, &p.opt, nullptr, &p.cam, mjCAT_ALL, &p.scn);
  if (p.o.showForces) addForceArrows(p.m, p.b, d, &p.scn);
  addLines(p.b, d, &p.scn);
  mjrRect vp = {0, 0, p.o.width, p.o.height};
  mjr_setBuffer(mjFB_OFFSCREEN, &p.con);
  mjr_render(vp, &p.scn, &p.con);
  // sky, wet hull parts and sea into the same framebuffer (seadraw.h)
  p.sea.capture(d);
  p.sea.draw(p.scn, p.cam, vp, p.o.showWet);

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
