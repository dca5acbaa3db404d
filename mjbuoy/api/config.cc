// parse and validate the "mjbuoy.*" <custom> entries (schema: docs/mjcf.md)
#include "api/config.h"
#include "api/radconfig.h"
#include "api/seaconfig.h"
#include "api/moorconfig.h"
#include "sea/seacheck.h"

#include <fnmatch.h>

#include <cmath>
#include <cstddef>
#include <cstring>
#include <sstream>

namespace mjb {

static const char kPre[] = "mjbuoy.";

// gravity magnitude [m/s^2] accepted
static const double kMinG = 0.1, kMaxG = 100;

// one numeric field: name, value count, accepted range, unit, example
struct Field {
  const char* name;
  int n;
  double lo, hi;   // accepted range
  bool loopen;     // lo itself excluded
  const char* unit;
  const char* example;
  size_t off = 0;  // hull fields: offset in HullParams
  const struct Field* parts = nullptr;  // per-value name and range, if they differ
};

// defaults (docs/mjcf.md says why): simple damping off; form factor 1+k of
// a typical slender hull; quadratic drag from the dynamic pressure
// 0.5 rho v^2 = 500 Pa at 1 m/s (stagnation ~0.8 of it ahead, base suction
// ~0.4 behind), linear terms that settle slow motion, Kerner's exponent 0.5;
// slamming as Kerner with Gamma_max 100 m/s^2 and p = 2
static const HullParams kHullDefault = {
    {0, 0}, 1.3, {100, 400, 0.5}, {100, 200, 0.5}, 1.0, {1, 100, 2}};

// upper (and some lower) limits: physically meaningful ranges, so that no
// constant the kernels derive (rho g, k, omega, level + sum A, k depth, the
// drag at |v| / vref) overflows or cancels; each is justified in docs/mjcf.md
#define PART(name, lo, hi, open, unit) {name, 1, lo, hi, open, unit, ""}
static const Field kDampParts[2] = {
  PART("linear", 0, 1e12, false, "N s/m"),
  PART("angular", 0, 1e15, false, "N m s/rad"),
};
static const Field kDragParts[3] = {
  PART("linear coefficient", 0, 1e6, false, "N/m^2"),
  PART("quadratic coefficient", 0, 1e6, false, "N/m^2"),
  PART("exponent", 0, 8, false, "dimensionless"),
};
static const Field kSlamParts[3] = {
  PART("gain", 0, 1, false, "dimensionless"),
  PART("gamma_max", 0.01, 1e6, false, "m/s^2"),
  PART("power", 0, 16, true, "dimensionless"),
};
// waves and current: the ranges every entry shares (sea/seacheck.h)
#define WPART(j) PART(kWaveRange[j].name, kWaveRange[j].lo, kWaveRange[j].hi, false, \
                      kWaveRange[j].unit)
static const Field kWaveParts[5] = {WPART(0), WPART(1), WPART(2), WPART(3), WPART(4)};
#undef WPART
static const Field kCurrentParts[2] = {
  PART("x", kCurrentRange.lo, kCurrentRange.hi, false, "m/s"),
  PART("y", kCurrentRange.lo, kCurrentRange.hi, false, "m/s"),
};
#undef PART

// hull parameters
static const Field kHullFields[] = {
  {"damping", 2, 0, 0, false, "linear N s/m, angular N m s/rad", "3000 300",
   offsetof(HullParams, damp), kDampParts},
  {"viscous", 1, 0, 3, false, "form factor 1+k, 0 = off", "1.3",
   offsetof(HullParams, viscous)},
  {"drag", 3, 0, 0, false, "C_PD1 N/m^2, C_PD2 N/m^2, f_P", "100 400 0.5",
   offsetof(HullParams, drag), kDragParts},
  {"suction", 3, 0, 0, false, "C_SD1 N/m^2, C_SD2 N/m^2, f_S", "100 200 0.5",
   offsetof(HullParams, suction), kDragParts},
  {"vref", 1, 0.01, 150, false, "m/s", "1", offsetof(HullParams, vref)},
  {"slamming", 3, 0, 0, false, "gain, gamma_max m/s^2, power", "1 100 2",
   offsetof(HullParams, slam), kSlamParts},
};

