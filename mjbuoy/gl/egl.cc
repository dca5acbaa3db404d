// egl: headless GL context on Mesa's surfaceless EGL platform
#include "gl/egl.h"

#include <EGL/eglext.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace mjb {
namespace {

// is word in the space-separated list s
bool hasExt(const char* s, const char* word) {
  size_t n = std::strlen(word);
  for (const char* p = s; p && (p = std::strstr(p, word)); p += n) {
    if ((p == s || p[-1] == ' ') && (p[n] == ' ' || p[n] == 0)) return true;
  }
  return false;
}

std::string eglErr(const char* what) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), " (EGL error 0x%04X)", eglGetError());
  return what + std::string(buf);
}

GLADapiproc loadProc(const char* name) {
  return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name));
}

// the process-wide surfaceless display, initialized; EGL_NO_DISPLAY with
// the reason in err
EGLDisplay display(std::string* err) {
  const char* env = std::getenv("MJBUOY_EGL");
  if (env && !std::strcmp(env, "none")) {
    *err = "no EGL display: EGL is switched off by the environment (MJBUOY_EGL=none)";
    return EGL_NO_DISPLAY;
  }
  if (env && *env && std::strcmp(env, "surfaceless")) {
    *err = std::string("MJBUOY_EGL=") + env + ": unknown value (none, surfaceless or unset)";
    return EGL_NO_DISPLAY;
  }
  const char* ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExt(ext, "EGL_MESA_platform_surfaceless")) {
    *err = "no EGL display: libEGL lacks EGL_MESA_platform_surfaceless, "
           "Mesa's headless platform (is libegl-mesa0 installed?)";
    return EGL_NO_DISPLAY;
  }
  EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (dpy == EGL_NO_DISPLAY) {
    *err = eglErr("no EGL display: eglGetPlatformDisplay(surfaceless) failed");
    return EGL_NO_DISPLAY;
  }
  // initializing an initialized display is a no-op, so sharing it is fine
  EGLint major, minor;
  if (!eglInitialize(dpy, &major, &minor)) {
    *err = eglErr("no EGL display: eglInitialize of the surfaceless display failed "
                  "(is libgl1-mesa-dri installed?)");
    return EGL_NO_DISPLAY;
  }
  return dpy;
}

// a desktop GL context on dpy, newest first; a default one if neither
// version is there, so the caller can say which version the driver has
EGLContext makeContext(EGLDisplay dpy, std::string* err) {
  const char* ext = eglQueryString(dpy, EGL_EXTENSIONS);
  if (!hasExt(ext, "EGL_KHR_surfaceless_context")) {
    *err = "EGL display lacks EGL_KHR_surfaceless_context (contexts without a surface)";
    return EGL_NO_CONTEXT;
  }
  EGLConfig cfg = EGL_NO_CONFIG_KHR;
  if (!hasExt(ext, "EGL_KHR_no_config_context")) {
    const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLint n = 0;
    if (!eglChooseConfig(dpy, want, &cfg, 1, &n) || n < 1) {
      *err = eglErr("EGL display has no desktop OpenGL config");
      return EGL_NO_CONTEXT;
    }
  }
  const EGLint version[][2] = {{4, 5}, {4, 3}};
  EGLContext ctx = EGL_NO_CONTEXT;
  for (const EGLint* v : version) {
    const EGLint attr[] = {EGL_CONTEXT_MAJOR_VERSION, v[0], EGL_CONTEXT_MINOR_VERSION, v[1],
                           EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                           EGL_NONE};
    ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, attr);
    if (ctx != EGL_NO_CONTEXT) return ctx;
  }
  ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, nullptr);
  if (ctx == EGL_NO_CONTEXT) *err = eglErr("eglCreateContext of a desktop OpenGL context failed");
  return ctx;
}

}  // namespace

bool glCreate(GlContext* c, std::string* err) {
  *c = GlContext();
  EGLDisplay dpy = display(err);
  if (dpy == EGL_NO_DISPLAY) return false;

  // the bound API is per-thread state: put the caller's back
  EGLenum api = eglQueryAPI();
  if (!eglBindAPI(EGL_OPENGL_API)) {
    *err = eglErr("EGL has no desktop OpenGL (eglBindAPI(EGL_OPENGL_API) failed)");
    return false;
  }
  EGLContext ctx = makeContext(dpy, err);
  eglBindAPI(api);
  if (ctx == EGL_NO_CONTEXT) return false;
  c->dpy = dpy;
  c->ctx = ctx;

  bool ok = false;
  {
    GlCurrent cur(c);
    if (!cur.ok()) {
      *err = cur.error();
    } else if (!mjbLoadGLContext(&c->gl, loadProc) || !c->gl.GetString) {
      *err = "could not load the OpenGL functions (glad)";
    } else {
      auto str = [&](GLenum e) {
        const GLubyte* s = c->gl.GetString(e);
        return std::string(s ? reinterpret_cast<const char*>(s) : "?");
      };
      c->renderer = str(GL_RENDERER);
      c->version = str(GL_VERSION);
      c->gl.GetIntegerv(GL_MAJOR_VERSION, &c->major);
      c->gl.GetIntegerv(GL_MINOR_VERSION, &c->minor);
      // glad loads a version's functions only if the context has it
      ok = c->gl.VERSION_4_3 && c->gl.DispatchCompute;
      if (!ok) {
        *err = "mjbuoy's GL backend needs OpenGL 4.3 with compute shaders; " + c->renderer +
               " gives OpenGL " + c->version;
      }
    }
  }
  if (!ok) glDestroy(c);
  return ok;
}

void glDestroy(GlContext* c) {
  if (c->ctx != EGL_NO_CONTEXT) eglDestroyContext(c->dpy, c->ctx);
  *c = GlContext();
}

GlCurrent::GlCurrent(GlContext* c)
    : dpy_(c->dpy), ctx_(c->ctx), api_(eglQueryAPI()), pdpy_(eglGetCurrentDisplay()),
      pctx_(eglGetCurrentContext()), pdraw_(eglGetCurrentSurface(EGL_DRAW)),
      pread_(eglGetCurrentSurface(EGL_READ)) {
  if (ctx_ == EGL_NO_CONTEXT) {
    err_ = "no GL context (glCreate failed or was not called)";
    nested_ = true;
    return;
  }
  if (pctx_ == ctx_) {
    nested_ = ok_ = true;
    return;
  }
  if (pctx_ == EGL_NO_CONTEXT && !glxRelease(&glx_)) {
    err_ = "could not release the thread's current GLX context";
    nested_ = true;
    return;
  }
  eglBindAPI(EGL_OPENGL_API);
  if (!eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx_)) {
    err_ = eglErr("eglMakeCurrent of mjbuoy's GL context failed");
    return;
  }
  ok_ = true;
}

GlCurrent::~GlCurrent() {
  if (nested_) return;
  if (pctx_ != EGL_NO_CONTEXT) {
    eglMakeCurrent(pdpy_, pdraw_, pread_, pctx_);
  } else {
    eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  glxRestore(&glx_);
  eglBindAPI(api_);
}

}  // namespace mjb
