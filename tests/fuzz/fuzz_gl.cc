// libFuzzer target: the gl backend against the cpu reference (differential).
// Four small scenes, each compiled twice and attached once per backend at
// start-up (a gl attach compiles the shaders: too slow per input): a box
// barge, a capsule float and a sphere buoy with a small-inertia ballast,
// in still water, a one-wave sea with current, a two-wave finite-depth sea
// and a sea at fold 0.99. Bytes -> the scene, every body's position
// (height around the surface), orientation, velocity and the time. Both
// backends take the same state and step twice from it (the second step
// with a slamming history). Must hold: every wrench finite, and gl within
// the parity tolerance of tests/gl_parity_test.cc of the cpu: each force
// component within 1e-4 of the cpu force's norm or of the body's weight,
// each torque component likewise (weight x 1 m). Anything else traps.
// Radiation is off: it is the same cpu code on both backends, and its
// panel solves at start-up (three bodies, eight attaches) took about two
// of the test's three minutes under the fuzzer's instrumentation.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>
#include <mujoco/mujoco.h>

#include "mjbuoy.h"

namespace {

void fail(const char* what, int scene, int step, int body, int j, double g, double c) {
  std::fprintf(stderr, "fuzz_gl: %s: scene %d step %d body %d component %d: gl %.9g cpu %.9g\n",
               what, scene, step, body, j, g, c);
  __builtin_trap();
}

void quiet(const char*) {}

const char* kSea[] = {
    "",
    "<numeric name=\"mjbuoy.wave.a\" data=\"0.3 12 30 0 0.6\"/>"
    "<numeric name=\"mjbuoy.sea.current\" data=\"0.4 -0.2\"/>",
    "<numeric name=\"mjbuoy.sea.depth\" data=\"6\"/>"
    "<numeric name=\"mjbuoy.wave.a\" data=\"0.25 9 0 40 0.7\"/>"
    "<numeric name=\"mjbuoy.wave.b\" data=\"0.05 4 100 0 0.5\"/>",
    // A k Q = 0.7 (2 pi / 4) Q = 0.99
    "<numeric name=\"mjbuoy.wave.a\" data=\"0.7 4 0 0 0.90031\"/>",
};
const int kNScene = 4, kNBody = 3;

std::string xml(int sea) {
  return std::string("<mujoco><option timestep=\"0.002\"/><custom>"
                     "<text name=\"mjbuoy.hulls\" data=\"h*\"/>"
                     "<text name=\"mjbuoy.radiation\" data=\"off\"/>") + kSea[sea] +
         "</custom><worldbody>"
         "<body name=\"b\"><freejoint/><geom name=\"hb\" type=\"box\" size=\"1 0.5 0.25\" "
         "mass=\"500\"/></body>"
         "<body name=\"c\" pos=\"4 0 0\"><freejoint/><geom name=\"hc\" type=\"capsule\" "
         "size=\"0.3 0.8\" euler=\"0 90 0\" mass=\"150\"/></body>"
         "<body name=\"s\" pos=\"0 4 0\"><freejoint/><inertial pos=\"0 0 -0.1\" mass=\"100\" "
         "diaginertia=\"0.4 0.4 0.4\"/><geom name=\"hs\" type=\"sphere\" size=\"0.4\"/></body>"
         "</worldbody></mujoco>";
}

struct Side {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  mjbBuoy* b = nullptr;
};
Side gside[kNScene][2];  // [scene][cpu, gl], kept for the process

mjModel* load(const std::string& s) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "scene.xml", s.size());
  int i = mj_findFileVFS(&vfs, "scene.xml");
  std::copy(s.begin(), s.end(), static_cast<char*>(vfs.filedata[i]));
  char e[1024] = "";
  mjModel* m = mj_loadXML("scene.xml", &vfs, e, sizeof(e));
  mj_deleteVFS(&vfs);
  if (!m) std::fprintf(stderr, "fuzz_gl: scene does not compile: %s\n", e);
  return m;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  mju_user_warning = quiet;  // MuJoCo's warnings are checked through d->warning
  for (int sc = 0; sc < kNScene; sc++) {
    for (int be = 0; be < 2; be++) {
      Side& s = gside[sc][be];
      s.m = load(xml(sc));
      if (!s.m) __builtin_trap();
      char e[1024];
      s.b = mjb_attach(s.m, be ? "gl" : "cpu", e, sizeof(e));
      if (!s.b) {
        std::fprintf(stderr, "fuzz_gl: attach %s: %s\n", be ? "gl" : "cpu", e);
        __builtin_trap();
      }
      s.d = mj_makeData(s.m);
    }
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  const int sc = in.ConsumeIntegralInRange<int>(0, kNScene - 1);
  Side& c = gside[sc][0];
  Side& g = gside[sc][1];
  mj_resetData(c.m, c.d);
  mj_resetData(g.m, g.d);
  // states like tests/gl_parity_test.cc: afloat to airborne, any heading
  for (int b = 0; b < kNBody; b++) {
    double* q = c.d->qpos + 7 * b;
    q[0] += in.ConsumeFloatingPointInRange<double>(-2, 2);
    q[1] += in.ConsumeFloatingPointInRange<double>(-2, 2);
    q[2] = in.ConsumeFloatingPointInRange<double>(-1.2, 1.2);
    double u[4], n = 0;
    for (double& x : u) {
      x = in.ConsumeFloatingPointInRange<double>(-1, 1);
      n += x * x;
    }
    if (n < 1e-6) u[0] = n = 1;
    for (int j = 0; j < 4; j++) q[3 + j] = u[j] / std::sqrt(n);
    for (int j = 0; j < 6; j++) {
      c.d->qvel[6 * b + j] = in.ConsumeFloatingPointInRange<double>(j < 3 ? -3 : -2, j < 3 ? 3 : 2);
    }
  }
  c.d->time = in.ConsumeFloatingPointInRange<double>(0, 100);
  for (int k = 0; k < 2; k++) {
    // the same state on both, then one step each
    mju_copy(g.d->qpos, c.d->qpos, c.m->nq);
    mju_copy(g.d->qvel, c.d->qvel, c.m->nv);
    g.d->time = c.d->time;
    mj_step(c.m, c.d);
    mj_step(g.m, g.d);
    const mjtNum* wc = mjb_wrench(c.b, c.d);
    const mjtNum* wg = mjb_wrench(g.b, g.d);
    for (int b = 1; b <= kNBody; b++) {
      double weight = c.m->body_mass[b] * 9.81, fn = 0, tn = 0;
      for (int j = 0; j < 3; j++) {
        fn += wc[6 * b + j] * wc[6 * b + j];
        tn += wc[6 * b + 3 + j] * wc[6 * b + 3 + j];
      }
      double ftol = std::fmax(1e-4 * std::sqrt(fn), 1e-4 * weight);
      double ttol = std::fmax(1e-4 * std::sqrt(tn), 1e-4 * weight);
      for (int j = 0; j < 6; j++) {
        double x = wc[6 * b + j], y = wg[6 * b + j];
        if (!std::isfinite(x) || !std::isfinite(y)) fail("not finite", sc, k, b, j, y, x);
        if (std::fabs(x - y) > (j < 3 ? ftol : ttol)) fail("gl differs", sc, k, b, j, y, x);
      }
    }
    if (std::string(mjb_notices(c.b, c.d)) != "" || std::string(mjb_notices(g.b, g.d)) != "") {
      std::fprintf(stderr, "fuzz_gl: notices: cpu %s gl %s\n", mjb_notices(c.b, c.d),
                   mjb_notices(g.b, g.d));
      __builtin_trap();
    }
  }
  return 0;
}