// sea fields
static const Field kSeaFields[] = {
  {"density", 1, 1, 1e5, false, "kg/m^3", "1000"},
  {"level", 1, -1e4, 1e4, false, "m", "0"},
  {"depth", 1, 0.01, 11000, false, "m (omit for deep water)", "50"},
  {"viscosity", 1, 1e-8, 1, false, "m^2/s, kinematic", "1e-6"},
  {"current", 2, 0, 0, false, "m/s, x and y", "0.5 0", 0, kCurrentParts},
  {"ramp", 1, kRampRange.lo, kRampRange.hi, false, "s, 0 = off", "20"},
  {"seriestol", 1, 0, 1e-4, false, "fraction of rho g V, 0 = exact", "1e-5"},
};

static const Field kWave = {"wave", 5, 0, 0, false,
                            "amplitude m, wavelength m, direction deg, phase deg, steepness",
                            "0.5 20 0 0 0.6", 0, kWaveParts};
// a linear (Airy) component: the wave's parts without the steepness
static const Field kAiry = {"airy", 4, 0, 0, false,
                            "amplitude m, wavelength m, direction deg, phase deg",
                            "0.5 20 0 0", 0, kWaveParts};

// cpu backend threads: 0 picks them from the scene size and the cores
static const Field kThreads = {"threads", 1, 0, 64, false, "threads, 0 = auto", "0"};

// with radiation on for a hull's rigid group, the linear pressure and
// suction drag terms default to 0: a normal pressure linear in the
// velocity is the form of wave radiation damping, which the panel
// solution now gives; the quadratic (separation) terms, skin friction and
// slamming stay (docs/physics.md section 16). Values the user gave stay.
// radDrag records, per hull, which terms were zeroed (restoreDrag)
static void radiationDragDefaults(const mjModel* m, const std::vector<int>& gid,
                                  const RadConfig& rad,
                                  const std::vector<std::vector<char>>& set,
                                  const std::vector<char>& defSet,
                                  std::vector<HullParams>* par, std::vector<char>* radDrag) {
  const int kDrag = 2, kSuction = 3;  // kHullFields rows
  std::vector<int> hb;
  for (int g : gid) hb.push_back(m->geom_bodyid[g]);
  radDrag->assign(gid.size(), 0);
  for (size_t h = 0; h < gid.size(); h++) {
    if (!rad.groupRadiates(m, hb, m->body_weldid[hb[h]])) continue;
    char& z = (*radDrag)[h];
    if (!set[h][kDrag] && !defSet[kDrag]) (*par)[h].drag[0] = 0, z |= kRadDrag;
    if (!set[h][kSuction] && !defSet[kSuction]) (*par)[h].suction[0] = 0, z |= kRadSuction;
  }
}

void restoreDrag(HullParams* p, char* bits) {
  if (*bits & kRadDrag) p->drag[0] = kHullDefault.drag[0];
  if (*bits & kRadSuction) p->suction[0] = kHullDefault.suction[0];
  *bits = 0;
}

// range check of one value
static std::string checkValue(const char* name, const Field& f, const char* what,
                              double v, const char* example) {
  std::string pre = "mjbuoy: " + tag("numeric", name) + " " + what + " = " + fmt(v);
  if (!std::isfinite(v)) {
    return pre + " is not a finite number; give a finite value in " + f.unit +
           ", e.g. data=\"" + example + "\"";
  }
  bool low = f.loopen ? v <= f.lo : v < f.lo;
  if (low || v > f.hi) {
    std::string range = std::string(f.loopen ? "> " : ">= ") + fmt(f.lo);
    if (std::isfinite(f.hi)) range += " and <= " + fmt(f.hi);
    return pre + " is out of range: it must be " + range + " [" + f.unit +
           "]; fix its data attribute, e.g. data=\"" + example + "\"";
  }
  return "";
}

