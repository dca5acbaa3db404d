// libFuzzer target: the mjbuoy.* <custom> entries of a model (config.cc).
// Bytes -> the text of the <custom> section of a small MJCF model (a free
// box barge "hull" and a tetrahedron mesh "mesh" on one body, a floor plane
// "floor" on the world). The seeds (corpus/fuzz_config) are the <custom>
// sections of models/*.xml and docs/mjcf.md; fuzz_config.dict gives libFuzzer the
// entry names and the special values (nan, inf, huge, tiny, negative), so
// mutations explore valid and invalid names, value counts and values.
// The model is compiled by MuJoCo from memory (mjVFS) and attached with the
// cpu backend. Must hold: a failed attach says why (non-empty error); an
// attached model steps 5 times with a finite wrench (every part) and finite
// qacc while its state stays plausible (|qpos|, |qvel| < 1e6). Anything
// else traps. Radiation is off unless the input gives mjbuoy.radiation
// itself: on by default it would run the panel solver on every input.
// An input that turns radiation on for the barge (checked with the
// library's own parser, radconfig.h) gets its entries parsed and no
// attach: the solve alone takes 14 s under this build's instrumentation
// for the barge's 12 triangles at the default settings (0.4 s in a
// release build) and grows with the resolution the input asks for,
// beyond the 10 s an input may take before libFuzzer calls it a hang
// (run_fuzzer.cmake). The panel solver's own tests cover the solve
// (tests/panel_test.cc and the radiation tests).
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include <mujoco/mujoco.h>

#include "mjbuoy.h"
#include "api/radconfig.h"

namespace {

#define REQUIRE(c, what)                                                        \
  do {                                                                          \
    if (!(c)) {                                                                 \
      std::fprintf(stderr, "fuzz_config: %s:%d: %s (%s)\n", __FILE__, __LINE__, #c, \
                   std::string(what).c_str());                                  \
      __builtin_trap();                                                         \
    }                                                                           \
  } while (0)

void quiet(const char*) {}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  mju_user_warning = quiet;  // MuJoCo's warnings are checked through d->warning
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string body(reinterpret_cast<const char*>(data), size);
  const std::string rad = body.find("\"mjbuoy.radiation\"") == std::string::npos
                              ? "<text name=\"mjbuoy.radiation\" data=\"off\"/>\n"
                              : "";
  std::string xml =
      "<mujoco model=\"fuzz\">\n<option timestep=\"0.002\"/>\n"
      "<asset><mesh name=\"tet\" vertex=\"0 0 0  1 0 0  0 1 0  0 0 1\"/></asset>\n"
      "<custom>\n" + rad + body + "\n</custom>\n"
      "<worldbody>\n<geom name=\"floor\" type=\"plane\" size=\"5 5 .1\" pos=\"0 0 -10\"/>\n"
      "<body name=\"barge\" pos=\"0 0 0.1\"><freejoint/>\n"
      "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/>\n"
      "<geom name=\"mesh\" type=\"mesh\" mesh=\"tet\" pos=\"0 0 -0.5\" mass=\"10\"/>\n"
      "<site name=\"fair\" pos=\"1 0 -0.25\"/>\n"
      "</body>\n</worldbody>\n</mujoco>\n";

  static mjVFS vfs;  // 2 MB of names: once
  mj_defaultVFS(&vfs);
  if (mj_makeEmptyFileVFS(&vfs, "fuzz.xml", static_cast<int>(xml.size())) != 0) __builtin_trap();
  std::memcpy(vfs.filedata[0], xml.data(), xml.size());
  char err[1000] = "";
  mjModel* m = mj_loadXML("fuzz.xml", &vfs, err, sizeof(err));
  mj_deleteVFS(&vfs);
  if (!m) return 0;  // MuJoCo rejects the MJCF itself: not ours

  // radiation on for the barge (body 1, the only one with hull geoms):
  // its entries parse or attach must fail naming them; no solve
  mjb::RadConfig rc;
  const std::string rerr = mjb::parseRadConfig(m, &rc);
  if (rerr.empty() && rc.groupRadiates(m, {1}, 1)) {
    mj_deleteModel(m);
    return 0;
  }

  err[0] = 0;
  mjbBuoy* b = mjb_attach(m, "cpu", err, sizeof(err));
  REQUIRE(rerr.empty() || !b, "attach accepted radiation entries its parser refuses: " + rerr);
  if (!b) {
    REQUIRE(err[0] != 0, "attach failed without a reason\n" + xml);
    mj_deleteModel(m);
    return 0;
  }
  mjData* d = mj_makeData(m);
  // mj_forward + mj_Euler is mj_step without MuJoCo's own divergence check
  // (a reset at |qacc| > 1e10 would hide a NaN); steps stop once the state
  // leaves what a boat can do. Every value is bounded to a physical range
  // (docs/mjcf.md: a current of 5e5 m/s, corpus regress-huge-current, is now
  // refused at attach), but values inside the ranges can still be stiff for
  // the 2 ms step (damping 1e12 N s/m on a 500 kg barge) and throw the
  // barge off: finite, not our concern
  for (int s = 0; s < 5; s++) {
    bool plausible = true;
    for (int i = 0; i < m->nq; i++) plausible = plausible && std::fabs(d->qpos[i]) < 1e6;
    for (int i = 0; i < m->nv; i++) plausible = plausible && std::fabs(d->qvel[i]) < 1e6;
    if (!plausible) break;
    mj_forward(m, d);
    for (int p = -1; p < mjbNPART; p++) {
      const mjtNum* w = p < 0 ? mjb_wrench(b, d) : mjb_wrenchPart(b, d, p);
      // without hulls mjbuoy adds no force and may never see d
      if (!w && mjb_info(b).nhull == 0) continue;
      REQUIRE(w, "no wrench");
      for (int i = 0; i < 6 * m->nbody; i++) {
        REQUIRE(std::isfinite(w[i]), "wrench part " + std::to_string(p) + "\n" + xml);
      }
    }
    for (int i = 0; i < m->nv; i++) REQUIRE(std::isfinite(d->qacc[i]), "qacc\n" + xml);
    mj_Euler(m, d);
  }
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
  return 0;
}
