// wind forces, changing the sea between steps, validation of the new
// entries (docs/physics.md, "Irregular seas and wind"; docs/mjcf.md 7-9)
#include <malloc.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testutil.h"

// every allocation of this process is counted: mjb_setSea must not
// allocate. Plain builds replace operator new (the library's containers
// allocate through it); under AddressSanitizer, whose own operator new
// must pair with its delete, its malloc hook counts every allocation
static std::atomic<long> gnew{0}, gfree{0};
#if defined(__SANITIZE_ADDRESS__)
const bool kAllMallocs = true;  // the hook sees C mallocs too (the GL driver's)
// the sanitizer runtime's hook (sanitizer/allocator_interface.h, which
// g++ does not ship)
extern "C" int __sanitizer_install_malloc_and_free_hooks(
    void (*malloc_hook)(const volatile void*, size_t), void (*free_hook)(const volatile void*));
static void countHook(const volatile void*, size_t) { gnew++; }
static void freeHook(const volatile void* p) {  // both hooks are required
  if (p) gfree++;
}
static const int kHooked = __sanitizer_install_malloc_and_free_hooks(countHook, freeHook);
#else
const bool kAllMallocs = false;
void* operator new(size_t n) {
  gnew++;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  if (p) gfree++;
  std::free(p);
}
void operator delete(void* p, size_t) noexcept {
  if (p) gfree++;
  std::free(p);
}
#endif

namespace {

using mjbt::Scene;

// a dry box L x B x H = 2 x 1 x 1 m held 10 m above a flat sea, as a hull
// or as a superstructure geom on a box hull
std::string boxXml(const std::string& wind, const std::string& extra = "") {
  return R"(<mujoco><option timestep="0.01"/><custom>
    <text name="mjbuoy.hulls" data="box"/>
    <numeric name="mjbuoy.hull.slamming" data="0 100 2"/>)" + wind + R"(</custom>
    <worldbody><body name="b" pos="0 0 10"><freejoint/>
      <geom name="box" type="box" size="1 0.5 0.5" mass="500"/>)" + extra +
         R"(</body></worldbody></mujoco>)";
}