// count and range check of a numeric entry
static std::string checkNumeric(const mjModel* m, int i, const Field& f) {
  const char* name = m->names + m->name_numericadr[i];
  int n = m->numeric_size[i];
  if (n != f.n) {
    return "mjbuoy: " + tag("numeric", name) + " has " + std::to_string(n) +
           " value(s), expected " + std::to_string(f.n) + " (" + f.unit +
           "), e.g. data=\"" + f.example + "\"";
  }
  const mjtNum* v = m->numeric_data + m->numeric_adr[i];
  for (int j = 0; j < n; j++) {
    const Field& fj = f.parts ? f.parts[j] : f;
    std::string what = n == 1 ? "value" : "value " + std::to_string(j + 1);
    if (f.parts) what += " (" + std::string(fj.name) + ")";
    std::string e = checkValue(name, fj, what.c_str(), v[j], f.example);
    if (!e.empty()) return e;
  }
  return "";
}

// the values of hull field f inside p
static double* param(HullParams* p, const Field& f) {
  return reinterpret_cast<double*>(reinterpret_cast<char*>(p) + f.off);
}

static const Field* findField(const Field* fs, int n, const char* name) {
  for (int i = 0; i < n; i++) {
    if (!std::strcmp(fs[i].name, name)) return fs + i;
  }
  return nullptr;
}

static std::string fieldList(const Field* fs, int n) {
  std::string s;
  for (int i = 0; i < n; i++) s += (i ? ", " : "") + std::string(fs[i].name);
  return s;
}

static const char kNumericNames[] =
    "mjbuoy.sea.<field>, mjbuoy.wave.<label>, mjbuoy.airy.<label>, "
    "mjbuoy.spectrum.<label>.<field>, mjbuoy.wind.<field>, mjbuoy.hull.<param>, "
    "mjbuoy.geom.<geom>.<param>, mjbuoy.threads, mjbuoy.radiation.<field>";

// hull geom list: whitespace-separated geom names or fnmatch patterns. A
// pattern skips geoms that cannot be hulls ("*" with a floor in the scene);
// a plain name of such a geom is an error.
static std::string parseHulls(const mjModel* m, const char* name, const char* text,
                              std::vector<char>* is) {
  std::istringstream in(text);
  std::string pat;
  int count = 0;
  while (in >> pat) {
    count++;
    int hits = 0;
    bool glob = pat.find_first_of("*?[") != std::string::npos;
    for (int g = 0; g < m->ngeom; g++) {
      const char* gn = m->names + m->name_geomadr[g];
      if (!gn[0] || fnmatch(pat.c_str(), gn, 0)) continue;
      int t = m->geom_type[g];
      if (t != mjGEOM_MESH && t != mjGEOM_BOX && t != mjGEOM_SPHERE &&
          t != mjGEOM_CYLINDER && t != mjGEOM_CAPSULE && t != mjGEOM_ELLIPSOID) {
        if (glob) continue;
        return "mjbuoy: " + tag("text", name) + " names geom \"" + gn +
               "\", whose type cannot be a hull; accepted geom types: mesh, box, "
               "sphere, cylinder, capsule, ellipsoid";
      }
      hits++;
      (*is)[g] = 1;
    }
    if (!hits) {
      return "mjbuoy: " + tag("text", name) + " entry \"" + pat +
             "\" matches no named geom that can be a hull; give geom names (shell "
             "patterns such as \"boat*_hull\" are allowed)";
    }
  }
  if (!count) {
    return "mjbuoy: " + tag("text", name) +
           " is empty; list the hull geom names, e.g. data=\"hull\"";
  }
  return "";
}

