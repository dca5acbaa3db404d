// invalid MJCF entries: each class fails the load with its own message
#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

// a valid scene plus `custom` entries; returns mjb_attach's error
std::string attachError(const std::string& custom, const std::string& extra = "") {
  std::string xml =
      "<mujoco>" + extra + "<custom>" + custom +
      "</custom><worldbody><geom name=\"floor\" type=\"plane\" size=\"5 5 1\"/>"
      "<geom name=\"fixed\" type=\"box\" size=\"1 1 1\" pos=\"0 0 -5\"/>"
      "<body name=\"b\"><freejoint/>"
      "<geom name=\"hull\" type=\"box\" size=\"1 0.5 0.25\"/></body></worldbody></mujoco>";
  std::string err;
  mjModel* m = loadXML(xml, &err);
  if (!m) return "mujoco: " + err;
  char e[1024] = "";
  mjbBuoy* b = mjb_attach(m, nullptr, e, sizeof(e));
  std::string out = b ? "" : e;
  if (b) mjb_detach(b);
  mj_deleteModel(m);
  return out;
}

const char kHull[] = "<text name=\"mjbuoy.hulls\" data=\"hull\"/>";

struct Case {
  const char* what;
  std::string custom, extra;
  std::vector<std::string> expect;  // substrings of the message
};

TEST(Config, ValidSceneAttaches) {
  EXPECT_EQ(attachError(std::string(kHull) +
                        "<numeric name=\"mjbuoy.sea.density\" data=\"1025\"/>"
                        "<numeric name=\"mjbuoy.wave.swell\" data=\"0.5 20 30 0 0.6\"/>"
                        "<numeric name=\"mjbuoy.airy.chop\" data=\"0.1 5 60 90\"/>"
                        "<text name=\"mjbuoy.sea.pressure\" data=\"kerner\"/>"
                        "<numeric name=\"mjbuoy.hull.damping\" data=\"10 1\"/>"
                        "<numeric name=\"mjbuoy.geom.hull.damping\" data=\"20 2\"/>"
                        "<numeric name=\"mjbuoy.sea.current\" data=\"0.5 0\"/>"
                        "<text name=\"mjbuoy.backend\" data=\"cpu\"/>"),
            "");
}