// hand calculation: a 10 m/s wind along +x on the 1 x 1 m face of the box
// (C_d = 1.2): 0.5 rho C_d U^2 B H = 0.5 1.225 1.2 100 1 = 73.5 N; skin
// friction (C_f = 0.01) on the four faces along the flow, 4 x 2 x 1 = 8
// m^2: 0.5 rho C_f U^2 8 = 4.9 N; together 78.4 N along +x, no torque
// about the centre of the box
TEST(Wind, StillBoxInWindGetsHandDrag) {
  Scene s(boxXml(R"(<numeric name="mjbuoy.wind.speed" data="10"/>
    <numeric name="mjbuoy.wind.drag" data="1.2 0.01"/>)"));
  ASSERT_TRUE(s.ok()) << s.err;
  mj_forward(s.m, s.d);
  const mjtNum* w = mjb_wrenchPart(s.b, s.d, mjbPART_WIND) + 6 * s.body("b");
  EXPECT_NEAR(w[0], 78.4, 1e-9);
  EXPECT_NEAR(w[1], 0, 1e-9);
  EXPECT_NEAR(w[2], 0, 1e-9);
  for (int j = 3; j < 6; j++) EXPECT_NEAR(w[j], 0, 1e-9);
  std::printf("[wind] still box, 10 m/s: Fx %.6f N (hand 78.4 N)\n", w[0]);
  // all of it reaches the total wrench: the box is dry, no water force
  EXPECT_NEAR(mjb_wrench(s.b, s.d)[6 * s.body("b")], 78.4, 1e-9);
}

// the same relative flow from towing the box at -10 m/s through still air
// (wind entries present, speed 0); wind from 90 degrees hits the 2 x 1 m
// side: 0.5 1.225 1.2 100 2 = 147 N, friction on 4 faces of 1 + 1 + 2 + 2
// = 6 m^2: 0.5 1.225 0.01 100 6 = 3.675 N; 150.675 N along +y
TEST(Wind, TowedBoxAndBeamWind) {
  {
    Scene s(boxXml(R"(<numeric name="mjbuoy.wind.speed" data="0"/>
      <numeric name="mjbuoy.wind.drag" data="1.2 0.01"/>)"));
    ASSERT_TRUE(s.ok()) << s.err;
    s.d->qvel[0] = -10;
    mj_forward(s.m, s.d);
    EXPECT_NEAR(mjb_wrenchPart(s.b, s.d, mjbPART_WIND)[6 * s.body("b")], 78.4, 1e-9);
  }
  Scene s(boxXml(R"(<numeric name="mjbuoy.wind.speed" data="10"/>
    <numeric name="mjbuoy.wind.direction" data="90"/>
    <numeric name="mjbuoy.wind.drag" data="1.2 0.01"/>)"));
  ASSERT_TRUE(s.ok()) << s.err;
  mj_forward(s.m, s.d);
  const mjtNum* w = mjb_wrenchPart(s.b, s.d, mjbPART_WIND) + 6 * s.body("b");
  EXPECT_NEAR(w[0], 0, 1e-9);
  EXPECT_NEAR(w[1], 150.675, 1e-9);
}

// a superstructure geom (a 1 x 1 x 1 m cabin 1 m above the box's centre)
// catches 0.5 1.225 1 100 1 = 61.25 N (C_d 1, C_f 0) more than the box,
// at the cabin's height: a torque of 61.25 N x 1 m (+ the box's own
// heel arm 0) about +y, relative to the COM
TEST(Wind, SuperstructureGeomCatchesWind) {
  Scene s(boxXml(R"(<numeric name="mjbuoy.wind.speed" data="10"/>
    <numeric name="mjbuoy.wind.drag" data="1 0"/>
    <text name="mjbuoy.wind.geoms" data="cabin"/>)",
                 R"(<geom name="cabin" type="box" size="0.5 0.5 0.5" pos="0 0 1" mass="0"/>)"));
  ASSERT_TRUE(s.ok()) << s.err;
  mj_forward(s.m, s.d);
  const int b = s.body("b");
  const mjtNum* w = mjb_wrenchPart(s.b, s.d, mjbPART_WIND) + 6 * b;
  EXPECT_NEAR(w[0], 61.25 + 61.25, 1e-9);  // box face 1 x 1 m, cabin face 1 x 1 m
  // torque about the COM (the box centre, the cabin is massless): the
  // cabin's 61.25 N at z = +1 m gives tau_y = 61.25 N m
  EXPECT_NEAR(w[4], 61.25, 1e-9);
}

// a floating box barge in a 20 m/s wind moves downwind
TEST(Wind, FloatingHullDriftsDownwind) {
  Scene s(R"(<mujoco><option timestep="0.01"/><custom>
    <text name="mjbuoy.hulls" data="hull"/>
    <numeric name="mjbuoy.wind.speed" data="20"/>
    <numeric name="mjbuoy.wind.direction" data="45"/>
    </custom><worldbody><body name="b" pos="0 0 0"><freejoint/>
    <geom name="hull" type="box" size="2 1 0.5" mass="2000"/></body></worldbody></mujoco>)");
  ASSERT_TRUE(s.ok()) << s.err;
  for (int i = 0; i < 1000; i++) mj_step(s.m, s.d);
  double x = s.d->qpos[0], y = s.d->qpos[1];
  std::printf("[wind] barge after 10 s in 20 m/s towards 45 deg: x %.3f y %.3f m\n", x, y);
  EXPECT_GT(x, 0.05);
  EXPECT_GT(y, 0.05);
  EXPECT_GT(s.d->qvel[0], 0);
  EXPECT_GT(s.d->qvel[1], 0);
}

// the Froya spectrum's variance: sigma_u^2 = integral S df; gusts drawn
// from it reproduce the variance over a long record (the components hold
// the integral between 5e-4 and 0.5 Hz)
TEST(Wind, GustsHaveTheFroyaVariance) {
  Scene s(boxXml(R"(<numeric name="mjbuoy.wind.speed" data="15"/>
    <text name="mjbuoy.wind.gust" data="froya"/>
    <numeric name="mjbuoy.wind.gustcomponents" data="256"/>)"));
  ASSERT_TRUE(s.ok()) << s.err;
  // independent integral of the Froya formula (DNV-RP-C205 2.3.5),
  // trapezoids in log f
  double var = 0, l0 = std::log(5e-4), l1 = std::log(0.5), h = (l1 - l0) / 20000;
  for (int i = 0; i <= 20000; i++) {
    double f = std::exp(l0 + i * h), u = 1.5, ft = 172 * f * std::pow(u, -0.75);
    double S = 320 * u * u / std::pow(1 + std::pow(ft, 0.468), 5 / (3 * 0.468));
    var += (i == 0 || i == 20000 ? 0.5 : 1) * S * f * h;
  }
  double m = 0, v = 0;
  const int n = 200000;  // 20000 s every 0.1 s: ten times the longest gust period
  for (int i = 0; i < n; i++) {
    mjtNum u[2];
    mjb_windVelocity(s.b, i * 0.1, u);
    m += u[0];
    v += u[0] * u[0];
  }
  m /= n;
  v = v / n - m * m;
  std::printf("[wind] Froya 15 m/s: std %.3f m/s (spectrum %.3f)\n", std::sqrt(v), std::sqrt(var));
  EXPECT_NEAR(m, 15, 0.1);
  EXPECT_NEAR(std::sqrt(v), std::sqrt(var), 0.05 * std::sqrt(var));
}

// ---- mjb_setSea ----

const char* kSeaBody = R"(</custom><worldbody><body name="b" pos="0 0 0"><freejoint/>
    <geom name="hull" type="box" size="2 1 0.5" mass="2000"/></body></worldbody></mujoco>)";

// the model a fresh attach sees: JONSWAP Hs 1.5 m Tp 6 s, 48 components,
// seed 4, spreading 8 towards 20 deg, a current and wind; no start-up ramp,
// as the zeroed mjbSea given to mjb_setSea below
std::string seaXml(bool withSea) {
  std::string s = R"(<mujoco><option timestep="0.01"/><custom>
    <text name="mjbuoy.hulls" data="hull"/>
    <numeric name="mjbuoy.hull.slamming" data="0 100 2"/>
    <numeric name="mjbuoy.sea.capacity" data="64"/>
    <numeric name="mjbuoy.sea.ramp" data="0"/>
    <numeric name="mjbuoy.wind.drag" data="1 0.002"/>)";
  if (withSea) {
    s += R"(<text name="mjbuoy.spectrum.a.type" data="jonswap"/>
    <numeric name="mjbuoy.spectrum.a.hs" data="1.5"/>
    <numeric name="mjbuoy.spectrum.a.tp" data="6"/>
    <numeric name="mjbuoy.spectrum.a.components" data="48"/>
    <numeric name="mjbuoy.spectrum.a.seed" data="4"/>
    <numeric name="mjbuoy.spectrum.a.spreading" data="8"/>
    <numeric name="mjbuoy.spectrum.a.direction" data="20"/>
    <numeric name="mjbuoy.sea.current" data="0.3 -0.1"/>
    <numeric name="mjbuoy.wind.speed" data="12"/>
    <numeric name="mjbuoy.wind.direction" data="-30"/>)";
  }
  return s + kSeaBody;
}

