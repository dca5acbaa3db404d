// radiation robustness (docs/robustness.md, "Radiation"): the memory's
// sampling bounded at small timesteps and following a changed timestep,
// the panel solver's memory estimated before it allocates, cache files
// checked against their key, the lowest documented frequency
#include <sys/resource.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/buoy.h"
#include "radiation/radcache.h"
#include "radiation/radiation.h"
#include "testutil.h"

namespace {

using mjbt::Scene;

// a 1 m x 1 m x 0.5 m box floating at half its height (256.25 kg: the
// displaced 0.25 m^3 at rho 1025), radiation on, opt is the <option>
// element's attributes and extra goes into <custom>
std::string box(const std::string& opt, const std::string& extra = "",
                const char* omega = "1 9 4") {
  return "<mujoco><option " + opt + "/><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
         "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
         "<text name=\"mjbuoy.radiation.diffraction\" data=\"off\"/>"
         "<numeric name=\"mjbuoy.radiation.omega\" data=\"" + std::string(omega) + "\"/>" +
         extra + "</custom><worldbody><body name=\"boat\"><freejoint/>"
         "<geom name=\"hull\" type=\"box\" size=\"0.5 0.5 0.25\" mass=\"256.25\"/>"
         "</body></worldbody></mujoco>";
}

const mjb::Radiation& rad(const Scene& s) { return mjb::buoyOf(s.b)->rad; }
const mjb::HydroCoef& coef(const Scene& s) { return mjb::buoyOf(s.b)->coef.at(0).second; }

// heave of the box dropped 5 cm, its z every `every` steps for T seconds;
// the notices of every step into *notes
std::vector<double> drop(Scene* s, double T, std::string* notes = nullptr, int every = 1) {
  s->d->qpos[2] += 0.05;
  std::vector<double> z;
  long n = mjbt::stepsTo(s->m, s->d, T);
  for (long k = 0; k < n; k++) {
    mj_step(s->m, s->d);
    if ((k + 1) % every == 0) z.push_back(s->d->qpos[2]);
    if (notes) *notes += mjb_notices(s->b, s->d);
  }
  return z;
}

// at a timestep of 1e-7 s a memory of seconds would be ~1e7 samples per
// pair (the attach aborted in std::bad_alloc; at 1e-5 s it took 25 to 52
// s): the kernel is sampled at a bounded rate for the state-space fit,
// whose modes are continuous in time, and the history ring holds 2
// samples; the run is finite
TEST(RadRobust, TinyTimestepSamplesTheKernelAtABoundedRate) {
  for (const char* dt : {"timestep=\"1e-7\"", "timestep=\"1e-5\""}) {
    Scene s(box(dt));
    ASSERT_TRUE(s.ok()) << dt << ": " << s.err;
    const mjb::Radiation& r = rad(s);
    ASSERT_EQ(r.rb.size(), 1u);
    EXPECT_LE(r.rb[0].nk, mjb::kMaxKernelSamples) << dt;
    EXPECT_LE(r.nh, 2) << dt;
    EXPECT_GT(r.rb[0].ss.size(), 0) << dt << ": state-space memory expected";
    for (int i = 0; i < 10; i++) mj_step(s.m, s.d);
    EXPECT_TRUE(std::isfinite(s.d->qpos[2])) << dt;
  }
}

// the convolution cannot be resampled: at a timestep whose history would
// pass the bound the attach is refused with the cost and the settings
TEST(RadRobust, TinyTimestepConvolutionIsRefusedWithItsCost) {
  std::string x = "<text name=\"mjbuoy.radiation.memorymodel\" data=\"convolution\"/>";
  mjModel* m = mjbt::loadXML(box("timestep=\"1e-7\"", x));
  ASSERT_TRUE(m);
  char e[1024] = "";
  mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof e);
  EXPECT_FALSE(b);
  std::string err = e;
  for (const char* want : {"samples", "MB", "opt.timestep", "mjbuoy.radiation.memory",
                           "mjbuoy.radiation.memorymodel"})
    EXPECT_NE(err.find(want), std::string::npos) << want << ": " << err;
  if (b) mjb_detach(b);
  mj_deleteModel(m);
}