TEST(Config, EachInvalidEntryNamesItself) {
  const std::vector<Case> cases = {
    {"negative density", "<numeric name=\"mjbuoy.sea.density\" data=\"-5\"/>", "",
     {"mjbuoy.sea.density", "-5", ">= 1 and <= 100000", "kg/m^3"}},
    {"zero density", "<numeric name=\"mjbuoy.sea.density\" data=\"0\"/>", "",
     {"mjbuoy.sea.density", "out of range"}},
    {"nan level", "<numeric name=\"mjbuoy.sea.level\" data=\"nan\"/>", "",
     {"mjbuoy.sea.level", "not a finite number"}},
    {"wrong count", "<numeric name=\"mjbuoy.sea.current\" data=\"1 2 3\"/>", "",
     {"mjbuoy.sea.current", "3 value(s), expected 2"}},
    {"unknown sea field", "<numeric name=\"mjbuoy.sea.densty\" data=\"1000\"/>", "",
     {"unknown entry", "mjbuoy.sea.densty", "density, level"}},
    {"unknown top level", "<numeric name=\"mjbuoy.seas.density\" data=\"1000\"/>", "",
     {"unknown entry", "mjbuoy.seas.density"}},
    {"unknown text", "<text name=\"mjbuoy.hull\" data=\"hull\"/>", "",
     {"unknown entry", "<text name=\"mjbuoy.hull\">"}},
    {"negative wavelength", "<numeric name=\"mjbuoy.wave.a\" data=\"1 -20 0 0 0.5\"/>", "",
     {"mjbuoy.wave.a", "wavelength", "-20", ">= 0.05"}},
    {"steepness above 1", "<numeric name=\"mjbuoy.wave.a\" data=\"0.1 20 0 0 1.5\"/>", "",
     {"mjbuoy.wave.a", "steepness", "1.5", "<= 1"}},
    {"negative amplitude", "<numeric name=\"mjbuoy.wave.a\" data=\"-1 20 0 0 0.5\"/>", "",
     {"mjbuoy.wave.a", "amplitude", ">= 0"}},
    {"wave count", "<numeric name=\"mjbuoy.wave.a\" data=\"1 20 0\"/>", "",
     {"mjbuoy.wave.a", "3 value(s), expected 5"}},
    {"folding waves", "<numeric name=\"mjbuoy.wave.a\" data=\"3 10 0 0 1\"/>", "",
     {"fold", "< 1", "1.88"}},
    {"hull name matches nothing", "<text name=\"mjbuoy.hulls\" data=\"hul\"/>", "",
     {"mjbuoy.hulls", "\"hul\"", "matches no named geom"}},
    {"hull of a plane", "<text name=\"mjbuoy.hulls\" data=\"floor\"/>", "",
     {"\"floor\"", "cannot be a hull", "mesh, box, sphere"}},
    {"empty hull list", "<text name=\"mjbuoy.hulls\" data=\" \"/>", "",
     {"mjbuoy.hulls", "is empty"}},
    {"negative damping", "<numeric name=\"mjbuoy.hull.damping\" data=\"-1 0\"/>", "",
     {"mjbuoy.hull.damping", "value 1", "-1", ">= 0"}},
    {"unknown hull param", "<numeric name=\"mjbuoy.hull.dampnig\" data=\"1 0\"/>", "",
     {"unknown entry", "mjbuoy.hull.dampnig", "damping"}},
    {"override of a non-hull", "<numeric name=\"mjbuoy.geom.fixed.damping\" data=\"1 0\"/>",
     "", {"mjbuoy.geom.fixed.damping", "\"fixed\"", "not listed in mjbuoy.hulls"}},
    {"override of a missing geom", "<numeric name=\"mjbuoy.geom.ghost.damping\" data=\"1 0\"/>",
     "", {"\"ghost\"", "does not exist"}},
    {"override unknown param", "<numeric name=\"mjbuoy.geom.hull.dragg\" data=\"1 0\"/>", "",
     {"unknown entry", "mjbuoy.geom.hull.dragg", "mjbuoy.geom.<geom>.<param>"}},
    {"slamming gain above 1", "<numeric name=\"mjbuoy.hull.slamming\" data=\"2 100 2\"/>", "",
     {"mjbuoy.hull.slamming", "value 1 (gain)", "<= 1"}},
    {"zero gamma_max", "<numeric name=\"mjbuoy.geom.hull.slamming\" data=\"1 0 2\"/>", "",
     {"mjbuoy.geom.hull.slamming", "gamma_max", ">= 0.01", "m/s^2"}},
    {"negative drag exponent", "<numeric name=\"mjbuoy.hull.drag\" data=\"10 10 -1\"/>", "",
     {"mjbuoy.hull.drag", "exponent", ">= 0"}},
    {"form factor above 3", "<numeric name=\"mjbuoy.hull.viscous\" data=\"4\"/>", "",
     {"mjbuoy.hull.viscous", "<= 3"}},
    {"zero reference speed", "<numeric name=\"mjbuoy.hull.vref\" data=\"0\"/>", "",
     {"mjbuoy.hull.vref", ">= 0.01", "m/s"}},
    {"negative viscosity", "<numeric name=\"mjbuoy.sea.viscosity\" data=\"-1e-6\"/>", "",
     {"mjbuoy.sea.viscosity", ">= 1e-08"}},
    {"numeric hull list", "<numeric name=\"mjbuoy.hulls\" data=\"1\"/>", "",
     {"mjbuoy.hulls", "must be a <text> entry"}},
    {"override of a world-body hull",
     "<text name=\"mjbuoy.hulls\" data=\"hull fixed\"/>"
     "<numeric name=\"mjbuoy.geom.fixed.damping\" data=\"1 0\"/>", "",
     {"\"fixed\"", "on the world body"}},
    {"unknown backend", "<text name=\"mjbuoy.backend\" data=\"cuda\"/>", "",
     {"mjbuoy.backend", "\"cuda\"", "accepted: cpu"}},
    {"airy with a steepness", "<numeric name=\"mjbuoy.airy.a\" data=\"0.5 20 0 0 0.6\"/>", "",
     {"mjbuoy.airy.a", "5 value(s), expected 4"}},
    {"airy zero wavelength", "<numeric name=\"mjbuoy.airy.a\" data=\"0.5 0 0 0\"/>", "",
     {"mjbuoy.airy.a", "wavelength", "out of range"}},
    {"unknown pressure model", "<text name=\"mjbuoy.sea.pressure\" data=\"nonlinear\"/>", "",
     {"mjbuoy.sea.pressure", "\"nonlinear\"", "linear", "kerner"}},
    {"sideways gravity", "", "<option gravity=\"1 0 -9.81\"/>",
     {"gravity", "along -z"}},
    {"zero gravity", "", "<option gravity=\"0 0 0\"/>", {"gravity", "along -z"}},
  };
  for (const Case& c : cases) {
    std::string custom = c.custom;
    if (custom.find("mjbuoy.hulls") == std::string::npos) custom = kHull + custom;
    std::string e = attachError(custom, c.extra);
    ASSERT_FALSE(e.empty()) << c.what << ": attached without error";
    EXPECT_EQ(e.rfind("mjbuoy: ", 0), 0u) << c.what << ": " << e;
    for (const std::string& sub : c.expect) {
      EXPECT_NE(e.find(sub), std::string::npos)
          << c.what << ": message lacks \"" << sub << "\": " << e;
    }
  }
}