void changeSeaMatchesFreshAttach(const char* backend) {
  mjModel* m1 = mjbt::loadXML(seaXml(false));
  mjModel* m2 = mjbt::loadXML(seaXml(true));
  ASSERT_TRUE(m1 && m2);
  char e[1024];
  mjbBuoy* b1 = mjb_attach(m1, backend, e, sizeof(e));
  ASSERT_TRUE(b1) << e;
  ASSERT_STREQ(mjb_info(b1).backend, backend);
  mjbBuoy* b2 = mjb_attach(m2, backend, e, sizeof(e));
  ASSERT_TRUE(b2) << e;
  mjData* d1 = mj_makeData(m1);
  mjData* d2 = mj_makeData(m2);
  for (int i = 0; i < 50; i++) mj_step(m1, d1);  // in flat water
  mjbSpectrum sp;
  mjb_defaultSpectrum(&sp);
  sp.hs = 1.5, sp.tp = 6, sp.n = 48, sp.seed = 4, sp.spread = 8, sp.dir = 20;
  mjbSea sea = {};
  sea.current[0] = 0.3, sea.current[1] = -0.1;
  sea.spectrum = &sp, sea.nspectrum = 1;
  sea.wind.speed = 12, sea.wind.dir = -30, sea.wind.ngust = 128, sea.wind.seed = 1;
  {  // the counter sees allocations (else the check below could not fail)
    long c0 = gnew;
    std::vector<double> probe(10);  // one allocation (its buffer)
    probe[3] = 1;
    ASSERT_GE(gnew - c0, 1) << probe[3];
  }
  long n0 = gnew, f0 = gfree;
  struct mallinfo2 a0 = mallinfo2();
  ASSERT_EQ(mjb_setSea(b1, &sea, e, sizeof(e)), 1) << e;
  struct mallinfo2 a1 = mallinfo2();
  if (kAllMallocs && std::string(backend) == "gl") {
    // the GL driver (Mesa llvmpipe) mallocs scratch of its own in the
    // upload (3 blocks measured) and frees it before the call returns:
    // nothing outlives the call; our code calls no operator new
    EXPECT_EQ(gnew - n0, gfree - f0);
  } else {
    EXPECT_EQ(gnew - n0, 0);  // no operator new (our code); ASan: no malloc at all
  }
  EXPECT_EQ(a1.uordblks, a0.uordblks);
  EXPECT_EQ(mjb_waves(b1, nullptr, 0), 48);
  // the same state in the fresh model
  mju_copy(d2->qpos, d1->qpos, m1->nq);
  mju_copy(d2->qvel, d1->qvel, m1->nv);
  d2->time = d1->time;
  mj_forward(m1, d1);
  mj_forward(m2, d2);
  double c1[6 * 48], c2[6 * 48];
  mjb_waves(b1, c1, 48);
  mjb_waves(b2, c2, 48);
  for (int i = 0; i < 6 * 48; i++) EXPECT_EQ(c1[i], c2[i]) << i;
  EXPECT_EQ(mjb_seaHeight(b1, 1, 2, d1->time), mjb_seaHeight(b2, 1, 2, d2->time));
  for (int p : {int(mjbPART_PRESSURE), int(mjbPART_DRAG), int(mjbPART_VISCOUS),
                int(mjbPART_WIND)}) {
    const mjtNum* w1 = mjb_wrenchPart(b1, d1, p) + 6;
    const mjtNum* w2 = mjb_wrenchPart(b2, d2, p) + 6;
    for (int j = 0; j < 6; j++) {
      EXPECT_NEAR(w1[j], w2[j], 1e-7 * (1 + std::fabs(w2[j]))) << "part " << p << " " << j;
    }
  }
  // the wind did act: 12 m/s on the dry part of the hull
  EXPECT_GT(std::fabs(mjb_wrenchPart(b1, d1, mjbPART_WIND)[6]), 1.0);
  mj_deleteData(d1);
  mj_deleteData(d2);
  mjb_detach(b1);
  mjb_detach(b2);
  mj_deleteModel(m1);
  mj_deleteModel(m2);
}

