// model-level faults and extremes: hull scale from 1 mm to 1 km, masses
// MuJoCo rejects, hulls on welded, sliding and hinged bodies, a time step
// too long for the heave (docs/robustness.md)
#include <cstdlib>
#include <sstream>

#include <gtest/gtest.h>

#include "api/radconfig.h"
#include "testutil.h"

namespace mjbt {
namespace {

bool has(const std::string& s, const std::string& sub) { return s.find(sub) != std::string::npos; }

bool finite(const mjtNum* x, int n) {
  for (int i = 0; i < n; i++) if (!std::isfinite(x[i])) return false;
  return true;
}

// a free box hull of half sizes (a, b, c) and density half the water's,
// its centre starting `lift` above its floating height, stepped with dt on
// backend be for T s with mjbuoy's default hydrodynamics only (no simple
// damping). Floating height of the centre: c - draft = c - c = 0 (draft =
// rho_b / rho_w * 2c = c). Returns the mean and spread of the centre
// height over the last fifth of the run, and whether anything went
// non-finite or MuJoCo reset the state
struct Settle {
  double z = NAN, spread = NAN;  // mean centre height and max |z - mean| late in the run [m]
  bool finite = true;
  std::string warn;
};

Settle settleBox(double a, double b, double c, double dt, double T, const char* be) {
  char xml[1024];
  double mass = 0.5 * kRho * 8 * a * b * c;
  std::snprintf(xml, sizeof(xml),
                "<mujoco><option timestep=\"%.17g\"/><custom>"
                "<text name=\"mjbuoy.hulls\" data=\"hull\"/></custom><worldbody>"
                "<body name=\"b\" pos=\"0 0 %.17g\"><freejoint/>"
                "<geom name=\"hull\" type=\"box\" size=\"%.17g %.17g %.17g\" mass=\"%.17g\"/>"
                "</body></worldbody></mujoco>",
                dt, 0.2 * c, a, b, c, mass);
  Settle r;
  std::string e;
  mjModel* m = loadXML(xml, &e);
  EXPECT_TRUE(m) << e;
  if (!m) return r;
  char err[1024];
  mjbBuoy* bu = mjb_attach(m, be, err, sizeof(err));
  EXPECT_TRUE(bu) << err;
  if (!bu) {
    mj_deleteModel(m);
    return r;
  }
  r.warn = mjb_warnings(bu);
  mjData* d = mj_makeData(m);
  long n = std::lround(T / dt), k0 = n - n / 5;
  double sum = 0, lo = INFINITY, hi = -INFINITY;
  for (long k = 0; k < n; k++) {
    mj_step(m, d);
    if (!finite(d->qpos, m->nq) || !finite(d->qvel, m->nv) ||
        !finite(mjb_wrench(bu, d), 6 * m->nbody) || d->warning[mjWARN_BADQACC].number) {
      r.finite = false;
      break;
    }
    if (k >= k0) {
      double z = d->xpos[5];
      sum += z;
      lo = std::fmin(lo, z);
      hi = std::fmax(hi, z);
    }
  }
  r.z = sum / (n - k0);
  r.spread = std::fmax(hi - r.z, r.z - lo);
  mj_deleteData(d);
  mjb_detach(bu);
  mj_deleteModel(m);
  return r;
}

TEST(RobustModel, TinyAndHugeBoxesSettleAtTheirDrafts) {
  // 1 mm cube (5e-7 kg) and a 1000 x 200 x 20 m barge (2e9 kg), both at
  // half the water's density: draft = half the height, centre at z = 0.
  // Heave period 2 pi sqrt(draft / g): 45 ms and 6.3 s, so the steps are
  // 0.1 ms and 20 ms (1/450 and 1/315 of it); default hydrodynamic forces
  // settle both
  struct Case {
    const char* name;
    double a, b, c, dt, T;
  } cases[] = {{"1 mm cube", 5e-4, 5e-4, 5e-4, 1e-4, 1}, {"1 km barge", 500, 100, 10, 0.02, 300}};
  for (const Case& c : cases) {
    for (const char* be : {"cpu", "gl"}) {
      Settle r = settleBox(c.a, c.b, c.c, c.dt, c.T, be);
      SCOPED_TRACE(std::string(c.name) + " on " + be);
      EXPECT_TRUE(r.finite);
      EXPECT_EQ(r.warn, "");
      // mean over the last fifth at the draft within 0.5%, and the heave
      // from the 0.2 c start decayed below a tenth (the barge's drag per
      // kg is 1/1000 of the cube's: without radiation, on by default, it
      // rang for minutes, 0.13 m late spread; with it 0.53 mm)
      EXPECT_NEAR(r.z, 0, 0.005 * c.c);
      EXPECT_LT(r.spread, 0.1 * 0.2 * c.c);
      std::printf("[robust] %s on %s: centre %.3g m (draft %.3g m), late spread %.3g m\n",
                  c.name, be, r.z, c.c, r.spread);
    }
  }
}

TEST(RobustModel, ZeroOrNegativeMassIsRejectedByMuJoCo) {
  // MuJoCo's compiler refuses these before mjbuoy sees the model
  auto err = [](const char* body) {
    std::string e;
    mjModel* m = loadXML(std::string("<mujoco><worldbody><body name=\"b\"><freejoint/>") + body +
                             "</body></worldbody></mujoco>", &e);
    if (m) mj_deleteModel(m);
    return m ? std::string("compiled") : e;
  };
  EXPECT_TRUE(has(err("<geom name=\"hull\" type=\"box\" size=\"1 1 1\" mass=\"0\"/>"),
                  "mass and inertia of moving bodies must be larger than mjMINVAL"));
  EXPECT_TRUE(has(err("<geom name=\"hull\" type=\"box\" size=\"1 1 1\" mass=\"-1\"/>"),
                  "mass, inertia or density are negative in geom 'hull'"));
  EXPECT_TRUE(has(err("<inertial pos=\"0 0 0\" mass=\"-1\" diaginertia=\"1 1 1\"/>"
                      "<geom name=\"hull\" type=\"box\" size=\"1 1 1\"/>"),
                  "mass and inertia of moving bodies must be larger than mjMINVAL"));
}

// box hull 2 x 1 x 0.5 m, 300 kg in all: draft 0.15 m, centre at z = 0.1
const char kHead[] =
    "<mujoco><option timestep=\"0.002\"/><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
    "<numeric name=\"mjbuoy.hull.damping\" data=\"3000 300\"/></custom><worldbody>";
const char kTail[] = "</worldbody></mujoco>";

TEST(RobustModel, HullOnAWeldedChildActsThroughTheParentsJoint) {
  // the hull's body has no joint of its own: its wrench reaches the free
  // joint of the parent it is welded to. Child mass 100 or 0 (a massless
  // body carrying only the shape): the same total 300 kg, the same draft
  for (const char* child : {"100", "0"}) {
    std::string parent = std::to_string(300 - std::atoi(child));
    Scene s(std::string(kHead) + "<body name=\"b\" pos=\"0 0 0.3\"><freejoint/>"
            "<inertial pos=\"0 0 0\" mass=\"" + parent + "\" diaginertia=\"20 70 80\"/>"
            "<body name=\"c\"><geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"" +
            child + "\"/></body></body>" + kTail);
    ASSERT_TRUE(s.ok()) << s.err;
    EXPECT_STREQ(mjb_warnings(s.b), "");
    int b = s.body("b");
    EXPECT_NEAR(s.settle(30, 5, [&] { return s.d->xpos[3 * b + 2]; }), 0.1, 0.005 * 0.15)
        << "child mass " << child;
  }
}

TEST(RobustModel, SlammingStopsTheWholeRigidGroup) {
  // slamming may stop at most the mass moving rigidly with the hull: a hull
  // on a massless (or 100 kg) child welded to a 300 kg assembly must feel
  // the same slamming as the same hull on the 300 kg body itself (before,
  // a massless child got none)
  // with radiation on (explicitly: the added mass must not slow the dry
  // fall, docs/physics.md "Immersion factor"; before, the box fell at
  // g m / (m + A33) and had not reached the water in the 1.5 s) and off
  for (bool rad : {false, true}) {
    SCOPED_TRACE(rad ? "radiation on" : "radiation off");
    auto peak = [&](const std::string& body) {
      std::string head = kHead;
      if (rad) {
        head.insert(head.find("</custom>"), "<text name=\"mjbuoy.radiation\" data=\"on\"/>");
      }
      Scene s(head + body + kTail);
      EXPECT_TRUE(s.ok()) << s.err;
      if (!s.ok()) return 0.0;
      int b = s.body("b");
      double worst = 0;
      for (long k = 0, n = mjbt::stepsTo(s.m, s.d, 1.5); k < n; k++) {
        mj_step(s.m, s.d);
        const mjtNum* f = mjb_wrenchPart(s.b, s.d, mjbPART_SLAM);
        for (int c = 0; c < s.m->nbody; c++) worst = std::max(worst, std::fabs(f[6 * c + 2]));
      }
      EXPECT_GT(s.d->xpos[3 * b + 2], -1.0);
      return worst;
    };
    const std::string inert = "<inertial pos=\"0 0 0\" mass=\"";
    const std::string box = "type=\"box\" size=\"1 0.5 0.25\"";
    double direct = peak("<body name=\"b\" pos=\"0 0 3\"><freejoint/><geom name=\"hull\" " + box +
                         " mass=\"300\"/></body>");
    EXPECT_GT(direct, 0);
    if (!(direct > 0)) continue;
    for (const char* child : {"0", "100"}) {
      // the same mass distribution: the parent carries the rest of the solid
      // box's mass and inertia (m (b^2 + c^2) / 12 per axis: 31.25 106.25 125
      // kg m^2 at 300 kg), since slamming is sized by the effective mass at
      // each wet point, which depends on the inertia as well
      const double f = (300 - std::atoi(child)) / 300.0;
      std::string parent = std::to_string(300 - std::atoi(child));
      std::string I = std::to_string(31.25 * f) + " " + std::to_string(106.25 * f) + " " +
                      std::to_string(125 * f);
      double welded = peak("<body name=\"b\" pos=\"0 0 3\"><freejoint/>" + inert + parent +
                           "\" diaginertia=\"" + I + "\"/><body name=\"c\"><geom name=\"hull\" " +
                           box + " mass=\"" + child + "\"/></body></body>");
      EXPECT_NEAR(welded, direct, 0.05 * direct) << "child mass " << child;
    }
  }
}

TEST(RobustModel, HullOnASlideSettlesAtItsDraft) {
  Scene s(std::string(kHead) + "<body name=\"b\" pos=\"0 0 0.3\">"
          "<joint type=\"slide\" axis=\"0 0 1\"/>"
          "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\" mass=\"300\"/></body>" + kTail);
  ASSERT_TRUE(s.ok()) << s.err;
  int b = s.body("b");
  EXPECT_NEAR(s.settle(30, 5, [&] { return s.d->xpos[3 * b + 2]; }), 0.1, 0.005 * 0.15);
}

TEST(RobustModel, HingedArmSettlesAtTheAnalyticAngle) {
  // a buoyant arm on a hinge 5 m down (always submerged): box L 2 x 0.5 x
  // 0.2 m (rho V = 200 kg), 100 kg with its COM e = 0.5 m below the arm's
  // axis. Moments about the hinge of buoyancy at the box centre and weight
  // at the COM balance at (rho V - m) (L/2) cos(th) = m e sin(th):
  // tan(th) = (rho V - m) L / (2 m e) = 2, th = 63.43 deg above horizontal
  const double th = std::atan(2.0);
  Scene s("<mujoco><option timestep=\"0.002\"/><custom><text name=\"mjbuoy.hulls\" "
          "data=\"hull\"/></custom><worldbody><body name=\"arm\" pos=\"0 0 -5\">"
          "<joint type=\"hinge\" axis=\"0 1 0\" damping=\"800\"/>"
          "<inertial pos=\"1 0 -0.5\" mass=\"100\" diaginertia=\"10 40 40\"/>"
          "<geom name=\"hull\" type=\"box\" pos=\"1 0 0\" size=\"1 0.25 0.1\"/></body>" +
          std::string(kTail));
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_STREQ(mjb_warnings(s.b), "");
  double a = s.settle(30, 5, [&] {
    const mjtNum* c = s.d->geom_xpos;  // box centre
    return std::atan2(c[2] + 5, c[0]);
  });
  EXPECT_NEAR(a, th, 0.005 * th) << "analytic " << th * 180 / M_PI << " deg";
}

TEST(RobustModel, DefaultRadiationCoversHingedHulls) {
  // radiation on by default (no mjbuoy.radiation entry: RadConfig::on true,
  // given false) covers every group that can move: the free one, the
  // hinged arm and the slide, each about its equilibrium along its joints
  // (docs/mjcf.md, "Radiation"); an off entry naming a body wins
  std::string e;
  mjModel* m = loadXML("<mujoco><worldbody><body name=\"free\"><freejoint/>"
                       "<geom type=\"box\" size=\"1 1 1\"/><body name=\"welded\">"
                       "<geom type=\"box\" size=\"1 1 1\"/></body></body>"
                       "<body name=\"arm\"><joint type=\"hinge\"/><geom type=\"box\" "
                       "size=\"1 1 1\"/></body><body name=\"slide\"><joint type=\"slide\"/>"
                       "<geom type=\"box\" size=\"1 1 1\"/></body></worldbody></mujoco>", &e);
  ASSERT_TRUE(m) << e;
  const int fr = mj_name2id(m, mjOBJ_BODY, "free"), we = mj_name2id(m, mjOBJ_BODY, "welded");
  const int arm = mj_name2id(m, mjOBJ_BODY, "arm"), sl = mj_name2id(m, mjOBJ_BODY, "slide");
  const std::vector<int> hb = {fr, we, arm, sl};
  mjb::RadConfig def;
  def.on = true;  // the default once it flips
  EXPECT_TRUE(def.groupRadiates(m, hb, m->body_weldid[we]));  // the free group, welded hull
  EXPECT_TRUE(def.groupRadiates(m, hb, arm));
  EXPECT_TRUE(def.groupRadiates(m, hb, sl));
  mjb::RadConfig asked = def;  // <text name="mjbuoy.radiation" data="on"/>
  asked.given = true;
  EXPECT_TRUE(asked.groupRadiates(m, hb, arm));
  EXPECT_TRUE(asked.groupRadiates(m, hb, sl));
  mjb::RadConfig named = def;  // mjbuoy.radiation.body.arm off
  named.offBody.push_back(arm);
  EXPECT_FALSE(named.groupRadiates(m, hb, arm));
  EXPECT_TRUE(named.groupRadiates(m, hb, sl));
  mjb::RadConfig off = def;  // <text name="mjbuoy.radiation" data="off"/>
  off.on = false;
  off.given = true;
  EXPECT_FALSE(off.groupRadiates(m, hb, arm));
  mj_deleteModel(m);
}

TEST(RobustModel, HullWeldedToTheWorldIsIgnored) {
  // no joint between the hull's body and the world: it cannot move
  Scene s(std::string(kHead) + "<body name=\"fixed\" pos=\"0 0 0\">"
          "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\"/></body>" + kTail);
  ASSERT_TRUE(s.ok()) << s.err;
  std::string w = mjb_warnings(s.b);
  EXPECT_TRUE(has(w, "geom \"hull\" is listed as a hull but is on body \"fixed\", which has "
                     "no joint between it and the world body; it cannot move and is ignored"))
      << w;
  EXPECT_TRUE(has(w, "no hull geoms: mjbuoy adds no force")) << w;
  EXPECT_EQ(mjb_info(s.b).nhull, 0);
  mj_step(s.m, s.d);
  EXPECT_EQ(mjb_wrench(s.b, s.d), nullptr);  // the callback never ran for it
}

TEST(RobustModel, HugeTimestepWarnsAndStaysFinite) {
  // 1 m cube, 500 kg: heave period 2 pi sqrt(m / (rho g A)) = 1.419 s. A
  // 0.5 s step is past the explicit stability limit T / pi: warned at load;
  // the forces stay finite but the motion gains energy (the quadratic drag
  // overshoots within one step) and the cube is thrown out of the water.
  // At the step the warning suggests, T / 20, it floats at its draft
  const double T = 2 * M_PI * std::sqrt(500 / (kRho * kG * 1));
  auto xml = [](const char* dt) {
    return std::string("<mujoco><option timestep=\"") + dt + "\"/><custom>"
           "<text name=\"mjbuoy.hulls\" data=\"hull\"/></custom><worldbody>"
           "<body name=\"b\" pos=\"0 0 0.2\"><freejoint/>"
           "<geom name=\"hull\" type=\"box\" size=\"0.5 0.5 0.5\" mass=\"500\"/></body>" +
           kTail;
  };
  Scene s(xml("0.5"));
  ASSERT_TRUE(s.ok()) << s.err;
  std::string w = mjb_warnings(s.b);
  char expect[128];
  std::snprintf(expect, sizeof(expect), "heave period 2 pi sqrt(m / (rho g A_wp)) is about %.3g s",
                T);
  EXPECT_TRUE(has(w, "<option timestep=\"0.5\"> is too long for hull geom \"hull\"")) << w;
  EXPECT_TRUE(has(w, expect)) << w;
  EXPECT_TRUE(has(w, "use timestep <= 0.0709")) << w;
  double zmax = -INFINITY;
  for (int k = 0; k < 2000; k++) {
    mj_step(s.m, s.d);
    ASSERT_TRUE(finite(mjb_wrench(s.b, s.d), 6 * s.m->nbody)) << "step " << k;
    ASSERT_TRUE(finite(s.d->qpos, s.m->nq) && finite(s.d->qvel, s.m->nv)) << "step " << k;
    zmax = std::fmax(zmax, s.d->qpos[2]);
  }
  EXPECT_GT(zmax, 100) << "the warning says a step above T/pi is unstable";

  Scene t(xml("0.0709"));
  ASSERT_TRUE(t.ok()) << t.err;
  EXPECT_STREQ(mjb_warnings(t.b), "");
  double z = t.settle(60, 10, [&] { return t.d->qpos[2]; });
  EXPECT_NEAR(z, 0, 0.005 * 0.5);  // draft 0.5 m: centre at the surface
}

// attach error for a scene with one free box hull plus `custom` entries
std::string attachError(const std::string& custom) {
  std::string e;
  mjModel* m = loadXML("<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>" + custom +
                       "</custom><worldbody><body><freejoint/><geom name=\"hull\" type=\"box\" "
                       "size=\"1 0.5 0.25\" mass=\"300\"/></body></worldbody></mujoco>", &e);
  if (!m) return "mujoco: " + e;
  char err[1024] = "";
  mjbBuoy* b = mjb_attach(m, "cpu", err, sizeof(err));
  if (b) mjb_detach(b);
  mj_deleteModel(m);
  return b ? "" : err;
}

TEST(RobustConfig, NonFiniteInAnyFieldIsNamed) {
  // nan, inf and -inf in each value of each numeric entry: an error naming
  // the entry, the value's position and "not a finite number"
  struct Entry {
    const char* name;
    int n;
    const char* valid;  // a valid value list to poke one value into
  } entries[] = {
      {"mjbuoy.sea.density", 1, "1000"},        {"mjbuoy.sea.level", 1, "0"},
      {"mjbuoy.sea.depth", 1, "50"},            {"mjbuoy.sea.viscosity", 1, "1e-6"},
      {"mjbuoy.sea.current", 2, "0.5 0"},       {"mjbuoy.wave.w", 5, "0.5 20 0 0 0.5"},
      {"mjbuoy.hull.damping", 2, "10 1"},       {"mjbuoy.hull.viscous", 1, "1.3"},
      {"mjbuoy.hull.drag", 3, "100 400 0.5"},   {"mjbuoy.hull.suction", 3, "100 200 0.5"},
      {"mjbuoy.hull.vref", 1, "1"},             {"mjbuoy.hull.slamming", 3, "1 100 2"},
      {"mjbuoy.geom.hull.drag", 3, "100 400 0.5"},
  };
  int checked = 0;
  for (const Entry& en : entries) {
    ASSERT_EQ(attachError(std::string("<numeric name=\"") + en.name + "\" data=\"" + en.valid +
                          "\"/>"), "") << en.name;
    for (int j = 0; j < en.n; j++) {
      for (const char* bad : {"nan", "inf", "-inf"}) {
        std::istringstream in(en.valid);
        std::string v, data;
        for (int k = 0; in >> v; k++) data += (k ? " " : "") + (k == j ? std::string(bad) : v);
        std::string e = attachError(std::string("<numeric name=\"") + en.name + "\" data=\"" +
                                    data + "\"/>");
        SCOPED_TRACE(std::string(en.name) + " = \"" + data + "\"");
        EXPECT_TRUE(has(e, en.name)) << e;
        EXPECT_TRUE(has(e, "is not a finite number")) << e;
        if (en.n > 1) {
          EXPECT_TRUE(has(e, "value " + std::to_string(j + 1))) << e;
        }
        checked++;
      }
    }
  }
  EXPECT_EQ(checked, 3 * 27);
  // a zero wavelength is out of range like a negative one
  std::string e = attachError("<numeric name=\"mjbuoy.wave.w\" data=\"0.5 0 0 0 0.5\"/>");
  EXPECT_TRUE(has(e, "mjbuoy.wave.w") && has(e, "wavelength") && has(e, ">= 0.05")) << e;
}

TEST(RobustConfig, SceneWithoutHullsIsANoOp) {
  // no mjbuoy entries at all: attaches, says so, and the body falls freely:
  // MuJoCo's semi-implicit Euler gives z_n = z0 - g dt^2 n (n + 1) / 2
  const char* xml = "<mujoco><option timestep=\"0.001\"/><worldbody><body pos=\"0 0 10\">"
                    "<freejoint/><geom type=\"box\" size=\"1 0.5 0.25\" mass=\"300\"/></body>"
                    "</worldbody></mujoco>";
  mjModel* m = loadXML(xml);
  ASSERT_TRUE(m);
  char e[1024];
  mjbBuoy* b = mjb_attach(m, nullptr, e, sizeof(e));
  ASSERT_TRUE(b) << e;
  EXPECT_TRUE(has(mjb_warnings(b), "the model has no mjbuoy.* entries: mjbuoy adds no force"))
      << mjb_warnings(b);
  EXPECT_EQ(mjb_info(b).nhull, 0);
  mjData* d = mj_makeData(m);
  for (int k = 0; k < 2000; k++) mj_step(m, d);
  EXPECT_EQ(mjb_wrench(b, d), nullptr);
  for (int i = 0; i < m->nv; i++) EXPECT_EQ(d->qfrc_passive[i], 0);
  const double dt = 0.001, n = 2000;
  EXPECT_NEAR(d->qpos[2], 10 - 0.5 * kG * dt * dt * n * (n + 1), 1e-9);
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
}

}  // namespace
}  // namespace mjbt
