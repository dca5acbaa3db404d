// GL plumbing of the compute backend: headless EGL context, embedded
// programs, shared layouts, segmented reduction, timers, context hygiene
#include <dlfcn.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "gl/egl.h"
#include "gl/glprog.h"
#include "gl/gltimer.h"
#include "shared.h"

namespace mjb {
namespace {

using glsl::SelftestItem;
using glsl::SelftestSegment;

GLADapiproc eglProc(const char* name) {
  return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name));
}

// a caller's own EGL context, separate from the library's
struct Own {
  EGLDisplay dpy = EGL_NO_DISPLAY;
  EGLContext ctx = EGL_NO_CONTEXT;
  EGLSurface surf = EGL_NO_SURFACE;  // a 16x16 pbuffer, or none
  GladGLContext gl{};
};

// create o (compat or core 4.5 profile), make it current
::testing::AssertionResult makeOwn(Own* o, bool compat, bool pbuffer) {
  o->dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (o->dpy == EGL_NO_DISPLAY || !eglInitialize(o->dpy, nullptr, nullptr)) {
    return ::testing::AssertionFailure() << "no display";
  }
  eglBindAPI(EGL_OPENGL_API);
  const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                         EGL_NONE};
  EGLConfig cfg;
  EGLint n = 0;
  if (!eglChooseConfig(o->dpy, want, &cfg, 1, &n) || n < 1) {
    return ::testing::AssertionFailure() << "no config";
  }
  const EGLint attr[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                         compat ? EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT
                                : EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                         EGL_NONE};
  o->ctx = eglCreateContext(o->dpy, cfg, EGL_NO_CONTEXT, attr);
  if (o->ctx == EGL_NO_CONTEXT) return ::testing::AssertionFailure() << "no context";
  if (pbuffer) {
    const EGLint size[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
    o->surf = eglCreatePbufferSurface(o->dpy, cfg, size);
    if (o->surf == EGL_NO_SURFACE) return ::testing::AssertionFailure() << "no pbuffer";
  }
  if (!eglMakeCurrent(o->dpy, o->surf, o->surf, o->ctx)) {
    return ::testing::AssertionFailure() << "eglMakeCurrent failed";
  }
  if (!mjbLoadGLContext(&o->gl, eglProc)) return ::testing::AssertionFailure() << "no GL";
  return ::testing::AssertionSuccess();
}

void freeOwn(Own* o) {
  eglMakeCurrent(o->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (o->surf != EGL_NO_SURFACE) eglDestroySurface(o->dpy, o->surf);
  eglDestroyContext(o->dpy, o->ctx);
}

// a valid compute shader for the caller's contexts
const char* kCaller = R"(#version 430
layout(local_size_x = 1) in;
layout(std430, binding = 3) buffer B { float v[]; };
void main() { v[0] = 1.0; }
)";

// self test data: segments of uneven lengths (one empty) over the items
const int kSegLen[] = {1, 7, 64, 0, 1000, 3};

struct Selftest {
  std::vector<SelftestItem> item;
  std::vector<SelftestSegment> seg;
};

// exact: every product and partial sum is a multiple of 1/8 below 2^21, so
// float results do not depend on the order of the additions
Selftest exactData() {
  Selftest s;
  int start = 0;
  for (int len : kSegLen) {
    s.seg.push_back({start, len, -1, 0});
    start += len;
  }
  for (int i = 0; i < start; i++) {
    s.item.push_back({0.25f * (i % 17) - 2, 1 + 0.5f * (i % 5), float(i % 3) - 1, -1});
  }
  return s;
}

Selftest randomData() {
  Selftest s = exactData();
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1, 1);
  for (SelftestItem& it : s.item) it = {u(rng), u(rng), u(rng), -1};
  return s;
}