TEST(SetSea, TakesEffectAtOnceWithoutAllocatingCpu) { changeSeaMatchesFreshAttach("cpu"); }
TEST(SetSea, TakesEffectAtOnceWithoutAllocatingGl) { changeSeaMatchesFreshAttach("gl"); }

// a box with radiation and diffraction (docs/physics.md section 15): the
// component rows of the diffraction table are rewritten by mjb_setSea
// without allocating, steps allocate nothing, and the result is the fresh
// attach's with the same waves (steepness 0: Airy) in the model
std::string radBoxXml(const std::string& waves) {
  return R"(<mujoco><option timestep="0.01"/><custom>
    <text name="mjbuoy.hulls" data="box"/>
    <text name="mjbuoy.radiation" data="on"/>
    <numeric name="mjbuoy.radiation.omega" data="1 9 4"/>
    <numeric name="mjbuoy.sea.capacity" data="8"/>
    <numeric name="mjbuoy.sea.ramp" data="0"/>)" + waves + R"(</custom>
    <worldbody><body name="b"><freejoint/>
      <geom name="box" type="box" size="1 0.5 0.5" mass="1000"/>
    </body></worldbody></mujoco>)";
}

TEST(SetSea, DiffractionFollowsWithoutAllocating) {
  const double w[3][5] = {{0.1, 6, 30, 10, 0}, {0.05, 3, -60, 80, 0}, {0.08, 12, 170, 0, 0}};
  std::string ws;
  for (int i = 0; i < 3; i++) {
    char b[200];
    std::snprintf(b, sizeof b, "<numeric name=\"mjbuoy.wave.w%d\" data=\"%g %g %g %g %g\"/>", i,
                  w[i][0], w[i][1], w[i][2], w[i][3], w[i][4]);
    ws += b;
  }
  Scene a(radBoxXml("<numeric name=\"mjbuoy.airy.x\" data=\"0.1 20 0 0\"/>")), b(radBoxXml(ws));
  ASSERT_TRUE(a.ok() && b.ok()) << a.err << b.err;
  for (int i = 0; i < 20; i++) mj_step(a.m, a.d);
  mjbSea sea = {};
  sea.wave = &w[0][0];
  sea.nwave = 3;
  char e[512] = "";
  long n0 = gnew;
  ASSERT_EQ(mjb_setSea(a.b, &sea, e, sizeof e), 1) << e;
  EXPECT_EQ(gnew - n0, 0);
  n0 = gnew;
  for (int i = 0; i < 20; i++) mj_step(a.m, a.d);
  EXPECT_EQ(gnew - n0, 0);
  // the same state (memory restarted in both) in both models
  mj_resetData(a.m, a.d);
  for (Scene* c : {&a, &b}) {
    c->d->time = 1.7;
    c->d->qpos[0] = 0.3, c->d->qpos[2] = -0.05;
    c->d->qvel[1] = 0.1;
    mj_forward(c->m, c->d);
  }
  for (int j = 0; j < a.m->nv; j++) {
    EXPECT_NEAR(a.d->qfrc_passive[j], b.d->qfrc_passive[j],
                1e-7 * (1 + std::fabs(b.d->qfrc_passive[j]))) << j;
  }
}

