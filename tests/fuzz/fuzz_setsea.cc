// libFuzzer target: mjb_setSea (api/seasetter.cc), the C API's way to
// change the sea between steps. Bytes -> an mjbSea: current, up to 4 listed
// waves, up to 2 spectra (PM, JONSWAP or a table of up to 6 pairs), wind
// and ramp. Each number is read as a selector byte: most pick one of a
// few telling values (0, NaN, inf, huge, tiny, negative, and values inside
// the accepted ranges) scaled by a second byte, the rest take 8 raw bytes
// of a double, so mutations explore both the ranges' edges and garbage.
// The model (a free box barge "hull", capacity for 8192 components) is
// attached once with the cpu backend; every input starts from a fresh
// mjData. Must hold: a refused sea says why (non-empty error) and leaves
// the model's sea as it was (the same components); an accepted sea steps 5
// times with a finite wrench and finite qacc while the state stays
// plausible (|qpos|, |qvel| < 1e6). Anything else traps; an input whose
// steps take over 10 s is a hang (run_fuzzer.cmake): a cost cliff that the
// validator let through.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "mjbuoy.h"

namespace {

#define REQUIRE(c, what)                                                             \
  do {                                                                               \
    if (!(c)) {                                                                      \
      std::fprintf(stderr, "fuzz_setsea: %s:%d: %s (%s)\n", __FILE__, __LINE__, #c, \
                   std::string(what).c_str());                                       \
      __builtin_trap();                                                              \
    }                                                                                \
  } while (0)

void quiet(const char*) {}

const char kXML[] =
    "<mujoco model=\"fuzz\"><option timestep=\"0.005\"/><custom>"
    "<text name=\"mjbuoy.hulls\" data=\"hull\"/>"
    "<text name=\"mjbuoy.radiation\" data=\"off\"/>"
    "<numeric name=\"mjbuoy.sea.capacity\" data=\"8192\"/>"
    "<numeric name=\"mjbuoy.wave.a\" data=\"0.2 10 0 0 0.2\"/>"
    "</custom><worldbody><body name=\"barge\" pos=\"0 0 0\"><freejoint/>"
    "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"256\"/>"
    "</body></worldbody></mujoco>";

mjModel* gm = nullptr;
mjbBuoy* gb = nullptr;

// the bytes as a stream of numbers; past the end every read is 0
struct Reader {
  const uint8_t* p;
  size_t n;
  uint8_t byte() { return n ? (n--, *p++) : 0; }
  double num() {
    static const double kPick[16] = {0, std::numeric_limits<double>::quiet_NaN(),
                                     std::numeric_limits<double>::infinity(), -1e308, 1e308,
                                     1e-308, -1, 0.05, 0.5, 1, 3.3, 8, 20, 100, 4096, 3600};
    uint8_t s = byte();
    if (s < 240) return kPick[s % 16] * (1 + byte() / 64.0);
    double v = 0;
    uint8_t raw[8];
    for (uint8_t& r : raw) r = byte();
    std::memcpy(&v, raw, 8);
    return v;
  }
  int count(int max) { return byte() % (max + 1); }
};

// one spectrum from r; table: its storage (6 pairs)
void readSpectrum(Reader* r, mjbSpectrum* s, double* table) {
  mjb_defaultSpectrum(s);
  s->type = r->byte() % 4;  // 3: not a type
  s->hs = r->num();
  s->tp = r->num();
  s->wind = r->byte() % 2 ? r->num() : 0;
  s->gamma = r->num();
  s->ntable = r->count(6);
  for (int i = 0; i < 2 * s->ntable; i++) table[i] = r->num();
  s->table = table;
  s->dir = r->num();
  s->spread = r->num();
  const double n = r->num();  // a count: NaN and huge doubles become -1 (refused)
  s->n = std::isfinite(n) && std::fabs(n) < 1e9 ? int(n) : -1;
  s->wmin = r->byte() % 2 ? r->num() : 0;
  s->wmax = s->wmin != 0 ? r->num() : 0;
  s->seed = r->byte();
}

// steps d five times (mj_forward + mj_Euler: MuJoCo's own divergence reset
// would hide a NaN), each with a finite wrench and qacc
void stepFinite(mjData* d, const std::string& what) {
  for (int s = 0; s < 5; s++) {
    bool plausible = true;
    for (int i = 0; i < gm->nq; i++) plausible = plausible && std::fabs(d->qpos[i]) < 1e6;
    for (int i = 0; i < gm->nv; i++) plausible = plausible && std::fabs(d->qvel[i]) < 1e6;
    if (!plausible) break;
    mj_forward(gm, d);
    const mjtNum* w = mjb_wrench(gb, d);
    REQUIRE(w, "no wrench");
    for (int i = 0; i < 6 * gm->nbody; i++) REQUIRE(std::isfinite(w[i]), "wrench " + what);
    for (int i = 0; i < gm->nv; i++) REQUIRE(std::isfinite(d->qacc[i]), "qacc " + what);
    mj_Euler(gm, d);
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  mju_user_warning = quiet;
  char err[1000] = "";
  static mjVFS vfs;
  mj_defaultVFS(&vfs);
  if (mj_makeEmptyFileVFS(&vfs, "fuzz.xml", sizeof(kXML) - 1) != 0) __builtin_trap();
  std::memcpy(vfs.filedata[0], kXML, sizeof(kXML) - 1);
  gm = mj_loadXML("fuzz.xml", &vfs, err, sizeof(err));
  mj_deleteVFS(&vfs);
  REQUIRE(gm, err);
  gb = mjb_attach(gm, "cpu", err, sizeof(err));
  REQUIRE(gb, err);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Reader r{data, size};
  mjbSea sea;
  std::memset(&sea, 0, sizeof(sea));
  sea.current[0] = r.num();
  sea.current[1] = r.num();
  double wave[4 * 5];
  sea.nwave = r.count(4);
  for (int i = 0; i < 5 * sea.nwave; i++) wave[i] = r.num();
  sea.wave = wave;
  mjbSpectrum spec[2];
  double table[2][12];
  sea.nspectrum = r.count(2);
  for (int i = 0; i < sea.nspectrum; i++) readSpectrum(&r, &spec[i], table[i]);
  sea.spectrum = spec;
  sea.wind.speed = r.num();
  sea.wind.dir = r.num();
  sea.wind.gust = r.byte() % 3;  // 2: not a gust spectrum
  sea.wind.ngust = int(r.byte()) * 4;
  sea.wind.seed = r.byte();
  sea.ramp = r.byte() % 2 ? r.num() : -1;

  const int before = mjb_waves(gb, nullptr, 0);
  std::vector<double> was(6 * before);
  mjb_waves(gb, was.data(), before);
  char err[1000] = "";
  const int ok = mjb_setSea(gb, &sea, err, sizeof(err));
  if (!ok) {
    REQUIRE(err[0] != 0, "refused without a reason");
    REQUIRE(mjb_waves(gb, nullptr, 0) == before, "a refused sea changed the component count");
    std::vector<double> now(6 * before);
    mjb_waves(gb, now.data(), before);
    REQUIRE(now == was, "a refused sea changed the components");
  }
  mjData* d = mj_makeData(gm);
  stepFinite(d, ok ? "after an accepted sea" : "after a refused sea");
  mj_deleteData(d);
  return 0;
}