std::string setBackend(const char* name, const std::string& where, Config* c) {
  if (std::strcmp(name, "cpu") && std::strcmp(name, "gl") && std::strcmp(name, "auto")) {
    return "mjbuoy: " + where + " value \"" + name +
           "\" is not a backend; accepted: cpu, gl, auto";
  }
  c->backend = name;
  return "";
}

// gravity must point down z: the sea is z = eta(x, y, t); sets c->sea.g
static std::string parseGravity(const mjModel* m, Config* c) {
  const mjtNum* gv = m->opt.gravity;
  if (gv[0] != 0 || gv[1] != 0 || !(gv[2] < 0) || !std::isfinite(gv[2])) {
    return "mjbuoy: <option gravity=\"" + fmt(gv[0]) + " " + fmt(gv[1]) + " " +
           fmt(gv[2]) + "\"> is not supported: mjbuoy needs gravity along -z "
           "(the sea surface is z = eta(x, y)), e.g. gravity=\"0 0 -9.81\"";
  }
  c->sea.g = -gv[2];
  if (c->sea.g < kMinG || c->sea.g > kMaxG) {
    return "mjbuoy: <option gravity=\"" + fmt(gv[0]) + " " + fmt(gv[1]) + " " + fmt(gv[2]) +
           "\"> is out of range for mjbuoy: its magnitude g = " + fmt(c->sea.g) +
           " m/s^2 must be >= " + fmt(kMinG) + " and <= " + fmt(kMaxG) +
           " (a world with a sea: Titan 1.35, Earth 9.81, Jupiter 24.8); e.g. gravity=\"0 0 "
           "-9.81\"";
  }
  return "";
}

// the text entries: the hull list into is (anyHullList: given), the
// backend, the pressure model
static std::string parseText(const mjModel* m, Config* c, std::vector<char>* is,
                             bool* anyHullList) {
  const size_t np = sizeof(kPre) - 1;
  auto has = [&](const char* s) { return !std::strncmp(s, kPre, np); };
  for (int i = 0; i < m->ntext; i++) {
    const char* name = m->names + m->name_textadr[i];
    if (!has(name)) continue;
    const char* key = name + np;
    const char* text = m->text_data + m->text_adr[i];
    if (isSeaExtra(key) || isRadEntry(key) || isMoorEntry(key)) continue;  // *config.cc
    if (!std::strcmp(key, "hulls")) {
      *anyHullList = true;
      std::string e = parseHulls(m, name, text, is);
      if (!e.empty()) return e;
    } else if (!std::strcmp(key, "backend")) {
      std::string e = setBackend(text, tag("text", name), c);
      if (!e.empty()) return e;
    } else if (!std::strncmp(key, "sensor.", 7)) {
      continue;  // sensor bindings: sensor.cc, once the hulls are built
    } else if (!std::strcmp(key, "sea.pressure")) {
      if (!std::strcmp(text, "kerner")) {
        c->sea.kerner = true;
      } else if (!std::strcmp(text, "linear")) {
        c->sea.kerner = false;
      } else {
        return "mjbuoy: " + tag("text", name) + " data = \"" + text +
               "\" is not a pressure model; give \"linear\" (linear wave theory, the "
               "default) or \"kerner\" (rho g (eta - z)), e.g. data=\"linear\"";
      }
    } else if (!std::strcmp(key, "sea.integration")) {
      std::string e = integrationCheck(text, ("mjbuoy: " + tag("text", name) + " data").c_str(),
                                       &c->sea.integration);
      if (!e.empty()) return e;
    } else {
      return "mjbuoy: unknown entry " + tag("text", name) +
             "; text entries are mjbuoy.hulls, mjbuoy.backend, mjbuoy.sea.pressure, "
             "mjbuoy.sea.integration, "
             "mjbuoy.sensor.<sensor>, mjbuoy.spectrum.<label>.type, mjbuoy.wind.gust, "
             "mjbuoy.wind.geoms and mjbuoy.radiation[.<field>] (numeric entries: " +
             kNumericNames + "; see docs/mjcf.md)";
    }
  }
  return "";
}

