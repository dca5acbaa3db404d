// mesh files of a model checked before MuJoCo reads them (mjb_checkModelFile).
// MuJoCo 2.2's OBJ reader accepts a face index out of range (it then reads
// past its vertex array) and "v nan ..." lines, and its compiled mjModel
// keeps no file names, so mjbuoy cannot check at mjb_attach: this reads the
// MJCF itself (tinyxml2), follows <include> and <compiler meshdir/assetdir>,
// and checks every OBJ and STL mesh file it names.
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "mjbuoy.h"

namespace {

std::string dirOf(const std::string& path) {
  size_t s = path.rfind('/');
  return s == std::string::npos ? "" : path.substr(0, s + 1);
}

std::string join(const std::string& dir, const std::string& f) {
  return f.empty() || f[0] == '/' || dir.empty() ? f : dir + f;
}

bool endsWith(std::string s, const char* ext) {
  for (char& c : s) c = std::tolower(static_cast<unsigned char>(c));
  size_t n = std::strlen(ext);
  return s.size() >= n && s.compare(s.size() - n, n, ext) == 0;
}

std::string where(const std::string& file, long line) {
  return "mjbuoy: mesh file " + file + " line " + std::to_string(line) + ": ";
}

// counts of an OBJ file's v, vt and vn lines: in the whole file, and seen
// so far (negative indices count back from the face)
struct ObjCounts {
  long total[3] = {0, 0, 0};
  long seen[3] = {0, 0, 0};
};

const char* kObjKey[3] = {"v", "vt", "vn"};
const char* kObjWhat[3] = {"vertex", "texture coordinate", "normal"};

// the index of kind j ("v", "vt", "vn") in one slot of a face corner; ""
// or the error. MuJoCo 2.2 (user_mesh.cc LoadOBJ) reads a corner's vt and
// vn entries whenever the file has any vt or vn lines, also for a corner
// without that index (then at -1): outside its arrays
std::string checkSlot(const std::string& tok, const std::string& part, int j,
                      const ObjCounts& n, const std::string& file, long line) {
  long nt = n.total[j], ns = n.seen[j];
  std::string what = kObjWhat[j];
  if (part.empty()) {
    return where(file, line) + "face corner \"" + tok + "\" has no " + what +
           " index, but the file has " + std::to_string(nt) + " \"" + kObjKey[j] +
           "\" lines (MuJoCo 2.2 then reads outside its " + what +
           " array); give every corner one or remove the \"" + kObjKey[j] + "\" lines";
  }
  char* end;
  long i = std::strtol(part.c_str(), &end, 10);
  if (end == part.c_str() || *end) {
    return where(file, line) + "face corner \"" + tok + "\" has no " + what +
           " index; fix the face";
  }
  std::string plural = j ? std::string(" \"") + kObjKey[j] + "\" lines" : " vertices";
  std::string range = " (the file has " + std::to_string(nt) + plural +
                      ": OBJ indices run from 1 to " + std::to_string(nt) + ", or -1 back to -" +
                      std::to_string(ns) + " from the face)";
  std::string face = j ? "face " + what + " index " : "face index ";
  if (i == 0) return where(file, line) + face + "0 is invalid" + range + "; fix the face";
  if (i > nt || -i > ns) {
    return where(file, line) + face + std::to_string(i) + " is out of range" + range +
           "; fix the face";
  }
  return "";
}

// an OBJ face corner ("7", "7/1", "7//2", "-1/2/3"): its vertex index, and
// its vt and vn indices where the file has vt or vn lines
std::string checkCorner(const std::string& tok, const ObjCounts& n, const std::string& file,
                        long line) {
  std::string part[3];
  size_t a = tok.find('/'), b = a == std::string::npos ? a : tok.find('/', a + 1);
  part[0] = tok.substr(0, a);
  if (a != std::string::npos) part[1] = tok.substr(a + 1, b == std::string::npos ? b : b - a - 1);
  if (b != std::string::npos) part[2] = tok.substr(b + 1);
  for (int j = 0; j < 3; j++) {
    if (j > 0 && n.total[j] == 0) continue;  // MuJoCo ignores the slot then
    std::string e = checkSlot(tok, part[j], j, n, file, line);
    if (!e.empty()) return e;
  }
  return "";
}

// the kind of an OBJ line: 0 v, 1 vt, 2 vn, -1 other
int objKind(const std::string& key) {
  for (int j = 0; j < 3; j++) {
    if (key == kObjKey[j]) return j;
  }
  return -1;
}

// a "v" line's three coordinates
std::string checkVertex(std::istringstream& s, const std::string& file, long line) {
  std::string tok;
  for (int j = 0; j < 3; j++) {
    if (!(s >> tok)) {
      return where(file, line) + "vertex has " + std::to_string(j) +
             " coordinates, expected 3 (x y z); fix the vertex";
    }
    char* end;
    double x = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end) {
      return where(file, line) + "vertex coordinate \"" + tok + "\" is not a number; fix the vertex";
    }
    if (!std::isfinite(x)) {
      return where(file, line) + "vertex coordinate \"" + tok +
             "\" is not a finite number (MuJoCo would load a different mesh); fix the vertex";
    }
  }
  return "";
}