// opt.timestep changed after attach: the state-space memory follows the
// new step (its modes are continuous in time), so the run equals one
// attached at the new step; the reference is that independent attach
TEST(RadRobust, TimestepChangedAfterAttachIsFollowed) {
  Scene a(box("timestep=\"0.002\""));
  Scene b(box("timestep=\"0.001\""));
  ASSERT_TRUE(a.ok() && b.ok()) << a.err << b.err;
  a.m->opt.timestep = 0.001;
  std::string n;
  std::vector<double> za = drop(&a, 3, &n), zb = drop(&b, 3);
  ASSERT_EQ(za.size(), zb.size());
  double worst = 0;
  for (size_t k = 0; k < za.size(); k++) worst = std::max(worst, std::fabs(za[k] - zb[k]));
  // the fits of kernels sampled at 2 ms and 1 ms differ within kFitTolT
  EXPECT_LT(worst, 0.01 * 0.05) << "largest heave difference [m]";
  EXPECT_NE(n.find("opt.timestep"), std::string::npos) << n;
}

// the convolution's samples are fixed at the attach's step: after a change
// its memory is left out with a notice naming the step and the fix
TEST(RadRobust, TimestepChangedAfterAttachStopsTheConvolution) {
  std::string x = "<text name=\"mjbuoy.radiation.memorymodel\" data=\"convolution\"/>";
  Scene a(box("timestep=\"0.002\"", x));
  ASSERT_TRUE(a.ok()) << a.err;
  a.m->opt.timestep = 0.001;
  std::string n;
  drop(&a, 0.1, &n);
  EXPECT_NE(n.find("opt.timestep"), std::string::npos) << n;
  EXPECT_NE(n.find("0.002"), std::string::npos) << n;
  EXPECT_NE(n.find("memory"), std::string::npos) << n;
}

// the lowest documented frequency (docs/mjcf.md: mjbuoy.radiation.omega,
// 1e-3 rad/s) solves: in deep water B_33 -> 0 and A_33 tends to a finite
// positive limit as omega -> 0 (Hulme 1982, hemisphere; Newman 1977,
// sec. 6.16), so the coefficients there are finite, B_33 is a small share
// of its peak, A_33 positive
TEST(RadRobust, LowestDocumentedFrequencySolves) {
  Scene s(box("timestep=\"0.002\"", "", "0.001 9 4"));
  ASSERT_TRUE(s.ok()) << s.err;
  const mjb::HydroCoef& c = coef(s);
  double peak = 0;
  for (int w = 0; w < c.nw(); w++) peak = std::max(peak, c.B[36 * w + 14]);
  EXPECT_LT(std::fabs(c.B[14]), 1e-3 * peak);
  EXPECT_GT(c.A[14], 0);
  EXPECT_TRUE(std::isfinite(c.A[14]));
}

// a fresh empty directory under $TMPDIR, removed with its files at the end
struct TmpDir {
  std::string path;
  TmpDir() {
    const char* t = std::getenv("TMPDIR");
    std::string p = std::string(t && *t ? t : "/tmp") + "/mjbuoy-radrobust-XXXXXX";
    std::vector<char> b(p.begin(), p.end());
    b.push_back(0);
    if (mkdtemp(b.data())) path = b.data();
  }
  ~TmpDir() {
    if (!path.empty()) std::system(("rm -rf '" + path + "'").c_str());
  }
};

