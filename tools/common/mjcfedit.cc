// mjbuoy.* <custom> entries edited with tinyxml2; the result compiled from
// a MuJoCo VFS (mjcfedit.h)
#include "mjcfedit.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

namespace mjbtool {

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

// the <custom> children of the model, in document order
static std::vector<XMLElement*> customs(XMLElement* root) {
  std::vector<XMLElement*> v;
  for (XMLElement* c = root->FirstChildElement("custom"); c; c = c->NextSiblingElement("custom")) {
    v.push_back(c);
  }
  return v;
}

XMLElement* findEntry(XMLElement* root, const std::string& name) {
  for (XMLElement* c : customs(root)) {
    for (XMLElement* e = c->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const char* n = e->Attribute("name");
      if (n && name == n) return e;
    }
  }
  return nullptr;
}

void setEntry(tinyxml2::XMLDocument& doc, XMLElement* root, const std::string& name,
              const std::string& data, bool text) {
  XMLElement* e = findEntry(root, name);
  if (!e) {
    std::vector<XMLElement*> cs = customs(root);
    XMLElement* c = cs.empty() ? nullptr : cs[0];
    if (!c) {
      c = doc.NewElement("custom");
      root->InsertFirstChild(c);
    }
    e = doc.NewElement(text ? "text" : "numeric");
    e->SetAttribute("name", name.c_str());
    c->InsertEndChild(e);
  }
  e->SetName(text ? "text" : "numeric");
  e->DeleteAttribute("size");  // numeric size must not contradict the new data
  e->SetAttribute("data", data.c_str());
}

void removeEntries(XMLElement* root, const std::string& name, bool prefix) {
  for (XMLElement* c : customs(root)) {
    for (XMLElement* e = c->FirstChildElement(); e;) {
      XMLElement* next = e->NextSiblingElement();
      const char* n = e->Attribute("name");
      if (n && (prefix ? std::string(n).rfind(name, 0) == 0 : name == n)) c->DeleteChild(e);
      e = next;
    }
  }
}

void removeSea(XMLElement* root) {
  // listed Gerstner and Airy components, and spectra (docs/mjcf.md sections 3 and 8)
  for (const char* p : {"mjbuoy.wave.", "mjbuoy.airy.", "mjbuoy.spectrum."}) {
    removeEntries(root, p, true);
  }
}

mjModel* loadFromMemory(const std::string& modelPath, const std::string& xml,
                        const std::string& tag, char* err, int errsz) {
  fs::path model(modelPath);
  std::string vname = "." + tag + "-" + model.filename().string();
  std::unique_ptr<mjVFS> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), vname.c_str(), (int)xml.size()) != 0) {
    std::snprintf(err, errsz, "cannot create the in-memory model file");
    return nullptr;
  }
  int id = mj_findFileVFS(vfs.get(), vname.c_str());
  std::memcpy(vfs->filedata[id], xml.data(), xml.size());
  std::string vpath = (model.parent_path() / vname).string();
  mjModel* m = mj_loadXML(vpath.c_str(), vfs.get(), err, errsz);
  mj_deleteVFS(vfs.get());
  return m;
}

}  // namespace mjbtool