TEST(SetSea, RejectsBadInputAndKeepsTheSea) {
  Scene s(seaXml(true));
  ASSERT_TRUE(s.ok()) << s.err;
  mjbSpectrum sp;
  mjb_defaultSpectrum(&sp);
  sp.hs = -1;
  mjbSea sea = {};
  sea.spectrum = &sp, sea.nspectrum = 1;
  char e[512];
  EXPECT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 0);
  EXPECT_NE(std::string(e).find("spectrum 0 hs = -1 is out of range: it must be > 0"),
            std::string::npos) << e;
  sp.hs = 1;
  sp.n = 65;  // one more than mjbuoy.sea.capacity
  EXPECT_EQ(mjb_setSea(s.b, &sea, e, sizeof(e)), 0);
  EXPECT_NE(std::string(e).find("65 wave components exceed the 64 reserved"), std::string::npos) << e;
  EXPECT_EQ(mjb_waves(s.b, nullptr, 0), 48);
}

// spectra add to each other and to listed waves: the count is the sum and
// the variance too, m0 = Hs1^2 / 16 + Hs2^2 / 16 + A^2 / 2 (each spectrum's
// components hold its m0 over its range: 0.5-4 wp holds 99.9% of a
// JONSWAP's (gamma 3.3), 99.5% of a PM's, DNV-RP-C205 3.5.5)
TEST(SeaEntries, SpectraAddToEachOtherAndToWaves) {
  Scene s(R"(<mujoco><custom><text name="mjbuoy.hulls" data="hull"/>
    <numeric name="mjbuoy.wave.w" data="0.2 30 0 0 0"/>
    <text name="mjbuoy.spectrum.a.type" data="jonswap"/>
    <numeric name="mjbuoy.spectrum.a.hs" data="1"/><numeric name="mjbuoy.spectrum.a.tp" data="5"/>
    <numeric name="mjbuoy.spectrum.a.components" data="40"/>
    <text name="mjbuoy.spectrum.b.type" data="pm"/>
    <numeric name="mjbuoy.spectrum.b.hs" data="0.5"/><numeric name="mjbuoy.spectrum.b.tp" data="9"/>
    <numeric name="mjbuoy.spectrum.b.components" data="20"/><numeric name="mjbuoy.spectrum.b.seed" data="2"/>
    )" + std::string(kSeaBody));
  ASSERT_TRUE(s.ok()) << s.err;
  ASSERT_EQ(mjb_waves(s.b, nullptr, 0), 61);
  double c[6 * 61], m0 = 0;
  mjb_waves(s.b, c, 61);
  for (int i = 0; i < 61; i++) m0 += c[6 * i] * c[6 * i] / 2;
  EXPECT_NEAR(m0, 1.0 / 16 * 0.999 + 0.25 / 16 * 0.995 + 0.02, 2e-4);
  // the listed wave keeps its Gerstner description; spectra are linear
  EXPECT_EQ(c[0], 0.2);
  EXPECT_EQ(c[5], 0);
}

