// moorconfig: parse and validate mjbuoy.linetype.<type>.<field>,
// mjbuoy.line.<line>.<field> and mjbuoy.seabed.<field> (docs/mooring.md)
#include "api/moorconfig.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include "util/fmt.h"

namespace mjb {

namespace {

const char kPre[] = "mjbuoy.";

// one numeric field: name, value count, accepted range, unit, example
struct MField {
  const char* name;
  int n;
  double lo, hi;
  bool loopen, whole;
  const char* unit;
  const char* example;
};

// ranges: physical lines (fibre ropes of grams per metre to the heaviest
// chain, 1e5 kg/m) and seas; each keeps the derived constants finite
const MField kTypeFields[] = {
    {"mass", 1, 0, 1e5, true, false, "kg/m, mass per unstretched length", "150"},
    {"diameter", 1, 0, 10, true, false, "m, volume-equivalent diameter", "0.18"},
    {"ea", 1, 0, 1e13, true, false, "N, axial stiffness", "1.5e9"},
    {"damping", 1, -10, 1e13, false, false,
     "N s, internal damping; negative: ratio of a segment's critical damping", "-0.5"},
    {"cdn", 1, 0, 10, false, false, "normal drag coefficient", "1.2"},
    {"cdt", 1, 0, 10, false, false, "tangential drag coefficient", "0.008"},
    {"can", 1, 0, 10, false, false, "normal added-mass coefficient", "1"},
    {"cat", 1, 0, 10, false, false, "tangential added-mass coefficient", "0"},
};
const int kNType = sizeof(kTypeFields) / sizeof(kTypeFields[0]);
const MField kLineFields[] = {
    {"length", 1, 0, 1e5, true, false, "m, unstretched length", "250"},
    {"segments", 1, 1, 1000, false, true, "segments, a whole number", "20"},
    {"anchor", 3, -1e5, 1e5, false, false, "m, world point x y z", "100 0 -50"},
};
const int kNLine = sizeof(kLineFields) / sizeof(kLineFields[0]);
const MField kBedFields[] = {
    {"stiffness", 1, 0, 1e12, true, false, "Pa/m, per contact area d L", "3e6"},
    {"damping", 1, 0, 1e12, false, false, "Pa s/m, per contact area d L", "3e5"},
    {"friction", 2, 0, 10, false, false, "axial and lateral friction coefficients", "0.5 1"},
    {"slip", 1, 1e-6, 10, true, false, "m/s, speed of full friction", "0.01"},
};
const int kNBed = sizeof(kBedFields) / sizeof(kBedFields[0]);

struct LineIn {
  std::string type, anchor, fairlead;  // type name, site names
  double len = 0, anchorP[3] = {0, 0, 0};
  int nseg = 20;
  bool hasLen = false, hasAnchorP = false;
};

std::string fields(const MField* f, int n) {
  std::string s;
  for (int i = 0; i < n; i++) s += (i ? ", " : "") + std::string(f[i].name);
  return s;
}

const MField* find(const MField* f, int n, const std::string& name) {
  for (int i = 0; i < n; i++) if (name == f[i].name) return f + i;
  return nullptr;
}

// count and range of a numeric entry; who names the line, type or bed
std::string check(const mjModel* m, int i, const MField& f, const std::string& who) {
  const char* name = m->names + m->name_numericadr[i];
  const std::string at = "mjbuoy: " + who + " " + tag("numeric", name) + ": " + f.name;
  int n = m->numeric_size[i];
  if (n != f.n) {
    return at + " has " + std::to_string(n) + " value(s), expected " + std::to_string(f.n) +
           " (" + f.unit + "), e.g. data=\"" + f.example + "\"";
  }
  const mjtNum* v = m->numeric_data + m->numeric_adr[i];
  for (int j = 0; j < n; j++) {
    const double x = v[j];
    bool low = f.loopen ? !(x > f.lo) : !(x >= f.lo);
    if (!std::isfinite(x) || low || x > f.hi || (f.whole && x != std::floor(x))) {
      return at + " = " + fmt(x) + " is out of range: it must be " +
             (f.whole ? "a whole number " : "") + (f.loopen ? "> " : ">= ") + fmt(f.lo) +
             " and <= " + fmt(f.hi) + " [" + f.unit + "]; fix its data, e.g. data=\"" +
             f.example + "\"";
    }
  }
  return "";
}

// "<name>.<field>" split at the last dot (names may hold dots)
bool split(const char* rest, std::string* name, std::string* field) {
  const char* dot = std::strrchr(rest, '.');
  if (!dot || dot == rest || !dot[1]) return false;
  *name = std::string(rest, dot - rest);
  *field = dot + 1;
  return true;
}

std::string lineWho(const std::string& n) { return "line \"" + n + "\""; }

// site id of name for line ln's end field, or an error
std::string site(const mjModel* m, const std::string& ln, const char* field,
                 const std::string& name, int* id) {
  *id = mj_name2id(m, mjOBJ_SITE, name.c_str());
  if (*id >= 0) return "";
  return "mjbuoy: " + lineWho(ln) + " " + field + " names site \"" + name +
         "\", which the model does not have; add <site name=\"" + name +
         "\"/> to the body it attaches to, or fix the name";
}

std::string readNumeric(const mjModel* m, std::map<std::string, LineType>* types,
                        std::map<std::string, std::vector<char>>* tset,
                        std::map<std::string, LineIn>* lines, std::vector<std::string>* order,
                        Seabed* bed) {
  const size_t np = sizeof(kPre) - 1;
  for (int i = 0; i < m->nnumeric; i++) {
    const char* name = m->names + m->name_numericadr[i];
    if (std::strncmp(name, kPre, np)) continue;
    const char* key = name + np;
    const mjtNum* v = m->numeric_data + m->numeric_adr[i];
    std::string who, fld;
    if (!std::strncmp(key, "linetype.", 9)) {
      if (!split(key + 9, &who, &fld)) {
        return "mjbuoy: " + tag("numeric", name) + " is not mjbuoy.linetype.<type>.<field>";
      }
      const MField* f = find(kTypeFields, kNType, fld);
      if (!f) {
        return "mjbuoy: unknown entry " + tag("numeric", name) + "; line type fields are " +
               fields(kTypeFields, kNType) + " (docs/mooring.md)";
      }
      std::string e = check(m, i, *f, "line type \"" + who + "\"");
      if (!e.empty()) return e;
      LineType& t = (*types)[who];
      std::vector<char>& s = (*tset)[who];
      s.resize(kNType, 0);
      s[f - kTypeFields] = 1;
      double* dst[] = {&t.mass, &t.diam, &t.ea, &t.ba, &t.cdn, &t.cdt, &t.can, &t.cat};
      *dst[f - kTypeFields] = v[0];
    } else if (!std::strncmp(key, "line.", 5)) {
      if (!split(key + 5, &who, &fld)) {
        return "mjbuoy: " + tag("numeric", name) + " is not mjbuoy.line.<line>.<field>";
      }
      const MField* f = find(kLineFields, kNLine, fld);
      if (!f) {
        return "mjbuoy: unknown entry " + tag("numeric", name) + "; numeric line fields are " +
               fields(kLineFields, kNLine) + ", text fields type, anchor, fairlead";
      }
      std::string e = check(m, i, *f, lineWho(who));
      if (!e.empty()) return e;
      if (!lines->count(who)) order->push_back(who);
      LineIn& l = (*lines)[who];
      if (f == kLineFields) l.len = v[0], l.hasLen = true;
      if (f == kLineFields + 1) l.nseg = int(v[0]);
      if (f == kLineFields + 2) {
        for (int k = 0; k < 3; k++) l.anchorP[k] = v[k];
        l.hasAnchorP = true;
      }
    } else if (!std::strncmp(key, "seabed.", 7)) {
      const MField* f = find(kBedFields, kNBed, key + 7);
      if (!f) {
        return "mjbuoy: unknown entry " + tag("numeric", name) + "; seabed fields are " +
               fields(kBedFields, kNBed) + " (its depth is mjbuoy.sea.depth)";
      }
      std::string e = check(m, i, *f, "seabed");
      if (!e.empty()) return e;
      if (f == kBedFields) bed->k = v[0];
      if (f == kBedFields + 1) bed->c = v[0];
      if (f == kBedFields + 2) bed->mu[0] = v[0], bed->mu[1] = v[1];
      if (f == kBedFields + 3) bed->vs = v[0];
    }
  }
  return "";
}

std::string readText(const mjModel* m, std::map<std::string, LineIn>* lines,
                     std::vector<std::string>* order) {
  const size_t np = sizeof(kPre) - 1;
  for (int i = 0; i < m->ntext; i++) {
    const char* name = m->names + m->name_textadr[i];
    if (std::strncmp(name, kPre, np)) continue;
    const char* key = name + np;
    if (!isMoorEntry(key)) continue;
    std::string who, fld;
    if (std::strncmp(key, "line.", 5) || !split(key + 5, &who, &fld) ||
        (fld != "type" && fld != "anchor" && fld != "fairlead")) {
      return "mjbuoy: unknown entry " + tag("text", name) + "; text entries of lines are "
             "mjbuoy.line.<line>.type, .anchor (a site) and .fairlead (a site); line types and "
             "the seabed take numeric entries (docs/mooring.md)";
    }
    const char* text = m->text_data + m->text_adr[i];
    if (!lines->count(who)) order->push_back(who);
    LineIn& l = (*lines)[who];
    (fld == "type" ? l.type : fld == "anchor" ? l.anchor : l.fairlead) = text;
  }
  return "";
}

// fill one end from a site
void siteEnd(const mjModel* m, int id, LineEnd* e) {
  e->site = id;
  e->body = m->site_bodyid[id];
  e->moves = m->body_weldid[e->body] != 0;
}

// site positions at qpos0 [m] (attach-time only: allocates)
std::vector<double> sitesAtRest(const mjModel* m) {
  std::vector<double> p(3 * m->nsite);
  mjData* d = mj_makeData(m);
  if (!d) return p;
  mj_kinematics(m, d);
  for (int i = 0; i < 3 * m->nsite; i++) p[i] = d->site_xpos[i];
  mj_deleteData(d);
  return p;
}

// why line ln's entries are incomplete (type, its required fields, length, fairlead, one
// anchor), or ""
std::string lineInError(const std::string& ln, const LineIn& in,
                        const std::map<std::string, LineType>& types,
                        const std::map<std::string, std::vector<char>>& tset) {
  const char* need[3] = {"mass", "diameter", "ea"};
  const std::string at = "mjbuoy: " + lineWho(ln) + ": ";
  const std::string ent = "mjbuoy.line." + ln;
  if (in.type.empty()) {
    return at + "no type; add <text name=\"" + ent + ".type\" data=\"<type>\"/> naming a "
           "mjbuoy.linetype.<type>";
  }
  if (!types.count(in.type)) {
    return at + "type \"" + in.type + "\" has no mjbuoy.linetype." + in.type +
           ".* entries; define it (mass, diameter, ea at least) or fix the name";
  }
  for (int k = 0; k < 3; k++) {
    if (!tset.at(in.type)[k]) {
      return "mjbuoy: line type \"" + in.type + "\" has no " + need[k] + "; add <numeric "
             "name=\"mjbuoy.linetype." + in.type + "." + need[k] + "\" data=\"" +
             kTypeFields[k].example + "\"/> (" + kTypeFields[k].unit + ")";
    }
  }
  if (!in.hasLen) {
    return at + "no length; add <numeric name=\"" + ent + ".length\" data=\"250\"/> "
           "(unstretched length, m, > 0)";
  }
  if (in.fairlead.empty()) {
    return at + "no fairlead; add <text name=\"" + ent + ".fairlead\" data=\"<site>\"/>";
  }
  if (in.anchor.empty() == !in.hasAnchorP) {
    return at + "give exactly one anchor: a site, <text name=\"" + ent +
           ".anchor\" data=\"<site>\"/>, or a world point, <numeric name=\"" + ent +
           ".anchor\" data=\"x y z\"/>";
  }
  return "";
}

// line ln from its checked entries: its type, length, segments, and its ends at the sites'
// rest positions rest (m) or the anchor's world point; "" or the site's error
std::string buildLine(const mjModel* m, const std::string& ln, const LineIn& in,
                      const std::map<std::string, LineType>& types,
                      const std::vector<double>& rest, MoorLine* L) {
  L->line.name = ln;
  L->line.t = types.at(in.type);
  L->line.len = in.len;
  L->line.nseg = in.nseg;
  int id;
  std::string e;
  if (!in.anchor.empty()) {
    e = site(m, ln, "anchor", in.anchor, &id);
    if (!e.empty()) return e;
    siteEnd(m, id, &L->end[0]);
    for (int k = 0; k < 3; k++) L->end[0].p[k] = rest[3 * id + k];
  } else {
    for (int k = 0; k < 3; k++) L->end[0].p[k] = in.anchorP[k];
  }
  e = site(m, ln, "fairlead", in.fairlead, &id);
  if (!e.empty()) return e;
  siteEnd(m, id, &L->end[1]);
  for (int k = 0; k < 3; k++) L->end[1].p[k] = rest[3 * id + k];
  return "";
}

// the bed's height (m) and the sorted, unique bodies that line ends move with
void placeBedAndBodies(const Sea& sea, Mooring* mo) {
  // the bed: at the sea's depth; in a deep sea (no depth) at the lowest
  // anchor that cannot move, and none when every anchor moves
  double low = INFINITY;
  for (const MoorLine& L : mo->line) {
    if (!L.end[0].moves) low = std::fmin(low, L.end[0].p[2]);
  }
  if (sea.depth > 0) {
    mo->bed.z = sea.level - sea.depth;
  } else {
    mo->defaultBed = true;
    mo->bed.z = std::isfinite(low) ? low : -1e30;
  }
  for (const MoorLine& L : mo->line) {
    for (const LineEnd& n : L.end) if (n.moves) mo->body.push_back(n.body);
  }
  std::sort(mo->body.begin(), mo->body.end());
  mo->body.erase(std::unique(mo->body.begin(), mo->body.end()), mo->body.end());
}

// each line's derived quantities; an error for a fixed end below the bed, a warning for ends
// farther apart than the line's length plus kOverStrain
std::string deriveLines(const Sea& sea, Mooring* mo, std::vector<std::string>* warn) {
  LineWater w = {&sea, &mo->bed, sea.level, 0};
  for (MoorLine& L : mo->line) {
    Line& l = L.line;
    for (int k = 0; k < 2; k++) {
      if (L.end[k].moves || L.end[k].p[2] >= mo->bed.z - 1e-6) continue;
      return "mjbuoy: " + lineWho(l.name) + ": its " + (k ? "fairlead" : "anchor") +
             " at z = " + fmt(L.end[k].p[2]) + " m is below the seabed at z = " +
             fmt(mo->bed.z) + " m (mjbuoy.sea.level - mjbuoy.sea.depth); raise it or set "
             "mjbuoy.sea.depth";
    }
    std::string e = lineDerive(w, &l);
    if (!e.empty()) return e;
    double span = 0;
    for (int k = 0; k < 3; k++) span += std::pow(L.end[1].p[k] - L.end[0].p[k], 2);
    span = std::sqrt(span);
    if (span > (1 + kOverStrain) * l.len) {
      warn->push_back("line \"" + l.name + "\": its ends are " + fmt(span) +
                      " m apart at the model's rest pose, more than its length " + fmt(l.len) +
                      " m plus " + fmt(100 * kOverStrain) + "%: it starts overloaded");
    }
  }
  return "";
}

}  // namespace

bool isMoorEntry(const char* key) {
  return !std::strncmp(key, "line.", 5) || !std::strncmp(key, "linetype.", 9) ||
         !std::strncmp(key, "seabed.", 7);
}

bool hasLines(const mjModel* m) {
  for (int i = 0; i < m->nnumeric; i++) {
    if (!std::strncmp(m->names + m->name_numericadr[i], "mjbuoy.line.", 12)) return true;
  }
  for (int i = 0; i < m->ntext; i++) {
    if (!std::strncmp(m->names + m->name_textadr[i], "mjbuoy.line.", 12)) return true;
  }
  return false;
}

std::string parseMooring(const mjModel* m, const Sea& sea, Mooring* mo,
                         std::vector<std::string>* warn) {
  *mo = Mooring();
  std::map<std::string, LineType> types;
  std::map<std::string, std::vector<char>> tset;
  std::map<std::string, LineIn> lines;
  std::vector<std::string> order;
  std::string e = readNumeric(m, &types, &tset, &lines, &order, &mo->bed);
  if (e.empty()) e = readText(m, &lines, &order);
  if (!e.empty()) return e;
  if (order.empty()) return "";
  std::vector<double> rest = sitesAtRest(m);
  for (const std::string& ln : order) {
    const LineIn& in = lines[ln];
    e = lineInError(ln, in, types, tset);
    if (!e.empty()) return e;
    MoorLine L;
    e = buildLine(m, ln, in, types, rest, &L);
    if (!e.empty()) return e;
    mo->line.push_back(L);
  }
  placeBedAndBodies(sea, mo);
  return deriveLines(sea, mo, warn);
}

}  // namespace mjb
