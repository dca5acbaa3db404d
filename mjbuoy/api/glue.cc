// MuJoCo glue: public API, registry of attached models, mjcb_passive
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <thread>

#include "api/buoy.h"
#include "hull/hull.h"
#include "hull/windload.h"
#include "util/pool.h"
#include "api/radattach.h"
#include "radiation/radiation.h"
#include "mjbuoy.h"
#include "api/seasetter.h"

using mjb::Buoy;
using mjb::State;

struct mjbBuoy_ {
  Buoy b;
  std::shared_mutex mu;                               // guards data
  std::map<const mjData*, std::unique_ptr<State>> data;
};

namespace {

// attached models; the callback looks its model up here. gattached is also
// the registry of live handles: mjb_detach of anything else is a no-op
std::shared_mutex gmu;
std::vector<mjbBuoy*> gattached;

// the mjcb_passive chain (docs/robustness.md). Installing pushes the
// callback found in mjcb_passive, detaching the last model pops it back if
// mjbuoy's trampoline is still installed. A user's callback installed after
// mjb_attach that chains to the trampoline stays on top when mjbuoy
// detaches; a later attach then pushes that user callback, which calls the
// trampoline again from inside itself. The trampoline counts its nesting
// per thread: at depth k it calls the k-th callback down the chain, and
// mjbuoy adds its forces only at depth 1, so no call recurses and each
// callback runs once per evaluation.
std::vector<mjfGeneric> gchain;
thread_local int gdepth = 0;
mjfSensor gprevSensor = nullptr;  // mjcb_sensor found then, chained too

mjbBuoy* find(const mjModel* m) {
  for (mjbBuoy* b : gattached) if (b->b.m == m) return b;
  return nullptr;
}

bool hasEntries(const mjModel* m) {
  for (int i = 0; i < m->nnumeric; i++) {
    if (!std::strncmp(m->names + m->name_numericadr[i], "mjbuoy.", 7)) return true;
  }
  for (int i = 0; i < m->ntext; i++) {
    if (!std::strncmp(m->names + m->name_textadr[i], "mjbuoy.", 7)) return true;
  }
  return false;
}

// once per mjData episode: the callback runs inside fwdVelocity, whose
// count is 0 until the first evaluation of a new (or reset) mjData ends.
// Keyed on the data, not on model addresses, which a deleted model recycles
void warnUnknown(const mjModel* m, const mjData* d) {
  if (d->timer[mjTIMER_VELOCITY].number != 0 || !hasEntries(m)) return;
  mju_warning("mjbuoy: a model with mjbuoy.* entries was stepped without mjb_attach (a copy "
              "made with mj_copyModel?): it gets no buoyancy. Attach every copy: "
              "mjb_attach(copy, ...)");
}

// is s stale for d: d is another mjData at a recycled address or was reset.
// The callback runs inside fwdVelocity, whose count d->timer[VELOCITY]
// rises by one when the stage ends: outside a callback, a count at or below
// the one stamped means that stage never ended for this d (a new mjData, or
// mj_resetData zeroing the timers). Another buffer, or time below the first
// call of the current step, says the same.
bool stale(const State* s, const mjData* d) {
  long n = d->timer[mjTIMER_VELOCITY].number;
  // time is compared with the first call of the current step (stepClock):
  // the stages of one RK4 step move it back and forth
  return d->buffer != s->buf || (gdepth > 0 ? n < s->vcount : n <= s->vcount) ||
         (s->key >= 0 && d->time < s->tcur);
}

// forget what s knew of an earlier mjData or episode
void renew(State* s, const mjData* d) {
  std::fill(s->wrench.begin(), s->wrench.end(), 0.0);
  std::fill(s->part.begin(), s->part.end(), 0.0);
  std::fill(s->bad.begin(), s->bad.end(), 0);
  std::fill(s->told.begin(), s->told.end(), 0);
  std::fill(s->dwrench.begin(), s->dwrench.end(), 0.0);
  std::fill(s->dtold.begin(), s->dtold.end(), 0);
  s->notices.clear();
  s->key = -1;
  s->hasPrev = false;
  s->buf = d->buffer;
  s->vcount = -1;
  mjb::radRestart(&s->rad);
}

}  // namespace

