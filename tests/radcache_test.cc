// the panel solver's cache (mjbuoy/radiation/radcache.h; docs/mjcf.md section 11,
// "Cache"): exact round trip, hits, misses, corrupt and foreign files
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
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
#include "testutil.h"

namespace {

using mjbt::Scene;

// a fresh empty directory under $TMPDIR, removed with its files at the end
struct TmpDir {
  std::string path;
  TmpDir() {
    const char* t = std::getenv("TMPDIR");
    std::string p = std::string(t && *t ? t : "/tmp") + "/mjbuoy-radcache-XXXXXX";
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
void spit(const std::string& p, const std::string& s) {
  std::ofstream f(p, std::ios::binary | std::ios::trunc);
  f << s;
}

// a 1 m x 1 m x 0.5 m box centred on the mean sea level at qpos0 (the
// panel solver takes its lower half) with radiation at 4 frequencies; extra goes into
// <custom>, size is the box's half sizes, omega mjbuoy.radiation.omega
std::string box(const std::string& dir, const std::string& extra = "",
                const char* size = "0.5 0.5 0.25", const char* omega = "1 9 4") {
  return "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
         "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
         "<text name=\"mjbuoy.radiation.cache\" data=\"" + dir + "\"/>"
         "<numeric name=\"mjbuoy.radiation.omega\" data=\"" + omega + "\"/>" + extra +
         "</custom><worldbody><body name=\"boat\"><freejoint/>"
         "<geom name=\"hull\" type=\"box\" size=\"" + size + "\" mass=\"256.25\"/>"
         "</body></worldbody></mujoco>";
}

const mjb::RadCacheStats& stats(const Scene& s) { return mjb::buoyOf(s.b)->radcache; }
const mjb::HydroCoef& coef(const Scene& s) { return mjb::buoyOf(s.b)->coef.at(0).second; }

// bit-identical: every double of both the same bytes
void expectSame(const mjb::HydroCoef& a, const mjb::HydroCoef& b) {
  EXPECT_EQ(std::memcmp(a.Ainf, b.Ainf, sizeof a.Ainf), 0);
  EXPECT_EQ(std::memcmp(a.ref, b.ref, sizeof a.ref), 0);
  EXPECT_EQ(a.omega, b.omega);
  EXPECT_EQ(a.A, b.A);
  EXPECT_EQ(a.B, b.B);
  EXPECT_EQ(a.heading, b.heading);
  EXPECT_EQ(a.Xre, b.Xre);
  EXPECT_EQ(a.Xim, b.Xim);
  EXPECT_EQ(a.FKre, b.FKre);
  EXPECT_EQ(a.FKim, b.FKim);
}

// store then load gives back the same bits, X and FK included, values that
// do not survive a decimal round trip at 6 digits included (1/3, 1e-300)
TEST(RadCache, RoundTripIsBitIdentical) {
  TmpDir t;
  ASSERT_FALSE(t.path.empty());
  mjb::HydroCoef c;
  c.rho = 1025.0 / 3, c.g = 9.80665, c.depth = 0;
  c.ref[0] = 1.0 / 3, c.ref[1] = -1e-300, c.ref[2] = 0.1;
  c.omega = {0.5, 1.0 / 7, 3};
  c.heading = {0, M_PI / 3};
  for (int i = 0; i < 36; i++) c.Ainf[i] = std::sqrt(i + 0.5);
  for (int i = 0; i < 36 * 3; i++) c.A.push_back(std::exp(0.01 * i)), c.B.push_back(-1.0 / (i + 3));
  for (int i = 0; i < 36; i++) {
    c.Xre.push_back(std::sin(i)), c.Xim.push_back(std::cos(i));
    c.FKre.push_back(i / 7.0), c.FKim.push_back(-i / 11.0);
  }
  mjb::PanelMesh p;
  p.vert = {0, 0, -1, 1, 0, 0, 0, 1, 0};
  p.face = {0, 1, 2, -1};
  std::string key = mjb::radCacheKey(p, mjb::PanelMesh(), c.omega, c.heading, c), note;
  ASSERT_TRUE(mjb::radCacheStore(t.path, key, c, &note)) << note;
  mjb::HydroCoef r;
  ASSERT_TRUE(mjb::radCacheLoad(t.path, key, &r, &note)) << note;
  expectSame(c, r);
  EXPECT_EQ(std::memcmp(&c.rho, &r.rho, 8), 0);
  EXPECT_EQ(std::memcmp(&c.g, &r.g, 8), 0);
  // another mesh is another key: a plain miss, no note
  p.vert[2] = -1.0000001;
  std::string k2 = mjb::radCacheKey(p, mjb::PanelMesh(), c.omega, c.heading, c);
  EXPECT_NE(k2, key);
  EXPECT_FALSE(mjb::radCacheLoad(t.path, k2, &r, &note));
  EXPECT_EQ(note, "");
}

// the second attach of the same model reads the file the first one wrote
// and gets the same coefficients (and so the same inertia matrix)
TEST(RadCache, SecondAttachHitsTheCache) {
  TmpDir t;
  Scene a(box(t.path));
  ASSERT_TRUE(a.ok()) << a.err;
  EXPECT_EQ(stats(a).miss, 1);
  EXPECT_EQ(stats(a).write, 1);
  EXPECT_EQ(stats(a).hit, 0);
  Scene b(box(t.path));
  ASSERT_TRUE(b.ok()) << b.err;
  EXPECT_EQ(stats(b).hit, 1);
  EXPECT_EQ(stats(b).miss, 0);
  EXPECT_EQ(stats(b).write, 0);
  EXPECT_STREQ(mjb_warnings(b.b), mjb_warnings(a.b));
  expectSame(coef(a), coef(b));
  mj_forward(a.m, a.d);
  mj_forward(b.m, b.d);
  for (int i = 0; i < a.m->nM; i++) EXPECT_EQ(a.d->qM[i], b.d->qM[i]) << i;
}

// a cache file damaged in one byte, cut short, or emptied is never used:
// recomputed (same result as a cold solve), named in a warning, rewritten
TEST(RadCache, CorruptFileIsRecomputed) {
  TmpDir t;
  // drift off: one file (the drift table's own file: tests/meandrift_td_test.cc)
  const std::string off = "<text name=\"mjbuoy.radiation.drift\" data=\"off\"/>";
  Scene a(box(t.path, off));
  ASSERT_TRUE(a.ok()) << a.err;
  mjb::HydroCoef ref = coef(a);
  std::string file;
  // the one file the first attach wrote
  FILE* p = popen(("ls '" + t.path + "'").c_str(), "r");
  char line[512] = "";
  ASSERT_TRUE(p && std::fgets(line, sizeof line, p));
  pclose(p);
  line[std::strcspn(line, "\n")] = 0;
  file = t.path + "/" + line;
  std::string good = slurp(file);
  ASSERT_GT(good.size(), 100u);
  struct Case { const char* what; std::string bytes; const char* want; };
  std::string flip = good;
  flip[flip.size() / 2] ^= 0x10;  // one bit in the middle of the coefficients
  const Case cs[] = {{"bit flip", flip, "checksum"},
                     {"truncated", good.substr(0, good.size() - 9), "checksum"},
                     {"header only", good.substr(0, 12), "truncated"}};
  for (const Case& c : cs) {
    spit(file, c.bytes);
    Scene s(box(t.path, off));
    ASSERT_TRUE(s.ok()) << s.err;
    EXPECT_EQ(stats(s).hit, 0) << c.what;
    EXPECT_EQ(stats(s).miss, 1) << c.what;
    EXPECT_EQ(stats(s).write, 1) << c.what;
    std::string w = mjb_warnings(s.b);
    EXPECT_NE(w.find(file), std::string::npos) << c.what << ": " << w;
    EXPECT_NE(w.find(c.want), std::string::npos) << c.what << ": " << w;
    expectSame(ref, coef(s));
    EXPECT_EQ(slurp(file), good) << c.what << ": rewritten whole";
  }
}

// a file of the user's at the cache file's name is not a cache file: it is
// neither read nor replaced
TEST(RadCache, ForeignFileIsLeftAlone) {
  TmpDir t;
  Scene a(box(t.path));
  ASSERT_TRUE(a.ok()) << a.err;
  FILE* p = popen(("ls '" + t.path + "'").c_str(), "r");
  char line[512] = "";
  ASSERT_TRUE(p && std::fgets(line, sizeof line, p));
  pclose(p);
  line[std::strcspn(line, "\n")] = 0;
  std::string file = t.path + "/" + line, mine = "my notes, not a cache file\n";
  spit(file, mine);
  Scene s(box(t.path));
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_EQ(stats(s).miss, 1);
  EXPECT_EQ(stats(s).write, 0);
  EXPECT_NE(std::string(mjb_warnings(s.b)).find("is not an mjbuoy cache file"), std::string::npos)
      << mjb_warnings(s.b);
  EXPECT_EQ(slurp(file), mine);
}

// every input of the solution is in the key: a changed mesh, frequency,
// density, gravity, lid or refinement misses; an unchanged one hits
TEST(RadCache, ChangedMeshOrSettingMisses) {
  TmpDir t;
  Scene a(box(t.path));
  ASSERT_TRUE(a.ok()) << a.err;
  struct Case { const char* what; std::string xml; };
  const Case cs[] = {
      {"mesh", box(t.path, "", "0.5 0.5001 0.25")},
      {"omega", box(t.path, "", "0.5 0.5 0.25", "1 9.001 4")},
      {"density", box(t.path, "<numeric name=\"mjbuoy.sea.density\" data=\"1020\"/>")},
      {"gravity", box(t.path) .replace(8, 0, "<option gravity=\"0 0 -9.8\"/>")},
      {"lid", box(t.path, "<text name=\"mjbuoy.radiation.lid\" data=\"off\"/>")},
      {"refine", box(t.path, "<numeric name=\"mjbuoy.radiation.refine\" data=\"1\"/>")},
  };
  for (const Case& c : cs) {
    Scene s(c.xml);
    ASSERT_TRUE(s.ok()) << c.what << ": " << s.err;
    EXPECT_EQ(stats(s).hit, 0) << c.what;
    EXPECT_EQ(stats(s).miss, 1) << c.what;
  }
  Scene same(box(t.path));
  ASSERT_TRUE(same.ok()) << same.err;
  EXPECT_EQ(stats(same).hit, 1);
}

// a hull above the panel budget (mjbuoy.radiation.panels) is solved on a
// coarsened copy, whose panels are the key: a changed budget is a new
// solution, the same one a hit; the warning names the body and the counts
std::string wigley(const std::string& dir, int budget) {
  return "<mujoco><asset><mesh name=\"w\" file=\"" MJB_MODELS "/meshes/wigley_2800.obj\"/>"
         "</asset><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
         "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
         "<text name=\"mjbuoy.radiation.diffraction\" data=\"off\"/>"
         "<text name=\"mjbuoy.radiation.cache\" data=\"" + dir + "\"/>"
         "<numeric name=\"mjbuoy.radiation.omega\" data=\"2 8 3\"/>"
         "<numeric name=\"mjbuoy.radiation.panels\" data=\"" + std::to_string(budget) + "\"/>"
         "</custom><worldbody><body name=\"boat\"><freejoint/>"
         "<geom name=\"hull\" type=\"mesh\" mesh=\"w\" mass=\"176.2\"/>"
         "</body></worldbody></mujoco>";
}

TEST(RadCache, CoarseningBudgetIsInTheKey) {
  TmpDir t;
  Scene a(wigley(t.path, 400));
  ASSERT_TRUE(a.ok()) << a.err;
  EXPECT_EQ(stats(a).miss, 1);
  std::string w = mjb_warnings(a.b);
  EXPECT_NE(w.find("radiation of body \"boat\": hull coarsened for the panel solver from "),
            std::string::npos) << w;
  EXPECT_NE(w.find("mjbuoy.radiation.panels = 400"), std::string::npos) << w;
  EXPECT_NE(w.find("displaced volume"), std::string::npos) << w;
  Scene b(wigley(t.path, 300));
  ASSERT_TRUE(b.ok()) << b.err;
  EXPECT_EQ(stats(b).hit, 0);
  EXPECT_EQ(stats(b).miss, 1);
  Scene c(wigley(t.path, 400));
  ASSERT_TRUE(c.ok()) << c.err;
  EXPECT_EQ(stats(c).hit, 1);
  expectSame(coef(a), coef(c));
}

// a cache directory that cannot be made (its parent is a file) is a
// warning naming it: the coefficients are computed all the same
TEST(RadCache, UnwritableDirectoryIsAWarning) {
  TmpDir t;
  spit(t.path + "/file", "x");
  std::string dir = t.path + "/file/cache";
  Scene s(box(dir));
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_EQ(stats(s).miss, 1);
  EXPECT_EQ(stats(s).write, 0);
  EXPECT_NE(std::string(mjb_warnings(s.b)).find("cannot make the directory " + dir),
            std::string::npos) << mjb_warnings(s.b);
  EXPECT_GT(coef(s).Ainf[14], 0);
}

// three free boxes (2 m x 1 m x 0.5 m, half under water) turned by 0, 25
// and 70 deg about the vertical, apart, with diffraction at 4 frequencies
std::string fleet(const std::string& dir) {
  std::string x = "<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h0 h1 h2\"/>"
                  "<text name=\"mjbuoy.radiation\" data=\"on\"/>"
                  "<text name=\"mjbuoy.radiation.cache\" data=\"" + dir + "\"/>"
                  "<numeric name=\"mjbuoy.radiation.omega\" data=\"1 9 4\"/>"
                  "</custom><worldbody>";
  const char* yaw[3] = {"0", "25", "70"};
  for (int i = 0; i < 3; i++) {
    const std::string n = std::to_string(i);
    x += "<body name=\"b" + n + "\" pos=\"" + std::to_string(5 * i) + " 0 0\" euler=\"0 0 " +
         yaw[i] + "\"><freejoint/><geom name=\"h" + n + "\" type=\"box\" size=\"1 0.5 0.25\" "
         "mass=\"512.5\"/></body>";
  }
  return x + "</worldbody></mujoco>";
}

// the progress lines of an attach (mjb_setProgress)
void keepLine(const char* line, void* out) { ((std::vector<std::string>*)out)->push_back(line); }

// the progress lines while it lives: the receiver is removed however the
// test ends (the lines die with it)
struct Lines {
  std::vector<std::string> v;
  Lines() { mjb_setProgress(keepLine, &v); }
  ~Lines() { mjb_setProgress(nullptr, nullptr); }
};

// identical hulls turned about the vertical are solved once: the potential
// flow problem is invariant under that turn (docs/physics.md section 13,
// "Identical hulls"), so each box's added mass and damping in its own axes
// are the unturned box's; the progress lines say what is solved, reused
// and read from the cache, and nothing once the receiver is removed
TEST(RadCache, IdenticalHullsSolveOnce) {
  TmpDir t;
  Lines kept;
  std::vector<std::string>& lines = kept.v;
  Scene a(fleet(t.path));
  ASSERT_TRUE(a.ok()) << a.err;
  EXPECT_EQ(stats(a).miss, 1);
  EXPECT_EQ(stats(a).same, 2);
  ASSERT_EQ(lines.size(), 3u);
  for (const char* w : {"radiation of body \"b0\": panel solver: ", " body and ", " lid panels",
                        "4 frequencies 1 to 9 rad/s", "36 headings", "deep water: about "})
    EXPECT_NE(lines[0].find(w), std::string::npos) << w << " in " << lines[0];
  EXPECT_EQ(lines[1], "radiation of body \"b1\": the same panels as body \"b0\" (an identical "
                      "hull): its solution");
  // the reused solutions were stored under each hull's own key: the next
  // attach solves nothing and has the same numbers, bit for bit, as the first
  Scene b(fleet(t.path));
  ASSERT_TRUE(b.ok()) << b.err;
  EXPECT_EQ(stats(b).hit, 3);
  EXPECT_EQ(stats(b).miss, 0);
  ASSERT_EQ(lines.size(), 6u);
  for (int i = 0; i < 3; i++) {
    const std::string w = "radiation of body \"b" + std::to_string(i) + "\": read from the cache ";
    EXPECT_NE(lines[3 + i].find(w + t.path + "/"), std::string::npos) << lines[3 + i];
  }
  const auto& ca = mjb::buoyOf(a.b)->coef;
  const auto& cb = mjb::buoyOf(b.b)->coef;
  ASSERT_EQ(cb.size(), ca.size());
  for (size_t i = 0; i < ca.size(); i++) {
    EXPECT_EQ(cb[i].second.A, ca[i].second.A) << i;
    EXPECT_EQ(cb[i].second.B, ca[i].second.B) << i;
  }
  mjb_setProgress(nullptr, nullptr);
  Scene c(fleet(t.path));
  EXPECT_EQ(lines.size(), 6u);
  const auto& cf = mjb::buoyOf(a.b)->coef;
  ASSERT_EQ(cf.size(), 3u);
  double ba = 0, bb = 0;
  for (double v : cf[0].second.A) ba = std::max(ba, std::fabs(v));
  for (double v : cf[0].second.B) bb = std::max(bb, std::fabs(v));
  for (int i = 1; i < 3; i++) {
    const mjb::HydroCoef &u = cf[0].second, &v = cf[i].second;
    ASSERT_EQ(u.A.size(), v.A.size());
    for (size_t k = 0; k < u.A.size(); k++) {
      EXPECT_NEAR(v.A[k], u.A[k], 1e-9 * ba) << i << " " << k;
      EXPECT_NEAR(v.B[k], u.B[k], 1e-9 * bb) << i << " " << k;
    }
  }
}

// bodies without names are named by their ids in the progress lines, the
// reused solution's line too, and the attach succeeds
TEST(RadCache, UnnamedIdenticalHullsNamedByTheirIds) {
  TmpDir t;
  Lines kept;
  const std::vector<std::string>& lines = kept.v;
  std::string x = fleet(t.path);
  for (int i = 0; i < 3; i++) {
    const std::string from = "<body name=\"b" + std::to_string(i) + "\"";
    x.replace(x.find(from), from.size(), "<body");
  }
  Scene a(x);
  ASSERT_TRUE(a.ok()) << a.err;
  EXPECT_EQ(stats(a).same, 2);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].find("radiation of body 1 (no name): panel solver: "), 0u) << lines[0];
  EXPECT_EQ(lines[1], "radiation of body 2 (no name): the same panels as body 1 (no name) (an "
                      "identical hull): its solution");
}

// where the cache lives: the MJCF entry, else MJBUOY_RADIATION_CACHE, else
// $XDG_CACHE_HOME/mjbuoy, else ~/.cache/mjbuoy; "off" turns it off
TEST(RadCache, DirectoryPrecedence) {
  struct Env {
    const char* name;
    std::string old;
    bool had;
    explicit Env(const char* n) : name(n) {
      const char* v = std::getenv(n);
      had = v, old = v ? v : "";
    }
    ~Env() { had ? setenv(name, old.c_str(), 1) : unsetenv(name); }
  } e1(mjb::kRadCacheEnv), e2("XDG_CACHE_HOME"), e3("HOME");
  setenv("HOME", "/home/u", 1);
  unsetenv("XDG_CACHE_HOME");
  unsetenv(mjb::kRadCacheEnv);
  EXPECT_EQ(mjb::radCacheDir(""), "/home/u/.cache/mjbuoy");
  setenv("XDG_CACHE_HOME", "/xdg", 1);
  EXPECT_EQ(mjb::radCacheDir(""), "/xdg/mjbuoy");
  setenv(mjb::kRadCacheEnv, "/ci/cache", 1);
  EXPECT_EQ(mjb::radCacheDir(""), "/ci/cache");
  EXPECT_EQ(mjb::radCacheDir("/model/dir"), "/model/dir");
  EXPECT_EQ(mjb::radCacheDir("off"), "");
  setenv(mjb::kRadCacheEnv, "off", 1);
  EXPECT_EQ(mjb::radCacheDir(""), "");
  EXPECT_EQ(mjb::radCacheDir("/model/dir"), "/model/dir");
}

}  // namespace