// hull geoms on the world body, or on a body welded to it (no joint on
// the way), cannot move: dropped from is with a warning
static void dropFixedHulls(const mjModel* m, std::vector<char>* isp, Config* c) {
  std::vector<char>& is = *isp;
  for (int g = 0; g < m->ngeom; g++) {
    int bd = m->geom_bodyid[g];
    if (is[g] && m->body_weldid[bd] == 0) {
      std::string on = bd == 0 ? std::string("belongs to the world body")
                               : std::string("is on body \"") + (m->names + m->name_bodyadr[bd]) +
                                     "\", which has no joint between it and the world body";
      c->warn.push_back(std::string("geom \"") + (m->names + m->name_geomadr[g]) +
                        "\" is listed as a hull but " + on + "; it cannot move and is ignored");
      is[g] = 0;
    }
  }
}

// the hulls' coefficients as the entries give them: the hull geoms (gid)
// and the geoms listed before dropFixedHulls (listed), the defaults (def,
// with defSet: mjbuoy.hull.<param> given), each hull's (par, with set:
// mjbuoy.geom.<geom>.<param> given)
struct HullEntries {
  std::vector<int> gid;
  std::vector<char> listed;
  HullParams def;
  std::vector<HullParams> par;
  std::vector<std::vector<char>> set;
  std::vector<char> defSet;
};

// numeric entry i, mjbuoy.geom.<geom>.<param> (key: after "mjbuoy."),
// into he's hull of that geom
static std::string geomEntry(const mjModel* m, int i, const char* name, const char* key,
                             HullEntries* he) {
  const int nhf = sizeof(kHullFields) / sizeof(kHullFields[0]);
  const mjtNum* v = m->numeric_data + m->numeric_adr[i];
  const std::vector<int>& gid = he->gid;
  const std::vector<char>& listed = he->listed;
  // mjbuoy.geom.<geom>.<param>: geom names may hold dots, params do not
  const char* rest = key + 5;
  const char* dot = std::strrchr(rest, '.');
  const Field* f = dot ? findField(kHullFields, nhf, dot + 1) : nullptr;
  if (!f) {
    return "mjbuoy: unknown entry " + tag("numeric", name) +
           "; per-hull entries are mjbuoy.geom.<geom>.<param> with param one of " +
           fieldList(kHullFields, nhf) + " (see docs/mjcf.md)";
  }
  std::string gname(rest, dot - rest);
  int g = mj_name2id(m, mjOBJ_GEOM, gname.c_str());
  int h = -1;
  for (size_t j = 0; j < gid.size(); j++) if (gid[j] == g) h = j;
  if (g < 0 || h < 0) {
    return "mjbuoy: " + tag("numeric", name) + " refers to geom \"" + gname + "\", " +
           (g < 0 ? "which does not exist"
            : listed[g] ? "which is on the world body (or welded to it) and so is not a hull"
                        : "which is not listed in mjbuoy.hulls") +
           "; fix the name or add the geom to <text name=\"mjbuoy.hulls\">";
  }
  std::string e = checkNumeric(m, i, *f);
  if (!e.empty()) return e;
  for (int j = 0; j < f->n; j++) param(&he->par[h], *f)[j] = v[j];
  he->set[h][f - kHullFields] = 1;
  return "";
}