void mjb::makeState(const Buoy& b, State* s) {
  const size_t nw = std::max(b.wcap, b.cfg.sea.waves.size());
  mjb::makeHullState(b, nw, s);
  mjb::makeCpuState(b, b.cfg.sea, b.wcap, b, &s->cpu);
  s->dwrench.assign(6 * b.diff.db.size(), 0);
  s->dtold.assign(b.diff.db.size(), 0);
}

namespace {

// the state of d, renewed if it is stale; fresh says the state was created
State* state(mjbBuoy* b, const mjData* d, bool create) {
  State* s = nullptr;
  {
    std::shared_lock<std::shared_mutex> lk(b->mu);
    auto it = b->data.find(d);
    if (it != b->data.end()) s = it->second.get();
  }
  if (!s) {
    if (!create) return nullptr;
    std::unique_lock<std::shared_mutex> lk(b->mu);
    auto& u = b->data[d];
    if (!u) {
      u = std::make_unique<State>();
      mjb::makeState(b->b, u.get());
      mjb::radMakeState(b->b.rad, &u->rad);
      u->buf = d->buffer;
    }
    s = u.get();
  }
  if (stale(s, d)) renew(s, d);
  return s;
}

// mj_applyFT restricted to the dofs that move body: the same J^T [f; tq]
// (J from cdof as in mj_jac) without clearing and scanning all nv columns,
// which made a fleet of n free boats cost O(n^2) per step
void applyFT(const mjModel* m, mjData* d, const mjtNum f[3], const mjtNum tq[3],
             const mjtNum pt[3], int body, mjtNum* qfrc) {
  mjtNum off[3];
  mju_sub3(off, pt, d->subtree_com + 3 * m->body_rootid[body]);
  while (body && !m->body_dofnum[body]) body = m->body_parentid[body];
  if (!body) return;
  for (int i = m->body_dofadr[body] + m->body_dofnum[body] - 1; i >= 0; i = m->dof_parentid[i]) {
    const mjtNum* c = d->cdof + 6 * i;  // [angular; linear] motion of dof i
    mjtNum t[3];
    mju_cross(t, c, off);
    qfrc[i] += (c[3] + t[0]) * f[0] + (c[4] + t[1]) * f[1] + (c[5] + t[2]) * f[2];
    qfrc[i] += c[0] * tq[0] + c[1] * tq[1] + c[2] * tq[2];
  }
}

// forces of one evaluation for an attached model
void compute(mjbBuoy* b, const mjModel* m, mjData* d) {
  State* s = state(b, d, true);
  if (b->b.gl) {
    mjb::glWrench(b->b.gl, b->b, b->b.cfg.sea, m, d, s, &s->gl);
  } else {
    mjb::cpuWrench(b->b, b->b.cfg.sea, b->b, m, d, s, &s->cpu);
  }
  const Buoy& B = b->b;
  const mjb::WindIO io = {B.gl ? nullptr : s->h.data(), s->crest, s->bad.data(),
                          s->part.data() + 6 * m->nbody * mjbPART_WIND, s->wrench.data()};
  mjb::windWrench(B, B.wind, B.cfg.sea, m, d, io);
  for (int bd : b->b.body) {
    const mjtNum* w = s->wrench.data() + 6 * bd;
    applyFT(m, d, w, w + 3, d->xipos + 3 * bd, bd, d->qfrc_passive);
  }
  // wind on superstructure bodies that carry no hull (hull/windload.cc)
  for (int bd : b->b.wind.extra) {
    const mjtNum* w = s->wrench.data() + 6 * bd;
    applyFT(m, d, w, w + 3, d->xipos + 3 * bd, bd, d->qfrc_passive);
  }
  // added mass into qM, Kirchhoff and memory forces (radstep.cc), scaled
  // by each body's immersion from this call's pressure force
  if (!b->b.rad.rb.empty()) {
    const mjb::Sea& sea = b->b.cfg.sea;
    mjb::radImmersion(b->b.rad, s->part.data() + 6 * m->nbody * mjbPART_PRESSURE, s->bad.data(),
                      s->badPart.data() + mjbPART_PRESSURE, mjbNPART, sea.rho * sea.g, &s->rad);
  }
  mjb::radiationStep(b->b.rad, m, d, &s->rad, b->b.cfg.sea, &s->notices, b->b.pool);
  // diffraction excitation of the same bodies, per wave component (diffract.cc)
  const mjb::Diffraction& df = b->b.diff;
  if (!df.db.empty()) {
    mjb::diffractionStep(df, b->b.cfg.sea, m, d, s->dwrench.data(), s->dtold.data(),
                         &s->notices);
    for (size_t i = 0; i < df.db.size(); i++) {
      mjtNum* w = s->dwrench.data() + 6 * i;
      int bd = df.db[i].body;
      // a diffraction force acts on the wetted surface (immersion factor)
      const int ri = df.db[i].ri;
      if (ri >= 0) for (int j = 0; j < 6; j++) w[j] *= s->rad.imm[ri];
      applyFT(m, d, w, w + 3, d->xipos + 3 * bd, bd, d->qfrc_passive);
    }
  }
  s->vcount = d->timer[mjTIMER_VELOCITY].number;
}

// the trampoline installed in mjcb_passive (see gchain)
void passive(const mjModel* m, mjData* d) {
  struct Depth {
    Depth() { gdepth++; }
    ~Depth() { gdepth--; }
  } depth;
  mjfGeneric next = nullptr;
  mjbBuoy* b;
  {
    std::shared_lock<std::shared_mutex> lk(gmu);
    int k = int(gchain.size()) - gdepth;
    if (k >= 0) next = gchain[k];
    b = gdepth == 1 ? find(m) : nullptr;
  }
  if (next && next != passive) next(m, d);
  if (gdepth != 1) return;
  if (!b) {
    warnUnknown(m, d);
    return;
  }
  if (!b->b.hull.empty() || !b->b.wind.body.empty() || !b->b.rad.rb.empty()) compute(b, m, d);
}

// user sensors: the user's callback first, then the ones mjbuoy binds
// (sensor.cc), so a sensor bound to mjbuoy gets mjbuoy's value
void sensorcb(const mjModel* m, mjData* d, int stage) {
  if (gprevSensor) gprevSensor(m, d, stage);
  mjbBuoy* b;
  {
    std::shared_lock<std::shared_mutex> lk(gmu);
    b = find(m);
  }
  if (!b || b->b.sensor.empty()) return;
  mjb::fillSensors(b->b, m, d, state(b, d, false), stage);
}

// cpu threads: mjbuoy.threads, or with 0 (auto) every core (up to
// kMaxAuto) once the scene has kParMin triangles: below that the few us of
// handing chunks to a worker are not repaid (docs/mjcf.md); never more
// than the hulls' chunks (mjb::hullChunks). The hulls are cut at body
// boundaries into kChunks chunks per thread of about equal triangle
// counts, claimed dynamically so a busy core does not stall a step; with
// fewer bodies than 2 per thread that cannot balance, and each hull is
// split among the threads instead (cpu.cc hullWrench)
const int kParMin = 2000, kMaxAuto = 8, kChunks = 4;

void threads(Buoy* B) {
  int n = B->cfg.threads;
  if (n == 0) {
    n = int(B->face.size() / 3) >= kParMin ? int(std::thread::hardware_concurrency()) : 1;
    n = std::max(1, std::min(n, kMaxAuto));
  }
  int parts = 0;
  for (const mjb::Hull& h : B->hull) parts += mjb::hullChunks(h.nt);
  n = std::max(1, std::min(n, parts));
  B->splitHulls = int(B->body.size()) < 2 * n;
  int nc = std::min(n > 1 ? kChunks * n : 1, int(B->body.size()));
  B->split.assign(1, 0);
  long total = B->face.size() / 3, acc = 0;
  for (size_t h = 0; h < B->hull.size(); h++) {
    acc += B->hull[h].nt;
    bool bodyEnd = h + 1 == B->hull.size() || B->hull[h + 1].body != B->hull[h].body;
    long part = B->split.size();  // the chunk this boundary would close
    if (bodyEnd && part < nc && acc * nc >= total * part) B->split.push_back(h + 1);
  }
  if (B->split.back() != int(B->hull.size())) B->split.push_back(B->hull.size());
  B->nthreads = n;
  if (n > 1) B->pool = mjb::poolMake(n - 1);
  if (!B->pool) {
    B->nthreads = 1;
    B->split = {0, int(B->hull.size())};
    B->splitHulls = false;
  }
}

void copyError(const std::string& e, char* error, int error_sz) {
  if (error && error_sz > 0) std::snprintf(error, error_sz, "%s", e.c_str());
}

// the hull set of B.m from B.cfg: each hull geom's mesh, grouped by body
// so each body's triangles are contiguous, its triangle areas, mass share
// and bounding radius; "" or the error
std::string makeHulls(Buoy* b) {
  Buoy& B = *b;
  const mjModel* m = B.m;
  std::vector<int> order = B.cfg.geom;
  std::stable_sort(order.begin(), order.end(), [&](int a, int c) {
    return m->geom_bodyid[a] < m->geom_bodyid[c];
  });
  std::vector<std::string>& warn = B.cfg.warn;
  for (int g : order) {
    size_t k = std::find(B.cfg.geom.begin(), B.cfg.geom.end(), g) - B.cfg.geom.begin();
    std::string se = mjb::sizeError(m, g);
    if (!se.empty()) return se;
    mjb::Mesh mesh = mjb::hullMesh(m, g, &warn);
    mjb::Hull h;
    h.geom = g;
    h.body = m->geom_bodyid[g];
    h.v0 = B.vert.size() / 3;
    h.nv = mesh.nv();
    h.t0 = B.face.size() / 3;
    h.nt = mesh.nf();
    h.par = B.cfg.param[k];
    h.radDrag = B.cfg.radDrag[k];
    h.area = 0;
    // all that moves rigidly with it: a hull on a massless child welded to
    // its parent still stops the parent
    h.mass = m->body_subtreemass[m->body_weldid[h.body]];
    for (int f = 0; f < mesh.nf(); f++) {
      const double* a = &mesh.v[3 * mesh.f[3 * f]];
      const double* bb = &mesh.v[3 * mesh.f[3 * f + 1]];
      const double* c = &mesh.v[3 * mesh.f[3 * f + 2]];
      mjtNum u[3], v[3], x[3];
      for (int j = 0; j < 3; j++) {
        u[j] = bb[j] - a[j];
        v[j] = c[j] - a[j];
      }
      mju_cross(x, u, v);
      B.tarea.push_back(0.5 * mju_norm3(x));
      h.area += B.tarea.back();
    }
    if (!(h.area > 0)) {
      return std::string("mjbuoy: hull geom \"") + (m->names + m->name_geomadr[g]) +
             "\" has no surface area (no faces, or all faces degenerate); "
             "give it a closed triangle mesh";
    }
    B.vert.insert(B.vert.end(), mesh.v.begin(), mesh.v.end());
    for (int i : mesh.f) B.face.push_back(i + h.v0);
    B.hull.push_back(h);
    if (B.body.empty() || B.body.back() != h.body) B.body.push_back(h.body);
  }
  // the mass a rigid group carries is shared among its hulls by area
  // (slamming stops it)
  for (mjb::Hull& h : B.hull) {
    double s = 0;
    for (const mjb::Hull& o : B.hull) {
      if (m->body_weldid[o.body] == m->body_weldid[h.body]) s += o.area;
    }
    h.share = h.area / s;
    h.mass *= h.share;
  }
  // bounding radius of each hull about its body origin (vertices are in the
  // body frame), for skipping hulls entirely above the waves
  for (mjb::Hull& h : B.hull) {
    h.rad = 0;
    for (int i = h.v0; i < h.v0 + h.nv; i++) h.rad = std::max(h.rad, mju_norm3(&B.vert[3 * i]));
  }
  return "";
}

// the backend B->cfg.backend asks for: gl when asked (or, with auto, when
// an EGL display with GL >= 4.3 compute is there), else cpu with a
// notice; "" or the error when gl is required and not available
std::string chooseBackend(Buoy* b) {
  Buoy& B = *b;
  B.renderer = "CPU";
  if (B.cfg.backend == "cpu") return "";
  std::string ge;
  if (!B.hull.empty() && mjb::glMake(B, B.cfg.sea, B.wcap, &B.gl, &B.renderer, &ge)) {
    B.cfg.backend = "gl";
  } else if (B.cfg.backend == "gl" && !B.hull.empty()) {
    return "mjbuoy: backend gl is not available: " + ge +
           "; use backend cpu or auto (docs/mjcf.md)";
  } else {
    if (!B.hull.empty()) {
      B.cfg.warn.push_back("backend auto: no usable GL (" + ge + "); running on cpu");
    }
    B.cfg.backend = "cpu";
  }
  return "";
}

}  // namespace