std::string slurp(const std::string& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// the key bytes of a cache file (radcache.cc layout: magic, format,
// version, u64 n, key)
std::string fileKey(const std::string& s) {
  uint64_t n = 0;
  std::memcpy(&n, s.data() + 16, 8);
  return s.substr(24, n);
}

// a cache file with a valid checksum whose payload does not fit its key
// or physics (another frequency count, 1e290 coefficients, a reference
// point 1e6 m away, frequencies out of order) is not used: named in a
// warning, recomputed to the cold solve's values, rewritten
TEST(RadRobust, CachePayloadIsCheckedAgainstItsKey) {
  TmpDir t;
  std::string cache = "<text name=\"mjbuoy.radiation.cache\" data=\"" + t.path + "\"/>";
  Scene a(box("timestep=\"0.002\"", cache));
  ASSERT_TRUE(a.ok()) << a.err;
  mjb::HydroCoef ref = coef(a);
  FILE* p = popen(("ls '" + t.path + "'").c_str(), "r");
  char line[512] = "";
  ASSERT_TRUE(p && std::fgets(line, sizeof line, p));
  pclose(p);
  line[std::strcspn(line, "\n")] = 0;
  const std::string file = t.path + "/" + line, good = slurp(file), key = fileKey(good);
  mjb::HydroCoef c0;
  std::string note;
  ASSERT_TRUE(mjb::radCacheLoad(t.path, key, &c0, &note)) << note;
  struct Case { const char* what; void (*bad)(mjb::HydroCoef*); };
  const Case cs[] = {
      {"one frequency fewer", [](mjb::HydroCoef* c) {
         c->omega.pop_back();
         c->A.resize(36 * c->omega.size());
         c->B.resize(36 * c->omega.size());
       }},
      {"1e290 damping", [](mjb::HydroCoef* c) { c->B[14] = 1e290; }},
      {"1e290 added mass", [](mjb::HydroCoef* c) { c->Ainf[14] = 1e290; }},
      {"reference 1e6 m away", [](mjb::HydroCoef* c) { c->ref[0] = 1e6; }},
      {"frequencies out of order", [](mjb::HydroCoef* c) { std::swap(c->omega[0], c->omega[1]); }},
      {"negative frequency", [](mjb::HydroCoef* c) { c->omega[0] = -1; }},
  };
  for (const Case& k : cs) {
    mjb::HydroCoef bad = c0;
    k.bad(&bad);
    ASSERT_TRUE(mjb::radCacheStore(t.path, key, bad, &note)) << note;
    Scene s(box("timestep=\"0.002\"", cache));
    ASSERT_TRUE(s.ok()) << k.what << ": " << s.err;
    const mjb::RadCacheStats& st = mjb::buoyOf(s.b)->radcache;
    EXPECT_EQ(st.hit, 0) << k.what;
    EXPECT_EQ(st.miss, 1) << k.what;
    EXPECT_EQ(st.write, 1) << k.what;
    std::string w = mjb_warnings(s.b);
    EXPECT_NE(w.find(file), std::string::npos) << k.what << ": " << w;
    EXPECT_EQ(coef(s).B, ref.B) << k.what;
    EXPECT_EQ(std::memcmp(coef(s).Ainf, ref.Ainf, sizeof ref.Ainf), 0) << k.what;
    EXPECT_EQ(slurp(file), good) << k.what << ": rewritten whole";
  }
}

// the soft address-space limit lowered for a scope, restored after
struct AsLimit {
  rlimit old{};
  bool ok = false;
  explicit AsLimit(rlim_t bytes) {
    if (getrlimit(RLIMIT_AS, &old) != 0) return;
    rlimit r = old;
    r.rlim_cur = std::min<rlim_t>(bytes, old.rlim_max);
    ok = setrlimit(RLIMIT_AS, &r) == 0;
  }
  ~AsLimit() {
    if (ok) setrlimit(RLIMIT_AS, &old);
  }
};

// the address space this process uses now [bytes] (/proc/self/statm)
double vmBytes() {
  FILE* f = std::fopen("/proc/self/statm", "r");
  long pages = 0;
  if (f) {
    if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  return double(pages) * sysconf(_SC_PAGESIZE);
}

// the 7744-triangle Wigley hull solved whole (mjbuoy.radiation.panels 0)
// at refinement 1: about 15000 wet panels, whose dense complex systems
// need tens of GB. Under an address-space limit 400 MB above what the
// process holds the attach is refused before allocating, with the
// estimate and the setting (never an exception through mjb_attach); on by
// default it is a warning and the hull keeps its drag terms
TEST(RadRobust, PanelMemoryIsEstimatedBeforeAllocating) {
  auto xml = [](bool explicitOn) {
    return std::string("<mujoco><asset><mesh name=\"w\" file=\"" MJB_MODELS
                       "/meshes/wigley_7744.obj\"/></asset><custom>"
                       "<text name=\"mjbuoy.hulls\" data=\"hull\"/>") +
           (explicitOn ? "<text name=\"mjbuoy.radiation\" data=\"on\"/>" : "") +
           "<text name=\"mjbuoy.radiation.cache\" data=\"off\"/>"
           "<numeric name=\"mjbuoy.radiation.panels\" data=\"0\"/>"
           "<numeric name=\"mjbuoy.radiation.refine\" data=\"1\"/>"
           "</custom><worldbody><body name=\"boat\"><freejoint/>"
           "<geom name=\"hull\" type=\"mesh\" mesh=\"w\" mass=\"176.2\"/>"
           "</body></worldbody></mujoco>";
  };
  for (bool on : {true, false}) {
    mjModel* m = mjbt::loadXML(xml(on));
    ASSERT_TRUE(m);
    char e[2048] = "";
    mjbBuoy* b = nullptr;
    {
      AsLimit lim(rlim_t(vmBytes() + 400e6));
      ASSERT_TRUE(lim.ok);
      b = mjb_attach(m, "cpu", e, sizeof e);
    }
    std::string msg = on ? std::string(e) : b ? mjb_warnings(b) : std::string(e);
    EXPECT_EQ(bool(b), !on) << msg;
    for (const char* want : {"GB", "mjbuoy.radiation.panels", "wet panels"})
      EXPECT_NE(msg.find(want), std::string::npos) << want << ": " << msg;
    if (b) {
      EXPECT_TRUE(mjb::buoyOf(b)->rad.rb.empty());
      mjb_detach(b);
    }
    mj_deleteModel(m);
  }
}

// advice to refine the panels names the panel budget and the value to
// set: a refined hull above an explicit mjbuoy.radiation.panels is
// coarsened back to it, so raising mjbuoy.radiation.refine alone changes
// nothing. The case: a 2 x 1 m box
// of 500 kg in water of density 1e5 floats at 500 / (1e5 x 2) = 2.5 mm,
// which its 12-triangle mesh's metre-wide panels do not resolve (A_inf
// indefinite, the error of RobustLimits.DensestWaterWithRadiationNamesThe
// UnresolvedDraft)
TEST(RadRobust, RefineAdviceNamesThePanelBudget) {
  mjModel* m = mjbt::loadXML(
      "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
      "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
      "<numeric name=\"mjbuoy.sea.density\" data=\"1e5\"/>"
      "<numeric name=\"mjbuoy.radiation.panels\" data=\"300\"/></custom>"
      "<worldbody><body name=\"box\" pos=\"0 0 0.2475\"><freejoint/>"
      "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"500\"/>"
      "</body></worldbody></mujoco>");
  ASSERT_TRUE(m);
  char e[2048] = "";
  mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof e);
  EXPECT_FALSE(b);
  std::string err = e;
  EXPECT_NE(err.find("not positive semi-definite"), std::string::npos) << err;
  EXPECT_NE(err.find("mjbuoy.radiation.refine"), std::string::npos) << err;
  // the value to set: a refine level up quadruples the panels, so the
  // budget must hold 4 x 300
  EXPECT_NE(err.find("set <numeric name=\"mjbuoy.radiation.panels\" data=\"1200\"/> (now 300"),
            std::string::npos) << err;
  if (b) mjb_detach(b);
  mj_deleteModel(m);
}

}  // namespace