// the numeric entries: sea fields, waves, hull defaults and per-hull
// values into he, threads; any: an mjbuoy.* entry was seen
static std::string parseNumeric(const mjModel* m, Config* c, HullEntries* he, bool* anyp) {
  const size_t np = sizeof(kPre) - 1;
  auto has = [&](const char* s) { return !std::strncmp(s, kPre, np); };
  const int nhf = sizeof(kHullFields) / sizeof(kHullFields[0]);
  const int nsf = sizeof(kSeaFields) / sizeof(kSeaFields[0]);
  HullParams& def = he->def;
  std::vector<char>& defSet = he->defSet;
  bool& any = *anyp;
  for (int i = 0; i < m->nnumeric; i++) {
    const char* name = m->names + m->name_numericadr[i];
    if (!has(name)) continue;
    any = true;
    const char* key = name + np;
    const mjtNum* v = m->numeric_data + m->numeric_adr[i];
    if (isSeaExtra(key) || isRadEntry(key) || isMoorEntry(key)) continue;  // *config.cc
    if (!std::strncmp(key, "sea.", 4)) {
      const Field* f = findField(kSeaFields, nsf, key + 4);
      if (!f) {
        return "mjbuoy: unknown entry " + tag("numeric", name) + "; sea fields are " +
               fieldList(kSeaFields, nsf) + ", capacity (see docs/mjcf.md)";
      }
      std::string e = checkNumeric(m, i, *f);
      if (!e.empty()) return e;
      Sea& s = c->sea;
      if (f == kSeaFields + 0) s.rho = v[0];
      if (f == kSeaFields + 1) s.level = v[0];
      if (f == kSeaFields + 2) s.depth = v[0];
      if (f == kSeaFields + 3) s.nu = v[0];
      if (f == kSeaFields + 4) { s.current[0] = v[0]; s.current[1] = v[1]; }
      if (f == kSeaFields + 5) s.ramp = v[0];
      if (f == kSeaFields + 6) s.seriestol = v[0];
    } else if (!std::strncmp(key, "wave.", 5) && key[5]) {
      std::string e = checkNumeric(m, i, kWave);
      if (!e.empty()) return e;
      c->sea.waves.push_back(Wave{v[0], v[1], v[2], v[3], v[4], 0, 0, 0, 0, 0});
    } else if (!std::strncmp(key, "airy.", 5) && key[5]) {
      std::string e = checkNumeric(m, i, kAiry);
      if (!e.empty()) return e;
      Wave w{v[0], v[1], v[2], v[3], 0, 0, 0, 0, 0, 0};
      w.kind = 1;
      c->sea.waves.push_back(w);
    } else if (!std::strncmp(key, "hull.", 5)) {
      const Field* f = findField(kHullFields, nhf, key + 5);
      if (!f) {
        return "mjbuoy: unknown entry " + tag("numeric", name) + "; hull parameters are " +
               fieldList(kHullFields, nhf) + " (see docs/mjcf.md)";
      }
      std::string e = checkNumeric(m, i, *f);
      if (!e.empty()) return e;
      for (int j = 0; j < f->n; j++) param(&def, *f)[j] = v[j];
      defSet[f - kHullFields] = 1;
    } else if (!std::strncmp(key, "geom.", 5)) {
      std::string e = geomEntry(m, i, name, key, he);
      if (!e.empty()) return e;
    } else if (!std::strcmp(key, "threads")) {
      std::string e = checkNumeric(m, i, kThreads);
      if (!e.empty()) return e;
      if (v[0] != std::floor(v[0])) {
        return "mjbuoy: " + tag("numeric", name) + " value = " + fmt(v[0]) +
               " is not a whole number of threads; give 0 (auto) or a count from 1 to 64, "
               "e.g. data=\"0\"";
      }
      c->threads = int(v[0]);
    } else if (!std::strcmp(key, "hulls") || !std::strcmp(key, "backend")) {
      return "mjbuoy: " + tag("numeric", name) + " must be a <text> entry, e.g. "
             "<text name=\"" + name + "\" data=\"" +
             (key[0] == 'h' ? "hull" : "cpu") + "\"/>";
    } else {
      return "mjbuoy: unknown entry " + tag("numeric", name) + "; numeric entries are " +
             kNumericNames + ", text entries mjbuoy.hulls, mjbuoy.backend, "
             "mjbuoy.sea.pressure and mjbuoy.sea.integration (see docs/mjcf.md)";
    }
  }
  return "";
}

