// mesh files MuJoCo 2.2 would load broken (issue 11 item 17): a face index
// out of range (MuJoCo reads past its vertex array) or 0, a non-finite
// vertex (a silently different mesh), a truncated STL, a face corner
// without the normal or texture index the file's vn or vt lines call for. mjb_checkModelFile
// refuses them with the file and line before mj_loadXML sees them.
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testutil.h"

namespace mjbt {
namespace {

// a temporary directory removed at the end
struct TmpDir {
  std::string path;
  std::vector<std::string> files;
  TmpDir() {
    char t[] = "/tmp/mjbuoy-meshfile-XXXXXX";
    path = mkdtemp(t);
  }
  ~TmpDir() {
    for (auto it = files.rbegin(); it != files.rend(); ++it) std::remove(it->c_str());
    std::remove((path + "/m").c_str());
    std::remove(path.c_str());
  }
  std::string write(const std::string& name, const std::string& text) {
    std::string p = path + "/" + name;
    std::ofstream(p, std::ios::binary) << text;
    files.push_back(p);
    return p;
  }
};

// a unit cube: 8 vertices, 12 outward triangles (1-based OBJ indices)
const char kCubeV[] =
    "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
    "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n";
const char kCubeF[] =
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
    "f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";

std::string model(const std::string& meshfile, const std::string& compiler = "") {
  return "<mujoco>" + compiler + "<asset><mesh name=\"hullmesh\" file=\"" + meshfile +
         "\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"hull\"/></custom>"
         "<worldbody><body pos=\"0 0 0\"><freejoint/><geom name=\"hull\" type=\"mesh\" "
         "mesh=\"hullmesh\" mass=\"500\"/></body></worldbody></mujoco>";
}

std::string check(const std::string& xmlpath, int* ok) {
  char e[1000] = "x";
  *ok = mjb_checkModelFile(xmlpath.c_str(), e, sizeof(e));
  return e;
}

TEST(RobustMeshFile, ValidObjPassesAndLoads) {
  TmpDir t;
  // normals and texture coordinates indexed by every face corner pass and
  // load (under AddressSanitizer this also checks libmujoco reads them in
  // bounds): the cube's 6 face normals and 4 corner texture coordinates
  std::string vtn = "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                    "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\n"
                    "f 1/1/1 3/3/1 2/2/1\nf 1/1/1 4/4/1 3/3/1\nf 5/1/2 6/2/2 7/3/2\n"
                    "f 5/1/2 7/3/2 8/4/2\nf 1/1/3 2/2/3 6/3/3\nf 1/1/3 6/3/3 5/4/3\n"
                    "f 2/1/4 3/2/4 7/3/4\nf 2/1/4 7/3/4 6/4/4\nf 3/1/5 4/2/5 8/3/5\n"
                    "f 3/1/5 8/3/5 7/4/5\nf -5/1/-1 -8/2/-1 -4/3/-1\nf -5/1/-1 -4/3/-1 -1/4/-1\n";
  t.write("cube_vn.obj", std::string(kCubeV) + vtn);
  int ok;
  std::string xvn = t.write("model_vn.xml", model("cube_vn.obj"));
  EXPECT_EQ(check(xvn, &ok), "");
  EXPECT_EQ(ok, 1);
  char evn[1000];
  mjModel* mvn = mj_loadXML(xvn.c_str(), nullptr, evn, sizeof(evn));
  ASSERT_TRUE(mvn) << evn;
  EXPECT_NEAR(mvn->body_mass[1], 500, 1e-9);
  mj_deleteModel(mvn);
  t.write("cube.obj", std::string(kCubeV) + kCubeF);
  std::string x = t.write("model.xml", model("cube.obj"));
  EXPECT_EQ(check(x, &ok), "");
  EXPECT_EQ(ok, 1);
  char e[1000];
  mjModel* m = mj_loadXML(x.c_str(), nullptr, e, sizeof(e));
  ASSERT_TRUE(m) << e;
  // the cube as MuJoCo compiled it has the volume 1 m^3 of the file
  EXPECT_NEAR(m->body_mass[1], 500, 1e-9);
  mj_deleteModel(m);
}

TEST(RobustMeshFile, BrokenObjIsRefusedWithFileAndLine) {
  struct Case {
    std::string obj;
    long line;
    std::vector<std::string> expect;
  } cases[] = {
      // face index 9 of 8 vertices, on line 9 + 12 = 21 (the last face)
      {std::string(kCubeV) + kCubeF + "f 1 2 9\n", 21,
       {"face index 9 is out of range", "the file has 8 vertices", "from 1 to 8"}},
      {std::string(kCubeV) + "f 0 2 3\n" + kCubeF, 9, {"face index 0 is invalid"}},
      // relative index -9 with 8 vertices before it; texture/normal forms
      {std::string(kCubeV) + "f -1/1 -2//1 -9/1/1\n" + kCubeF, 9,
       {"face index -9 is out of range", "-1 back to -8"}},
      {"v nan 0 0\n" + std::string(kCubeV + 17) + kCubeF, 1,
       {"vertex coordinate \"nan\" is not a finite number"}},
      {std::string(kCubeV) + "v 1 inf 0\n" + kCubeF, 9,
       {"vertex coordinate \"inf\" is not a finite number"}},
      {std::string(kCubeV) + "v 1 2\n" + kCubeF, 9, {"vertex has 2 coordinates, expected 3"}},
      // one normal and faces that do not index it: libmujoco 2.2.2 reads
      // its normal array at index -1 (an AddressSanitizer report in
      // mj_loadXML before this check)
      {std::string(kCubeV) + "vn 0 0 1\n" + kCubeF, 10,
       {"face corner \"1\" has no normal index", "the file has 1 \"vn\" lines"}},
      {std::string(kCubeV) + "vt 0 0\nf 1/1 2/2 3/1\n" + kCubeF, 10,
       {"face texture coordinate index 2 is out of range", "from 1 to 1"}},
      {std::string(kCubeV) + "vn 0 0 1\nf 1//1 2//1 3/1\n", 10,
       {"face corner \"3/1\" has no normal index"}},
  };
  for (const Case& c : cases) {
    TmpDir t;
    std::string obj = t.write("hull.obj", c.obj);
    std::string x = t.write("model.xml", model("hull.obj"));
    int ok;
    std::string e = check(x, &ok);
    EXPECT_EQ(ok, 0) << c.obj;
    EXPECT_NE(e.find("mesh file " + obj + " line " + std::to_string(c.line) + ": "),
              std::string::npos) << e;
    for (const std::string& s : c.expect) EXPECT_NE(e.find(s), std::string::npos) << s << " in " << e;
  }
}

// meshes named through <include> and <compiler meshdir>, as MuJoCo resolves them
TEST(RobustMeshFile, IncludeAndMeshdirAreFollowed) {
  TmpDir t;
  ASSERT_EQ(mkdir((t.path + "/m").c_str(), 0700), 0);
  std::string obj = t.write("m/hull.obj", std::string(kCubeV) + kCubeF + "f 1 2 10\n");
  t.write("assets.xml", "<mujoco><asset><mesh name=\"hullmesh\" file=\"hull.obj\"/></asset>"
                        "</mujoco>");
  std::string x = t.write(
      "model.xml",
      "<mujoco><compiler meshdir=\"m\"/><include file=\"assets.xml\"/>"
      "<worldbody><body><freejoint/><geom type=\"mesh\" mesh=\"hullmesh\"/></body>"
      "</worldbody></mujoco>");
  int ok;
  std::string e = check(x, &ok);
  EXPECT_EQ(ok, 0);
  EXPECT_NE(e.find(t.path + "/m/hull.obj line 21"), std::string::npos) << e;
}

// binary STL: 80-byte header, triangle count, 50 bytes per triangle
std::string stl(const std::vector<float>& tri) {
  std::string s(80, ' ');
  uint32_t n = tri.size() / 9;
  s.append(reinterpret_cast<const char*>(&n), 4);
  for (uint32_t t = 0; t < n; t++) {
    float nrm[3] = {0, 0, 1};
    s.append(reinterpret_cast<const char*>(nrm), 12);
    s.append(reinterpret_cast<const char*>(&tri[9 * t]), 36);
    s.append(2, '\0');
  }
  return s;
}

TEST(RobustMeshFile, BrokenStlIsRefused) {
  TmpDir t;
  std::vector<float> tri = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1};
  std::string f = t.write("a.stl", stl(tri));
  char e[1000];
  EXPECT_EQ(mjb_checkMeshFile(f.c_str(), e, sizeof(e)), 1) << e;
  tri[13] = NAN;  // triangle 2, second vertex, y
  f = t.write("b.stl", stl(tri));
  EXPECT_EQ(mjb_checkMeshFile(f.c_str(), e, sizeof(e)), 0);
  EXPECT_NE(std::string(e).find("triangle 2 (of 2) has a vertex coordinate that is not finite"),
            std::string::npos) << e;
  std::string s = stl(tri);
  f = t.write("c.stl", s.substr(0, s.size() - 10));
  EXPECT_EQ(mjb_checkMeshFile(f.c_str(), e, sizeof(e)), 0);
  EXPECT_NE(std::string(e).find("a binary STL of 2 triangles has 184 bytes, this file 174"),
            std::string::npos) << e;
}

}  // namespace
}  // namespace mjbt
