// modelload: the files of a model, the output guard around them, and the
// one loading path of the tools (see modelload.h)
#include "modelload.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <tinyxml2.h>

#include "mjbuoy.h"
#include "mjcfedit.h"

namespace fs = std::filesystem;

namespace mjbtool {
namespace {

struct Walk {
  fs::path modelDir;
  std::string meshdir, texturedir, assetdir;
  std::vector<std::string> meshish, textures, includes;  // as written
  int depth = 0;
};

void walk(const tinyxml2::XMLElement* e, Walk* w);

void include(const std::string& file, Walk* w) {
  if (w->depth > 20) return;  // MuJoCo refuses recursive includes itself
  w->includes.push_back(file);
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile((w->modelDir / file).string().c_str()) != tinyxml2::XML_SUCCESS) return;
  w->depth++;
  for (const tinyxml2::XMLElement* c = doc.FirstChildElement(); c; c = c->NextSiblingElement()) {
    walk(c, w);
  }
  w->depth--;
}

void walk(const tinyxml2::XMLElement* e, Walk* w) {
  const char* name = e->Name();
  const char* file = e->Attribute("file");
  if (!std::strcmp(name, "include")) {
    if (file) include(file, w);
    return;
  }
  if (!std::strcmp(name, "compiler")) {
    if (e->Attribute("meshdir")) w->meshdir = e->Attribute("meshdir");
    if (e->Attribute("texturedir")) w->texturedir = e->Attribute("texturedir");
    if (e->Attribute("assetdir")) w->assetdir = e->Attribute("assetdir");
  }
  if (file && (!std::strcmp(name, "mesh") || !std::strcmp(name, "hfield") ||
               !std::strcmp(name, "skin"))) {
    w->meshish.push_back(file);
  }
  if (!std::strcmp(name, "texture")) {
    for (const char* a : {"file", "fileright", "fileleft", "fileup", "filedown", "filefront",
                          "fileback"}) {
      if (e->Attribute(a)) w->textures.push_back(e->Attribute(a));
    }
  }
  for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    walk(c, w);
  }
}

// f under each of dirs (relative to the model's directory), those that exist
void addExisting(const Walk& w, const std::string& f, const std::vector<std::string>& dirs,
                 std::vector<std::string>* out) {
  for (const std::string& d : dirs) {
    fs::path p = fs::path(f).is_absolute() ? fs::path(f) : w.modelDir / d / f;
    std::error_code ec;
    if (fs::exists(p, ec)) out->push_back(p.lexically_normal().string());
  }
}

}  // namespace

std::vector<std::string> modelFiles(const std::string& xmlpath) {
  std::vector<std::string> out = {xmlpath};
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(xmlpath.c_str()) != tinyxml2::XML_SUCCESS || !doc.RootElement()) return out;
  Walk w;
  w.modelDir = fs::path(xmlpath).parent_path();
  walk(doc.RootElement(), &w);
  // MuJoCo 2.2: meshdir, else assetdir, for meshes, height fields and skins;
  // texturedir, else assetdir, for textures; the model's directory if none
  std::string md = !w.meshdir.empty() ? w.meshdir : w.assetdir;
  std::string td = !w.texturedir.empty() ? w.texturedir : w.assetdir;
  for (const std::string& f : w.includes) addExisting(w, f, {""}, &out);
  for (const std::string& f : w.meshish) addExisting(w, f, {md, ""}, &out);
  for (const std::string& f : w.textures) addExisting(w, f, {td, ""}, &out);
  std::sort(out.begin() + 1, out.end());
  out.erase(std::unique(out.begin() + 1, out.end()), out.end());
  return out;
}

bool checkOutputs(const std::string& model, std::vector<PathUse> uses, std::string* err) {
  std::vector<std::string> files = modelFiles(model);
  for (size_t i = 0; i < files.size(); i++) {
    uses.push_back({files[i], i == 0 ? "model" : "file that the model " + model + " reads:", false});
  }
  for (const PathUse& u : uses) {
    if (u.output && !checkWritable(u.path, u.what, err)) return false;
  }
  return checkDistinct(uses, err);
}

mjModel* loadModel(const std::string& path, const std::string* xml, const std::string& tag,
                   std::string* err) {
  char e[2048] = "";
  if (!mjb_checkModelFile(path.c_str(), e, sizeof(e))) {
    *err = "cannot load " + path + ": " + e;
    return nullptr;
  }
  mjModel* m = xml ? loadFromMemory(path, *xml, tag, e, sizeof(e))
                   : mj_loadXML(path.c_str(), nullptr, e, sizeof(e));
  if (!m) *err = "cannot load " + path + (xml ? " with the changes applied" : "") + ": " + e;
  return m;
}

}  // namespace mjbtool