mjbBuoy* mjb_attach(const mjModel* m, const char* backend, char* error, int error_sz) {
  copyError("", error, error_sz);
  if (!m) {
    copyError("mjbuoy: mjb_attach was given a NULL model", error, error_sz);
    return nullptr;
  }
  auto b = std::make_unique<mjbBuoy>();
  Buoy& B = b->b;
  B.m = m;
  std::string e = mjb::parseConfig(m, &B.cfg);
  if (e.empty() && backend) e = mjb::setBackend(backend, "the backend argument", &B.cfg);
  if (!e.empty()) {
    copyError(e, error, error_sz);
    return nullptr;
  }

  e = makeHulls(&B);
  if (!e.empty()) {
    copyError(e, error, error_sz);
    return nullptr;
  }
  // room for mjb_setSea, and the wind's surfaces
  B.wcap = std::max<size_t>(B.cfg.capacity, B.cfg.sea.waves.size());
  B.cfg.sea.waves.reserve(B.wcap);
  B.cfg.sea.order.reserve(B.wcap);  // Sea::derive rebuilds it in mjb_setSea
  mjb::windMake(B, B.cfg.wind, &B.cfg.warn, &B.wind);
  // radiation (on by default for free hull bodies, seconds per hull:
  // docs/mjcf.md section 11), before the backend: a group it skips takes
  // back its linear drag terms (radattach.cc skipGroup), which the gl
  // backend copies at setup
  e = mjb::attachRadiation(&B);
  if (!e.empty()) {
    copyError(e, error, error_sz);
    mjb::restoreModel(m, B.rad);
    return nullptr;
  }
  // gl: required; auto: gl when there, else cpu with a notice
  e = chooseBackend(&B);
  if (!e.empty()) {
    copyError(e, error, error_sz);
    mjb::restoreModel(m, B.rad);
    return nullptr;
  }
  for (const std::string& w : B.cfg.warn) B.warnings += "mjbuoy: warning: " + w + "\n";
  if (B.cfg.backend == "cpu") threads(&B);
  e = mjb::parseSensors(&B);
  if (!e.empty()) {
    copyError(e, error, error_sz);
    mjb::restoreModel(m, B.rad);
    mjb::glFree(&B.gl);
    mjb::poolFree(B.pool);
    return nullptr;
  }

  mjbBuoy* out = b.release();
  std::unique_lock<std::shared_mutex> lk(gmu);
  if (gattached.empty() && mjcb_passive != passive) {
    // nothing can chain to mjbuoy through an empty slot: older entries are gone
    if (!mjcb_passive) gchain.clear();
    gchain.push_back(mjcb_passive);
    mjcb_passive = passive;
  }
  if (gattached.empty() && mjcb_sensor != sensorcb) {
    gprevSensor = mjcb_sensor;
    mjcb_sensor = sensorcb;
  }
  gattached.push_back(out);
  return out;
}

