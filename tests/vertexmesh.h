// test helpers of the vertex integration tests (vertexint_test.cc,
// vertexforms_test.cc): the Wigley model, the Wigley 576 with its edges
// halved, and a scene whose mesh comes from OBJ text
#ifndef MJBUOY_TESTS_VERTEXMESH_H_
#define MJBUOY_TESTS_VERTEXMESH_H_

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <mujoco/mujoco.h>

#include "mjbuoy.h"

namespace mjbt {

// one free Wigley hull (mesh wigley_<tris>.obj, the bench's mass and
// inertia), radiation off, one thread, with the custom entries custom
inline std::string wigleyModel(int tris, const std::string& custom) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
    << "/meshes/wigley_" << tris << ".obj\"/></asset><custom>"
    << "<text name=\"mjbuoy.hulls\" data=\"h*\"/>" << custom
    << "<text name=\"mjbuoy.radiation\" data=\"off\"/>"
    << "<numeric name=\"mjbuoy.threads\" data=\"1\"/>"
    << "</custom><worldbody><body pos=\"0 0 0\"><freejoint/>"
    << "<inertial pos=\"0 0 -0.08\" mass=\"176.2\" diaginertia=\"6.02 237.28 238.6\"/>"
    << "<geom name=\"h0\" type=\"mesh\" mesh=\"w\" contype=\"0\" conaffinity=\"0\"/>"
    << "</body></worldbody></mujoco>";
  return s.str();
}

// models/meshes/wigley_576.obj with every triangle split in 4 at its
// edges' midpoints, times times: the same surface, every edge halved each
// time (shared midpoints kept shared), as OBJ text
inline std::string refinedWigley(int times) {
  std::ifstream in(MJB_MODELS "/meshes/wigley_576.obj");
  std::vector<std::array<double, 3>> v;
  std::vector<std::array<int, 3>> f;
  std::string tag;
  while (in >> tag) {
    if (tag == "v") {
      std::array<double, 3> p;
      in >> p[0] >> p[1] >> p[2];
      v.push_back(p);
    } else if (tag == "f") {
      std::array<int, 3> t;
      for (int& i : t) {
        std::string w;
        in >> w;
        i = std::stoi(w) - 1;
      }
      f.push_back(t);
    }
    std::getline(in, tag);
  }
  for (int r = 0; r < times; r++) {
    std::map<std::pair<int, int>, int> mid;
    auto at = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back({(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2});
      return mid[key] = int(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> g;
    for (const auto& t : f) {
      const int ab = at(t[0], t[1]), bc = at(t[1], t[2]), ca = at(t[2], t[0]);
      g.push_back({t[0], ab, ca});
      g.push_back({ab, t[1], bc});
      g.push_back({ca, bc, t[2]});
      g.push_back({ab, bc, ca});
    }
    f.swap(g);
  }
  std::ostringstream o;
  o.precision(17);
  for (const auto& p : v) o << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
  for (const auto& t : f) o << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  return o.str();
}

// xml with its Wigley 576 mesh file replaced by w.obj, the OBJ text a
// MeshScene puts in its VFS
inline std::string onTextMesh(std::string xml) {
  const std::string from = MJB_MODELS "/meshes/wigley_576.obj";
  xml.replace(xml.find(from), from.size(), "w.obj");
  return xml;
}

// a Scene whose model's mesh w comes from OBJ text (in the VFS)
struct MeshScene {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  mjbBuoy* b = nullptr;
  std::string err;
  MeshScene(const std::string& xml, const std::string& obj) {
    mjVFS vfs;
    mj_defaultVFS(&vfs);
    for (auto& fl : {std::make_pair("model.xml", &xml), std::make_pair("w.obj", &obj)}) {
      mj_makeEmptyFileVFS(&vfs, fl.first, int(fl.second->size()));
      std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, fl.first)], fl.second->data(),
                  fl.second->size());
    }
    char e[1024] = "";
    m = mj_loadXML("model.xml", &vfs, e, sizeof e);
    mj_deleteVFS(&vfs);
    if (m) b = mjb_attach(m, nullptr, e, sizeof e);
    if (b) d = mj_makeData(m);
    err = e;
  }
  ~MeshScene() {
    if (d) mj_deleteData(d);
    if (b) mjb_detach(b);
    if (m) mj_deleteModel(m);
  }
  bool ok() const { return m && b && d; }
};

}  // namespace mjbt

#endif  // MJBUOY_TESTS_VERTEXMESH_H_
