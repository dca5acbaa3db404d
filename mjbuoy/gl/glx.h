// glx: save, release and restore a GLX context that is current on this
// thread, so the EGL context of egl.h can be made current (libglvnd allows
// one current context per thread across EGL and GLX). The GLX functions are
// looked up in an already loaded libGLX / libGL (dlopen RTLD_NOLOAD): a
// process that never loaded GLX cannot have a GLX context current, and
// mjbuoy does not link GLX or X11.
#ifndef MJBUOY_GLX_H_
#define MJBUOY_GLX_H_

namespace mjb {

// what the thread had current; X11 and GLX types as opaque values
struct GlxCurrent {
  void* dpy = nullptr;         // Display*
  void* ctx = nullptr;         // GLXContext, null: none was current
  unsigned long draw = 0;      // GLXDrawable
  unsigned long read = 0;
};

// if a GLX context is current on this thread, save it in s and release it;
// false if releasing failed
bool glxRelease(GlxCurrent* s);

// make the context saved by glxRelease current again (no-op if none);
// false if that failed
bool glxRestore(GlxCurrent* s);

}  // namespace mjb

#endif  // MJBUOY_GLX_H_