void mjb_detach(mjbBuoy* b) {
  if (!b) return;
  {
    std::unique_lock<std::shared_mutex> lk(gmu);
    auto it = std::find(gattached.begin(), gattached.end(), b);
    if (it == gattached.end()) {
      lk.unlock();
      mju_warning("mjbuoy: mjb_detach was given a handle that is not attached (detached "
                  "already?); ignored. A handle is invalid after mjb_detach");
      return;
    }
    gattached.erase(it);
    if (gattached.empty() && mjcb_passive == passive && !gchain.empty()) {
      mjcb_passive = gchain.back();
      gchain.pop_back();
    }
    if (gattached.empty() && mjcb_sensor == sensorcb) {
      mjcb_sensor = gprevSensor;
      gprevSensor = nullptr;
    }
  }
  for (auto& kv : b->data) mjb::glFreeState(b->b.gl, &kv.second->gl);
  mjb::restoreModel(b->b.m, b->b.rad);
  mjb::glFree(&b->b.gl);
  mjb::poolFree(b->b.pool);
  delete b;
}

int mjb_bindData(mjbBuoy* b, const mjData* d) {
  if (!b || !d) return 0;
  return state(b, d, true) != nullptr;
}

void mjb_unbindData(mjbBuoy* b, const mjData* d) {
  if (!b) return;
  std::unique_lock<std::shared_mutex> lk(b->mu);
  auto it = b->data.find(d);
  if (it == b->data.end()) return;
  mjb::glFreeState(b->b.gl, &it->second->gl);
  b->data.erase(it);
}

