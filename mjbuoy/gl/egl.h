// egl: the library's own headless OpenGL context (EGL, Mesa's surfaceless
// platform, no window and no surface), for the GL compute backend.
//
// The context is never left current: GlCurrent makes it current for a scope
// and then gives the calling thread back exactly what it had, so a program
// that renders with its own context (MuJoCo's mjr_* included) is not
// disturbed. One thread at a time may use a GlContext.
//
// EGL vs GLX: EGL cannot save or restore a GLX context, and libglvnd (how
// Debian ships Mesa) keeps ONE current context per thread across EGL and
// GLX: eglMakeCurrent fails with EGL_BAD_ACCESS while a GLX context is
// current. So when the thread has a GLX context current (a GLFW viewer on
// X11, say), GlCurrent looks it up with glXGetCurrent* (resolved with dlsym
// in an already loaded libGLX, never loading it: glx.h), releases it, does
// its work and makes it current again with glXMakeContextCurrent, same
// display, drawables and context. Its GL state (bindings, program) is
// untouched because it is a different context.
//
// The EGL display is the process-wide surfaceless display and is never
// terminated: EGL without EGL_KHR_display_reference (Mesa 22) does not count
// initializations, so eglTerminate would pull it from under any other user
// in the process. glDestroy destroys only our context.
//
// Environment: MJBUOY_EGL=none makes glCreate fail as if there were no EGL
// display (to test the fallbacks); unset, empty or "surfaceless" is the
// default. Any other value is an error.
#ifndef MJBUOY_EGL_H_
#define MJBUOY_EGL_H_

#include <string>

#include <glad/gl.h>
#include <EGL/egl.h>

#include "gl/glx.h"

namespace mjb {

struct GlContext {
  EGLDisplay dpy = EGL_NO_DISPLAY;
  EGLContext ctx = EGL_NO_CONTEXT;
  GladGLContext gl{};     // GL functions, call only while current
  int major = 0;          // GL version
  int minor = 0;
  std::string renderer;   // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version;    // GL_VERSION
};

// create c: surfaceless EGL display, desktop GL context (4.5 core, else 4.3
// core) with compute shaders, no surface; loads c->gl. false with the
// reason in err (c is then empty). Leaves the thread's current context as
// it was.
bool glCreate(GlContext* c, std::string* err);

// destroy c's context (not the shared display); c may be empty or current
void glDestroy(GlContext* c);

// makes c current on this thread for its lifetime, then restores the
// thread's EGL display, context, draw and read surfaces and bound API, or
// its GLX context (see above). Nests: a guard inside a guard of the same
// context does nothing.
class GlCurrent {
 public:
  explicit GlCurrent(GlContext* c);
  ~GlCurrent();
  GlCurrent(const GlCurrent&) = delete;
  GlCurrent& operator=(const GlCurrent&) = delete;

  bool ok() const { return ok_; }
  const std::string& error() const { return err_; }

 private:
  EGLDisplay dpy_;            // ours, kept in case c is destroyed inside
  EGLContext ctx_;
  EGLenum api_;               // the thread's before: bound API
  EGLDisplay pdpy_;           // current display, context and surfaces
  EGLContext pctx_;
  EGLSurface pdraw_, pread_;
  GlxCurrent glx_;            // or its GLX context
  bool nested_ = false, ok_ = false;
  std::string err_;
};

}  // namespace mjb

#endif  // MJBUOY_EGL_H_
