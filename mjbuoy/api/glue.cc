// MuJoCo glue: public API, registry of attached models, mjcb_passive
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <shared_mutex>
#include <stdexcept>
#include <thread>

#include "api/buoy.h"
#include "hull/hull.h"
#include "hull/windload.h"
#include "util/cpus.h"
#include "util/pool.h"
#include "api/radattach.h"
#include "radiation/radiation.h"
#include "mjbuoy.h"
#include "api/seasetter.h"
#include "api/moorconfig.h"
#include "api/moorstep.h"
#include "api/progress.h"
#include "sea/wind.h"
#include "util/fmt.h"

using mjb::Buoy;
using mjb::State;

struct mjbBuoy_ {
  Buoy b;
  std::shared_mutex mu;                               // guards data
  // held shared by each callback for its whole run, exclusive by what
  // replaces or frees what a callback reads (mjb_setSea, setHydroCoef,
  // mjb_detach): the threading contract of mjbuoy.h
  std::shared_mutex run;
  std::atomic<bool> toldAlloc{false};  // a state could not be allocated: warned
  // mjData frozen by mjb_freezeData: their state and time then (guarded by mu)
  struct Frozen {
    State snap;
    double t;
  };
  std::map<const mjData*, Frozen> frozen;
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
// the mjcb_sensor chain, kept the same way: a user's sensor callback that
// chains to mjbuoy's across detach and re-attach must not recurse
std::vector<mjfSensor> gschain;
thread_local int gsdepth = 0;

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
  mjb::moorRestart(&s->moor);
}

}  // namespace

void mjb::makeState(const Buoy& b, State* s) {
  const size_t nw = std::max(b.wcap, b.cfg.sea.waves.size());
  mjb::makeHullState(b, nw, s);
  mjb::makeCpuState(b, b.cfg.sea, b.wcap, b, &s->cpu);
  s->dwrench.assign(6 * b.diff.db.size(), 0);
  s->dtold.assign(b.diff.db.size(), 0);
}