std::string checkObj(const std::string& file) {
  std::ifstream in(file);
  if (!in) return "";  // MuJoCo reports a missing file itself
  std::vector<std::string> lines;
  ObjCounts n;
  for (std::string l; std::getline(in, l);) {
    lines.push_back(l);
    std::istringstream s(l);
    std::string key;
    s >> key;
    if (int j = objKind(key); j >= 0) n.total[j]++;
  }
  for (size_t k = 0; k < lines.size(); k++) {
    std::istringstream s(lines[k]);
    std::string key, tok;
    s >> key;
    long line = long(k) + 1;
    if (int j = objKind(key); j >= 0) {
      n.seen[j]++;
      std::string e = j == 0 ? checkVertex(s, file, line) : "";
      if (!e.empty()) return e;
    } else if (key == "f") {
      while (s >> tok) {
        std::string e = checkCorner(tok, n, file, line);
        if (!e.empty()) return e;
      }
    }
  }
  return "";
}

std::string checkStl(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (data.size() < 84) {
    return "mjbuoy: mesh file " + file + ": " + std::to_string(data.size()) +
           " bytes is shorter than a binary STL header (84 bytes); MuJoCo 2.2 reads binary STL";
  }
  uint32_t n;
  std::memcpy(&n, data.data() + 80, 4);
  if (data.size() != 84 + 50 * uint64_t(n)) {
    return "mjbuoy: mesh file " + file + ": a binary STL of " + std::to_string(n) +
           " triangles has " + std::to_string(84 + 50 * uint64_t(n)) + " bytes, this file " +
           std::to_string(data.size()) + " (truncated, or ASCII STL, which MuJoCo 2.2 does not "
           "read); export it as binary STL";
  }
  for (uint32_t t = 0; t < n; t++) {
    for (int j = 3; j < 12; j++) {  // the three vertices; the normal is not used
      float x;
      std::memcpy(&x, data.data() + 84 + 50 * size_t(t) + 4 * j, 4);
      if (!std::isfinite(x)) {
        return "mjbuoy: mesh file " + file + ": triangle " + std::to_string(t + 1) +
               " (of " + std::to_string(n) + ") has a vertex coordinate that is not finite; "
               "fix the mesh";
      }
    }
  }
  return "";
}

struct Walk {
  std::string modelDir;  // meshes and includes resolve against the main file's directory
  std::string meshdir;
  std::vector<std::string> meshes;
  std::string error;
  int depth = 0;
  bool radian = false;    // <compiler angle="radian">
  std::string angled;     // the first mjbuoy entry holding an angle [deg]
};