// run both stages of shaders/selftest.comp on s, read the results back
::testing::AssertionResult runSelftest(const GladGLContext& gl, GLuint prog, Selftest* s,
                                       GlTimer* timer = nullptr) {
  const int n = s->item.size(), nseg = s->seg.size();
  GLuint buf[2];
  gl.GenBuffers(2, buf);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[0]);
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, n * sizeof(SelftestItem), s->item.data(),
                GL_DYNAMIC_COPY);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[1]);
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, nseg * sizeof(SelftestSegment), s->seg.data(),
                GL_DYNAMIC_COPY);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, SELFTEST_ITEMS, buf[0]);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, SELFTEST_SEGMENTS, buf[1]);
  gl.UseProgram(prog);
  gl.Uniform1i(gl.GetUniformLocation(prog, "nitem"), n);
  GLint stage = gl.GetUniformLocation(prog, "stage");

  int t0 = timer ? timerStage(timer, "saxpy") : 0, t1 = timer ? timerStage(timer, "reduce") : 0;
  if (timer) timerBegin(timer, t0);
  gl.Uniform1i(stage, 0);
  gl.DispatchCompute((n + SELFTEST_LOCAL - 1) / SELFTEST_LOCAL, 1, 1);
  gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (timer) timerEnd(timer, t0);
  if (timer) timerBegin(timer, t1);
  gl.Uniform1i(stage, 1);
  gl.DispatchCompute(nseg, 1, 1);
  gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  if (timer) timerEnd(timer, t1);

  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[0]);
  gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, n * sizeof(SelftestItem), s->item.data());
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[1]);
  gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, nseg * sizeof(SelftestSegment),
                      s->seg.data());
  gl.DeleteBuffers(2, buf);
  gl.UseProgram(0);
  GLenum e = gl.GetError();
  if (e != GL_NO_ERROR) return ::testing::AssertionFailure() << "GL error 0x" << std::hex << e;
  return ::testing::AssertionSuccess();
}

// the self test's outputs against the CPU; exact, or to float precision
void checkSelftest(const Selftest& in, const Selftest& out, bool exact) {
  for (size_t i = 0; i < in.item.size(); i++) {
    const SelftestItem& it = in.item[i];
    double y = double(it.a) * it.x + it.b;
    if (exact) {
      ASSERT_EQ(out.item[i].y, float(y)) << "item " << i;
    } else {
      ASSERT_NEAR(out.item[i].y, y, 1e-6) << "item " << i;
    }
  }
  for (size_t k = 0; k < in.seg.size(); k++) {
    const SelftestSegment& sg = in.seg[k];
    double sum = 0, mag = 0;
    for (int i = sg.start; i < sg.start + sg.count; i++) {
      sum += double(in.item[i].a) * in.item[i].x + in.item[i].b;
      mag += std::fabs(out.item[i].y);
    }
    EXPECT_EQ(out.seg[k].start, sg.start);
    EXPECT_EQ(out.seg[k].count, sg.count);
    if (exact) {
      EXPECT_EQ(out.seg[k].sum, float(sum)) << "segment " << k << " of " << sg.count;
    } else {
      EXPECT_NEAR(out.seg[k].sum, sum, 1e-6 * (1 + mag)) << "segment " << k << " of " << sg.count;
    }
  }
}

TEST(GlContext, CreatesHeadlessContext) {
  GlContext c;
  std::string err;
  ASSERT_TRUE(glCreate(&c, &err)) << err;
  std::printf("GL_RENDERER: %s\nGL_VERSION: %s\n", c.renderer.c_str(), c.version.c_str());
  EXPECT_GE(c.major * 10 + c.minor, 43);
  EXPECT_TRUE(c.gl.DispatchCompute);
  // created without being left current
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  {
    GlCurrent cur(&c);
    ASSERT_TRUE(cur.ok()) << cur.error();
    EXPECT_EQ(eglGetCurrentContext(), c.ctx);
    EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), EGL_NO_SURFACE);
    GLint n = 0;
    c.gl.GetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &n);
    EXPECT_GE(n, 16384);
    {
      GlCurrent inner(&c);  // nested: a no-op
      EXPECT_TRUE(inner.ok());
    }
    EXPECT_EQ(eglGetCurrentContext(), c.ctx);
  }
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  glDestroy(&c);
  EXPECT_EQ(c.ctx, EGL_NO_CONTEXT);
  glDestroy(&c);  // twice is harmless
}

TEST(GlContext, CreateDestroyRepeatedly) {
  // the display is shared and stays initialized; contexts come and go
  for (int i = 0; i < 3; i++) {
    GlContext c;
    std::string err;
    ASSERT_TRUE(glCreate(&c, &err)) << err;
    glDestroy(&c);
  }
}

