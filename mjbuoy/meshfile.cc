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

// a vertex index of an OBJ face corner ("7", "7/1", "7//2", "-1/2/3")
std::string checkCorner(const std::string& tok, long nv, long nseen, const std::string& file,
                        long line) {
  char* end;
  long i = std::strtol(tok.c_str(), &end, 10);
  if (end == tok.c_str()) {
    return where(file, line) + "face corner \"" + tok + "\" has no vertex index; fix the face";
  }
  std::string range = " (the file has " + std::to_string(nv) +
                      " vertices: OBJ indices run from 1 to " + std::to_string(nv) +
                      ", or -1 back to -" + std::to_string(nseen) + " from the face)";
  if (i == 0) return where(file, line) + "face index 0 is invalid" + range + "; fix the face";
  if (i > nv || -i > nseen) {
    return where(file, line) + "face index " + std::to_string(i) + " is out of range" + range +
           "; fix the face";
  }
  return "";
}

std::string checkObj(const std::string& file) {
  std::ifstream in(file);
  if (!in) return "";  // MuJoCo reports a missing file itself
  std::vector<std::string> lines;
  long nv = 0;
  for (std::string l; std::getline(in, l);) {
    lines.push_back(l);
    if (l.size() > 1 && l[0] == 'v' && std::isspace(static_cast<unsigned char>(l[1]))) nv++;
  }
  long seen = 0;
  for (size_t k = 0; k < lines.size(); k++) {
    std::istringstream s(lines[k]);
    std::string key, tok;
    s >> key;
    long line = long(k) + 1;
    if (key == "v") {
      seen++;
      for (int j = 0; j < 3; j++) {
        if (!(s >> tok)) {
          return where(file, line) + "vertex has " + std::to_string(j) +
                 " coordinates, expected 3 (x y z); fix the vertex";
        }
        char* end;
        double x = std::strtod(tok.c_str(), &end);
        if (end == tok.c_str() || *end) {
          return where(file, line) + "vertex coordinate \"" + tok +
                 "\" is not a number; fix the vertex";
        }
        if (!std::isfinite(x)) {
          return where(file, line) + "vertex coordinate \"" + tok +
                 "\" is not a finite number (MuJoCo would load a different mesh); fix the "
                 "vertex";
        }
      }
    } else if (key == "f") {
      while (s >> tok) {
        std::string e = checkCorner(tok, nv, seen, file, line);
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
};

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
  return 1;
}