// does the mjbuoy entry hold an angle in degrees: a direction (of a
// spectrum, the wind), or a listed wave (its direction and phase)
bool holdsAngle(const char* name) {
  if (std::strncmp(name, "mjbuoy.", 7)) return false;
  size_t n = std::strlen(name);
  return !std::strncmp(name + 7, "wave.", 5) || !std::strncmp(name + 7, "airy.", 5) ||
         (n > 10 && !std::strcmp(name + n - 10, ".direction"));
}

void walk(const tinyxml2::XMLElement* e, Walk* w);

void include(const char* file, Walk* w) {
  if (w->depth > 20) return;  // MuJoCo refuses recursive includes itself
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(join(w->modelDir, file).c_str()) != tinyxml2::XML_SUCCESS) return;
  w->depth++;
  for (const tinyxml2::XMLElement* c = doc.FirstChildElement(); c; c = c->NextSiblingElement()) {
    walk(c, w);
  }
  w->depth--;
}

void walk(const tinyxml2::XMLElement* e, Walk* w) {
  const char* name = e->Name();
  if (!std::strcmp(name, "include") && e->Attribute("file")) {
    include(e->Attribute("file"), w);
    return;
  }
  if (!std::strcmp(name, "compiler")) {
    if (e->Attribute("assetdir") && w->meshdir.empty()) w->meshdir = e->Attribute("assetdir");
    if (e->Attribute("meshdir")) w->meshdir = e->Attribute("meshdir");
    if (e->Attribute("angle")) w->radian = !std::strcmp(e->Attribute("angle"), "radian");
  }
  if (!std::strcmp(name, "numeric") && e->Attribute("name") && w->angled.empty() &&
      holdsAngle(e->Attribute("name"))) {
    w->angled = e->Attribute("name");
  }
  if (!std::strcmp(name, "mesh") && e->Attribute("file")) w->meshes.push_back(e->Attribute("file"));
  for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    walk(c, w);
  }
}

}  // namespace

int mjb_checkMeshFile(const char* path, char* error, int error_sz) {
  if (error && error_sz > 0) error[0] = 0;
  if (!path) return 1;
  std::string f = path;
  std::string e = endsWith(f, ".obj") ? checkObj(f) : endsWith(f, ".stl") ? checkStl(f) : "";
  if (e.empty()) return 1;
  if (error && error_sz > 0) std::snprintf(error, error_sz, "%s", e.c_str());
  return 0;
}

int mjb_checkModelFile(const char* xmlpath, char* error, int error_sz) {
  if (error && error_sz > 0) error[0] = 0;
  if (!xmlpath) return 1;
  tinyxml2::XMLDocument doc;
  // an unreadable or malformed file: MuJoCo's own loader says why
  if (doc.LoadFile(xmlpath) != tinyxml2::XML_SUCCESS || !doc.RootElement()) return 1;
  Walk w;
  w.modelDir = dirOf(xmlpath);
  walk(doc.RootElement(), &w);
  std::string dir = w.meshdir.empty() ? w.modelDir : join(w.modelDir, w.meshdir);
  if (!dir.empty() && dir.back() != '/') dir += '/';
  for (const std::string& f : w.meshes) {
    if (!mjb_checkMeshFile(join(dir, f).c_str(), error, error_sz)) return 0;
  }
  // MuJoCo converts the angles of its own attributes, never <custom> data,
  // and mjModel keeps no trace of the unit: said here, where the file is read
  if (w.radian && !w.angled.empty()) {
    mju_warning_s("mjbuoy: the model sets <compiler angle=\"radian\">, but mjbuoy's angles "
                  "are degrees whatever the compiler's unit (MuJoCo passes <custom> data "
                  "through unconverted): <numeric name=\"%s\"> is read in degrees; give "
                  "its angles in degrees (90, not 1.5708)", w.angled.c_str());
  }
  return 1;
}
