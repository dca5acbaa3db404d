// mjbuoy-scenario: apply a scenario to its model. The model's MJCF is edited
// with tinyxml2 (mjbuoy.* custom entries, waves, mesh files) and compiled
// from a MuJoCo VFS under a name in the model's own directory, so relative
// mesh paths (and <compiler meshdir>) resolve as they do for the model
// itself and nothing is written to disk.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fnmatch.h>
#include <sstream>

#include <tinyxml2.h>

#include "guard.h"
#include "mjcfedit.h"
#include "modelload.h"
#include "radnotice.h"
#include "scenario.h"

namespace scn {

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

Sim::~Sim() {
  if (d) {
    if (b) mjb_unbindData(b, d);
    mj_deleteData(d);
  }
  if (b) mjb_detach(b);
  if (m) mj_deleteModel(m);
}

using mjbtool::findEntry;
using mjbtool::removeEntries;
using mjbtool::setEntry;

std::string editModel(const Scenario& s) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(s.model.c_str()) != tinyxml2::XML_SUCCESS) {
    throw Invalid(s.file, s.line, "cannot read model " + s.model + ": " + doc.ErrorStr());
  }
  XMLElement* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "mujoco") {
    throw Invalid(s.file, s.line, "model " + s.model + " is not MJCF (root element <mujoco>)");
  }
  if (s.calm) mjbtool::removeSea(root);  // no listed waves and no spectra (docs/mjcf.md section 8)
  for (const Entry& e : s.entries) {
    if (e.remove) {
      removeEntries(root, e.name, false);
    } else {
      setEntry(doc, root, e.name, e.data, e.text);
    }
  }
  for (const Wave& w : s.waves) {
    std::string name = "mjbuoy.wave." + w.name;
    double v[5] = {w.amplitude, w.wavelength, w.direction, w.phase, w.steepness};
    const char* what[5] = {"amplitude", "wavelength", "direction", "phase", "steepness"};
    XMLElement* old = findEntry(root, name);
    std::vector<double> prev;
    if (old && old->Attribute("data")) {
      std::istringstream in(old->Attribute("data"));
      double x;
      while (in >> x) prev.push_back(x);
    }
    for (int i = 0; i < 5; i++) {
      if (!std::isnan(v[i])) continue;
      if (prev.size() == 5) {
        v[i] = prev[i];
      } else if (i < 2) {
        throw Invalid(s.file, w.line,
                      "<wave>: the model has no wave \"" + w.name + "\" to modify, so " +
                          what[i] + " is needed (a new wave needs amplitude and wavelength "
                          "or wavenumber)");
      } else {
        v[i] = 0;
      }
    }
    std::string data;
    for (int i = 0; i < 5; i++) data += (i ? " " : "") + exact(v[i]);
    setEntry(doc, root, name, data, false);
  }
  for (const MeshFile& mf : s.meshes) {
    bool found = false;
    for (XMLElement* a = root->FirstChildElement("asset"); a; a = a->NextSiblingElement("asset")) {
      for (XMLElement* e = a->FirstChildElement("mesh"); e; e = e->NextSiblingElement("mesh")) {
        const char* n = e->Attribute("name");
        const char* f = e->Attribute("file");
        // MuJoCo names a mesh without a name attribute after its file
        std::string name = n ? n : f ? fs::path(f).stem().string() : "";
        if (name == mf.name) {
          e->SetAttribute("file", mf.file.c_str());
          found = true;
        }
      }
    }
    if (!found) {
      throw Invalid(s.file, mf.line, "<mesh>: model " + s.model_attr + " has no <mesh name=\"" +
                                         mf.name + "\"> in its <asset>");
    }
  }
  tinyxml2::XMLPrinter p;
  doc.Print(&p);
  return p.CStr();
}

// the line of the scenario element an mjb_attach message is about
static int lineOf(const Scenario& s, const std::string& err) {
  for (const Entry& e : s.entries) {
    if (err.find("\"" + e.name + "\"") != std::string::npos) return e.line;
  }
  for (const Wave& w : s.waves) {
    if (err.find("\"mjbuoy.wave." + w.name + "\"") != std::string::npos) return w.line;
  }
  if (err.find("mjbuoy.wave.") != std::string::npos) {
    if (!s.waves.empty()) return s.waves[0].line;
  }
  if (err.find("mjbuoy.sea.") != std::string::npos && s.sea_line) return s.sea_line;
  return s.line;
}

static std::string bodyName(const mjModel* m, int b) {
  return m->names + m->name_bodyadr[b];
}

// body names or shell patterns, space separated, against the model's bodies
static std::vector<int> resolveBodies(const Scenario& s, const mjModel* m,
                                      const std::string& spec, int line) {
  std::vector<int> out;
  std::istringstream in(spec);
  std::string w;
  while (in >> w) {
    int n = 0;
    for (int b = 1; b < m->nbody; b++) {
      if (fnmatch(w.c_str(), bodyName(m, b).c_str(), 0) == 0) {
        n++;
        bool dup = false;
        for (int o : out) dup = dup || o == b;
        if (!dup) out.push_back(b);
      }
    }
    if (!n) {
      std::string names;
      for (int b = 1; b < m->nbody && b <= 12; b++) names += (b > 1 ? ", " : "") + bodyName(m, b);
      if (m->nbody > 13) names += ", ...";
      throw Invalid(s.file, line, "no body \"" + w + "\" in model " + s.model_attr +
                                      " (bodies: " + names + ")");
    }
  }
  return out;
}