TEST(GlContext, MjbuoyEglNoneFails) {
  GlContext c;
  std::string err;
  setenv("MJBUOY_EGL", "none", 1);
  bool ok = glCreate(&c, &err);
  unsetenv("MJBUOY_EGL");
  EXPECT_FALSE(ok);
  EXPECT_NE(err.find("no EGL display"), std::string::npos) << err;
  EXPECT_NE(err.find("(MJBUOY_EGL=none)"), std::string::npos) << err;
  EXPECT_EQ(c.ctx, EGL_NO_CONTEXT);
  GlCurrent cur(&c);  // a guard on a failed context fails cleanly
  EXPECT_FALSE(cur.ok());

  setenv("MJBUOY_EGL", "bogus", 1);
  ok = glCreate(&c, &err);
  unsetenv("MJBUOY_EGL");
  EXPECT_FALSE(ok);
  EXPECT_NE(err.find("MJBUOY_EGL=bogus"), std::string::npos) << err;

  ASSERT_TRUE(glCreate(&c, &err)) << err;
  glDestroy(&c);
}

// run by CTest as gl.old_gl_fails with MESA_GL_VERSION_OVERRIDE=3.3, which
// Mesa reads once per process
TEST(GlContext, OldGlFails) {
  if (!std::getenv("MESA_GL_VERSION_OVERRIDE")) {
    GTEST_FAIL() << "needs MESA_GL_VERSION_OVERRIDE (ctest runs it as gl.old_gl_fails)";
  }
  GlContext c;
  std::string err;
  EXPECT_FALSE(glCreate(&c, &err));
  std::printf("%s\n", err.c_str());
  EXPECT_NE(err.find("needs OpenGL 4.3 with compute shaders"), std::string::npos) << err;
  EXPECT_EQ(c.ctx, EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
}

TEST(GlProgram, SelftestSharedLayoutsAndReduction) {
  GlContext c;
  std::string err;
  ASSERT_TRUE(glCreate(&c, &err)) << err;
  GlCurrent cur(&c);
  ASSERT_TRUE(cur.ok()) << cur.error();
  const GladGLContext& gl = c.gl;
  GLuint prog = glProgram(gl, "selftest.comp", &err);
  ASSERT_NE(prog, 0u) << err;

  // the driver's std430 layout is the C++ layout of shaders/shared.h
  auto offset = [&](const char* var, GLenum prop) {
    GLuint i = gl.GetProgramResourceIndex(prog, GL_BUFFER_VARIABLE, var);
    GLint v = -1;
    if (i != GL_INVALID_INDEX) gl.GetProgramResourceiv(prog, GL_BUFFER_VARIABLE, i, 1, &prop, 1,
                                                       nullptr, &v);
    return v;
  };
  EXPECT_EQ(offset("item[0].x", GL_TOP_LEVEL_ARRAY_STRIDE), GLint(sizeof(SelftestItem)));
  EXPECT_EQ(offset("item[0].x", GL_OFFSET), GLint(offsetof(SelftestItem, x)));
  EXPECT_EQ(offset("item[0].y", GL_OFFSET), GLint(offsetof(SelftestItem, y)));
  EXPECT_EQ(offset("seg[0].start", GL_TOP_LEVEL_ARRAY_STRIDE), GLint(sizeof(SelftestSegment)));
  EXPECT_EQ(offset("seg[0].sum", GL_OFFSET), GLint(offsetof(SelftestSegment, sum)));
  EXPECT_EQ(offset("seg[0].pad", GL_OFFSET), GLint(offsetof(SelftestSegment, pad)));

  Selftest in = exactData(), out = in;
  ASSERT_TRUE(runSelftest(gl, prog, &out));
  checkSelftest(in, out, true);

  // any values: close to the CPU, and the same bits every run
  Selftest rin = randomData(), r1 = rin, r2 = rin;
  ASSERT_TRUE(runSelftest(gl, prog, &r1));
  ASSERT_TRUE(runSelftest(gl, prog, &r2));
  checkSelftest(rin, r1, false);
  for (size_t k = 0; k < rin.seg.size(); k++) {
    EXPECT_EQ(std::memcmp(&r1.seg[k].sum, &r2.seg[k].sum, sizeof(float)), 0) << "segment " << k;
  }
  gl.DeleteProgram(prog);
}

TEST(GlProgram, EveryEmbeddedShaderBuilds) {
  GlContext c;
  std::string err;
  ASSERT_TRUE(glCreate(&c, &err)) << err;
  GlCurrent cur(&c);
  ASSERT_TRUE(cur.ok()) << cur.error();
  int n = 0;
  for (const char* name; (name = shaderName(n)); n++) {
    GLuint p = glProgram(c.gl, name, &err);
    EXPECT_NE(p, 0u) << err;
    c.gl.DeleteProgram(p);
  }
  EXPECT_GE(n, 1);
  const char* files = nullptr;
  ASSERT_TRUE(shaderSource("selftest.comp", &files));
  EXPECT_STREQ(files, "0 shaders/selftest.comp, 1 shaders/shared.h");
  EXPECT_EQ(shaderSource("nosuch.comp"), nullptr);
  EXPECT_EQ(glProgram(c.gl, "nosuch.comp", &err), 0u);
  EXPECT_NE(err.find("shaders/nosuch.comp"), std::string::npos) << err;
}

TEST(GlProgram, ErrorsNameTheShaderAndHaveTheLog) {
  GlContext c;
  std::string err;
  ASSERT_TRUE(glCreate(&c, &err)) << err;
  GlCurrent cur(&c);
  ASSERT_TRUE(cur.ok()) << cur.error();

  const char* broken = "#version 430\nlayout(local_size_x = 1) in;\nvoid main() {\n  float x = ;\n}\n";
  EXPECT_EQ(glProgramSource(c.gl, "broken.comp", broken, &err), 0u);
  std::printf("%s\n", err.c_str());
  EXPECT_EQ(err.rfind("broken.comp: compile failed:\n", 0), 0u) << err;
  EXPECT_NE(err.find("error"), std::string::npos) << err;  // the driver's log
  EXPECT_NE(err.find("0:4"), std::string::npos) << err;    // its line

  // compiles, but a compute program needs main: a link error
  const char* nomain = "#version 430\nlayout(local_size_x = 1) in;\nvoid f() {}\n";
  EXPECT_EQ(glProgramSource(c.gl, "nomain.comp", nomain, &err), 0u);
  std::printf("%s\n", err.c_str());
  EXPECT_EQ(err.rfind("nomain.comp: link failed:\n", 0), 0u) << err;
  EXPECT_GT(err.size(), std::strlen("nomain.comp: link failed:\n")) << err;
  EXPECT_EQ(c.gl.GetError(), GLenum(GL_NO_ERROR));
}

TEST(GlTimer, TimesStagesWithoutStalling) {
  GlContext c;
  std::string err;
  ASSERT_TRUE(glCreate(&c, &err)) << err;
  GlCurrent cur(&c);
  ASSERT_TRUE(cur.ok()) << cur.error();
  GLint bits = 0;
  c.gl.GetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
  EXPECT_GT(bits, 0);
  GLuint prog = glProgram(c.gl, "selftest.comp", &err);
  ASSERT_NE(prog, 0u) << err;

  GlTimer t;
  timerInit(&t, &c.gl, 2);
  const int nframe = 10;
  for (int f = 0; f < nframe; f++) {
    Selftest s = randomData();
    ASSERT_TRUE(runSelftest(c.gl, prog, &s, &t));
    timerFrame(&t);
  }
  long early = t.stage[0].n;  // collected by timerFrame, without waiting
  timerFlush(&t);
  ASSERT_EQ(t.stage.size(), 2u);
  for (const GlStage& s : t.stage) {
    EXPECT_EQ(s.n, nframe) << s.name;
    EXPECT_GE(s.last, 0) << s.name;
    EXPECT_LT(s.mean(), 1000) << s.name;  // [ms]
    std::printf("%-6s mean %.4f ms last %.4f ms over %ld frames\n", s.name.c_str(), s.mean(),
                s.last, s.n);
  }
  std::printf("%ld of %d saxpy results read before the flush\n", early, nframe);
  EXPECT_EQ(timerStage(&t, "saxpy"), 0);
  timerFree(&t);
  c.gl.DeleteProgram(prog);
  EXPECT_EQ(c.gl.GetError(), GLenum(GL_NO_ERROR));
}

TEST(GlCurrent, KeepsTheCallersEglContextAndBindings) {
  GlContext lib;
  std::string err;
  ASSERT_TRUE(glCreate(&lib, &err)) << err;

  // the caller: its own context on a pbuffer, a program and an SSBO bound;
  // a few extra names so its ids differ from the library's
  Own own;
  ASSERT_TRUE(makeOwn(&own, false, true));
  GLuint buf[4];
  own.gl.GenBuffers(4, buf);
  own.gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[3]);
  own.gl.BufferData(GL_SHADER_STORAGE_BUFFER, 64, nullptr, GL_DYNAMIC_DRAW);
  own.gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, buf[3]);
  own.gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[2]);
  GLuint prog = glProgramSource(own.gl, "caller.comp", kCaller, &err);
  ASSERT_NE(prog, 0u) << err;
  own.gl.UseProgram(prog);
  EGLenum api = eglQueryAPI();

  // library work in between
  {
    GlCurrent cur(&lib);
    ASSERT_TRUE(cur.ok()) << cur.error();
    EXPECT_EQ(eglGetCurrentContext(), lib.ctx);
    GLuint p = glProgram(lib.gl, "selftest.comp", &err);
    ASSERT_NE(p, 0u) << err;
    Selftest in = exactData(), out = in;
    ASSERT_TRUE(runSelftest(lib.gl, p, &out));
    checkSelftest(in, out, true);
    lib.gl.DeleteProgram(p);
  }

  EXPECT_EQ(eglGetCurrentContext(), own.ctx);
  EXPECT_EQ(eglGetCurrentDisplay(), own.dpy);
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), own.surf);
  EXPECT_EQ(eglGetCurrentSurface(EGL_READ), own.surf);
  EXPECT_EQ(eglQueryAPI(), api);
  GLint p = 0, b = 0, b3 = 0;
  own.gl.GetIntegerv(GL_CURRENT_PROGRAM, &p);
  own.gl.GetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &b);
  own.gl.GetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 3, &b3);
  EXPECT_EQ(GLuint(p), prog);
  EXPECT_EQ(GLuint(b), buf[2]);
  EXPECT_EQ(GLuint(b3), buf[3]);
  EXPECT_EQ(own.gl.GetError(), GLenum(GL_NO_ERROR));

  // the caller's context still computes
  own.gl.DispatchCompute(1, 1, 1);
  own.gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  float v = 0;
  own.gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[3]);
  own.gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(v), &v);
  EXPECT_EQ(v, 1.0f);

  // destroying the library's context leaves the shared display usable
  glDestroy(&lib);
  EXPECT_EQ(eglGetCurrentContext(), own.ctx);
  own.gl.DeleteProgram(prog);
  own.gl.DeleteBuffers(4, buf);
  freeOwn(&own);
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
}