size_t mjb::stateBytes(const Buoy& b, int nthreads) {
  const size_t nw = std::max(b.wcap, b.cfg.sea.waves.size());
  return mjb::cpuStateBytes(b, b.cfg.sea, b.wcap, nthreads) + mjb::hullStateBytes(b, nw);
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
    // attach bounded its size (kMaxState); the allocation can still fail,
    // here and not in MuJoCo's C frames: nullptr, which the callers report
    try {
      auto& u = b->data[d];
      if (!u) {
        u = std::make_unique<State>();
        mjb::makeState(b->b, u.get());
        mjb::radMakeState(b->b.rad, &u->rad);
        mjb::moorMakeState(b->b.moor, b->b.m->nbody, &u->moor);
        u->buf = d->buffer;
      }
      s = u.get();
    } catch (const std::exception&) {
      b->data.erase(d);
      return nullptr;
    }
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

// the frozen state back into s (same sizes: no allocation), but for what
// describes d's qM as it is now, not history: radiation's stamp of the
// added mass in it (radstep.cc), which a step from the velocity stage
// (finite differences) would otherwise add a second time
void thaw(State* s, State* snap) {
  const long ms = s->rad.mstamp;
  s->rad.mdiag.swap(snap->rad.mdiag);
  *s = *snap;
  s->rad.mstamp = ms;
}

// forces of one evaluation for an attached model
void compute(mjbBuoy* b, const mjModel* m, mjData* d) {
  // frozen (mjb_freezeData): every call computes from the frozen state at
  // the frozen time, so repeated steps of d (finite differences) see what
  // a fresh copy of d would; d's time is put back on return
  mjbBuoy::Frozen* fz = nullptr;
  {
    std::shared_lock<std::shared_mutex> lk(b->mu);
    auto it = b->frozen.find(d);
    if (it != b->frozen.end()) fz = &it->second;
  }
  struct Clock {
    mjData* d;
    double t;
    ~Clock() { d->time = t; }
  } clock{d, d->time};
  if (fz) d->time = fz->t;
  State* s = state(b, d, true);
  if (s && fz) thaw(s, &fz->snap);
  if (!s) {
    if (!b->toldAlloc.exchange(true)) {
      mju_warning_i("mjbuoy: out of memory for an mjData's state (about %d MB): it gets no "
                    "force from mjbuoy. Call mjb_bindData after mj_makeData to have it "
                    "reported there; lower mjbuoy.threads or mjbuoy.sea.capacity",
                    int(mjb::stateBytes(b->b, b->b.nthreads) >> 20));
    }
    return;
  }
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
  // mooring lines: one wrench per body at their ends (moorstep.cc)
  if (!b->b.moor.line.empty()) {
    mjb::moorStep(b->b.moor, b->b.cfg.sea, m, d, &s->moor, &s->notices, b->b.pool);
    for (int bd : b->b.moor.body) {
      const mjtNum* w = s->moor.wrench.data() + 6 * bd;
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
  std::shared_lock<std::shared_mutex> run;  // b stays whole until we return
  {
    std::shared_lock<std::shared_mutex> lk(gmu);
    int k = int(gchain.size()) - gdepth;
    if (k >= 0) next = gchain[k];
    b = gdepth == 1 ? find(m) : nullptr;
    if (b) run = std::shared_lock<std::shared_mutex>(b->run);
  }
  if (next && next != passive) next(m, d);
  if (gdepth != 1) return;
  if (!b) {
    warnUnknown(m, d);
    return;
  }
  if (!b->b.hull.empty() || !b->b.wind.body.empty() || !b->b.rad.rb.empty() ||
      !b->b.moor.line.empty()) {
    compute(b, m, d);
  }
}

// user sensors: the user's callback first, then the ones mjbuoy binds
// (sensor.cc), so a sensor bound to mjbuoy gets mjbuoy's value
void sensorcb(const mjModel* m, mjData* d, int stage) {
  struct Depth {
    Depth() { gsdepth++; }
    ~Depth() { gsdepth--; }
  } depth;
  mjfSensor next = nullptr;
  mjbBuoy* b;
  std::shared_lock<std::shared_mutex> run;  // b stays whole until we return
  {
    std::shared_lock<std::shared_mutex> lk(gmu);
    int k = int(gschain.size()) - gsdepth;
    if (k >= 0) next = gschain[k];
    b = gsdepth == 1 ? find(m) : nullptr;
    if (b) run = std::shared_lock<std::shared_mutex>(b->run);
  }
  if (next && next != sensorcb) next(m, d, stage);
  if (!b || b->b.sensor.empty()) return;
  mjb::fillSensors(b->b, m, d, state(b, d, false), stage);
}

// cpu threads: mjbuoy.threads, or with 0 (auto) every CPU of the
// process's allocation (util/cpus.h: affinity mask, Slurm's; up to
// kMaxAuto) once the scene has kParMin triangles: below that the few us of
// handing chunks to a worker are not repaid (docs/mjcf.md); never more
// than the hulls' chunks (mjb::hullChunks). The hulls are cut at body
// boundaries into kChunks chunks per thread of about equal triangle
// counts, claimed dynamically so a busy core does not stall a step; with
// fewer bodies than 2 per thread that cannot balance, and each hull is
// split among the threads instead (cpu.cc hullWrench)
const int kParMin = 2000, kMaxAuto = 8, kChunks = 4;

// the most one mjData's state may take [bytes]: its scratch grows with
// threads x wave components x hull size (stateBytes). Auto
// threads stay within it; past it attach refuses, naming the settings
const size_t kMaxState = size_t(1) << 30;

void threads(Buoy* B) {
  int n = B->cfg.threads;
  if (n == 0) {
    n = int(B->face.size() / 3) >= kParMin ? mjb::usableCpus() : 1;
    n = std::max(1, std::min(n, kMaxAuto));
    while (n > 1 && mjb::stateBytes(*B, n) > kMaxState) n--;
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

// the cost rule's warning (docs/robustness.md, "Sea"): a component many
// times shorter than a hull's triangles adds almost nothing to the force
// (its pressure averages out over each triangle) but costs each step series
// terms and surface iterations in proportion to the wavelengths per
// triangle. Named once, the shortest, against the longest hull edge
void warnShortWaves(const Buoy& B, std::vector<std::string>* warn) {
  const std::vector<mjb::Wave>& w = B.cfg.sea.waves;
  if (w.empty() || B.face.empty()) return;
  double e2 = 0;
  int g = -1;
  for (const mjb::Hull& h : B.hull) {
    for (int t = h.t0; t < h.t0 + h.nt; t++) {
      for (int j = 0; j < 3; j++) {
        const double* p = &B.vert[3 * B.face[3 * t + j]];
        const double* q = &B.vert[3 * B.face[3 * t + (j + 1) % 3]];
        double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                    (p[2] - q[2]) * (p[2] - q[2]);
        if (d2 > e2) e2 = d2, g = h.geom;
      }
    }
  }
  size_t k = 0;
  for (size_t i = 1; i < w.size(); i++) if (w[i].len < w[k].len) k = i;
  const double edge = std::sqrt(e2), kShortFactor = 8;
  if (!(w[k].len * kShortFactor < edge)) return;
  warn->push_back("a wave component of wavelength " + mjb::fmt(w[k].len) + " m is more than " +
                  mjb::fmt(kShortFactor) + " times shorter than the longest edge (" +
                  mjb::fmt(edge) + " m) of hull geom \"" + (B.m->names + B.m->name_geomadr[g]) +
                  "\": its pressure averages out over each triangle while its cost per step "
                  "grows with the wavelengths per triangle; remove it (mjbuoy.wave.*, "
                  "mjbuoy.airy.*, a spectrum's range or tp), or refine the hull mesh if it matters");
}

void copyError(const std::string& e, char* error, int error_sz) {
  if (error && error_sz > 0) std::snprintf(error, error_sz, "%s", e.c_str());
}

// what replaces or frees a model's data waits for its callbacks to end, so
// from inside one of mjbuoy's callbacks (or one it chains to) on this thread
// it would wait for itself: refused, with the reason in error or a warning
bool insideCallback(const char* what, char* error, int error_sz) {
  if (gdepth == 0 && gsdepth == 0) return false;
  std::string e = std::string("mjbuoy: ") + what + " was called from inside an mjcb_passive or "
                  "mjcb_sensor callback; call it between steps (mjbuoy.h, threads); ignored";
  if (error) copyError(e, error, error_sz);
  else mju_warning_s("%s", e.c_str());
  return true;
}

// every live handle of one model keeps the model's own "simple dof" flags
// (radiation clears them): the last detach restores them, not the first.
// Called with gmu held exclusively, before b joins gattached
void shareSimple(mjbBuoy* b) {
  for (mjbBuoy* o : gattached) {
    if (o != b && o->b.m == b->b.m && !o->b.rad.simple0.empty()) {
      if (!b->b.rad.simple0.empty()) b->b.rad.simple0 = o->b.rad.simple0;
      return;
    }
  }
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
    h.vol = 0;
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
      h.vol += mju_dot3(a, x) / 6;  // V = sum a . (u x v) / 6 over a closed mesh
    }
    h.vol = std::fabs(h.vol);
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
  // vertex integration is the cpu lanes' (docs/physics.md "Vertex integration")
  if (B.cfg.sea.integration == mjb::kIntegrateVertex && !B.hull.empty()) {
    if (B.cfg.backend == "gl") {
      return "mjbuoy: mjbuoy.sea.integration = \"vertex\" is a cpu backend mode and the "
             "backend is gl; use backend cpu (or auto), or integration \"exact\" (docs/mjcf.md)";
    }
    B.cfg.backend = "cpu";
    return "";
  }
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

// the per-mjData state's size within kMaxState: "" or the error
std::string stateBound(const Buoy& B) {
  size_t need = mjb::stateBytes(B, B.nthreads);
  if (need <= kMaxState) return "";
  size_t tri = 0;
  for (const mjb::Hull& h : B.hull) tri = std::max(tri, size_t(h.nt));
  return "mjbuoy: each mjData would need about " + std::to_string(need >> 20) + " MB of state, "
         "above the " + std::to_string(kMaxState >> 20) + " MB mjbuoy allows (it grows with "
         "threads x wave components x hull size: " + std::to_string(B.nthreads) + " thread(s), " +
         std::to_string(B.wcap) + " components reserved, " + std::to_string(tri) +
         " triangles in the largest hull); lower mjbuoy.threads, mjbuoy.sea.capacity or the "
         "spectra's components, or coarsen the hull mesh";
}

}  // namespace

// mjb_attach's work, which may throw (std::bad_alloc)
static mjbBuoy* attachModel(const mjModel* m, const char* backend, bool radiation, char* error,
                            int error_sz) {
  copyError("", error, error_sz);
  if (!m) {
    copyError("mjbuoy: mjb_attach was given a NULL model", error, error_sz);
    return nullptr;
  }
  auto b = std::make_unique<mjbBuoy>();
  Buoy& B = b->b;
  B.m = m;
  std::string e = mjb::parseConfig(m, &B.cfg, radiation);
  if (e.empty() && backend) e = mjb::setBackend(backend, "the backend argument", &B.cfg);
  if (!e.empty()) {
    copyError(e, error, error_sz);
    return nullptr;
  }

  std::vector<std::string>& warn = B.cfg.warn;
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
  e = mjb::parseMooring(m, B.cfg.sea, &B.moor, &warn);
  if (!e.empty()) {
    copyError(e, error, error_sz);
    return nullptr;
  }
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
  warnShortWaves(B, &warn);
  for (const std::string& w : warn) B.warnings += "mjbuoy: warning: " + w + "\n";
  if (B.cfg.backend == "cpu") threads(&B);
  e = mjb::parseSensors(&B);
  if (e.empty()) e = stateBound(B);
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
    if (!mjcb_sensor) gschain.clear();
    gschain.push_back(mjcb_sensor);
    mjcb_sensor = sensorcb;
  }
  shareSimple(out);
  gattached.push_back(out);
  return out;
}

// no C++ exception crosses the C API: an allocation that fails inside the
// attach is an error, never an abort
// attachModel with no C++ exception crossing the C API
static mjbBuoy* attachGuarded(const mjModel* m, const char* backend, bool radiation,
                              char* error, int error_sz) {
  try {
    return attachModel(m, backend, radiation, error, error_sz);
  } catch (const std::bad_alloc&) {
    copyError("mjbuoy: out of memory in mjb_attach; use fewer or coarser hulls, or lower "
              "mjbuoy.radiation.panels", error, error_sz);
  } catch (const std::exception& e) {
    copyError(std::string("mjbuoy: mjb_attach failed: ") + e.what(), error, error_sz);
  }
  return nullptr;
}

mjbBuoy* mjb_attach(const mjModel* m, const char* backend, char* error, int error_sz) {
  return attachGuarded(m, backend, true, error, error_sz);
}

mjbBuoy* mjb_attachWithoutRadiation(const mjModel* m, const char* backend, char* error,
                                    int error_sz) {
  return attachGuarded(m, backend, false, error, error_sz);
}

void mjb_detach(mjbBuoy* b) {
  if (!b) return;
  if (insideCallback("mjb_detach", nullptr, 0)) return;
  bool last;  // no other handle of this model is live
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
    if (gattached.empty() && mjcb_sensor == sensorcb && !gschain.empty()) {
      mjcb_sensor = gschain.back();
      gschain.pop_back();
    }
    last = !find(b->b.m);
  }
  // callbacks that found b before it left gattached end first; none starts
  std::unique_lock<std::shared_mutex> wait(b->run);
  wait.unlock();
  for (auto& kv : b->data) mjb::glFreeState(b->b.gl, &kv.second->gl);
  if (last) mjb::restoreModel(b->b.m, b->b.rad);
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
  b->frozen.erase(d);
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

int mjb_freezeData(mjbBuoy* b, const mjData* d, int freeze) {
  if (!b || !d || b->b.gl) return 0;
  if (!freeze) {
    std::unique_lock<std::shared_mutex> lk(b->mu);
    auto it = b->frozen.find(d);
    if (it == b->frozen.end()) return 1;
    auto st = b->data.find(d);
    if (st != b->data.end()) thaw(st->second.get(), &it->second.snap);
    b->frozen.erase(it);
    return 1;
  }
  State* s = state(b, d, true);
  if (!s) return 0;
  try {
    std::unique_lock<std::shared_mutex> lk(b->mu);
    mjbBuoy::Frozen& f = b->frozen[d];
    f.snap = *s;
    f.t = d->time;
  } catch (const std::exception&) {
    return 0;
  }
  return 1;
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

void mjb_setProgress(mjbProgress fn, void* user) { mjb::progressSet(fn, user); }

int mjb_setSea(mjbBuoy* b, const mjbSea* sea, char* error, int error_sz) {
  if (!b || !sea) {
    copyError("mjbuoy: mjb_setSea was given a NULL model or sea", error, error_sz);
    return 0;
  }
  if (insideCallback("mjb_setSea", error, error_sz)) return 0;
  // a callback of this model running on another thread ends first, and no
  // other starts until the sea is whole (mjbuoy.h, threads)
  std::unique_lock<std::shared_mutex> lk(b->run);
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
  if (!v) return;
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
  if (insideCallback("setHydroCoef", nullptr, 0)) return "mjbuoy: setHydroCoef inside a callback";
  std::string e;
  {
    // no callback of this model may run meanwhile (mjbuoy.h, threads)
    std::unique_lock<std::shared_mutex> run(b->run);
    std::unique_lock<std::shared_mutex> lk(b->mu);
    b->b.rad.conv = b->b.cfg.rad.conv;
    b->b.rad.speed = b->b.cfg.rad.speed;
    std::copy(b->b.cfg.rad.roll, b->b.cfg.rad.roll + 2, b->b.rad.roll);
    e = setRadiation(b->b.m, body, c, tmem, &b->b.rad);
    for (std::string& n : b->b.rad.note) b->b.warnings += "mjbuoy: warning: " + n + "\n";
    b->b.rad.note.clear();
    // every mjData's history restarts with room for the new memory
    if (e.empty()) for (auto& kv : b->data) radMakeState(b->b.rad, &kv.second->rad);
  }
  // the registry's lock after the model's: a callback takes them in the
  // other order (the trampoline holds gmu while it takes run)
  std::unique_lock<std::shared_mutex> g(gmu);
  shareSimple(b);
  return e;
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

int mjb_lineCount(const mjbBuoy* b) { return b ? int(b->b.moor.line.size()) : 0; }

const mjtNum* mjb_lineWrench(const mjbBuoy* b, const mjData* d) {
  if (!b || !d || b->b.moor.line.empty()) return nullptr;
  State* s = state(const_cast<mjbBuoy*>(b), d, false);
  return s && !s->moor.wrench.empty() ? s->moor.wrench.data() : nullptr;
}

int mjb_seabed(const mjbBuoy* b, mjtNum* z) {
  if (!b) return 0;
  const mjb::Sea& sea = b->b.cfg.sea;
  double h = NAN;
  if (sea.depth > 0) {
    h = sea.level - sea.depth;
  } else if (!b->b.moor.line.empty() && b->b.moor.bed.z > -1e29) {
    h = b->b.moor.bed.z;  // deep sea: at the lowest fixed anchor
  }
  if (!std::isfinite(h)) return 0;
  if (z) *z = h;
  return 1;
}

int mjb_lineNodes(const mjbBuoy* b, const mjData* d, int line, mjtNum* pos, int max) {
  if (!b || !d || line < 0 || line >= int(b->b.moor.line.size())) return 0;
  State* s = state(const_cast<mjbBuoy*>(b), d, false);
  if (!s || s->moor.key < 0) return 0;
  const std::vector<double>& r = s->moor.ls[line].r;
  const int n = r.size() / 3;
  for (int i = 0; pos && i < std::min(n, max); i++) {
    for (int k = 0; k < 3; k++) pos[3 * i + k] = r[3 * i + k];
  }
  return n;
}

int mjb_lineTensions(const mjbBuoy* b, const mjData* d, int line, mjtNum* t, int max) {
  if (!b || !d || line < 0 || line >= int(b->b.moor.line.size())) return 0;
  State* s = state(const_cast<mjbBuoy*>(b), d, false);
  if (!s || s->moor.key < 0) return 0;
  const std::vector<double>& T = s->moor.ls[line].tseg;
  const int n = T.size();
  for (int i = 0; t && i < std::min(n, max); i++) t[i] = T[i];
  return n;
}