static void applyInit(const Scenario& s, const Init& in, const mjModel* m, mjData* d) {
  const double deg = M_PI / 180;
  if (!in.body.empty()) {
    if (in.body.find_first_of("*?[") != std::string::npos) {
      throw Invalid(s.file, in.line, "<init>: body \"" + in.body + "\": patterns are not "
                                     "supported in <init body>; name one body per <init>");
    }
    int b = mj_name2id(m, mjOBJ_BODY, in.body.c_str());
    if (b < 0) resolveBodies(s, m, in.body, in.line);  // throws with the body list
    int j = -1;
    for (int k = 0; k < m->njnt; k++) {
      if (m->jnt_bodyid[k] == b && m->jnt_type[k] == mjJNT_FREE) j = k;
    }
    if (j < 0) {
      throw Invalid(s.file, in.line, "<init>: body \"" + in.body + "\" has no free joint; "
                                     "set its joints with <init joint=... qpos=...>");
    }
    mjtNum* q = d->qpos + m->jnt_qposadr[j];
    mjtNum* v = d->qvel + m->jnt_dofadr[j];
    if (in.has_pos) mju_copy3(q, in.pos);
    if (in.has_rpy) {
      // R = Rz(yaw) Ry(pitch) Rx(roll), as mjbuoy-sim reports it
      mjtNum qx[4] = {std::cos(in.rpy[0] * deg / 2), std::sin(in.rpy[0] * deg / 2), 0, 0};
      mjtNum qy[4] = {std::cos(in.rpy[1] * deg / 2), 0, std::sin(in.rpy[1] * deg / 2), 0};
      mjtNum qz[4] = {std::cos(in.rpy[2] * deg / 2), 0, 0, std::sin(in.rpy[2] * deg / 2)};
      mjtNum t[4];
      mju_mulQuat(t, qz, qy);
      mju_mulQuat(q + 3, t, qx);
    }
    if (in.has_vel) mju_copy3(v, in.vel);
    if (in.has_angvel) {
      // free joint angular velocity is in the body frame
      mjtNum R[9], w[3] = {in.angvel[0] * deg, in.angvel[1] * deg, in.angvel[2] * deg};
      mju_quat2Mat(R, q + 3);
      mju_mulMatTVec(v + 3, R, w, 3, 3);
    }
  } else {
    int j = mj_name2id(m, mjOBJ_JOINT, in.joint.c_str());
    if (j < 0) {
      throw Invalid(s.file, in.line, "<init>: no joint \"" + in.joint + "\" in model " +
                                         s.model_attr);
    }
    int type = m->jnt_type[j];
    if (type != mjJNT_HINGE && type != mjJNT_SLIDE) {
      throw Invalid(s.file, in.line, "<init>: joint \"" + in.joint + "\" is not a hinge or "
                                     "slide; set a free body with <init body=...>");
    }
    double scale = type == mjJNT_HINGE ? deg : 1;
    if (in.has_qpos) d->qpos[m->jnt_qposadr[j]] = in.qpos * scale;
    if (in.has_qvel) d->qvel[m->jnt_dofadr[j]] = in.qvel * scale;
  }
}

std::unique_ptr<Sim> loadScenario(Scenario& s, const std::string& backend) {
  std::string xml = editModel(s);
  // mesh files MuJoCo 2.2 would load broken (mjbuoy.h): the model's own,
  // and those the scenario puts in their place
  char cerr[1024] = "";
  for (const MeshFile& mf : s.meshes) {
    if (!mjb_checkMeshFile(mf.file.c_str(), cerr, sizeof(cerr))) throw Invalid(s.file, mf.line, cerr);
  }
  // compile from memory under a name in the model's directory, through the
  // tools' one loading path (its own mesh files checked first)
  auto sim = std::make_unique<Sim>();
  char err[2048] = "";
  std::string lerr;
  sim->m = mjbtool::loadModel(s.model, &xml, "mjbuoy-scenario", &lerr);
  if (!sim->m) throw Invalid(s.file, s.line, lerr);  // "cannot load MODEL: reason"
  if (s.timestep > 0) sim->m->opt.timestep = s.timestep;
  std::string why;
  if (mjbtool::runSteps(s.duration, sim->m->opt.timestep, &why) < 1) throw Invalid(s.file, s.line, why);
  bool energy = false;
  for (const Check& c : s.checks) energy = energy || c.kind == Kind::ENERGY;
  if (energy) sim->m->opt.enableflags |= mjENBL_ENERGY;

  std::string be = !backend.empty() ? backend : s.backend;
  std::string plan = mjbtool::radiationPlan(sim->m);  // the panel solve is no silent wait
  if (!plan.empty()) std::fprintf(stderr, "mjbuoy-scenario: %s\n", plan.c_str());
  sim->b = mjb_attach(sim->m, be.empty() ? nullptr : be.c_str(), err, sizeof(err));
  if (!sim->b) throw Invalid(s.file, lineOf(s, err), err);
  sim->warnings = mjb_warnings(sim->b);

  for (Check& c : s.checks) {
    if (!c.body_spec.empty()) c.bodies = resolveBodies(s, sim->m, c.body_spec, c.line);
    if (!c.sensor.empty()) {
      std::string why;
      int adr = sensorAddress(sim->m, c.sensor, c.index, &why);
      if (adr < 0) throw Invalid(s.file, c.line, "<check>: " + why);
      c.bodies = {adr};
    }
    double span = c.to - c.from;
    if (c.stat != Stat::VALUE && c.kind != Kind::FINITE && span < sim->m->opt.timestep) {
      throw Invalid(s.file, c.line, "<check>: the window [" + num(c.from) + ", " + num(c.to) +
                                        "] s is shorter than the time step " +
                                        num(sim->m->opt.timestep) + " s");
    }
  }
  sim->d = mj_makeData(sim->m);
  mjb_bindData(sim->b, sim->d);
  for (const Init& in : s.inits) applyInit(s, in, sim->m, sim->d);
  return sim;
}

}  // namespace scn