TEST(GlCurrent, GuardCost) {
  GlContext c;
  std::string err;
  ASSERT_TRUE(glCreate(&c, &err)) << err;
  const int n = 1000;
  auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < n; i++) {
    GlCurrent cur(&c);
    ASSERT_TRUE(cur.ok());
  }
  double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
  std::printf("make current and restore: %.1f us\n", us / n);
  glDestroy(&c);
}

// MuJoCo's renderer on the caller's context draws the same picture before
// and after library GL work
TEST(GlCurrent, MujocoRendererUnaffected) {
  const char* xml = R"(<mujoco>
  <visual><global offwidth="64" offheight="48"/></visual>
  <worldbody>
    <light pos="0 0 3"/>
    <geom type="plane" size="2 2 .1" rgba=".2 .3 .4 1"/>
    <body pos="0 0 .5"><freejoint/><geom type="box" size=".2 .3 .1" rgba=".9 .1 .1 1"/></body>
  </worldbody>
</mujoco>)";
  std::unique_ptr<mjVFS> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  ASSERT_EQ(mj_makeEmptyFileVFS(vfs.get(), "scene.xml", std::strlen(xml)), 0);
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), "scene.xml")], xml, std::strlen(xml));
  char error[500] = "";
  mjModel* m = mj_loadXML("scene.xml", vfs.get(), error, sizeof(error));
  mj_deleteVFS(vfs.get());
  ASSERT_TRUE(m) << error;
  mjData* d = mj_makeData(m);
  mj_forward(m, d);

  GlContext lib;
  std::string err;
  ASSERT_TRUE(glCreate(&lib, &err)) << err;
  Own own;
  ASSERT_TRUE(makeOwn(&own, true, false));
  mjvScene scn;
  mjvCamera cam;
  mjvOption opt;
  mjrContext con;
  mjv_defaultScene(&scn);
  mjv_defaultCamera(&cam);
  mjv_defaultOption(&opt);
  mjr_defaultContext(&con);
  mjv_makeScene(m, &scn, 100);
  mjr_makeContext(m, &con, mjFONTSCALE_100);
  mjr_setBuffer(mjFB_OFFSCREEN, &con);
  cam.lookat[2] = 0.3;
  cam.distance = 3;
  mjrRect vp = {0, 0, 64, 48};
  auto render = [&]() {
    std::vector<unsigned char> rgb(3 * 64 * 48);
    mjv_updateScene(m, d, &opt, nullptr, &cam, mjCAT_ALL, &scn);
    mjr_render(vp, &scn, &con);
    mjr_readPixels(rgb.data(), nullptr, vp, &con);
    return rgb;
  };
  std::vector<unsigned char> before = render();
  {
    GlCurrent cur(&lib);
    ASSERT_TRUE(cur.ok()) << cur.error();
    GLuint p = glProgram(lib.gl, "selftest.comp", &err);
    ASSERT_NE(p, 0u) << err;
    Selftest s = exactData();
    ASSERT_TRUE(runSelftest(lib.gl, p, &s));
    lib.gl.DeleteProgram(p);
  }
  EXPECT_EQ(eglGetCurrentContext(), own.ctx);
  std::vector<unsigned char> after = render();
  EXPECT_EQ(before, after);
  int red = 0;  // the box is in the picture
  for (size_t i = 0; i < after.size(); i += 3) red += after[i] > 100 && after[i + 1] < 60;
  EXPECT_GT(red, 10);

  mjr_freeContext(&con);
  mjv_freeScene(&scn);
  freeOwn(&own);
  glDestroy(&lib);
  mj_deleteData(d);
  mj_deleteModel(m);
}

