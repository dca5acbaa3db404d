// world: loading a scene the way mjbuoy-sim does (the --set edits of
// tools/sim/simsea.cc, tools/common/modelload.h), attaching mjbuoy
#include "world.h"

#include <unistd.h>

#include <climits>
#include <mutex>
#include <string>
#include <sys/stat.h>

#include <tinyxml2.h>

#include "mjcfedit.h"
#include "modelload.h"
#include "simsea.h"

namespace mjbpy {

World::~World() {
  if (b) {
    if (d) mjb_unbindData(b, d);
    mjb_detach(b);
  }
  if (d) mj_deleteData(d);
  if (m) mj_deleteModel(m);
}

static std::mutex g_warnMutex;
static std::string g_lastWarning;

static void onWarning(const char* msg) {
  std::lock_guard<std::mutex> lock(g_warnMutex);
  g_lastWarning = msg;
  while (!g_lastWarning.empty() &&
         (g_lastWarning.back() == '.' || g_lastWarning.back() == '\n')) {
    g_lastWarning.pop_back();
  }
}

void installWarningHandler() { mju_user_warning = onWarning; }

bool diverged(const mjData* d, std::string* why) {
  const int kinds[3] = {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC};
  const char* names[3] = {"bad qpos", "bad qvel", "bad qacc"};
  for (int k = 0; k < 3; k++) {
    if (d->warning[kinds[k]].number > 0) {
      std::lock_guard<std::mutex> lock(g_warnMutex);
      *why = "MuJoCo reset the state: " +
             (g_lastWarning.empty() ? std::string(names[k]) + " (NaN, Inf or a huge value)"
                                    : g_lastWarning);
      return true;
    }
  }
  return false;
}

static bool isXmlText(const std::string& s) {
  size_t i = s.find_first_not_of(" \t\r\n");
  return i != std::string::npos && s[i] == '<';
}

static std::string cwd() {
  char buf[PATH_MAX];
  return getcwd(buf, sizeof(buf)) ? std::string(buf) : std::string(".");
}

// every <text|numeric name="mjbuoy.spectrum.<label>.type"> below e
static void scanLabels(const tinyxml2::XMLElement* e, std::vector<std::string>* out) {
  const std::string pre = "mjbuoy.spectrum.", post = ".type";
  for (; e; e = e->NextSiblingElement()) {
    const char* n = e->Attribute("name");
    std::string name = n ? n : "";
    if (name.size() > pre.size() + post.size() && name.rfind(pre, 0) == 0 &&
        name.compare(name.size() - post.size(), post.size(), post) == 0) {
      out->push_back(name.substr(pre.size(), name.size() - pre.size() - post.size()));
    }
    scanLabels(e->FirstChildElement(), out);
  }
}

std::vector<std::string> spectrumLabels(const LoadSpec& spec, std::string* err) {
  std::vector<std::string> labels;
  tinyxml2::XMLDocument doc;
  bool ok = isXmlText(spec.source)
                ? doc.Parse(spec.source.c_str(), spec.source.size()) == tinyxml2::XML_SUCCESS
                : doc.LoadFile(spec.source.c_str()) == tinyxml2::XML_SUCCESS;
  if (!ok) {
    *err = "cannot read " + (isXmlText(spec.source) ? std::string("MJCF text") : spec.source) +
           ": " + doc.ErrorStr();
    return labels;
  }
  if (!spec.calm) scanLabels(doc.RootElement(), &labels);
  std::vector<std::string> more;
  for (const std::string& s : spec.set) {
    tinyxml2::XMLDocument one;
    size_t q = s.find('=');
    if (q == std::string::npos) continue;  // parseEdits names it
    std::string xml = "<e name=\"" + s.substr(0, q) + "\"/>";
    if (one.Parse(xml.c_str()) == tinyxml2::XML_SUCCESS) scanLabels(one.RootElement(), &more);
  }
  for (const std::string& l : more) {
    bool seen = false;
    for (const std::string& x : labels) seen = seen || x == l;
    if (!seen) labels.push_back(l);
  }
  return labels;
}

// the compiled model of spec; null with the reason in err
static mjModel* compile(const LoadSpec& spec, const std::string& name, std::string* err) {
  std::vector<std::string> sets = spec.set;
  if (spec.seeded) {
    std::vector<std::string> labels = spectrumLabels(spec, err);
    if (!err->empty()) return nullptr;
    if (labels.empty()) {
      *err = "seed " + std::to_string(spec.seed) + " given but " + name +
             " has no wave spectrum (mjbuoy.spectrum.<label>.type); give no seed, or add a "
             "spectrum (docs/mjcf.md section 8)";
      return nullptr;
    }
    for (size_t k = 0; k < labels.size(); k++) {
      sets.push_back("mjbuoy.spectrum." + labels[k] + ".seed=" + std::to_string(spec.seed + k));
    }
  }
  mjbsim::Edits edits;
  *err = mjbsim::parseEdits(sets, {}, spec.calm, &edits);
  if (!err->empty()) return nullptr;
  std::string xml;
  if (isXmlText(spec.source)) {
    // compiled as a file in the working directory: mesh files resolve from there
    std::string path = cwd() + "/(MJCF text)";
    if (!mjbsim::editedText(path, spec.source, edits, &xml, err)) return nullptr;
    char e[2048] = "";
    mjModel* m = mjbtool::loadFromMemory(path, xml, "mjbuoy-python", e, sizeof(e));
    if (!m) *err = "cannot load the MJCF text: " + std::string(e);
    return m;
  }
  struct stat st;
  if (stat(spec.source.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) {
    *err = "no model file " + spec.source + "; give the path of an MJCF file or MJCF text "
           "starting with '<'";
    return nullptr;
  }
  // as mjbuoy-sim loads it: mesh files checked, then compiled (tools/common/modelload.h)
  if (!edits.empty() && !mjbsim::editedModel(spec.source, edits, &xml, err)) return nullptr;
  return mjbtool::loadModel(spec.source, edits.empty() ? nullptr : &xml, "mjbuoy-python", err);
}

std::unique_ptr<World> loadWorld(const LoadSpec& spec, std::string* err) {
  err->clear();
  auto w = std::make_unique<World>();
  w->name = isXmlText(spec.source) ? "MJCF text" : spec.source;
  w->m = compile(spec, w->name, err);
  if (!w->m) {
    if (err->empty()) *err = "cannot load " + w->name;
    return nullptr;
  }
  char e[1024] = "";
  w->b = mjb_attach(w->m, spec.backend.empty() ? nullptr : spec.backend.c_str(), e, sizeof(e));
  if (!w->b) {
    mjbsim::Edits edits;
    std::vector<std::string> sets = spec.set;
    mjbsim::parseEdits(sets, {}, spec.calm, &edits);
    *err = w->name + ": " + mjbsim::blame(edits, e);
    return nullptr;
  }
  w->d = mj_makeData(w->m);
  if (!w->d || !mjb_bindData(w->b, w->d)) {
    *err = w->name + ": cannot allocate the simulation state (mj_makeData)";
    return nullptr;
  }
  return w;
}

}  // namespace mjbpy
