// mjbuoy-scenario: read and validate a scenario file (docs/scenarios.md)
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include <tinyxml2.h>

#include "pathcheck.h"
#include "scenario.h"
#include "scenario_xml.h"

namespace scn {

namespace fs = std::filesystem;
using tinyxml2::XMLAttribute;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

static std::string where(const std::string& file, int line) {
  return line > 0 ? file + ":" + std::to_string(line) : file;
}

Invalid::Invalid(const std::string& file, int line, const std::string& why)
    : std::runtime_error(where(file, line) + ": " + why) {}

std::string num(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.6g", v);
  return buf;
}

std::string exact(double v) {
  char buf[64];
  for (int p = 6; p <= 17; p++) {
    std::snprintf(buf, sizeof(buf), "%.*g", p, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

static const std::map<std::string, Quantity> kQuantities = {
    {"x", Quantity::X},         {"y", Quantity::Y},          {"z", Quantity::Z},
    {"roll", Quantity::ROLL},   {"pitch", Quantity::PITCH},  {"yaw", Quantity::YAW},
    {"tilt", Quantity::TILT},
    {"heave", Quantity::HEAVE}, {"eta", Quantity::ETA},      {"vx", Quantity::VX},
    {"vy", Quantity::VY},       {"vz", Quantity::VZ},        {"fx", Quantity::FX},
    {"fy", Quantity::FY},       {"fz", Quantity::FZ},        {"tx", Quantity::TX},
    {"ty", Quantity::TY},       {"tz", Quantity::TZ},        {"force", Quantity::FORCE},
    {"torque", Quantity::TORQUE}};

static bool isWrench(Quantity q) { return q >= Quantity::FX; }

bool quantityByName(const std::string& name, Quantity* q) {
  auto it = kQuantities.find(name);
  if (it == kQuantities.end()) return false;
  *q = it->second;
  return true;
}

static const std::map<std::string, int> kParts = {
    {"total", -1}, {"pressure", mjbPART_PRESSURE}, {"viscous", mjbPART_VISCOUS},
    {"drag", mjbPART_DRAG}, {"slamming", mjbPART_SLAM}, {"damping", mjbPART_DAMPING},
    {"wind", mjbPART_WIND}};

bool partByName(const std::string& name, int* part) {
  auto it = kParts.find(name);
  if (it == kParts.end()) return false;
  *part = it->second;
  return true;
}

static std::string keys(const std::map<std::string, Quantity>& m, bool wrench) {
  std::vector<std::string> v;
  for (auto& kv : m) {
    if (isWrench(kv.second) == wrench) v.push_back(kv.first);
  }
  return joined(v);
}

static void parseBounds(const El& e, Check& c) {
  bool lo = e.has("min"), hi = e.has("max"), tg = e.has("target"), tl = e.has("tol");
  if (tg != tl) e.fail(tg ? "target needs tol" : "tol needs target", tg ? "target" : "tol");
  if (tg && (lo || hi)) e.fail("give either target and tol or min and/or max, not both", "target");
  if (tg) {
    c.has_target = true;
    c.target = e.number("target");
    c.tol = e.number("tol");
    if (c.tol < 0) e.fail("tol = " + num(c.tol) + " must be >= 0", "tol");
    c.lo = c.target - c.tol;
    c.hi = c.target + c.tol;
    return;
  }
  if (lo) c.lo = e.number("min");
  if (hi) c.hi = e.number("max");
  if (!lo && !hi) {
    if (c.kind == Kind::ENERGY) {
      c.hi = 0;  // not growing
    } else {
      e.fail("a bound is needed: min and/or max, or target and tol");
    }
  }
  if (c.lo > c.hi) e.fail("min = " + num(c.lo) + " > max = " + num(c.hi), "min");
}

static void parseWindow(const El& e, Check& c, double duration) {
  c.from = e.number("from", 0);
  c.has_to = e.has("to");
  c.to = e.number("to", duration);
  if (c.from < 0) e.fail("from = " + num(c.from) + " must be >= 0", "from");
  if (c.to > duration) {
    e.fail("to = " + num(c.to) + " is after the end of the run (duration " + num(duration) + ")",
           "to");
  }
  if (c.from >= c.to) e.fail("the window is empty: from = " + num(c.from) + " >= to = " +
                             num(c.to), "from");
}

static void parseAt(const El& e, Check& c, double duration) {
  c.at = e.number("at");
  if (c.at < 0 || c.at > duration) {
    e.fail("at = " + num(c.at) + " must be within the run [0, " + num(duration) + "]", "at");
  }
  c.from = c.to = c.at;
}

static Check parseCheck(const XMLElement* x, const std::string& file, double duration) {
  static const std::map<std::string, std::pair<Kind, std::vector<std::string>>> kinds = {
      {"value", {Kind::VALUE, {"body", "quantity", "part", "sensor", "index", "at", "min", "max", "target", "tol"}}},
      {"range", {Kind::RANGE, {"body", "quantity", "part", "sensor", "index", "from", "to", "min", "max", "target", "tol"}}},
      {"mean", {Kind::MEAN, {"body", "quantity", "part", "sensor", "index", "from", "to", "min", "max", "target", "tol"}}},
      {"std", {Kind::STD, {"body", "quantity", "part", "sensor", "index", "from", "to", "min", "max", "target", "tol"}}},
      {"settled", {Kind::SETTLED, {"body", "quantity", "part", "sensor", "index", "from", "to", "max"}}},
      {"finite", {Kind::FINITE, {"from", "to", "maxqvel"}}},
      {"energy", {Kind::ENERGY, {"from", "to", "min", "max"}}},
      {"wrench", {Kind::WRENCH, {"body", "component", "part", "stat", "at", "from", "to", "min",
                                 "max", "target", "tol"}}},
  };
  const char* k = x->Attribute("kind");
  if (!k) {
    throw Invalid(file, x->GetLineNum(),
                  "<check>: missing attribute 'kind'; kinds: value, range, mean, std, settled, "
                  "finite, energy, wrench");
  }
  auto it = kinds.find(k);
  if (it == kinds.end()) {
    throw Invalid(file, x->GetLineNum(),
                  std::string("<check>: unknown kind \"") + k +
                      "\"; kinds: value, range, mean, std, settled, finite, energy, wrench");
  }
  std::vector<std::string> allowed = {"kind", "name"};
  allowed.insert(allowed.end(), it->second.second.begin(), it->second.second.end());
  El e(x, file, allowed);
  Check c;
  c.kind = it->second.first;
  c.kind_name = k;
  c.line = e.line();
  c.name = e.str("name", "");

  if (e.has("sensor")) {
    // any MuJoCo sensor (resolved against the model in scenario_model.cc)
    for (const char* a : {"body", "quantity", "part"}) {
      if (e.has(a)) e.fail(std::string("give sensor or body and quantity, not both (") + a + ")", a);
    }
    c.sensor = e.str("sensor");
    if (c.sensor.empty()) e.fail("sensor is empty", "sensor");
    c.quantity = Quantity::SENSOR;
    c.quantity_name = "sensor";
    double i = e.number("index", 0);
    if (i < 0 || i != std::floor(i) || i > 1e6) {
      e.fail("index = " + num(i) + " must be a whole number >= 0", "index");
    }
    c.index = (int)i;
  } else if (e.has("index")) {
    e.fail("index applies to sensor=\"NAME\" only", "index");
  } else if (c.kind != Kind::FINITE && c.kind != Kind::ENERGY) {
    c.body_spec = e.str("body");
    if (c.body_spec.find_first_not_of(" \t\n") == std::string::npos) e.fail("body is empty", "body");
    const char* qa = c.kind == Kind::WRENCH ? "component" : "quantity";
    c.quantity_name = e.str(qa);
    auto q = kQuantities.find(c.quantity_name);
    if (q == kQuantities.end() || (c.kind == Kind::WRENCH && !isWrench(q->second))) {
      e.fail(std::string("unknown ") + qa + " \"" + c.quantity_name + "\"; " +
                 (c.kind == Kind::WRENCH ? "components: " + keys(kQuantities, true)
                                         : "quantities: " + keys(kQuantities, false) + ", " +
                                               keys(kQuantities, true)),
             qa);
    }
    c.quantity = q->second;
    if (e.has("part")) {
      if (!isWrench(c.quantity)) {
        e.fail("part applies to wrench quantities only (" + keys(kQuantities, true) + ")", "part");
      }
      c.part_name = e.str("part");
      auto p = kParts.find(c.part_name);
      if (p == kParts.end()) {
        e.fail("unknown part \"" + c.part_name +
                   "\"; parts: total, pressure, viscous, drag, slamming, damping",
               "part");
      }
      c.part = p->second;
    }
  }

  switch (c.kind) {
    case Kind::VALUE: c.stat = Stat::VALUE; break;
    case Kind::RANGE: c.stat = Stat::RANGE; break;
    case Kind::MEAN: c.stat = Stat::MEAN; break;
    case Kind::STD: case Kind::SETTLED: c.stat = Stat::STD; break;
    case Kind::WRENCH: {
      std::string s = e.str("stat", e.has("at") ? "value" : "range");
      if (s == "value") c.stat = Stat::VALUE;
      else if (s == "range") c.stat = Stat::RANGE;
      else if (s == "mean") c.stat = Stat::MEAN;
      else if (s == "std") c.stat = Stat::STD;
      else e.fail("unknown stat \"" + s + "\"; stats: value, range, mean, std", "stat");
      break;
    }
    default: break;
  }

  bool timed = c.kind != Kind::FINITE && c.kind != Kind::ENERGY && c.stat == Stat::VALUE;
  if (timed) {
    if (e.has("from") || e.has("to")) e.fail("a value at a time takes 'at', not from/to", "from");
    parseAt(e, c, duration);
  } else {
    if (e.has("at")) e.fail("'at' needs stat=\"value\" (or kind=\"value\")", "at");
    parseWindow(e, c, duration);
  }

  if (c.kind == Kind::SETTLED) {
    c.hi = e.number("max");
    if (c.hi < 0) e.fail("max = " + num(c.hi) + " must be >= 0", "max");
  } else if (c.kind == Kind::FINITE) {
    c.maxqvel = e.number("maxqvel", 1000);
    if (c.maxqvel <= 0) e.fail("maxqvel = " + num(c.maxqvel) + " must be > 0", "maxqvel");
  } else {
    parseBounds(e, c);
  }
  return c;
}

// records the line where each mjbuoy entry is set, to refuse duplicates
class Seen {
 public:
  Seen(const std::string& file) : file_(file) {}
  void add(const std::string& name, int line) {
    auto it = lines_.find(name);
    if (it != lines_.end()) {
      throw Invalid(file_, line, name + " is set twice (first at line " +
                                     std::to_string(it->second) + ")");
    }
    lines_[name] = line;
  }

 private:
  const std::string& file_;
  std::map<std::string, int> lines_;
};

static void parseSea(const El& e, Scenario& s, Seen& seen) {
  s.sea_line = e.line();
  s.calm = e.flag("calm");
  for (const char* f : {"density", "level", "depth", "viscosity", "current"}) {
    if (!e.has(f)) continue;
    Entry en;
    en.name = std::string("mjbuoy.sea.") + f;
    en.line = e.line(f);
    if (std::string(f) == "depth" && e.str(f) == "deep") {
      en.remove = true;
    } else {
      std::vector<double> v = e.numbers(f, std::string(f) == "current" ? 2 : 1,
                                        std::string(f) == "current" ? "x and y, m/s" : "one number");
      for (size_t i = 0; i < v.size(); i++) en.data += (i ? " " : "") + exact(v[i]);
    }
    seen.add(en.name, en.line);
    s.entries.push_back(en);
  }
}

static void parseWave(const El& e, Scenario& s, Seen& seen) {
  Wave w;
  w.line = e.line();
  w.name = e.str("name");
  if (w.name.empty() || w.name.find_first_of(" \t\r\n") != std::string::npos) {
    e.fail("name=\"" + w.name + "\" must be a non-empty label without spaces", "name");
  }
  const double nan = std::nan("");
  w.amplitude = e.number("amplitude", nan);
  if (e.has("wavelength") && e.has("wavenumber")) {
    e.fail("give wavelength or wavenumber, not both", "wavenumber");
  }
  w.wavelength = e.number("wavelength", nan);
  if (e.has("wavenumber")) {
    double k = e.number("wavenumber");
    if (k <= 0) e.fail("wavenumber = " + num(k) + " must be > 0 [rad/m]", "wavenumber");
    w.wavelength = 2 * M_PI / k;
  }
  w.direction = e.number("direction", nan);
  w.phase = e.number("phase", nan);
  w.steepness = e.number("steepness", nan);
  seen.add("mjbuoy.wave." + w.name, w.line);
  s.waves.push_back(w);
}

static void parseEntry(const El& e, Scenario& s, Seen& seen) {
  Entry en;
  en.line = e.line();
  en.text = e.tag() == "text";
  en.name = e.str("name");
  if (en.name.rfind("mjbuoy.", 0) != 0 || en.name.size() <= 7) {
    e.fail("name=\"" + en.name + "\": only mjbuoy.* entries can be set (docs/mjcf.md)", "name");
  }
  en.remove = e.flag("remove");
  if (en.remove == e.has("data")) e.fail("give data or remove=\"true\" (exactly one)");
  if (!en.remove) {
    en.data = e.str("data");
    if (!en.text) e.parseNumbers("data", en.data);  // numbers only
  }
  seen.add(en.name, en.line);
  s.entries.push_back(en);
}

static void parseInit(const El& e, Scenario& s) {
  Init in;
  in.line = e.line();
  if (e.has("body") == e.has("joint")) e.fail("give body (a free body) or joint, exactly one");
  if (e.has("body")) {
    in.body = e.str("body");
    for (const char* a : {"qpos", "qvel"}) {
      if (e.has(a)) e.fail(std::string(a) + " belongs to <init joint=...>; a free body takes "
                           "pos, rpy, vel, angvel", a);
    }
    auto get = [&](const char* a, bool& has, double* out, const char* what) {
      if (!e.has(a)) return;
      has = true;
      std::vector<double> v = e.numbers(a, 3, what);
      for (int i = 0; i < 3; i++) out[i] = v[i];
    };
    get("pos", in.has_pos, in.pos, "x y z, m");
    get("rpy", in.has_rpy, in.rpy, "roll pitch yaw, deg");
    get("vel", in.has_vel, in.vel, "vx vy vz, m/s");
    get("angvel", in.has_angvel, in.angvel, "wx wy wz, deg/s");
    if (!(in.has_pos || in.has_rpy || in.has_vel || in.has_angvel)) {
      e.fail("sets nothing: give pos, rpy, vel and/or angvel");
    }
  } else {
    in.joint = e.str("joint");
    for (const char* a : {"pos", "rpy", "vel", "angvel"}) {
      if (e.has(a)) e.fail(std::string(a) + " belongs to <init body=...>; a joint takes qpos, qvel", a);
    }
    in.has_qpos = e.has("qpos");
    in.has_qvel = e.has("qvel");
    in.qpos = e.number("qpos", 0);
    in.qvel = e.number("qvel", 0);
    if (!in.has_qpos && !in.has_qvel) e.fail("sets nothing: give qpos and/or qvel");
  }
  s.inits.push_back(in);
}

static Scenario parseDoc(const tinyxml2::XMLDocument& doc, tinyxml2::XMLError err,
                        const std::string& file);

Scenario parseScenario(const std::string& file) {
  tinyxml2::XMLDocument doc;
  tinyxml2::XMLError err = doc.LoadFile(file.c_str());
  if (err == tinyxml2::XML_ERROR_FILE_NOT_FOUND || err == tinyxml2::XML_ERROR_FILE_COULD_NOT_BE_OPENED) {
    throw Invalid(file, 0, "cannot open the scenario file");
  }
  return parseDoc(doc, err, file);
}

Scenario parseScenarioText(const std::string& xml, const std::string& file) {
  tinyxml2::XMLDocument doc;
  tinyxml2::XMLError err = doc.Parse(xml.data(), xml.size());
  return parseDoc(doc, err, file);
}

Scenario parseScenarioDoc(const tinyxml2::XMLDocument& doc, const std::string& file) {
  return parseDoc(doc, doc.ErrorID(), file);
}

// the document as loaded or parsed; err: tinyxml2's status
static Scenario parseDoc(const tinyxml2::XMLDocument& doc, tinyxml2::XMLError err,
                        const std::string& file) {
  Scenario s;
  s.file = file;
  if (err != tinyxml2::XML_SUCCESS) {
    std::string why = doc.ErrorStr();
    // tinyxml2 says "Error=XML_... ErrorID=N (0x..) Line number=L: detail"
    size_t colon = why.find(": ");
    throw Invalid(file, doc.ErrorLineNum(),
                  std::string("malformed XML (") + doc.ErrorName() + ")" +
                      (colon != std::string::npos ? ": " + why.substr(colon + 2) : ""));
  }
  const XMLElement* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "scenario") {
    throw Invalid(file, root ? root->GetLineNum() : 0,
                  std::string("the root element must be <scenario>, not <") +
                      (root ? root->Name() : "") + ">");
  }
  El r(root, file, {"model", "duration", "backend", "timestep", "name"});
  s.line = r.line();
  fs::path dir = fs::path(file).parent_path();
  s.model_attr = r.str("model");
  fs::path mp = dir / s.model_attr;
  if (std::string why = pathcheck::whyNotAFile(mp); !why.empty()) {
    r.fail("model \"" + s.model_attr + "\" " + why + " (looked for " + mp.string() +
               "; the path is relative to the scenario file)",
           "model");
  }
  s.model = pathcheck::absolutePath(mp);
  s.duration = r.number("duration");
  if (s.duration <= 0) r.fail("duration = " + num(s.duration) + " must be > 0 [s]", "duration");
  s.timestep = r.number("timestep", 0);
  if (r.has("timestep") && s.timestep <= 0) {
    r.fail("timestep = " + num(s.timestep) + " must be > 0 [s]", "timestep");
  }
  s.backend = r.str("backend", "");
  if (r.has("backend") && s.backend.empty()) r.fail("backend is empty", "backend");
  s.name = r.str("name", fs::path(file).stem().string());

  Seen seen(file);
  for (const XMLNode* n = root->FirstChild(); n; n = n->NextSibling()) {
    if (n->ToComment() || n->ToDeclaration()) continue;
    if (const tinyxml2::XMLText* t = n->ToText()) {
      std::string v = t->Value();
      if (v.find_first_not_of(" \t\r\n") == std::string::npos) continue;
      throw Invalid(file, n->GetLineNum(), "unexpected text \"" + v + "\" in <scenario>");
    }
    const XMLElement* x = n->ToElement();
    if (!x) continue;
    std::string tag = x->Name();
    if (x->FirstChildElement()) {
      throw Invalid(file, x->FirstChildElement()->GetLineNum(),
                    "<" + tag + "> takes no child elements");
    }
    if (tag == "sea") {
      if (s.sea_line) {
        throw Invalid(file, x->GetLineNum(), "a second <sea> (the first is at line " +
                                                 std::to_string(s.sea_line) + ")");
      }
      parseSea(El(x, file, {"density", "level", "depth", "viscosity", "current", "calm"}), s, seen);
    } else if (tag == "wave") {
      parseWave(El(x, file, {"name", "amplitude", "wavelength", "wavenumber", "direction",
                             "phase", "steepness"}), s, seen);
    } else if (tag == "numeric" || tag == "text") {
      parseEntry(El(x, file, {"name", "data", "remove"}), s, seen);
    } else if (tag == "mesh") {
      El e(x, file, {"name", "file"});
      MeshFile mf;
      mf.line = e.line();
      mf.name = e.str("name");
      fs::path p = dir / e.str("file");
      if (std::string why = pathcheck::whyNotAFile(p); !why.empty()) {
        e.fail("mesh file \"" + e.str("file") + "\" " + why + " (looked for " + p.string() +
                   "; the path is relative to the scenario file)",
               "file");
      }
      mf.file = pathcheck::absolutePath(p);
      s.meshes.push_back(mf);
    } else if (tag == "init") {
      parseInit(El(x, file, {"body", "joint", "pos", "rpy", "vel", "angvel", "qpos", "qvel"}), s);
    } else if (tag == "check") {
      s.checks.push_back(parseCheck(x, file, s.duration));
    } else {
      throw Invalid(file, x->GetLineNum(),
                    "unknown element <" + tag +
                        ">; a <scenario> holds sea, wave, numeric, text, mesh, init and check");
    }
  }
  if (s.checks.empty()) throw Invalid(file, s.line, "<scenario> has no <check>: nothing to test");
  return s;
}

}  // namespace scn
