// glx: release and restore a current GLX context around our EGL work
#include "gl/glx.h"

#include <dlfcn.h>
#include <link.h>

#include <cstring>
#include <mutex>
#include <string>

namespace mjb {
namespace {

struct Glx {
  void* (*getContext)();
  void* (*getDisplay)();
  unsigned long (*getDraw)();
  unsigned long (*getRead)();
  int (*makeCurrent)(void*, unsigned long, unsigned long, void*);
};

// path of a loaded libGLX (libglvnd) or libGL, found without touching the
// file system (dlopen of a library that is not loaded searches the disk)
int findLib(struct dl_phdr_info* info, size_t, void* out) {
  const char* base = std::strrchr(info->dlpi_name, '/');
  base = base ? base + 1 : info->dlpi_name;
  if (std::strncmp(base, "libGLX.so", 9) && std::strncmp(base, "libGL.so", 8)) return 0;
  *static_cast<std::string*>(out) = info->dlpi_name;
  return !std::strncmp(base, "libGLX.so", 9);  // prefer libGLX
}

// the GLX functions if GLX is loaded, else null; looked up again until
// found since the program may load GLX later
const Glx* glx() {
  static std::mutex mtx;
  static Glx fn;
  static bool found = false;
  std::lock_guard<std::mutex> lock(mtx);
  if (found) return &fn;
  std::string path;
  dl_iterate_phdr(findLib, &path);
  if (path.empty()) return nullptr;
  void* h = dlopen(path.c_str(), RTLD_LAZY | RTLD_NOLOAD);  // kept open: never unloaded
  if (!h) return nullptr;
  fn.getContext = reinterpret_cast<void* (*)()>(dlsym(h, "glXGetCurrentContext"));
  fn.getDisplay = reinterpret_cast<void* (*)()>(dlsym(h, "glXGetCurrentDisplay"));
  fn.getDraw = reinterpret_cast<unsigned long (*)()>(dlsym(h, "glXGetCurrentDrawable"));
  fn.getRead = reinterpret_cast<unsigned long (*)()>(dlsym(h, "glXGetCurrentReadDrawable"));
  fn.makeCurrent = reinterpret_cast<int (*)(void*, unsigned long, unsigned long, void*)>(
      dlsym(h, "glXMakeContextCurrent"));
  found = fn.getContext && fn.getDisplay && fn.getDraw && fn.getRead && fn.makeCurrent;
  if (!found) dlclose(h);
  return found ? &fn : nullptr;
}

}  // namespace

bool glxRelease(GlxCurrent* s) {
  *s = GlxCurrent();
  const Glx* g = glx();
  if (!g) return true;
  void* ctx = g->getContext();
  if (!ctx) return true;
  void* dpy = g->getDisplay();
  unsigned long draw = g->getDraw(), read = g->getRead();
  if (!g->makeCurrent(dpy, 0, 0, nullptr)) return false;
  s->dpy = dpy;
  s->ctx = ctx;
  s->draw = draw;
  s->read = read;
  return true;
}

bool glxRestore(GlxCurrent* s) {
  if (!s->ctx) return true;
  const Glx* g = glx();
  bool ok = g && g->makeCurrent(s->dpy, s->draw, s->read, s->ctx);
  *s = GlxCurrent();
  return ok;
}

}  // namespace mjb
