// mjbuoy-sweep: read a sweep file, expand its cases and make each case's
// scenario (docs/sweeps.md)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <tinyxml2.h>

#include "modelload.h"
#include "mjbuoy_version.h"
#include "pathcheck.h"
#include "scenario_xml.h"
#include "sweep.h"

namespace swp {

namespace fs = std::filesystem;
using scn::El;
using scn::Invalid;
using scn::num;
using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

// elem[key=value]@attr, elem@attr or @attr
static void parsePath(const El& e, Axis& a) {
  static const std::regex re(R"(^([A-Za-z_][\w-]*)?(?:\[([A-Za-z_][\w-]*)=([^\]]+)\])?@([A-Za-z_][\w-]*)$)");
  std::smatch m;
  if (!std::regex_match(a.path, m, re) || (m[2].matched && !m[1].matched)) {
    e.fail("set=\"" + a.path + "\" is not a scenario field path: write ELEMENT@ATTRIBUTE, "
           "ELEMENT[KEY=VALUE]@ATTRIBUTE or @ATTRIBUTE (of <scenario>), e.g. "
           "wave[name=swell]@wavelength", "set");
  }
  a.elem = m[1].str() == "scenario" ? "" : m[1].str();
  a.key = m[2];
  a.keyval = m[3];
  a.attr = m[4];
}

// the values of an axis: a list, or a range with step or count
static void parseValues(const El& e, Axis& a) {
  bool list = e.has("values"), range = e.has("from") || e.has("to");
  if (list == range) e.fail("give values=\"...\" or a range from/to with step or count (exactly one)");
  if (list) {
    std::string v = e.str("values");
    char sep = v.find(';') != std::string::npos ? ';' : ' ';
    std::string tok;
    std::istringstream in(v);
    while (std::getline(in, tok, sep)) {
      size_t b = tok.find_first_not_of(" \t\r\n"), f = tok.find_last_not_of(" \t\r\n");
      if (b == std::string::npos) {
        if (sep == ';') e.fail("values=\"" + v + "\" has an empty item", "values");
        continue;
      }
      a.labels.push_back(tok.substr(b, f - b + 1));
    }
    if (a.labels.empty()) e.fail("values is empty", "values");
    for (const char* x : {"step", "count", "scale"}) {
      if (e.has(x)) e.fail(std::string(x) + " belongs to a range (from/to); values is a list", x);
    }
    return;
  }
  double from = e.number("from"), to = e.number("to");
  std::string scale = e.str("scale", "linear");
  if (scale != "linear" && scale != "log") e.fail("scale=\"" + scale + "\" must be linear or log", "scale");
  if (e.has("step") == e.has("count")) e.fail("a range needs step or count (exactly one)");
  bool log = scale == "log";
  if (log && (from <= 0 || to <= 0)) {
    e.fail("a log range needs from and to > 0 (from = " + num(from) + ", to = " + num(to) + ")", "from");
  }
  std::vector<double> v;
  if (e.has("count")) {
    double c = e.number("count");
    if (c < 1 || c != std::floor(c) || c > 1e6) e.fail("count = " + num(c) + " must be a whole number 1 .. 1e6", "count");
    int n = (int)c;
    if (n == 1 && from != to) e.fail("count = 1 needs from = to", "count");
    for (int i = 0; i < n; i++) {
      double f = n == 1 ? 0 : (double)i / (n - 1);
      v.push_back(i == n - 1 ? to : log ? from * std::pow(to / from, f) : from + f * (to - from));
    }
  } else {
    double st = e.number("step");
    // a log range steps by a factor
    if (log ? !(st > 0 && st != 1) : st == 0) {
      e.fail("step = " + num(st) + (log ? " must be a factor > 0 and != 1" : " must not be 0"), "step");
    }
    double span = log ? std::log(to / from) / std::log(st) : (to - from) / st;
    if (span < -1e-9) e.fail("step = " + num(st) + " goes away from to = " + num(to), "step");
    long n = (long)std::floor(span + 1e-9) + 1;
    if (n > 1000000) e.fail("the range has " + std::to_string(n) + " values; at most 1e6", "step");
    for (long i = 0; i < n; i++) v.push_back(log ? from * std::pow(st, (double)i) : from + i * st);
  }
  for (double x : v) a.labels.push_back(scn::exact(x));
}

static Axis parseAxis(const XMLElement* x, const std::string& file) {
  El e(x, file, {"name", "set", "values", "from", "to", "step", "count", "scale", "format"});
  Axis a;
  a.line = e.line();
  a.name = e.str("name");
  if (!std::regex_match(a.name, std::regex(R"(^[A-Za-z][A-Za-z0-9_]*$)"))) {
    e.fail("name=\"" + a.name + "\" must be a letter then letters, digits or _ (it is part of "
           "case ids and CSV columns)", "name");
  }
  a.path = e.str("set");
  parsePath(e, a);
  parseValues(e, a);
  std::string fmt = e.str("format", "{}");
  if (fmt.find("{}") == std::string::npos) e.fail("format=\"" + fmt + "\" has no {} for the value", "format");
  for (const std::string& l : a.labels) {
    std::string t = fmt;
    t.replace(t.find("{}"), 2, l);
    a.texts.push_back(t);
  }
  return a;
}

static Stat parseStat(const XMLElement* x, const std::string& file) {
  static const std::map<std::string, StatKind> kinds = {
      {"mean", StatKind::MEAN}, {"std", StatKind::STD},       {"significant", StatKind::SIG},
      {"max", StatKind::MAX},   {"min", StatKind::MIN},       {"rms", StatKind::RMS},
      {"tz", StatKind::TZ},     {"amplitude", StatKind::AMP}, {"phase", StatKind::PHASE},
      {"rao", StatKind::RAO},   {"period", StatKind::PERIOD}};
  El e(x, file, {"name", "stat", "body", "quantity", "part", "sensor", "index", "from", "to",
                       "period", "wave"});
  Stat s;
  s.line = e.line();
  s.name = e.str("name");
  if (!std::regex_match(s.name, std::regex(R"(^[A-Za-z][A-Za-z0-9_]*$)"))) {
    e.fail("name=\"" + s.name + "\" must be a letter then letters, digits or _", "name");
  }
  s.kind_name = e.str("stat");
  auto k = kinds.find(s.kind_name);
  if (k == kinds.end()) {
    e.fail("unknown stat \"" + s.kind_name + "\"; stats: mean, std, significant, max, min, rms, "
           "tz, amplitude, phase, rao, period", "stat");
  }
  s.kind = k->second;
  bool freq = s.kind == StatKind::AMP || s.kind == StatKind::PHASE || s.kind == StatKind::RAO ||
              s.kind == StatKind::PERIOD;
  if (freq) {
    if (e.has("period") == e.has("wave")) {
      e.fail("stat=\"" + s.kind_name + "\" needs the frequency: period=\"T\" [s] or wave=\"NAME\" "
             "(the wave mjbuoy.wave.NAME of the case), exactly one");
    }
    s.period = e.number("period", 0);
    if (e.has("period") && s.period <= 0) e.fail("period = " + num(s.period) + " must be > 0 [s]", "period");
    s.wave = e.str("wave", "");
  } else {
    for (const char* a : {"period", "wave"}) {
      if (e.has(a)) e.fail(std::string(a) + " applies to amplitude, phase, rao and period only", a);
    }
  }
  if (e.has("sensor")) {
    // any MuJoCo sensor, as in scenario checks (resolved in sweep_stats.cc)
    if (s.kind == StatKind::PERIOD || s.kind == StatKind::PHASE || s.kind == StatKind::RAO) {
      e.fail("stat=\"" + s.kind_name + "\" needs a body (the wave at it); sensor applies to the "
             "other stats", "sensor");
    }
    for (const char* a : {"body", "quantity", "part"}) {
      if (e.has(a)) e.fail(std::string("give sensor or body and quantity, not both (") + a + ")", a);
    }
    s.sensor = e.str("sensor");
    s.quantity = scn::Quantity::SENSOR;
    s.quantity_name = "sensor";
    double i = e.number("index", 0);
    if (i < 0 || i != std::floor(i) || i > 1e6) {
      e.fail("index = " + num(i) + " must be a whole number >= 0", "index");
    }
    s.index = (int)i;
  } else if (e.has("index")) {
    e.fail("index applies to sensor=\"NAME\" only", "index");
  } else if (s.kind != StatKind::PERIOD) {
    s.body = e.str("body");
    s.quantity_name = e.str("quantity");
    if (!scn::quantityByName(s.quantity_name, &s.quantity)) {
      e.fail("unknown quantity \"" + s.quantity_name + "\" (the quantities of scenario checks, "
             "docs/scenarios.md)", "quantity");
    }
    if (e.has("part")) {
      s.part_name = e.str("part");
      if (s.quantity < scn::Quantity::FX || !scn::partByName(s.part_name, &s.part)) {
        e.fail("part=\"" + s.part_name + "\": parts (pressure, viscous, drag, slamming, damping, "
               "total) apply to wrench quantities only", "part");
      }
    }
  }
  s.from = e.number("from", 0);
  s.has_to = e.has("to");
  s.to = e.number("to", 0);
  if (s.from < 0) e.fail("from = " + num(s.from) + " must be >= 0", "from");
  if (s.has_to && s.to <= s.from) e.fail("the window is empty: from = " + num(s.from) + " >= to = " + num(s.to), "to");
  return s;
}

static Plot parsePlot(const El& e) {
  Plot p;
  p.line = e.line();
  p.y = e.str("y");
  p.x = e.str("x");
  p.curves = e.str("curves", "");
  p.title = e.str("title", "");
  p.logx = e.flag("logx");
  p.logy = e.flag("logy");
  return p;
}

static void addDim(Sweep& s, Dim d, std::set<std::string>& names, const std::string& file) {
  for (int i : d.axes) {
    if (!names.insert(s.axes[i].name).second) {
      throw Invalid(file, s.axes[i].line, "a second axis named \"" + s.axes[i].name + "\"");
    }
  }
  s.ncases *= d.size;
  if (s.ncases > 100000000) throw Invalid(file, d.line, "more than 1e8 cases");
  s.dims.push_back(d);
}

static void parseZip(const XMLElement* x, const std::string& file, Sweep& s,
                     std::set<std::string>& names) {
  El e(x, file, {"name"});
  Dim d;
  d.line = e.line();
  d.name = e.str("name");
  if (!std::regex_match(d.name, std::regex(R"(^[A-Za-z][A-Za-z0-9_]*$)"))) {
    e.fail("name=\"" + d.name + "\" must be a letter then letters, digits or _", "name");
  }
  if (!names.insert(d.name).second) e.fail("a second axis or zip named \"" + d.name + "\"", "name");
  for (const XMLElement* c = x->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (std::string(c->Name()) != "axis") {
      throw Invalid(file, c->GetLineNum(), "<zip> holds <axis> elements only, not <" + std::string(c->Name()) + ">");
    }
    s.axes.push_back(parseAxis(c, file));
    const Axis& a = s.axes.back();
    if (d.axes.size() && (int)a.labels.size() != d.size) {
      throw Invalid(file, a.line, "<zip name=\"" + d.name + "\">: axis \"" + a.name + "\" has " +
                                      std::to_string(a.labels.size()) + " values, the first axis " +
                                      std::to_string(d.size) + " (zipped axes go together, so they need as many)");
    }
    d.size = (int)a.labels.size();
    d.axes.push_back((int)s.axes.size() - 1);
  }
  if (d.axes.empty()) e.fail("<zip> has no <axis>");
  names.erase(d.name);
  addDim(s, d, names, file);
  names.insert(d.name);
}

// checks the plots' names against the axes and statistics
static void checkPlots(const Sweep& s) {
  auto isAxis = [&](const std::string& n) {
    for (const Axis& a : s.axes) if (a.name == n) return true;
    return false;
  };
  auto isStat = [&](const std::string& n) {
    for (const Stat& t : s.stats) if (t.name == n) return true;
    return false;
  };
  for (const Plot& p : s.plots) {
    if (!isStat(p.y)) throw Invalid(s.given, p.line, "<plot>: y=\"" + p.y + "\" is not a <stat> name");
    if (!isStat(p.x) && !isAxis(p.x)) throw Invalid(s.given, p.line, "<plot>: x=\"" + p.x + "\" is not an axis or <stat> name");
    if (!p.curves.empty() && !isAxis(p.curves)) throw Invalid(s.given, p.line, "<plot>: curves=\"" + p.curves + "\" is not an axis name");
  }
}

static std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Sweep parseSweep(const std::string& path) {
  Sweep s;
  s.file = pathcheck::absolutePath(path);
  s.given = path;
  const std::string& file = path;
  tinyxml2::XMLDocument doc;
  tinyxml2::XMLError err = doc.LoadFile(path.c_str());
  if (err == tinyxml2::XML_ERROR_FILE_NOT_FOUND || err == tinyxml2::XML_ERROR_FILE_COULD_NOT_BE_OPENED) {
    throw Invalid(file, 0, "cannot open the sweep file");
  }
  if (err != tinyxml2::XML_SUCCESS) {
    throw Invalid(file, doc.ErrorLineNum(), std::string("malformed XML (") + doc.ErrorName() + ")");
  }
  const XMLElement* root = doc.RootElement();
  if (!root || std::string(root->Name()) != "sweep") {
    throw Invalid(file, root ? root->GetLineNum() : 0, "the root element must be <sweep>");
  }
  El r(root, file, {"scenario", "name"});
  s.line = r.line();
  s.name = r.str("name", fs::path(path).stem().string());
  // the name goes into job names, script comments and file names: no
  // spaces, newlines or shell characters
  if (!std::regex_match(s.name, std::regex(R"(^[A-Za-z0-9][A-Za-z0-9_.+-]{0,99}$)"))) {
    std::string shown;
    for (char c : s.name) shown += (unsigned char)c < 32 ? std::string("\\x") + "0123456789abcdef"[c >> 4] + "0123456789abcdef"[c & 15] : std::string(1, c);
    r.fail("name=\"" + shown + "\"" + (root->Attribute("name") ? "" : " (the file's stem)") +
           " must be a letter or digit then up to 99 letters, digits or _.+- (it names the Slurm "
           "job and the results); give <sweep name=\"...\">", "name");
  }
  fs::path bp = fs::path(path).parent_path() / r.str("scenario");
  s.base_line = r.line("scenario");
  if (std::string why = pathcheck::whyNotAFile(bp); !why.empty()) {
    r.fail("scenario \"" + r.str("scenario") + "\" " + why + " (looked for " + bp.string() +
           "; the path is relative to the sweep file)", "scenario");
  }
  s.base = pathcheck::absolutePath(bp);
  s.base_text = slurp(s.base);
  scn::parseScenario(s.base);  // the base itself must be valid

  std::set<std::string> names;
  for (const XMLNode* n = root->FirstChild(); n; n = n->NextSibling()) {
    if (n->ToComment() || n->ToDeclaration()) continue;
    if (const tinyxml2::XMLText* t = n->ToText()) {
      std::string v = t->Value();
      if (v.find_first_not_of(" \t\r\n") == std::string::npos) continue;
      throw Invalid(file, n->GetLineNum(), "unexpected text \"" + v + "\" in <sweep>");
    }
    const XMLElement* x = n->ToElement();
    if (!x) continue;
    std::string tag = x->Name();
    if (tag != "zip" && x->FirstChildElement()) {
      throw Invalid(file, x->FirstChildElement()->GetLineNum(), "<" + tag + "> takes no child elements");
    }
    if (tag == "axis") {
      s.axes.push_back(parseAxis(x, file));
      Dim d;
      d.name = s.axes.back().name;
      d.line = s.axes.back().line;
      d.size = (int)s.axes.back().labels.size();
      d.axes = {(int)s.axes.size() - 1};
      addDim(s, d, names, file);
    } else if (tag == "zip") {
      parseZip(x, file, s, names);
    } else if (tag == "stat") {
      s.stats.push_back(parseStat(x, file));
      for (size_t i = 0; i + 1 < s.stats.size(); i++) {
        if (s.stats[i].name == s.stats.back().name) {
          throw Invalid(file, x->GetLineNum(), "a second <stat> named \"" + s.stats[i].name + "\"");
        }
      }
      if (names.count(s.stats.back().name)) {
        throw Invalid(file, x->GetLineNum(), "<stat> \"" + s.stats.back().name + "\" has an axis's name");
      }
    } else if (tag == "plot") {
      s.plots.push_back(parsePlot(El(x, file, {"y", "x", "curves", "title", "logx", "logy"})));
    } else {
      throw Invalid(file, x->GetLineNum(), "unknown element <" + tag + ">; a <sweep> holds axis, zip, stat and plot");
    }
  }
  checkPlots(s);
  return s;
}

Case caseAt(const Sweep& s, long index) {
  Case c;
  c.index = index;
  c.at.assign(s.axes.size(), 0);
  long rest = index;
  std::vector<int> di(s.dims.size());
  for (int k = (int)s.dims.size() - 1; k >= 0; k--) {
    di[k] = (int)(rest % s.dims[k].size);
    rest /= s.dims[k].size;
  }
  for (size_t k = 0; k < s.dims.size(); k++) {
    int width = (int)std::to_string(std::max(s.dims[k].size - 1, 0)).size();
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%0*d", width, di[k]);
    c.id += (k ? "." : "") + s.dims[k].name + "-" + buf;
    for (int a : s.dims[k].axes) c.at[a] = di[k];
  }
  if (c.id.empty()) c.id = "case";
  return c;
}

// the element an axis sets, created when missing
static XMLElement* target(tinyxml2::XMLDocument& doc, const Sweep& s, const Axis& a) {
  XMLElement* root = doc.RootElement();
  if (a.elem.empty()) return root;
  std::vector<XMLElement*> found;
  for (XMLElement* e = root->FirstChildElement(a.elem.c_str()); e; e = e->NextSiblingElement(a.elem.c_str())) {
    const char* v = a.key.empty() ? nullptr : e->Attribute(a.key.c_str());
    if (a.key.empty() || (v && a.keyval == v)) found.push_back(e);
  }
  if (found.size() > 1) {
    throw Invalid(s.given, a.line, "set=\"" + a.path + "\" matches " + std::to_string(found.size()) +
                                      " <" + a.elem + "> elements of " + s.base +
                                      "; pick one with " + a.elem + "[name=...]@" + a.attr);
  }
  if (found.size() == 1) return found[0];
  XMLElement* e = doc.NewElement(a.elem.c_str());
  if (!a.key.empty()) e->SetAttribute(a.key.c_str(), a.keyval.c_str());
  root->InsertEndChild(e);
  return e;
}

static std::string describe(const Sweep& s, const Case& c) {
  std::string d = "case " + c.id;
  for (size_t i = 0; i < s.axes.size(); i++) {
    d += (i ? ", " : " (") + s.axes[i].name + " = " + s.axes[i].labels[c.at[i]];
  }
  return d + (s.axes.empty() ? "" : ")");
}

scn::Scenario caseScenario(const Sweep& s, const Case& c, std::string* xml) {
  tinyxml2::XMLDocument doc;
  doc.Parse(s.base_text.data(), s.base_text.size());
  if (doc.Error() || !doc.RootElement()) return scn::parseScenario(s.base);  // throws
  std::vector<int> lines(s.axes.size());
  for (size_t i = 0; i < s.axes.size(); i++) {
    const Axis& a = s.axes[i];
    XMLElement* e = target(doc, s, a);
    lines[i] = e->GetLineNum();
    e->SetAttribute(a.attr.c_str(), a.texts[c.at[i]].c_str());
  }
  if (xml) {
    tinyxml2::XMLPrinter p;
    doc.Print(&p);
    *xml = p.CStr();
  }
  try {
    return scn::parseScenarioDoc(doc, s.base);
  } catch (const Invalid& e) {
    // the axis whose element the error is about, else the sweep's root
    std::string w = e.what();
    int line = s.line;
    for (size_t i = 0; i < s.axes.size(); i++) {
      std::string at = s.base + ":" + std::to_string(lines[i]) + ":";
      if (w.rfind(at, 0) == 0 || lines[i] == 0) { line = s.axes[i].line; break; }
    }
    throw Invalid(s.given, line, describe(s, c) + ": " + w);
  }
}

// FNV-1a, 64 bit, continued from h
static unsigned long long fnv(const std::string& bytes, unsigned long long h) {
  for (unsigned char ch : bytes) { h ^= ch; h *= 1099511628211ull; }
  return h;
}

// the content of a file a case reads, as a hash (hex): its bytes, or
// "missing". Each file is read once per process (a run hashes every case)
static std::string fileDigest(const std::string& path) {
  static std::map<std::string, std::string> memo;
  auto it = memo.find(path);
  if (it != memo.end()) return it->second;
  std::string why = pathcheck::whyNotAFile(path), d = "missing";
  if (why.empty()) {
    std::ifstream in(path, std::ios::binary);
    std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    char buf[20];
    std::snprintf(buf, sizeof(buf), "%016llx", fnv(b, 1469598103934665603ull));
    d = buf;
  }
  return memo[path] = d;
}

std::vector<std::string> caseFiles(const scn::Scenario& sc) {
  std::vector<std::string> f = mjbtool::modelFiles(sc.model);
  for (const scn::MeshFile& m : sc.meshes) f.push_back(m.file);
  return f;
}

std::string caseHash(const Sweep& s, const std::string& xml, const std::vector<std::string>& files) {
  // what the case reads besides its scenario text: the mjbuoy that runs it,
  // and the content of the model, its includes and meshes
  std::string all = xml + "\nmjbuoy " + MJBUOY_VERSION_STRING;
  for (const std::string& f : files) all += "\n" + f + " " + fileDigest(f);
  for (const Stat& t : s.stats) {
    all += "\n" + t.name + " " + t.kind_name + " " + t.body + " " + t.quantity_name + " " +
           t.part_name + " " + scn::exact(t.from) + " " + (t.has_to ? scn::exact(t.to) : "end") +
           " " + scn::exact(t.period) + " " + t.wave;
  }
  unsigned long long h = fnv(all, 1469598103934665603ull);
  char buf[20];
  std::snprintf(buf, sizeof(buf), "%016llx", h);
  return buf;
}

std::string resultPath(const std::string& dir, const std::string& id) {
  return (fs::path(dir) / "cases" / (id + ".json")).string();
}

}  // namespace swp