// GLX: minimal declarations, looked up at run time so the test links no X11
struct Glx {
  void* x11 = nullptr;
  void* glx = nullptr;
  void* (*openDisplay)(const char*);
  int (*closeDisplay)(void*);
  int (*defaultScreen)(void*);
  int (*free)(void*);
  void** (*chooseFBConfig)(void*, int, const int*, int*);
  void* (*createNewContext)(void*, void*, int, void*, int);
  unsigned long (*createPbuffer)(void*, void*, const int*);
  void (*destroyPbuffer)(void*, unsigned long);
  void (*destroyContext)(void*, void*);
  int (*makeContextCurrent)(void*, unsigned long, unsigned long, void*);
  void* (*getCurrentContext)();
  unsigned long (*getCurrentDrawable)();
  GLADapiproc (*getProcAddress)(const char*);
};

template <typename T>
bool sym(void* lib, const char* name, T* f) {
  *f = reinterpret_cast<T>(dlsym(lib, name));
  return *f != nullptr;
}

Glx* glxFns;
GLADapiproc glxProc(const char* name) {
  return glxFns->getProcAddress(name);
}

// a GLX context (on an X server: DISPLAY) stays current around library work
TEST(GlCurrent, RestoresTheCallersGlxContext) {
  if (!std::getenv("DISPLAY")) {
    GTEST_FAIL() << "no X server (DISPLAY unset; ctest runs it under xvfb-run as "
                    "gl.glx_context_restored)";
  }
  Glx g;
  g.x11 = dlopen("libX11.so.6", RTLD_NOW | RTLD_LOCAL);
  g.glx = dlopen("libGLX.so.0", RTLD_NOW | RTLD_LOCAL);
  ASSERT_TRUE(g.x11 && g.glx);
  ASSERT_TRUE(sym(g.x11, "XOpenDisplay", &g.openDisplay) &&
              sym(g.x11, "XCloseDisplay", &g.closeDisplay) &&
              sym(g.x11, "XDefaultScreen", &g.defaultScreen) && sym(g.x11, "XFree", &g.free) &&
              sym(g.glx, "glXChooseFBConfig", &g.chooseFBConfig) &&
              sym(g.glx, "glXCreateNewContext", &g.createNewContext) &&
              sym(g.glx, "glXCreatePbuffer", &g.createPbuffer) &&
              sym(g.glx, "glXDestroyPbuffer", &g.destroyPbuffer) &&
              sym(g.glx, "glXDestroyContext", &g.destroyContext) &&
              sym(g.glx, "glXMakeContextCurrent", &g.makeContextCurrent) &&
              sym(g.glx, "glXGetCurrentContext", &g.getCurrentContext) &&
              sym(g.glx, "glXGetCurrentDrawable", &g.getCurrentDrawable) &&
              sym(g.glx, "glXGetProcAddressARB", &g.getProcAddress));
  void* dpy = g.openDisplay(nullptr);
  if (!dpy) GTEST_FAIL() << "cannot open DISPLAY " << std::getenv("DISPLAY");

  // GLX 1.3 constants
  const int kRenderType = 0x8011, kRgbaBit = 1, kDrawableType = 0x8010, kPbufferBit = 4,
            kRgbaType = 0x8014, kPbufferWidth = 0x8041, kPbufferHeight = 0x8040;
  const int want[] = {kRenderType, kRgbaBit, kDrawableType, kPbufferBit, 0};
  int n = 0;
  void** cfg = g.chooseFBConfig(dpy, g.defaultScreen(dpy), want, &n);
  ASSERT_TRUE(cfg && n > 0);
  void* ctx = g.createNewContext(dpy, cfg[0], kRgbaType, nullptr, 1);
  const int size[] = {kPbufferWidth, 16, kPbufferHeight, 16, 0};
  unsigned long pb = g.createPbuffer(dpy, cfg[0], size);
  g.free(cfg);
  ASSERT_TRUE(ctx && pb);
  ASSERT_TRUE(g.makeContextCurrent(dpy, pb, pb, ctx));
  glxFns = &g;
  GladGLContext gl{};
  ASSERT_TRUE(mjbLoadGLContext(&gl, glxProc));
  std::printf("GLX renderer: %s\n", reinterpret_cast<const char*>(gl.GetString(GL_RENDERER)));
  std::string err;
  GLuint prog = glProgramSource(gl, "caller.comp", kCaller, &err);
  ASSERT_NE(prog, 0u) << err;
  gl.UseProgram(prog);

  GlContext lib;
  ASSERT_TRUE(glCreate(&lib, &err)) << err;  // with the GLX context current
  EXPECT_EQ(g.getCurrentContext(), ctx);
  // what the guard works around: libglvnd refuses EGL while GLX is current
  EGLBoolean bare = eglMakeCurrent(lib.dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, lib.ctx);
  std::printf("bare eglMakeCurrent with GLX current: %s (EGL error 0x%04X)\n",
              bare ? "accepted" : "refused", eglGetError());
  if (bare) eglMakeCurrent(lib.dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  EXPECT_EQ(g.getCurrentContext(), ctx);
  {
    GlCurrent cur(&lib);
    ASSERT_TRUE(cur.ok()) << cur.error();
    EXPECT_EQ(eglGetCurrentContext(), lib.ctx);
    EXPECT_EQ(g.getCurrentContext(), nullptr);
    GLuint p = glProgram(lib.gl, "selftest.comp", &err);
    ASSERT_NE(p, 0u) << err;
    Selftest in = exactData(), out = in;
    ASSERT_TRUE(runSelftest(lib.gl, p, &out));
    checkSelftest(in, out, true);
  }
  EXPECT_EQ(g.getCurrentContext(), ctx);
  EXPECT_EQ(g.getCurrentDrawable(), pb);
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  GLint p = 0;
  gl.GetIntegerv(GL_CURRENT_PROGRAM, &p);
  EXPECT_EQ(GLuint(p), prog);
  EXPECT_EQ(gl.GetError(), GLenum(GL_NO_ERROR));

  glDestroy(&lib);
  gl.DeleteProgram(prog);
  g.makeContextCurrent(dpy, 0, 0, nullptr);
  g.destroyPbuffer(dpy, pb);
  g.destroyContext(dpy, ctx);
  g.closeDisplay(dpy);
}

}  // namespace
}  // namespace mjb