int mjb_copyData(mjbBuoy* b, mjData* dst, const mjData* src) {
  if (!b || !dst || !src) return 0;
  if (dst == src) return 1;
  State* s = state(b, src, false);
  if (!s) {
    mjb_unbindData(b, dst);  // src has no history: neither may dst
    return 1;
  }
  State* t = state(b, dst, true);
  // dst's own GL buffers (glCopyState copies into them)
  unsigned keep[3] = {t->gl.slambuf[0], t->gl.slambuf[1], t->gl.offbuf};
  *t = *s;
  t->gl.slambuf[0] = keep[0];
  t->gl.slambuf[1] = keep[1];
  t->gl.offbuf = keep[2];
  t->notices.reserve(s->notices.capacity());
  t->buf = dst->buffer;  // dst's counters and time are src's after mj_copyData
  return mjb::glCopyState(b->b.gl, &t->gl, &s->gl) ? 1 : 0;
}

const mjtNum* mjb_wrench(const mjbBuoy* b, const mjData* d) {
  if (!b) return nullptr;
  State* s = state(const_cast<mjbBuoy*>(b), d, false);
  return s ? s->wrench.data() : nullptr;
}

const mjtNum* mjb_wrenchPart(const mjbBuoy* b, const mjData* d, int part) {
  if (!b || part < 0 || part >= mjbNPART) return nullptr;
  State* s = state(const_cast<mjbBuoy*>(b), d, false);
  return s ? s->part.data() + 6 * b->b.m->nbody * part : nullptr;
}