// per-hull values not overridden take the (possibly user-set) defaults
static void fillDefaults(HullEntries* he) {
  const int nhf = sizeof(kHullFields) / sizeof(kHullFields[0]);
  HullParams& def = he->def;
  std::vector<HullParams>& par = he->par;
  for (size_t h = 0; h < he->gid.size(); h++) {
    for (int k = 0; k < nhf; k++) {
      if (he->set[h][k]) continue;
      for (int j = 0; j < kHullFields[k].n; j++) {
        param(&par[h], kHullFields[k])[j] = param(&def, kHullFields[k])[j];
      }
    }
  }
}

std::string parseConfig(const mjModel* m, Config* c, bool radiation) {
  *c = Config();
  std::string e = parseGravity(m, c);
  if (!e.empty()) return e;

  // hulls first: per-geom overrides refer to them
  std::vector<char> is(m->ngeom, 0);
  bool anyHullList = false;
  e = parseText(m, c, &is, &anyHullList);
  if (!e.empty()) return e;
  HullEntries he;
  he.listed = is;
  dropFixedHulls(m, &is, c);
  const int nhf = sizeof(kHullFields) / sizeof(kHullFields[0]);
  he.def = kHullDefault;
  for (int g = 0; g < m->ngeom; g++) if (is[g]) he.gid.push_back(g);
  he.par.assign(he.gid.size(), he.def);
  he.set.assign(he.gid.size(), std::vector<char>(nhf, 0));
  he.defSet.assign(nhf, 0);
  bool any = anyHullList;
  c->sea.ramp = -1;  // not given (mjbuoy.sea.ramp accepts only >= 0)
  e = parseNumeric(m, c, &he, &any);
  if (!e.empty()) return e;
  fillDefaults(&he);
  const std::vector<int>& gid = he.gid;
  std::vector<HullParams>& par = he.par;
  const std::vector<std::vector<char>>& set = he.set;
  const std::vector<char>& defSet = he.defSet;

  // the listed waves together: the highest crest above level, level + sum
  // A, stays a height a sea can have, and the surface does not fold
  double sum = 0, fold = 0;
  for (const Wave& w : c->sea.waves) waveSums(w.amp, w.len, w.steep, &sum, &fold);
  std::string ex = wavesCheck(sum, fold, "mjbuoy: ", "the mjbuoy.wave.* and mjbuoy.airy.* "
                              "entries", "mjbuoy.wave.*");
  if (!ex.empty()) return ex;
  ex = parseSeaExtra(m, gid, c);
  if (!ex.empty()) return ex;
  ex = parseRadConfig(m, &c->rad);
  if (!ex.empty()) return ex;
  if (!radiation) {  // as if the model said mjbuoy.radiation off, with no body override
    c->rad.on = false;
    c->rad.onBody.clear();
  }
  radiationDragDefaults(m, gid, c->rad, set, defSet, &par, &c->radDrag);
  c->sea.derive();
  // no mjbuoy.sea.ramp: a few periods of the dominant component (sea.h)
  if (c->sea.ramp < 0) c->sea.ramp = c->sea.defaultRamp();
  if (m->opt.density > 0 || m->opt.viscosity > 0) {
    c->warn.push_back("<option density/viscosity> is nonzero: MuJoCo's own fluid forces act "
                      "on every body as well as mjbuoy's (double counting); set them to 0");
  }
  if (gid.empty() && !hasLines(m)) {
    c->warn.push_back(any ? "no hull geoms: mjbuoy adds no force"
                          : "the model has no mjbuoy.* entries: mjbuoy adds no force");
  }
  c->geom = gid;
  c->param = par;
  return "";
}

}  // namespace mjb
