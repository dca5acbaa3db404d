// seaconfig: parse mjbuoy.spectrum.<label>.<field>, mjbuoy.wind.<field> and
// mjbuoy.sea.capacity (schema: docs/mjcf.md sections 8 and 9)
#include "api/seaconfig.h"

#include <fnmatch.h>

#include <cmath>
#include <cstring>
#include <map>
#include <sstream>

#include "api/config.h"
#include "sea/seacheck.h"
#include "sea/spectra.h"

namespace mjb {

bool isSeaExtra(const char* key) {
  return !std::strncmp(key, "spectrum.", 9) || !std::strncmp(key, "wind.", 5) ||
         !std::strcmp(key, "sea.capacity");
}

// one numeric field: name, count (0: any even count), range, unit, example
struct XField {
  const char* name;
  int n;
  double lo, hi;
  bool loopen, whole;
  const char* unit;
  const char* example;
};

static const XField kSpecFields[] = {
  {"hs", 1, 0, 50, true, false, "m", "2"},
  {"tp", 1, 0, 100, true, false, "s", "8"},
  {"wind", 1, 0, 100, true, false, "m/s at 10 m", "15"},
  {"gamma", 1, 1, 10, false, false, "dimensionless", "3.3"},
  {"table", 0, 0, INFINITY, false, false, "pairs of omega rad/s and S m^2 s/rad", "0.5 0 0.8 1.2 1.5 0"},
  {"direction", 1, kDirRange.lo, kDirRange.hi, false, false, "deg", "0"},
  {"spreading", 1, 0, 1000, false, false, "s of cos^2s, 0 = long-crested", "10"},
  {"components", 1, 1, 4096, false, true, "count", "64"},
  {"range", 2, 0, INFINITY, true, false, "rad/s, wmin wmax", "0.4 3"},
  {"seed", 1, 0, 9007199254740992.0, false, true, "whole number", "1"},
};

static const XField kWindFields[] = {
  {"speed", 1, kWindSpeedRange.lo, kWindSpeedRange.hi, false, false, "m/s, mean at 10 m", "10"},
  {"direction", 1, kDirRange.lo, kDirRange.hi, false, false, "deg, towards", "0"},
  {"density", 1, 0, INFINITY, true, false, "kg/m^3", "1.225"},
  {"drag", 2, 0, 10, false, false, "C_d per projected area, C_f per area", "1 0.002"},
  {"gustcomponents", 1, 1, kMaxGust, false, true, "count", "128"},
  {"seed", 1, 0, 9007199254740992.0, false, true, "whole number", "1"},
};

static const XField kCapacity = {"capacity", 1, 0, 65536, false, true, "components", "256"};

static std::string check(const mjModel* m, int i, const XField& f) {
  const char* name = m->names + m->name_numericadr[i];
  int n = m->numeric_size[i];
  const mjtNum* v = m->numeric_data + m->numeric_adr[i];
  if (f.n ? n != f.n : (n < 4 || n % 2)) {
    return "mjbuoy: " + tag("numeric", name) + " has " + std::to_string(n) + " value(s), expected " +
           (f.n ? std::to_string(f.n) : std::string("an even number >= 4")) + " (" + f.unit +
           "), e.g. data=\"" + f.example + "\"";
  }
  for (int j = 0; j < n; j++) {
    std::string what = n == 1 ? "value" : "value " + std::to_string(j + 1);
    std::string pre = "mjbuoy: " + tag("numeric", name) + " " + what + " = " + fmt(v[j]);
    if (!std::isfinite(v[j])) {
      return pre + " is not a finite number; give a finite value in " + f.unit +
             ", e.g. data=\"" + f.example + "\"";
    }
    bool low = f.loopen ? v[j] <= f.lo : v[j] < f.lo;
    if (low || v[j] > f.hi) {
      std::string range = std::string(f.loopen ? "> " : ">= ") + fmt(f.lo);
      if (std::isfinite(f.hi)) range += " and <= " + fmt(f.hi);
      return pre + " is out of range: it must be " + range + " [" + f.unit +
             "]; fix its data attribute, e.g. data=\"" + f.example + "\"";
    }
    if (f.whole && v[j] != std::floor(v[j])) {
      return pre + " is not a whole number [" + f.unit + "]; e.g. data=\"" + f.example + "\"";
    }
  }
  return "";
}

static const XField* find(const XField* fs, int n, const char* name) {
  for (int i = 0; i < n; i++) if (!std::strcmp(fs[i].name, name)) return fs + i;
  return nullptr;
}

static std::string list(const XField* fs, int n) {
  std::string s;
  for (int i = 0; i < n; i++) s += (i ? ", " : "") + std::string(fs[i].name);
  return s;
}

struct SpecIn {
  mjbSpectrum s;
  bool typed = false, hs = false, tp = false, wind = false, table = false;
  std::string first;  // an entry name of this spectrum, for messages
};

static std::string specText(const char* name, const char* field, const char* text,
                            SpecIn* in) {
  if (std::strcmp(field, "type")) {
    return "mjbuoy: unknown entry " + tag("text", name) +
           "; the text field of a spectrum is type (pm, jonswap or table; see docs/mjcf.md)";
  }
  if (!std::strcmp(text, "pm")) in->s.type = mjbSPEC_PM;
  else if (!std::strcmp(text, "jonswap")) in->s.type = mjbSPEC_JONSWAP;
  else if (!std::strcmp(text, "table")) in->s.type = mjbSPEC_TABLE;
  else {
    return "mjbuoy: " + tag("text", name) + " value \"" + text +
           "\" is not a spectrum type; accepted: pm, jonswap, table";
  }
  in->typed = true;
  return "";
}

static std::string specNumeric(const mjModel* m, int i, const char* field, SpecIn* in) {
  const char* name = m->names + m->name_numericadr[i];
  const int nf = sizeof(kSpecFields) / sizeof(kSpecFields[0]);
  const XField* f = find(kSpecFields, nf, field);
  if (!f) {
    return "mjbuoy: unknown entry " + tag("numeric", name) + "; spectrum fields are " +
           list(kSpecFields, nf) + " and the text field type (see docs/mjcf.md)";
  }
  std::string e = check(m, i, *f);
  if (!e.empty()) return e;
  const mjtNum* v = m->numeric_data + m->numeric_adr[i];
  mjbSpectrum& s = in->s;
  std::string k = f->name;
  if (k == "hs") s.hs = v[0], in->hs = true;
  if (k == "tp") s.tp = v[0], in->tp = true;
  if (k == "wind") s.wind = v[0], in->wind = true;
  if (k == "gamma") s.gamma = v[0];
  if (k == "table") s.table = v, s.ntable = m->numeric_size[i] / 2, in->table = true;
  if (k == "direction") s.dir = v[0];
  if (k == "spreading") s.spread = v[0];
  if (k == "components") s.n = int(v[0]);
  if (k == "range") s.wmin = v[0], s.wmax = v[1];
  if (k == "seed") s.seed = (unsigned long long)v[0];
  return "";
}

// the combination of fields a spectrum's type needs
static std::string specComplete(const std::string& label, const SpecIn& in, double g) {
  std::string pre = "mjbuoy: spectrum \"" + label + "\" (mjbuoy.spectrum." + label + ".*): ";
  if (!in.typed) {
    return pre + "no type; add <text name=\"mjbuoy.spectrum." + label +
           ".type\" data=\"jonswap\"/> (pm, jonswap or table)";
  }
  int t = in.s.type;
  if (t == mjbSPEC_TABLE && !in.table) return pre + "type table needs a table entry";
  if (t != mjbSPEC_TABLE && in.table) return pre + "a table is only read by type table";
  if (t == mjbSPEC_PM && in.wind && (in.hs || in.tp)) {
    return pre + "give either wind or hs and tp, not both (wind sets both)";
  }
  if (in.wind && t != mjbSPEC_PM) return pre + "wind is only read by type pm";
  if (t != mjbSPEC_TABLE && !in.wind && !(in.hs && in.tp)) {
    return pre + "needs hs and tp" + std::string(t == mjbSPEC_PM ? " (or wind)" : "");
  }
  return specCheck(in.s, g, pre.c_str());
}

static std::string windGeoms(const mjModel* m, const char* name, const char* text, Config* c) {
  std::istringstream in(text);
  std::string pat;
  while (in >> pat) {
    int hits = 0;
    for (int g = 0; g < m->ngeom; g++) {
      const char* gn = m->names + m->name_geomadr[g];
      if (!gn[0] || fnmatch(pat.c_str(), gn, 0)) continue;
      int t = m->geom_type[g];
      bool ok = t == mjGEOM_MESH || t == mjGEOM_BOX || t == mjGEOM_SPHERE ||
                t == mjGEOM_CYLINDER || t == mjGEOM_CAPSULE || t == mjGEOM_ELLIPSOID;
      bool hull = false;
      for (int h : c->geom) hull = hull || h == g;
      if (!ok || hull || m->body_weldid[m->geom_bodyid[g]] == 0) continue;
      c->wind.geom.push_back(g);
      hits++;
    }
    if (!hits) {
      return "mjbuoy: " + tag("text", name) + " entry \"" + pat +
             "\" matches no named geom that can catch wind (a mesh, box, sphere, cylinder, "
             "capsule or ellipsoid on a moving body, not a hull: hulls catch wind anyway)";
    }
  }
  return "";
}

static std::string windText(const mjModel* m, const char* name, const char* field,
                            const char* text, Config* c) {
  if (!std::strcmp(field, "gust")) {
    if (!std::strcmp(text, "none")) c->wind.w.gust = mjbGUST_NONE;
    else if (!std::strcmp(text, "froya")) c->wind.w.gust = mjbGUST_FROYA;
    else return "mjbuoy: " + tag("text", name) + " value \"" + text + "\" is not a gust spectrum; accepted: none, froya";
    return "";
  }
  if (!std::strcmp(field, "geoms")) return windGeoms(m, name, text, c);
  return "mjbuoy: unknown entry " + tag("text", name) + "; wind text fields are gust and geoms";
}

static std::string windNumeric(const mjModel* m, int i, const char* field, Config* c) {
  const char* name = m->names + m->name_numericadr[i];
  const int nf = sizeof(kWindFields) / sizeof(kWindFields[0]);
  const XField* f = find(kWindFields, nf, field);
  if (!f) {
    return "mjbuoy: unknown entry " + tag("numeric", name) + "; wind fields are " +
           list(kWindFields, nf) + " and the text fields gust and geoms (see docs/mjcf.md)";
  }
  std::string e = check(m, i, *f);
  if (!e.empty()) return e;
  const mjtNum* v = m->numeric_data + m->numeric_adr[i];
  WindParams& w = c->wind;
  std::string k = f->name;
  if (k == "speed") w.w.speed = v[0];
  if (k == "direction") w.w.dir = v[0];
  if (k == "density") w.rho = v[0];
  if (k == "drag") w.cd = v[0], w.cf = v[1];
  if (k == "gustcomponents") w.w.ngust = int(v[0]);
  if (k == "seed") w.w.seed = (unsigned long long)v[0];
  return "";
}

// label and field of "spectrum.<label>.<field>": labels may hold dots
static bool splitSpec(const char* key, std::string* label, const char** field) {
  const char* rest = key + 9;
  const char* dot = std::strrchr(rest, '.');
  if (!dot || dot == rest || !dot[1]) return false;
  *label = std::string(rest, dot - rest);
  *field = dot + 1;
  return true;
}

std::string parseSeaExtra(const mjModel* m, const std::vector<int>& hulls, Config* c) {
  c->geom = hulls;  // for windGeoms
  std::map<std::string, SpecIn> spec;  // ordered by label: a portable order
  auto blank = [] {
    SpecIn in;
    mjb_defaultSpectrum(&in.s);
    return in;
  };
  for (int i = 0; i < m->ntext; i++) {
    const char* name = m->names + m->name_textadr[i];
    if (std::strncmp(name, "mjbuoy.", 7) || !isSeaExtra(name + 7)) continue;
    const char* key = name + 7;
    const char* text = m->text_data + m->text_adr[i];
    std::string e;
    if (!std::strncmp(key, "spectrum.", 9)) {
      std::string label;
      const char* field;
      if (!splitSpec(key, &label, &field)) {
        return "mjbuoy: " + tag("text", name) + " is not mjbuoy.spectrum.<label>.type";
      }
      if (!spec.count(label)) spec[label] = blank();
      e = specText(name, field, text, &spec[label]);
    } else if (!std::strncmp(key, "wind.", 5)) {
      c->wind.on = true;
      e = windText(m, name, key + 5, text, c);
    } else {
      e = "mjbuoy: " + tag("text", name) + " must be a <numeric> entry, e.g. <numeric name=\"" +
          name + "\" data=\"256\"/>";
    }
    if (!e.empty()) return e;
  }
  for (int i = 0; i < m->nnumeric; i++) {
    const char* name = m->names + m->name_numericadr[i];
    if (std::strncmp(name, "mjbuoy.", 7) || !isSeaExtra(name + 7)) continue;
    const char* key = name + 7;
    std::string e;
    if (!std::strncmp(key, "spectrum.", 9)) {
      std::string label;
      const char* field;
      if (!splitSpec(key, &label, &field)) {
        return "mjbuoy: " + tag("numeric", name) +
               " is not mjbuoy.spectrum.<label>.<field>; fields: " +
               list(kSpecFields, sizeof(kSpecFields) / sizeof(kSpecFields[0]));
      }
      if (!spec.count(label)) spec[label] = blank();
      e = specNumeric(m, i, field, &spec[label]);
    } else if (!std::strncmp(key, "wind.", 5)) {
      c->wind.on = true;
      e = windNumeric(m, i, key + 5, c);
    } else {
      e = check(m, i, kCapacity);
      if (e.empty()) c->capacity = int(m->numeric_data[m->numeric_adr[i]]);
    }
    if (!e.empty()) return e;
  }
  if (c->wind.on) {
    std::string e = windCheck(c->wind.w, "mjbuoy: mjbuoy.wind.*: ");
    if (!e.empty()) return e;
  }
  for (auto& kv : spec) {
    std::string e = specComplete(kv.first, kv.second, c->sea.g);
    if (!e.empty()) return e;
    size_t n0 = c->sea.waves.size();
    c->sea.waves.resize(n0 + kv.second.s.n);
    specExpand(kv.second.s, c->sea.g, c->sea.depth, c->sea.waves.data() + n0);
    kv.second.s.table = nullptr;  // the model's memory: not kept
    c->spec.push_back(kv.second.s);
  }
  return "";
}

}  // namespace mjb