const char* mjb_notices(const mjbBuoy* b, const mjData* d) {
  if (!b) return "";
  State* s = state(const_cast<mjbBuoy*>(b), d, false);
  return s ? s->notices.c_str() : "";
}

mjbInfo mjb_info(const mjbBuoy* b) {
  mjbInfo i = {0, 0, 0, 0, "", ""};
  if (!b) return i;
  i.nhull = b->b.hull.size();
  i.nbody = b->b.body.size();
  i.ntri = b->b.face.size() / 3;
  i.nvert = b->b.vert.size() / 3;
  i.backend = b->b.cfg.backend.c_str();
  i.renderer = b->b.renderer.c_str();
  return i;
}

int mjb_stageTimes(const mjbBuoy* b, const char** name, double* ms, int n) {
  return b ? mjb::glStageTimes(b->b.gl, name, ms, n) : 0;
}

const char* mjb_warnings(const mjbBuoy* b) {
  return b ? b->b.warnings.c_str() : "";
}

int mjb_setSea(mjbBuoy* b, const mjbSea* sea, char* error, int error_sz) {
  if (!b || !sea) {
    copyError("mjbuoy: mjb_setSea was given a NULL model or sea", error, error_sz);
    return 0;
  }
  // no callback of this model may run meanwhile: its data lock, exclusive
  std::unique_lock<std::shared_mutex> lk(b->mu);
  if (!mjb::setSea(&b->b, *sea, error, error_sz)) return 0;
  if (b->b.gl) mjb::glSetSea(b->b.gl, b->b.cfg.sea);
  return 1;
}

