// defective hull meshes: each defect is named in a load warning with its
// count, repaired where the intent is unambiguous, and the repaired hull
// floats where the analytic result says (docs/robustness.md)
#include <array>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

// a 2 x 1 x 0.5 m box, centred on its body origin, outward faces wound
// counter-clockwise seen from outside
const double kV[8][3] = {{-1, -0.5, -0.25}, {1, -0.5, -0.25}, {1, 0.5, -0.25}, {-1, 0.5, -0.25},
                         {-1, -0.5, 0.25},  {1, -0.5, 0.25},  {1, 0.5, 0.25},  {-1, 0.5, 0.25}};
typedef std::array<int, 3> Tri;
const std::vector<Tri> kBox = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                               {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
// 300 kg: draft T = m / (rho L B) = 0.15 m, so the box centre (the body
// origin) floats at z = H/2 - T = 0.1 m; it starts 0.2 m higher
const double kMass = 300, kDraft = kMass / (kRho * 2 * 1), kZ = 0.25 - kDraft;

// vertex and face attributes; shared vertices (what MuJoCo's compiler
// checks for consistent winding) or a soup where every triangle has its
// own three (what MuJoCo 2.2 makes of OBJ files, unchecked)
std::string mesh(const std::vector<Tri>& f, bool soup,
                 const std::vector<std::array<double, 3>>& extra = {}) {
  std::ostringstream v, t;
  auto vert = [&](int i) {
    const double* p = i < 8 ? kV[i] : extra[i - 8].data();
    v << p[0] << " " << p[1] << " " << p[2] << " ";
  };
  if (soup) {
    int n = 0;
    for (const Tri& x : f) {
      for (int i : x) {
        vert(i);
        t << n++ << " ";
      }
    }
  } else {
    for (int i = 0; i < 8 + (int)extra.size(); i++) vert(i);
    for (const Tri& x : f) t << x[0] << " " << x[1] << " " << x[2] << " ";
  }
  return "vertex=\"" + v.str() + "\" face=\"" + t.str() + "\"";
}

// one free body carrying the mesh as hull "hull", with an explicit
// <inertial>: without one MuJoCo computes the inertia from the mesh and
// rejects meshes it cannot orient (MixedWinding below)
std::string scene(const std::string& meshAttr, const std::string& inertial =
                      "<inertial pos=\"0 0 0\" mass=\"300\" diaginertia=\"31.25 106.25 125\"/>") {
  return "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"m\" " + meshAttr +
         "/></asset><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/>"
         "<numeric name=\"mjbuoy.hull.damping\" data=\"3000 300\"/></custom><worldbody>"
         "<body name=\"b\" pos=\"0 0 0.3\"><freejoint/>" + inertial +
         "<geom name=\"hull\" type=\"mesh\" mesh=\"m\" contype=\"0\" conaffinity=\"0\"/>"
         "</body></worldbody></mujoco>";
}

bool has(const std::string& s, const std::string& sub) { return s.find(sub) != std::string::npos; }

// settled height of the box centre [m]
double settledZ(Scene* s) {
  int b = s->body("b");
  return s->settle(30, 5, [&] { return s->d->xpos[3 * b + 2]; });
}

TEST(RobustMesh, DuplicateVerticesAreWeldedSilently) {
  // every triangle with its own vertices: welded to the box's 8, no warning
  Scene s(scene(mesh(kBox, true)));
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_EQ(s.m->mesh_vertnum[0], 36);
  EXPECT_EQ(mjb_info(s.b).nvert, 8);
  EXPECT_EQ(mjb_info(s.b).ntri, 12);
  EXPECT_STREQ(mjb_warnings(s.b), "");
  EXPECT_NEAR(settledZ(&s), kZ, 0.005 * kDraft);
}

TEST(RobustMesh, MixedWindingIsNamedAndRewound) {
  // one bottom and one side triangle wound inward. Unrepaired, the inward
  // bottom triangle would pull down where it should push up (half the
  // bottom). MuJoCo rejects the mesh when it computes the body's inertia
  // from it; with an explicit <inertial> it compiles and mjbuoy repairs it
  std::vector<Tri> f = kBox;
  std::swap(f[0][1], f[0][2]);
  std::swap(f[6][1], f[6][2]);
  std::string e;
  mjModel* m = loadXML(scene(mesh(f, false), ""), &e);
  EXPECT_FALSE(m);
  EXPECT_TRUE(has(e, "faces have inconsistent orientation: m")) << e;
  if (m) mj_deleteModel(m);

  for (bool soup : {false, true}) {
    Scene s(scene(mesh(f, soup)));
    ASSERT_TRUE(s.ok()) << s.err;
    std::string w = mjb_warnings(s.b);
    EXPECT_TRUE(has(w, "hull geom \"hull\": 2 triangles wound against their neighbours "
                       "(mixed winding), re-wound")) << w;
    EXPECT_FALSE(has(w, "not closed")) << w;
    EXPECT_FALSE(has(w, "inverted")) << w;
    EXPECT_NEAR(settledZ(&s), kZ, 0.005 * kDraft) << (soup ? "soup" : "shared vertices");
  }
}

TEST(RobustMesh, InvertedMeshIsTurnedOutward) {
  // every face wound inward: buoyancy would pull the box down; turned
  // outward it floats at its draft
  std::vector<Tri> f = kBox;
  for (Tri& t : f) std::swap(t[1], t[2]);
  Scene s(scene(mesh(f, false)));
  ASSERT_TRUE(s.ok()) << s.err;
  std::string w = mjb_warnings(s.b);
  EXPECT_TRUE(has(w, "hull geom \"hull\": normals look inverted (enclosed volume -1 m^3 < 0), "
                     "turned outward")) << w;
  EXPECT_FALSE(has(w, "mixed winding")) << w;
  EXPECT_NEAR(settledZ(&s), kZ, 0.005 * kDraft);
}

TEST(RobustMesh, ZeroAreaTrianglesAreDropped) {
  // a T-junction: vertex 8 halfway along the bottom edge 0-1 splits side
  // triangle (0 1 5), and the sliver (0 1 8) closes the edges. MuJoCo
  // accepts it; mjbuoy drops the sliver and the mesh stays closed
  std::vector<Tri> f = kBox;
  f.erase(f.begin() + 4);
  f.push_back({0, 8, 5});
  f.push_back({8, 1, 5});
  f.push_back({0, 1, 8});
  Scene s(scene(mesh(f, false, {{0, -0.5, -0.25}})));
  ASSERT_TRUE(s.ok()) << s.err;
  std::string w = mjb_warnings(s.b);
  EXPECT_TRUE(has(w, "hull geom \"hull\": 1 zero-area triangle dropped (they carry no "
                     "pressure)")) << w;
  EXPECT_FALSE(has(w, "not closed")) << w;
  EXPECT_EQ(mjb_info(s.b).ntri, 13);
  EXPECT_NEAR(settledZ(&s), kZ, 0.005 * kDraft);

  // two corners at the same point (a soup, so MuJoCo compiles it): after
  // welding the triangle has a repeated vertex, also zero area
  std::vector<Tri> g = kBox;
  g.push_back({0, 1, 1});
  Scene t(scene(mesh(g, true)));
  ASSERT_TRUE(t.ok()) << t.err;
  w = mjb_warnings(t.b);
  EXPECT_TRUE(has(w, "1 zero-area triangle dropped")) << w;
  EXPECT_EQ(mjb_info(t.b).ntri, 12);
}

TEST(RobustMesh, DuplicateTrianglesAreDropped) {
  // two bottom triangles repeated, one with the same winding (it would
  // double the pressure on that half of the bottom: 0.15 m draft -> about
  // 0.1 m), one reversed (it would cancel it). Kept: the first copy of
  // each, which the winding check then confirms
  std::vector<Tri> f = kBox;
  f.push_back({0, 2, 1});
  f.push_back({0, 2, 3});
  Scene s(scene(mesh(f, true)));
  ASSERT_TRUE(s.ok()) << s.err;
  std::string w = mjb_warnings(s.b);
  EXPECT_TRUE(has(w, "hull geom \"hull\": 2 duplicate triangles (the same three vertices as "
                     "another) dropped")) << w;
  EXPECT_FALSE(has(w, "mixed winding")) << w;
  EXPECT_FALSE(has(w, "not closed")) << w;
  EXPECT_EQ(mjb_info(s.b).ntri, 12);
  EXPECT_NEAR(settledZ(&s), kZ, 0.005 * kDraft);
}

TEST(RobustMesh, OpenMeshIsExactWhileItsHoleIsDry) {
  // no deck (the two top triangles missing): 4 boundary edges. Afloat the
  // deck is 0.35 m above the water, so the draft is exact; held under with
  // the deck at depth D, the missing lid's downward pressure is absent:
  // F_z = rho g (D + H) A instead of rho g H A
  std::vector<Tri> f = kBox;
  f.erase(f.begin() + 2, f.begin() + 4);
  Scene s(scene(mesh(f, false)));
  ASSERT_TRUE(s.ok()) << s.err;
  std::string w = mjb_warnings(s.b);
  EXPECT_TRUE(has(w, "hull geom \"hull\": mesh is not closed (4 boundary edges, 0 non-manifold "
                     "edges)")) << w;
  EXPECT_NEAR(settledZ(&s), kZ, 0.005 * kDraft);
  mj_resetData(s.m, s.d);
  const double D = 2;
  s.d->qpos[2] = -D - 0.25;
  mj_forward(s.m, s.d);
  EXPECT_NEAR(s.wrench(s.body("b"))[2], kRho * kG * (D + 0.5) * 2, 1e-9 * kRho * kG * 5);
}

TEST(RobustMesh, SingleTriangleActsAsAPlate) {
  // one triangle of area 0.5 m^2 facing down (MuJoCo needs 4 vertices:
  // the 4th is unused). An open surface: the water pushes it up with
  // rho g h A at depth h, so 50 kg floats at h = m / (rho A) = 0.1 m.
  // Slamming is off: its stopping force m v 2 A_wet / S_total assumes at
  // most half a closed hull meets the water at once; a plate landing flat
  // has A_wet = S_total and would bounce back at the speed it came
  const double mass = 50, A = 0.5, h = mass / (kRho * A);
  std::string xml = scene("vertex=\"0 0 0 1 0 0 0 1 0 0 0 1\" face=\"0 2 1\"",
                          "<inertial pos=\"0.3333333 0.3333333 0\" mass=\"50\" "
                          "diaginertia=\"1 1 2\"/>");
  xml.replace(xml.find("3000 300\"/>"), 10,
              "500 20\"/><numeric name=\"mjbuoy.hull.slamming\" data=\"0 100 2\"/>");
  Scene s(xml);
  ASSERT_TRUE(s.ok()) << s.err;
  std::string w = mjb_warnings(s.b);
  EXPECT_TRUE(has(w, "hull geom \"hull\": mesh is not closed (3 boundary edges")) << w;
  EXPECT_EQ(mjb_info(s.b).ntri, 1);
  // mean height of the three corners, from MuJoCo's compiled mesh
  auto depth = [&] {
    const int g = 0;
    const float* v = s.m->mesh_vert + 3 * s.m->mesh_vertadr[s.m->geom_dataid[g]];
    const mjtNum* x = s.d->geom_xpos + 3 * g;
    const mjtNum* R = s.d->geom_xmat + 9 * g;
    double z = 0;
    for (int i = 0; i < 3; i++) z += (x[2] + R[6] * v[3 * i] + R[7] * v[3 * i + 1] + R[8] * v[3 * i + 2]) / 3;
    return z;
  };
  double z = s.settle(30, 5, depth);
  EXPECT_NEAR(z, -h, 0.005 * h);
  EXPECT_NEAR(roll(s.d, s.body("b")), 0, 1e-3);
}

TEST(RobustMesh, NoAreaLeftIsAnError) {
  // every face of zero area (four collinear vertices, so MuJoCo's four-
  // vertex minimum is met): nothing could carry pressure, so attaching fails
  Scene s(scene("vertex=\"0 0 0 1 0 0 2 0 0 3 0 0\" face=\"0 1 2 1 2 3\""));
  EXPECT_FALSE(s.ok());
  EXPECT_TRUE(has(s.err, "mjbuoy: hull geom \"hull\" has no surface area")) << s.err;
}

}  // namespace
}  // namespace mjbt