TEST(Config, PatternsSkipGeomsThatCannotBeHulls) {
  // "*" also matches the floor plane: skipped, not an error
  EXPECT_EQ(attachError("<text name=\"mjbuoy.hulls\" data=\"*\"/>"), "");
  EXPECT_NE(attachError("<text name=\"mjbuoy.hulls\" data=\"fl*\"/>")
                .find("matches no named geom that can be a hull"),
            std::string::npos);
}

TEST(Config, WarningsLoadAnyway) {
  // a world-body hull is ignored, opt.density double counts, no hulls left
  std::string xml =
      "<mujoco><option density=\"1.2\"/><custom>"
      "<text name=\"mjbuoy.hulls\" data=\"fixed\"/></custom><worldbody>"
      "<geom name=\"fixed\" type=\"box\" size=\"1 1 1\"/></worldbody></mujoco>";
  mjModel* m = loadXML(xml);
  ASSERT_TRUE(m);
  char e[1024];
  mjbBuoy* b = mjb_attach(m, nullptr, e, sizeof(e));
  ASSERT_TRUE(b) << e;
  std::string w = mjb_warnings(b);
  EXPECT_NE(w.find("\"fixed\""), std::string::npos) << w;
  EXPECT_NE(w.find("world body"), std::string::npos) << w;
  EXPECT_NE(w.find("double counting"), std::string::npos) << w;
  EXPECT_NE(w.find("no hull geoms"), std::string::npos) << w;
  EXPECT_EQ(mjb_info(b).nhull, 0);
  mjb_detach(b);
  mj_deleteModel(m);
}

TEST(Config, OpenAndInvertedMeshesWarn) {
  // a tetrahedron missing one face, and one wound inside out
  std::string xml =
      "<mujoco><asset>"
      "<mesh name=\"open\" vertex=\"0 0 0 1 0 0 0 1 0 0 0 1\" face=\"0 2 1 0 1 3 0 3 2\"/>"
      "<mesh name=\"inv\" vertex=\"0 0 0 1 0 0 0 1 0 0 0 1\" face=\"0 1 2 0 3 1 0 2 3 1 3 2\"/>"
      "</asset><custom><text name=\"mjbuoy.hulls\" data=\"a b\"/></custom><worldbody>"
      "<body><freejoint/><geom name=\"a\" type=\"mesh\" mesh=\"open\" mass=\"1\"/></body>"
      "<body><freejoint/><geom name=\"b\" type=\"mesh\" mesh=\"inv\" mass=\"1\"/></body>"
      "</worldbody></mujoco>";
  std::string err;
  mjModel* m = loadXML(xml, &err);
  ASSERT_TRUE(m) << err;
  char e[1024];
  mjbBuoy* b = mjb_attach(m, nullptr, e, sizeof(e));
  ASSERT_TRUE(b) << e;
  std::string w = mjb_warnings(b);
  EXPECT_NE(w.find("\"a\": mesh is not closed (3 boundary edges"), std::string::npos) << w;
  EXPECT_NE(w.find("\"b\": normals look inverted"), std::string::npos) << w;
  mjb_detach(b);
  mj_deleteModel(m);
}

TEST(Config, BackendArgumentOverridesAndIsChecked) {
  mjModel* m = loadXML("<mujoco><custom><text name=\"mjbuoy.hulls\" data=\"h\"/></custom>"
                       "<worldbody><body><freejoint/><geom name=\"h\" size=\"1\"/></body>"
                       "</worldbody></mujoco>");
  ASSERT_TRUE(m);
  char e[1024];
  mjbBuoy* b = mjb_attach(m, "vulkan", e, sizeof(e));
  EXPECT_FALSE(b);
  EXPECT_NE(std::string(e).find("\"vulkan\""), std::string::npos) << e;
  b = mjb_attach(m, "cpu", e, sizeof(e));
  ASSERT_TRUE(b) << e;
  EXPECT_STREQ(mjb_info(b).backend, "cpu");
  mjb_detach(b);
  mj_deleteModel(m);
}

}  // namespace
}  // namespace mjbt