int mjb_waves(const mjbBuoy* b, double* out, int max) {
  if (!b) return 0;
  const std::vector<mjb::Wave>& w = b->b.cfg.sea.waves;
  for (int i = 0; out && i < max && i < int(w.size()); i++) {
    double v[6] = {w[i].amp, w[i].omega, w[i].k, w[i].dir, w[i].phase, w[i].steep};
    std::memcpy(out + 6 * i, v, sizeof(v));
  }
  return w.size();
}

void mjb_windVelocity(const mjbBuoy* b, mjtNum t, mjtNum v[2]) {
  v[0] = v[1] = 0;
  if (!b || !b->b.wind.par.on) return;
  double u = mjb::windSpeed(b->b.wind, t), dr = b->b.wind.par.w.dir * M_PI / 180;
  v[0] = u * std::cos(dr);
  v[1] = u * std::sin(dr);
}

mjtNum mjb_seaHeight(const mjbBuoy* b, mjtNum x, mjtNum y, mjtNum t) {
  return b ? b->b.cfg.sea.height(x, y, t) : 0;
}

std::string mjb::setHydroCoef(mjbBuoy* b, int body, const HydroCoef& c, double tmem) {
  if (!b) return "mjbuoy: setHydroCoef was given a NULL model";
  // no callback of this model may run meanwhile: its data lock, exclusive
  std::unique_lock<std::shared_mutex> lk(b->mu);
  b->b.rad.conv = b->b.cfg.rad.conv;
  std::copy(b->b.cfg.rad.roll, b->b.cfg.rad.roll + 2, b->b.rad.roll);
  std::string e = setRadiation(b->b.m, body, c, tmem, &b->b.rad);
  for (std::string& n : b->b.rad.note) b->b.warnings += "mjbuoy: warning: " + n + "\n";
  b->b.rad.note.clear();
  if (!e.empty()) return e;
  // every mjData's history restarts with room for the new memory
  for (auto& kv : b->data) radMakeState(b->b.rad, &kv.second->rad);
  return "";
}

const mjb::Buoy* mjb::buoyOf(const mjbBuoy* b) { return b ? &b->b : nullptr; }

bool mjb::vertexSeconds(const mjbBuoy* b, const mjData* d, double* sec) {
  State* s = b ? state(const_cast<mjbBuoy*>(b), d, false) : nullptr;
  if (!s) return false;
  *sec = 0;
  for (double v : s->cpu.vsec) *sec += v;
  return true;
}

bool mjb::newtonStats(const mjbBuoy* b, const mjData* d, long* solves, long* steps) {
  State* s = b ? state(const_cast<mjbBuoy*>(b), d, false) : nullptr;
  if (!s) return false;
  *solves = *steps = 0;
  for (size_t i = 0; i < s->cpu.nsolve.size(); i++) {
    *solves += s->cpu.nsolve[i];
    *steps += s->cpu.niter[i];
  }
  return true;
}
