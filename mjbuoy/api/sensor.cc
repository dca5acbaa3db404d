// sensors: fill MuJoCo user sensors bound by "mjbuoy.sensor.<sensor>"
// <custom> text entries (docs/mjcf.md "Sensors", docs/physics.md section 9).
//
// MuJoCo 2.2 calls mjcb_sensor(m, d, stage) from mj_sensorPos, mj_sensorVel
// and mj_sensorAcc, each only when a user sensor needs that stage
// (sensor_needstage). mjcb_passive, where mjbuoy computes its forces, runs in
// mj_fwdVelocity, after mj_sensorPos and before mj_sensorVel: the surface
// elevations depend on positions and time only and work at any stage; the
// volume, area and wrench need stage vel or acc to be of this mj_forward.
#include "api/sensor.h"

#include <cmath>
#include <cstring>

#include "api/buoy.h"

namespace mjb {

namespace {

const char kPre[] = "mjbuoy.sensor.";

struct Quantity {
  const char* word;
  int kind, dim, part;
  bool site;   // bound to a site (else a body)
  bool force;  // needs this mj_forward's passive call: stage vel or acc
};

const Quantity kQuantity[] = {
    {"elevation", kSensElevation, 1, 0, true, false},
    {"relative_elevation", kSensRelElevation, 1, 0, true, false},
    {"submerged_volume", kSensVolume, 1, 0, false, true},
    {"wetted_area", kSensArea, 1, 0, false, true},
    {"wrench", kSensWrench, 6, mjbNPART, false, true},
};

const char* const kFamily[mjbNPART] = {"pressure", "viscous", "drag", "slam", "damping",
                                       "wind"};

const char kWords[] =
    "elevation, relative_elevation, submerged_volume, wetted_area, wrench, "
    "wrench pressure|viscous|drag|slam|damping|wind, fairlead_tension <line>, "
    "anchor_tension <line>, seabed_length <line>";

// a mooring line quantity: "fairlead_tension <line>", "anchor_tension
// <line>" (dim 1: magnitude, dim 3: the force on the end, world frame) or
// "seabed_length <line>" (docs/mooring.md "Sensors"); false if w[0] is none
bool bindLine(const Buoy& b, int id, const std::string& at, const std::string w[3], int nw,
              Sensor* out, std::string* err) {
  const bool fl = w[0] == "fairlead_tension", an = w[0] == "anchor_tension";
  if (!fl && !an && w[0] != "seabed_length") return false;
  const mjModel* m = b.m;
  out->id = id;
  out->kind = fl || an ? kSensTension : kSensBedLength;
  out->part = fl ? 1 : 0;
  out->obj = -1;
  for (size_t i = 0; nw == 2 && i < b.moor.line.size(); i++) {
    if (b.moor.line[i].line.name == w[1]) out->obj = i;
  }
  if (out->obj < 0) {
    *err = at + ": " + w[0] + " needs the name of a mooring line (mjbuoy.line.<line>.*), "
           "e.g. data=\"" + w[0] + " <line>\"";
    return true;
  }
  const int dim = m->sensor_dim[id];
  if (out->kind == kSensTension ? dim != 1 && dim != 3 : dim != 1) {
    *err = at + ": " + w[0] + " has dim=\"" + std::to_string(dim) + "\"; set dim=\"1\"" +
           (out->kind == kSensTension ? " (the tension) or dim=\"3\" (the force vector)" : "");
    return true;
  }
  if (m->sensor_needstage[id] == mjSTAGE_POS) {
    *err = at + ": " + w[0] + " is computed with the forces, after the position stage; set "
           "needstage=\"vel\" or \"acc\" on the user sensor";
  }
  return true;
}

std::string where(const char* sensor) {
  return std::string("mjbuoy: sensor \"") + sensor + "\" (<text name=\"" + kPre + sensor + "\">)";
}

// split data into its words (at most 3)
int words(const char* text, std::string w[3]) {
  int n = 0;
  const char* p = text;
  while (*p) {
    while (*p == ' ' || *p == '\t' || *p == '\n') p++;
    if (!*p) break;
    const char* e = p;
    while (*e && *e != ' ' && *e != '\t' && *e != '\n') e++;
    if (n < 3) w[n] = std::string(p, e - p);
    n++;
    p = e;
  }
  return n;
}

std::string bind(const Buoy& b, const char* name, const char* text, Sensor* out) {
  const mjModel* m = b.m;
  std::string at = where(name);
  int id = mj_name2id(m, mjOBJ_SENSOR, name);
  if (id < 0) {
    return at + ": the model has no sensor of that name; add <sensor><user name=\"" +
           std::string(name) + "\" .../></sensor> or fix the entry's name";
  }
  if (m->sensor_type[id] != mjSENS_USER) {
    return at + ": is not a user sensor; mjbuoy fills only <user> sensors";
  }
  std::string w[3];
  int nw = words(text, w);
  std::string lerr;
  if (nw >= 1 && bindLine(b, id, at, w, nw, out, &lerr)) return lerr;
  const Quantity* q = nullptr;
  for (const Quantity& k : kQuantity) {
    if (nw >= 1 && w[0] == k.word) q = &k;
  }
  if (!q || nw > (q->kind == kSensWrench ? 2 : 1)) {
    return at + ": data \"" + text + "\" is not a quantity; use one of " + kWords;
  }
  out->id = id;
  out->kind = q->kind;
  out->part = q->part;
  if (nw == 2) {
    out->part = -1;
    for (int p = 0; p < mjbNPART; p++) {
      if (w[1] == kFamily[p]) out->part = p;
    }
    if (out->part < 0) {
      return at + ": \"" + w[1] + "\" is not a force family; use pressure, viscous, drag, "
             "slam, damping or wind, or plain \"wrench\" for the total";
    }
  }
  if (m->sensor_dim[id] != q->dim) {
    return at + ": " + q->word + " has " + std::to_string(q->dim) + " value(s) but the sensor has dim=\"" +
           std::to_string(m->sensor_dim[id]) + "\"; set dim=\"" + std::to_string(q->dim) + "\"";
  }
  int ot = m->sensor_objtype[id], oid = m->sensor_objid[id];
  if (q->site) {
    if (ot != mjOBJ_SITE || oid < 0) {
      return at + ": " + q->word + " is measured at a site; give the user sensor "
             "objtype=\"site\" objname=\"<site>\"";
    }
    out->obj = oid;
    out->h0 = out->h1 = 0;
    return "";
  }
  if ((ot != mjOBJ_BODY && ot != mjOBJ_XBODY) || oid < 0) {
    return at + ": " + q->word + " belongs to a hull body; give the user sensor "
           "objtype=\"body\" objname=\"<body>\"";
  }
  out->obj = oid;
  out->h0 = out->h1 = -1;
  for (size_t h = 0; h < b.hull.size(); h++) {
    if (b.hull[h].body != oid) continue;
    if (out->h0 < 0) out->h0 = h;
    out->h1 = h + 1;
  }
  if (out->h0 < 0) {
    return at + ": body \"" + (m->names + m->name_bodyadr[oid]) +
           "\" carries no mjbuoy hull; bind it to a body with a geom listed in mjbuoy.hulls";
  }
  if (m->sensor_needstage[id] == mjSTAGE_POS) {
    return at + ": " + q->word + " is computed with the forces, after the position stage; "
           "set needstage=\"vel\" or \"acc\" on the user sensor";
  }
  if (q->kind == kSensArea && b.gl) {
    return at + ": wetted_area needs the cpu backend (the gl backend reads back only the "
           "wrench); set <text name=\"mjbuoy.backend\" data=\"cpu\"/>";
  }
  return "";
}

}  // namespace

std::string parseSensors(Buoy* b) {
  const mjModel* m = b->m;
  const size_t np = std::strlen(kPre);
  b->sensor.clear();
  for (int i = 0; i < m->ntext; i++) {
    const char* name = m->names + m->name_textadr[i];
    if (std::strncmp(name, kPre, np)) continue;
    Sensor s;
    std::string e = bind(*b, name + np, m->text_data + m->text_adr[i], &s);
    if (!e.empty()) return e;
    b->sensor.push_back(s);
  }
  return "";
}

void fillSensors(const Buoy& b, const mjModel* m, mjData* d, const State* s, int stage) {
  const int nb6 = 6 * m->nbody;
  for (const Sensor& q : b.sensor) {
    if (m->sensor_needstage[q.id] != stage) continue;
    mjtNum* out = d->sensordata + m->sensor_adr[q.id];
    switch (q.kind) {
      case kSensElevation:
      case kSensRelElevation: {
        const mjtNum* x = d->site_xpos + 3 * q.obj;
        double eta = b.cfg.sea.height(x[0], x[1], d->time);
        out[0] = q.kind == kSensElevation ? eta : eta - x[2];
        break;
      }
      case kSensVolume:
        // the vertical pressure force over rho g: the wet volume under a
        // flat surface, by the divergence theorem (physics.md section 9)
        if (s) out[0] = s->part[mjbPART_PRESSURE * nb6 + 6 * q.obj + 2] / (b.cfg.sea.rho * b.cfg.sea.g);
        break;
      case kSensArea:
        if (s) {
          double a = 0;
          for (int h = q.h0; h < q.h1; h++) a += s->hwet[h];
          out[0] = a;
        }
        break;
      case kSensTension:
        if (s && s->moor.key >= 0) {
          const double* f = &s->moor.fend[6 * q.obj + 3 * q.part];
          if (m->sensor_dim[q.id] == 1) {
            out[0] = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
          } else {
            for (int j = 0; j < 3; j++) out[j] = f[j];
          }
        }
        break;
      case kSensBedLength:
        if (s && s->moor.key >= 0) out[0] = s->moor.ls[q.obj].bedlen;
        break;
      case kSensWrench:
        if (s) {
          const double* w = q.part == mjbNPART ? s->wrench.data() + 6 * q.obj
                                               : s->part.data() + q.part * nb6 + 6 * q.obj;
          for (int j = 0; j < 6; j++) out[j] = w[j];
        }
        break;
    }
  }
}

}  // namespace mjb
