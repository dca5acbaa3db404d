// radconfig: parse mjbuoy.radiation, mjbuoy.radiation.{lid, diffraction, drift, entry, cache,
// memorymodel, group, omega, refine, panels, memory, rolldamping, rollzeta},
// mjbuoy.radiation.body.<body> and mjbuoy.radiation.{file, fileorigin, ulen}.<body>
// (schema: docs/mjcf.md)
#include "api/radconfig.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

#include "api/config.h"

namespace mjb {

bool RadConfig::radiates(int body) const {
  if (std::count(offBody.begin(), offBody.end(), body)) return false;
  return on || std::count(onBody.begin(), onBody.end(), body);
}

// whether the rigid group of root can move: not welded to the world, not
// mocap, some joint between it and the world (added mass needs a dof)
bool groupMoves(const mjModel* m, int root) {
  if (root <= 0 || m->body_mocapid[root] >= 0) return false;
  for (int b = root; b > 0; b = m->body_parentid[b])
    if (m->body_dofnum[b]) return true;
  return false;
}

bool RadConfig::groupRadiates(const mjModel* m, const std::vector<int>& hullBody,
                              int root) const {
  if (!groupMoves(m, root)) return false;
  // on by default for every group that can move, free or on joints: a
  // jointed hull radiates about its equilibrium along its joints
  // (radattach.cc, jointPose; docs/mjcf.md, "Radiation")
  bool yes = on, no = false;
  for (int hb : hullBody) {
    if (m->body_weldid[hb] != root) continue;
    for (int b : {hb, root}) {
      yes = yes || std::count(onBody.begin(), onBody.end(), b);
      no = no || std::count(offBody.begin(), offBody.end(), b);
    }
  }
  return yes && !no;
}

bool isRadEntry(const char* key) {
  return !std::strcmp(key, "radiation") || !std::strncmp(key, "radiation.", 10);
}

// "on" / "off" of a text entry
static std::string onOff(const char* name, const char* text, bool* v) {
  if (!std::strcmp(text, "on")) {
    *v = true;
  } else if (!std::strcmp(text, "off")) {
    *v = false;
  } else {
    return "mjbuoy: " + tag("text", name) + " data = \"" + text +
           "\" is not a switch; give \"on\" or \"off\", e.g. data=\"on\"";
  }
  return "";
}

static std::string checkRad(const char* name, const char* what, double v, double lo, double hi,
                            bool whole, const char* unit, const char* example);

// mjbuoy.radiation.file.<body>: a coefficient file; turns the body's radiation on
static std::string parseFile(const mjModel* m, const char* name, const char* text, RadConfig* r) {
  const char* body = name + 22;
  int b = mj_name2id(m, mjOBJ_BODY, body);
  if (b < 0) {
    return "mjbuoy: " + tag("text", name) + " refers to body \"" + body + "\", which does not "
           "exist; give the name of a body that carries hulls";
  }
  if (!*text) {
    return "mjbuoy: " + tag("text", name) + " is empty; give a coefficient file of WAMIT (.1), "
           "Capytaine (.nc) or BEMIO (.h5), e.g. data=\"/data/spar.h5\" (docs/interchange.md)";
  }
  RadConfig::File f;
  f.body = b;
  f.path = text;
  r->file.push_back(f);
  r->onBody.push_back(b);
  return "";
}

// mjbuoy.radiation.fileorigin.<body> (3 values, m) and
// mjbuoy.radiation.ulen.<body> (WAMIT's ULEN, m) of a body with a file
static std::string parseFileNumeric(const mjModel* m, const char* name, int n, const mjtNum* v,
                                    RadConfig* r) {
  const bool ulen = !std::strncmp(name + 7, "radiation.ulen.", 15);
  const char* body = name + 7 + (ulen ? 15 : 21);
  int b = mj_name2id(m, mjOBJ_BODY, body);
  RadConfig::File* f = nullptr;
  for (RadConfig::File& x : r->file) if (x.body == b && b >= 0) f = &x;
  if (!f) {
    return "mjbuoy: " + tag("numeric", name) + " needs a coefficient file for body \"" + body +
           "\"; add <text name=\"mjbuoy.radiation.file." + body + "\" data=\"...\"/> or remove it";
  }
  const char* ex = ulen ? "1" : "0 0 0";
  if (n != (ulen ? 1 : 3)) {
    return "mjbuoy: " + tag("numeric", name) + " has " + std::to_string(n) + " value(s), expected " +
           (ulen ? "1 (WAMIT's length scale ULEN, m)" : "3 (the file's origin in the body frame, m)") +
           ", e.g. data=\"" + ex + "\"";
  }
  if (ulen) {
    std::string e = checkRad(name, "value", v[0], 1e-6, 1e6, false, "m", ex);
    if (e.empty()) f->ulen = v[0];
    return e;
  }
  for (int k = 0; k < 3; k++) {
    std::string e = checkRad(name, "value", v[k], -1e6, 1e6, false, "m", ex);
    if (!e.empty()) return e;
    f->origin[k] = v[k];
  }
  return "";
}

// mjbuoy.radiation.group: "a b c; d e", groups split at ';', names at
// white space; the names are checked against the model at attach
static std::string parseGroup(const char* name, const char* text, RadConfig* r) {
  std::vector<std::string> g;
  std::string w;
  for (const char* c = text;; c++) {
    if (*c && *c != ';' && !std::isspace((unsigned char)*c)) {
      w += *c;
      continue;
    }
    if (!w.empty()) g.push_back(w), w.clear();
    if (*c && *c != ';') continue;
    if (g.empty()) {
      return "mjbuoy: " + tag("text", name) + " data = \"" + text + "\" has an empty group; "
             "give body names separated by spaces, groups by ';', e.g. data=\"float1 float2; "
             "float3 float4\"";
    }
    r->group.push_back(g), g.clear();
    if (!*c) break;
  }
  return "";
}

static std::string parseText(const mjModel* m, const char* name, const char* text, RadConfig* r) {
  const char* key = name + 7;
  if (!std::strcmp(key, "radiation.cache")) {
    if (!*text) {
      return "mjbuoy: " + tag("text", name) + " is empty; give a directory for the panel "
             "solver's cache files or \"off\", e.g. data=\"/tmp/mjbuoy-cache\"";
    }
    r->cache = text;
    return "";
  }
  if (!std::strcmp(key, "radiation.memorymodel")) {
    if (std::strcmp(text, "statespace") && std::strcmp(text, "convolution")) {
      return "mjbuoy: " + tag("text", name) + " data = \"" + text + "\" is not a memory model; "
             "give \"statespace\" or \"convolution\", e.g. data=\"convolution\"";
    }
    r->conv = !std::strcmp(text, "convolution");
    r->ssAsked = !r->conv;
    return "";
  }
  if (!std::strcmp(key, "radiation.speed")) {
    const char* kind[3] = {"off", "auto", "on"};
    for (int k = 0; k < 3; k++) {
      if (!std::strcmp(text, kind[k])) {
        r->speed = k;
        return "";
      }
    }
    return "mjbuoy: " + tag("text", name) + " data = \"" + text + "\" is not a forward-speed "
           "setting; give \"auto\" (hulls slender along x), \"on\" (every radiating body) or "
           "\"off\", e.g. data=\"auto\"";
  }
  if (!std::strncmp(key, "radiation.file.", 15)) return parseFile(m, name, text, r);
  if (!std::strcmp(key, "radiation.group")) return parseGroup(name, text, r);
  bool v = false;
  std::string e = onOff(name, text, &v);
  if (!e.empty()) return e;
  if (!std::strcmp(key, "radiation")) {
    r->on = v;
    r->given = true;
  } else if (!std::strcmp(key, "radiation.lid")) {
    r->lid = v;
  } else if (!std::strcmp(key, "radiation.diffraction")) {
    r->diffraction = v;
  } else if (!std::strcmp(key, "radiation.drift")) {
    r->drift = v;
  } else if (!std::strcmp(key, "radiation.entry")) {
    r->entry = v;
  } else if (!std::strncmp(key, "radiation.body.", 15)) {
    int b = mj_name2id(m, mjOBJ_BODY, key + 15);
    if (b < 0) {
      return "mjbuoy: " + tag("text", name) + " refers to body \"" + (key + 15) +
             "\", which does not exist; give the name of a body that carries hulls";
    }
    (v ? r->onBody : r->offBody).push_back(b);
  } else {
    return "mjbuoy: unknown entry " + tag("text", name) +
           "; radiation text entries are mjbuoy.radiation, mjbuoy.radiation.lid, "
           "mjbuoy.radiation.diffraction, mjbuoy.radiation.drift, mjbuoy.radiation.entry, "
           "mjbuoy.radiation.speed, "
           "mjbuoy.radiation.cache, mjbuoy.radiation.memorymodel, mjbuoy.radiation.group, "
           "mjbuoy.radiation.body.<body> "
           "and mjbuoy.radiation.file.<body> (see docs/mjcf.md)";
  }
  return "";
}

// one numeric value: whole or not, range [lo, hi]
static std::string checkRad(const char* name, const char* what, double v, double lo, double hi,
                            bool whole, const char* unit, const char* example) {
  if (!std::isfinite(v) || v < lo || v > hi || (whole && v != std::floor(v))) {
    return "mjbuoy: " + tag("numeric", name) + " " + what + " = " + fmt(v) + " is out of range: " +
           "it must be " + (whole ? "a whole number " : "") + ">= " + fmt(lo) + " and <= " +
           fmt(hi) + " [" + unit + "]; fix its data attribute, e.g. data=\"" + example + "\"";
  }
  return "";
}

// mjbuoy.radiation.rolldamping: linear and quadratic viscous roll damping,
// each 0 to 1e15 (the hull damping's angular bound, docs/mjcf.md section 2)
static std::string parseRollDamping(const char* name, int n, const mjtNum* v, RadConfig* r) {
  const char* ex = "2.7 0";
  if (n != 2) {
    return "mjbuoy: " + tag("numeric", name) + " has " + std::to_string(n) + " value(s), expected " +
           "2 (linear N m s/rad, quadratic N m s^2/rad^2), e.g. data=\"" + ex + "\"";
  }
  std::string e = checkRad(name, "value 1 (linear)", v[0], 0, 1e15, false, "N m s/rad", ex);
  if (e.empty()) e = checkRad(name, "value 2 (quadratic)", v[1], 0, 1e15, false, "N m s^2/rad^2", ex);
  if (e.empty()) {
    r->roll[0] = v[0];
    r->roll[1] = v[1];
    r->rollGiven = true;
  }
  return e;
}

// mjbuoy.radiation.rollzeta: a fraction of critical roll damping, 0 to 2
// (twice critical is far beyond any ship's: a typo, not a hull)
static std::string parseRollZeta(const char* name, int n, const mjtNum* v, RadConfig* r) {
  const char* ex = "0.1";  // the default, kRollZeta
  if (n != 1) {
    return "mjbuoy: " + tag("numeric", name) + " has " + std::to_string(n) + " value(s), expected " +
           "1 (fraction of critical roll damping), e.g. data=\"" + ex + "\"";
  }
  std::string e = checkRad(name, "value", v[0], 0, 2, false, "fraction of critical", ex);
  if (e.empty()) {
    r->zeta = v[0];
    r->zetaGiven = true;
  }
  return e;
}

static std::string parseNumeric(const mjModel* m, int i, RadConfig* r) {
  const char* name = m->names + m->name_numericadr[i];
  const char* key = name + 7;
  int n = m->numeric_size[i];
  const mjtNum* v = m->numeric_data + m->numeric_adr[i];
  if (!std::strcmp(key, "radiation.rolldamping")) return parseRollDamping(name, n, v, r);
  if (!std::strcmp(key, "radiation.rollzeta")) return parseRollZeta(name, n, v, r);
  if (!std::strncmp(key, "radiation.ulen.", 15) || !std::strncmp(key, "radiation.fileorigin.", 21))
    return parseFileNumeric(m, name, n, v, r);
  struct F { const char* key; int n; const char* unit; const char* ex; };
  static const F kF[] = {{"radiation.omega", 3, "rad/s, rad/s, count", "0.5 6 20"},
                         {"radiation.refine", 1, "refine level", "0"},
                         {"radiation.panels", 1, "wet panels, 0 = the hull's own", "400"},
                         {"radiation.memory", 1, "s, 0 = automatic", "0"}};
  const F* f = nullptr;
  for (const F& c : kF) if (!std::strcmp(key, c.key)) f = &c;
  if (!f) {
    return "mjbuoy: unknown entry " + tag("numeric", name) +
           "; radiation numeric entries are mjbuoy.radiation.omega, mjbuoy.radiation.refine, "
           "mjbuoy.radiation.panels, mjbuoy.radiation.memory, mjbuoy.radiation.rolldamping, "
           "mjbuoy.radiation.rollzeta, mjbuoy.radiation.fileorigin.<body> and "
           "mjbuoy.radiation.ulen.<body> (see docs/mjcf.md)";
  }
  if (n != f->n) {
    return "mjbuoy: " + tag("numeric", name) + " has " + std::to_string(n) + " value(s), expected " +
           std::to_string(f->n) + " (" + f->unit + "), e.g. data=\"" + f->ex + "\"";
  }
  std::string e;
  if (f == kF) {
    // up to 10^4 rad/s (a 0.1 mm ripple); count 2..200 (each costs a solve)
    e = checkRad(name, "value 1 (lowest omega)", v[0], 1e-3, 1e4, false, "rad/s", f->ex);
    if (e.empty()) e = checkRad(name, "value 2 (highest omega)", v[1], v[0] * (1 + 1e-6), 1e4,
                                false, "rad/s, above the lowest", f->ex);
    if (e.empty()) e = checkRad(name, "value 3 (count)", v[2], 2, 200, true, "frequencies", f->ex);
    for (int k = 0; k < 3; k++) r->omega[k] = v[k];
  } else if (f == kF + 1) {
    e = checkRad(name, "value", v[0], 0, 4, true, "times each panel is split in 4", f->ex);
    r->refine = (int)v[0];
    r->refineGiven = true;
  } else if (f == kF + 2) {
    // 0: no coarsening; else at least a coarse sphere's worth (the panel
    // count of the 12 x 24 hemisphere within 3% of Hulme is 288), at most
    // what a dense solve can hold (20000 complex unknowns: 6.4 GB)
    if (v[0] != 0) e = checkRad(name, "value", v[0], 100, 20000, true, "wet panels, 0 = no coarsening", f->ex);
    r->panels = e.empty() ? (int)v[0] : r->panels;
    r->panelsGiven = e.empty();
  } else {
    e = checkRad(name, "value", v[0], 0, 60, false, "s, 0 = automatic", f->ex);
    r->memory = v[0];
  }
  return e;
}

std::string parseRadConfig(const mjModel* m, RadConfig* r) {
  *r = RadConfig();
  for (int i = 0; i < m->ntext; i++) {
    const char* name = m->names + m->name_textadr[i];
    if (std::strncmp(name, "mjbuoy.", 7) || !isRadEntry(name + 7)) continue;
    std::string e = parseText(m, name, m->text_data + m->text_adr[i], r);
    if (!e.empty()) return e;
  }
  for (int i = 0; i < m->nnumeric; i++) {
    const char* name = m->names + m->name_numericadr[i];
    if (std::strncmp(name, "mjbuoy.", 7) || !isRadEntry(name + 7)) continue;
    std::string e = parseNumeric(m, i, r);
    if (!e.empty()) return e;
  }
  // the default fraction of critical only when the model sets no roll
  // damping of its own: given numbers replace it
  if (r->rollGiven && !r->zetaGiven) r->zeta = 0;
  return "";
}

}  // namespace mjb