// validation of the entries: entry, value and range in the message
TEST(SeaEntries, ErrorsNameEntryValueAndRange) {
  struct Case { const char* xml; const char* want; } cases[] = {
    {R"(<text name="mjbuoy.spectrum.a.type" data="jonswap"/>
        <numeric name="mjbuoy.spectrum.a.hs" data="-2"/><numeric name="mjbuoy.spectrum.a.tp" data="8"/>)",
     "<numeric name=\"mjbuoy.spectrum.a.hs\"> value = -2 is out of range: it must be > 0 and <= 50 [m]"},
    {R"(<text name="mjbuoy.spectrum.a.type" data="jonswap"/><numeric name="mjbuoy.spectrum.a.hs" data="2"/>
        <numeric name="mjbuoy.spectrum.a.tp" data="8"/><numeric name="mjbuoy.spectrum.a.gamma" data="30"/>)",
     "<numeric name=\"mjbuoy.spectrum.a.gamma\"> value = 30 is out of range: it must be >= 1 and <= 10"},
    {R"(<text name="mjbuoy.spectrum.a.type" data="bretschneider"/>)",
     "value \"bretschneider\" is not a spectrum type; accepted: pm, jonswap, table"},
    {R"(<numeric name="mjbuoy.spectrum.a.hs" data="2"/>)", "spectrum \"a\" (mjbuoy.spectrum.a.*): no type"},
    {R"(<text name="mjbuoy.spectrum.a.type" data="jonswap"/><numeric name="mjbuoy.spectrum.a.hs" data="2"/>)",
     "needs hs and tp"},
    {R"(<text name="mjbuoy.spectrum.a.type" data="table"/>
        <numeric name="mjbuoy.spectrum.a.table" data="0.5 0 0.4 1"/>)",
     "table pair 2 omega = 0.4 is out of range: omegas must be finite, > 0 and rising"},
    {R"(<text name="mjbuoy.spectrum.a.type" data="pm"/><numeric name="mjbuoy.spectrum.a.wind" data="10"/>
        <numeric name="mjbuoy.spectrum.a.components" data="2.5"/>)",
     "<numeric name=\"mjbuoy.spectrum.a.components\"> value = 2.5 is not a whole number"},
    {R"(<numeric name="mjbuoy.wind.speed" data="150"/>)",
     "<numeric name=\"mjbuoy.wind.speed\"> value = 150 is out of range: it must be >= 0 and <= 100 [m/s, mean at 10 m]"},
    {R"(<numeric name="mjbuoy.wind.drag" data="1"/>)",
     "<numeric name=\"mjbuoy.wind.drag\"> has 1 value(s), expected 2"},
    {R"(<numeric name="mjbuoy.wind.sped" data="1"/>)", "unknown entry <numeric name=\"mjbuoy.wind.sped\">"},
    {R"(<text name="mjbuoy.wind.geoms" data="nothing"/>)", "entry \"nothing\" matches no named geom"},
  };
  for (const Case& c : cases) {
    std::string xml = std::string(R"(<mujoco><custom><text name="mjbuoy.hulls" data="hull"/>)") +
                      c.xml + kSeaBody;
    mjModel* m = mjbt::loadXML(xml);
    ASSERT_TRUE(m);
    char e[1024];
    mjbBuoy* b = mjb_attach(m, "cpu", e, sizeof(e));
    EXPECT_EQ(b, nullptr);
    EXPECT_NE(std::string(e).find(c.want), std::string::npos) << e;
    if (b) mjb_detach(b);
    mj_deleteModel(m);
  }
}

}  // namespace
