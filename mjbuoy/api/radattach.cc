// radattach: panel solver to time-domain radiation at attach (radattach.h)
#include "api/radattach.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <new>
#include <stdexcept>
#include <utility>

#include "api/buoy.h"
#include "api/progress.h"
#include "api/radgroup.h"
#include "radiation/coefpsd.h"
#include "radiation/coefxform.h"
#include "radiation/diffract.h"
#include "radiation/driftattach.h"
#include "radiation/driftstep.h"
#include "hull/eqdraft.h"
#include "hull/jointeq.h"
#include "radiation/hydrostatic.h"
#include "radiation/panelcoarse.h"
#include "radiation/panelmesh.h"
#include "radiation/radcache.h"
#include "radiation/radimport.h"
#include "radiation/radmem.h"
#include "hull/rigid.h"
#include "util/bodylabel.h"
#include "util/fmt.h"

namespace mjb {

// f(a, length) for each panel edge from corner a (an edge shared by two
// panels comes twice)
template <class F>
static void eachEdge(const PanelMesh& p, F f) {
  for (int i = 0; i < p.nface(); i++) {
    const int* q = &p.face[4 * i];
    const int nv = q[3] < 0 ? 3 : 4;
    for (int k = 0; k < nv; k++) {
      const double* a = &p.vert[3 * q[k]];
      const double* b = &p.vert[3 * q[(k + 1) % nv]];
      f(a, std::hypot(std::hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]));
    }
  }
}

double panelEdge90(const PanelMesh& p) {
  std::vector<double> len;
  eachEdge(p, [&](const double*, double l) { len.push_back(l); });
  if (len.empty()) return 0;
  // nearest rank: the smallest length with at least 90% of them at or below
  const size_t r = size_t(std::ceil(0.9 * len.size())) - 1;
  std::nth_element(len.begin(), len.begin() + r, len.end());
  return len[r];
}

double defaultTopKR(double R, double h) {
  // 6 panels per wavelength: k_h = 2 pi / (6 h)
  const double kh = h > 0 ? 2 * M_PI / (6 * h) : INFINITY;
  return std::min(kTopKRMax, std::max(kTopKRMin, kh * R));
}

std::vector<double> defaultOmega(double R, double h, double g) {
  const int n = 20;
  double w0 = std::sqrt(g * 0.05 / R), w1 = std::sqrt(g * defaultTopKR(R, h) / R);
  std::vector<double> w(n);
  for (int i = 0; i < n; i++) w[i] = w0 + (w1 - w0) * i / (n - 1);
  return w;
}

double waterplaneRadius(const PanelMesh& p) {
  double az = 0, rmax = 0;
  for (int f = 0; f < p.nface(); f++) {
    const int* q = &p.face[4 * f];
    int nv = q[3] < 0 ? 3 : 4;
    for (int k = 0; k < nv; k++) {
      const double* a = &p.vert[3 * q[k]];
      const double* b = &p.vert[3 * q[(k + 1) % nv]];
      az += 0.5 * (a[0] * b[1] - a[1] * b[0]);  // z of the polygon's area vector
      rmax = std::max(rmax, std::hypot(a[0], a[1]));
    }
  }
  double r = std::sqrt(std::fabs(az) / M_PI);
  return r > 1e-6 * rmax ? r : rmax;
}

// A, B and A_inf are symmetric in potential flow (Newman 1977, sec. 4.13:
// Green's theorem); a collocation panel method is so only to its
// discretisation error (0.1% on a 24 x 8 hemisphere). Replaces each matrix
// by its symmetric part; returns the largest |M - M^T| / 2 over max |M| of
// each matrix
static double symmetrize(HydroCoef* c) {
  double worst = 0;
  auto sym = [&](double* M) {
    double big = 0, off = 0;
    for (int i = 0; i < 36; i++) big = std::max(big, std::fabs(M[i]));
    for (int i = 0; i < 6; i++)
      for (int j = 0; j < i; j++) {
        double a = 0.5 * (M[6 * i + j] + M[6 * j + i]);
        off = std::max(off, std::fabs(M[6 * i + j] - a));
        M[6 * i + j] = M[6 * j + i] = a;
      }
    if (big > 0) worst = std::max(worst, off / big);
  };
  sym(c->Ainf);
  for (int w = 0; w < c->nw(); w++) sym(&c->A[36 * w]), sym(&c->B[36 * w]);
  return worst;
}
static const double kAsymWarn = 0.02;

static const char* bodyName(const mjModel* m, int b) { return m->names + m->name_bodyadr[b]; }

// whether an entry names the group of root: mjbuoy.radiation.body.<b> on
// for root or one of its hull bodies, or mjbuoy.radiation.group
static bool namedOn(const Buoy& B, int root) {
  const RadConfig& r = B.cfg.rad;
  for (const Hull& h : B.hull) {
    if (B.m->body_weldid[h.body] != root) continue;
    for (int b : {h.body, root})
      if (std::count(r.onBody.begin(), r.onBody.end(), b)) return true;
  }
  // a body named in mjbuoy.radiation.group asks for radiation too
  for (const std::vector<std::string>& g : r.group)
    for (const std::string& n : g) {
      const int b = mj_name2id(B.m, mjOBJ_BODY, n.c_str());
      if (b >= 0 && B.m->body_weldid[b] == root) return true;
    }
  return false;
}

// a group on by default that gets no radiation after all (dry, too many
// panels, a failed solve): the warning why, and its hulls take back the
// linear drag terms the default had set to 0 for radiation (config.h,
// restoreDrag; docs/physics.md section 16): without radiation they are
// their only damping of slow heave
static std::string skipGroup(Buoy* B, int root, const std::string& why) {
  B->cfg.warn.push_back(why);
  for (Hull& h : B->hull)
    if (B->m->body_weldid[h.body] == root) restoreDrag(&h.par, &h.radDrag);
  return "";
}

// the steepest wave component beyond Miche's breaking limit, H / lambda =
// 0.142 tanh(k h) (deep water 0.142; H = 2 A for Airy and Gerstner waves
// alike), as a sentence; "" if none (docs/physics.md section 14, "Seas
// beyond breaking")
static std::string breakingWave(const Sea& s) {
  double worst = 0;
  std::string what;
  for (size_t i = 0; i < s.waves.size(); i++) {
    const Wave& w = s.waves[i];
    double lim = kBreakHL * (s.depth > 0 ? std::tanh(w.k * s.depth) : 1.0);
    double hl = 2 * w.amp / w.len;
    if (hl <= lim || hl / lim <= worst) continue;
    worst = hl / lim;
    char t[256];
    std::snprintf(t, sizeof(t), "wave component %d (amplitude %.4g m, wavelength %.4g m) is "
                  "steeper than a sea can be: H / lambda = %.3f above Miche's breaking "
                  "limit %.3f", int(i + 1), w.amp, w.len, hl, lim);
    what = t;
  }
  return what;
}

// whether the rigid group of root radiates (RadConfig::groupRadiates)
static bool groupRadiates(const Buoy& B, int root) {
  std::vector<int> hb;
  for (const Hull& h : B.hull) hb.push_back(h.body);
  return B.cfg.rad.groupRadiates(B.m, hb, root);
}

// w (world axes) in the axes turned by psi about the vertical: Z(-psi) w
// (t may be w)
static void toPanel(double psi, const double w[3], double t[3]) {
  const double c = std::cos(psi), s = std::sin(psi), x = w[0], y = w[1];
  t[0] = c * x + s * y;
  t[1] = -s * x + c * y;
  t[2] = w[2];
}

// the group's hull vertices in root's frame (float, as hullPanels takes
// them) and its faces
static void groupMesh(const Buoy& B, const mjData* d, int root, std::vector<float>* v,
                      std::vector<int>* f) {
  const mjModel* m = B.m;
  const mjtNum* Rr = d->xmat + 9 * root;
  for (const Hull& h : B.hull) {
    if (m->body_weldid[h.body] != root) continue;
    int v0 = v->size() / 3;
    const mjtNum* Rb = d->xmat + 9 * h.body;
    for (int i = h.v0; i < h.v0 + h.nv; i++) {
      mjtNum x[3], y[3], z[3];
      mju_rotVecMat(x, &B.vert[3 * i], Rb);
      for (int k = 0; k < 3; k++) y[k] = x[k] + d->xpos[3 * h.body + k] - d->xpos[3 * root + k];
      mju_rotVecMatT(z, y, Rr);
      for (int k = 0; k < 3; k++) v->push_back((float)z[k]);
    }
    for (int t = h.t0; t < h.t0 + h.nt; t++)
      for (int k = 0; k < 3; k++) f->push_back(B.face[3 * t + k] - h.v0 + v0);
  }
}

// what refines a hull's panels, naming mjbuoy.radiation.panels and the
// value to set: a refine level up splits each triangle in 4, so the
// budget must hold 4 times the np panels solved now (a budget below a
// hull's panels coarsens it back to the budget); with no budget (0) the
// refine level alone
static std::string refineHint(const RadConfig& rc, int np) {
  const int up = std::min(rc.refine + 1, 4);
  const std::string ref = "<numeric name=\"mjbuoy.radiation.refine\" data=\"" +
                          std::to_string(up) + "\"/>";
  if (rc.budget() <= 0) {
    return "refine the panels with " + ref + " (mjbuoy.radiation.panels = 0 already solves "
           "the full mesh; or give the hull a finer mesh)";
  }
  const int want = std::min(20000, (4 * std::max(np, rc.budget()) + 99) / 100 * 100);
  return "solve more panels: set <numeric name=\"mjbuoy.radiation.panels\" data=\"" +
         std::to_string(want) + "\"/> (now " + std::to_string(rc.budget()) + "; a hull finer "
         "than it is coarsened to it, 0 solves the full mesh), with " + ref + " if the hull's "
         "own mesh has fewer panels";
}

// warnings on c, then its symmetric part (who names the body; file: c is
// from a coefficient file, not the panel solver)
static void checkCoef(Buoy* B, const std::string& who, bool file, int np, HydroCoef* cp) {
  HydroCoef& c = *cp;
  const char* src = file ? "the coefficient file" : "the panel solver";
  // potential flow radiates energy: B_ii >= 0; a coarse mesh (or the lid
  // at high kR) can give small negative values, which the memory turns
  // into a source of energy
  for (int i = 0; i < 6; i++) {
    double big = 0, low = 0, wl = 0;
    for (int w = 0; w < c.nw(); w++) {
      double b = c.B[36 * w + 7 * i];
      big = std::max(big, std::fabs(b));
      if (b < low) low = b, wl = c.omega[w];
    }
    if (low < -0.01 * big) {
      static const char* kDof[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
      B->cfg.warn.push_back(who.substr(8) + ": " + src + "'s " + kDof[i] + " damping is " +
                            fmt(low) + " at omega " + fmt(wl) + " rad/s (below -1% of its peak " +
                            fmt(big) + "); " + (file ? std::string("check the file's damping") :
                            refineHint(B->cfg.rad, np) + ", or lower the highest frequency "
                            "(mjbuoy.radiation.omega)"));
    }
  }
  double asym = symmetrize(cp);
  if (asym > kAsymWarn) {
    B->cfg.warn.push_back(who.substr(8) + ": " + src + "'s added mass or damping is " +
                          fmt(100 * asym) + "% asymmetric (made symmetric)" + (file ? "" :
                          "; " + refineHint(B->cfg.rad, np)));
  }
  // damping that would feed energy: projected out, with a warning
  const size_t nw = B->cfg.warn.size();
  projectDamping(cp, who.substr(8), &B->cfg.warn);
  // its advice to refine names the budget and the value to set
  for (size_t i = nw; i < B->cfg.warn.size() && !file; i++)
    if (B->cfg.warn[i].find("mjbuoy.radiation.refine") != std::string::npos)
      B->cfg.warn[i] += "; " + refineHint(B->cfg.rad, np);
}

// what the panel solver is about to solve and its estimated time, for the
// progress line (mjb_setProgress)
static std::string solveLine(const PanelMesh& body, const PanelMesh& lid,
                             const std::vector<double>& omega, const std::vector<double>& head,
                             double depth) {
  const PanelCost pc = panelCost(body, lid, int(omega.size()), int(head.size()));
  char b[320];
  std::snprintf(b, sizeof b, "panel solver: %d body and %d lid panels (%s), %d frequencies "
                "%.3g to %.3g rad/s, %d headings, %s water: about %.2g s",
                body.nface(), lid.nface(), pc.ng == 4 ? "two mirror planes: 4 systems" :
                pc.ng == 2 ? "one mirror plane: 2 systems" : "no mirror symmetry",
                int(omega.size()), omega.empty() ? 0 : omega.front(),
                omega.empty() ? 0 : omega.back(), int(head.size()),
                depth > 0 ? ("depth " + fmt(depth) + " m").c_str() : "deep", pc.seconds);
  return b;
}

// a panel solution of this attach, reused by the identical hulls after it
// (turned about the vertical, the panel frame turns with them: panelYaw)
struct Solved {
  std::string who;
  PanelMesh body, lid;
  std::vector<double> omega, head;
  HydroCoef in, c;  // the input (rho, g, depth, ref) and the solution
  bool drift = false;
  DriftBody db;
  DriftTable dt;
};

// a and b within tol of each other, entry by entry, and of one size
static bool near(const double* a, const double* b, size_t n, double tol) {
  for (size_t i = 0; i < n; i++)
    if (!(std::fabs(a[i] - b[i]) <= tol)) return false;
  return true;
}
static bool near(const std::vector<double>& a, const std::vector<double>& b, double tol) {
  return a.size() == b.size() && near(a.data(), b.data(), a.size(), tol);
}

// the largest |x| of n values
static double most(const double* a, size_t n) {
  double m = 0;
  for (size_t i = 0; i < n; i++) m = std::max(m, std::fabs(a[i]));
  return m;
}

// whether s solved this problem: the same faces, vertices within 1e-9 of the
// mesh's size (the rounding of the turn by the yaw, far below the panels'
// discretisation error), frequencies within 1e-9 relative, the same
// headings and water, and (drift) the same dynamics within 1e-9 relative
static bool sameProblem(const Solved& s, const PanelMesh& body, const PanelMesh& lid,
                        const std::vector<double>& omega, const std::vector<double>& head,
                        const HydroCoef& in, const DriftBody* db) {
  if (s.body.face != body.face || s.lid.face != lid.face || s.head != head ||
      (db != nullptr) != s.drift || s.in.rho != in.rho || s.in.g != in.g ||
      s.in.depth != in.depth || !near(s.in.ref, in.ref, 3, 0))
    return false;
  const double tol = 1e-9 * (1 + most(body.vert.data(), body.vert.size()));
  if (!near(s.body.vert, body.vert, tol) || !near(s.lid.vert, lid.vert, tol) ||
      !near(s.omega, omega, 1e-9 * (omega.empty() ? 1 : omega.back())))
    return false;
  if (!db) return true;
  const DriftBody& a = s.db;
  if (a.free != db->free || !std::equal(a.dof, a.dof + 6, db->dof)) return false;
  for (auto pr : {std::make_pair(a.M, db->M), std::make_pair(a.C, db->C),
                  std::make_pair(a.D, db->D), std::make_pair(a.Cb, db->Cb)})
    if (!near(pr.first, pr.second, 36, 1e-9 * most(pr.second, 36) + 1e-300)) return false;
  return near(a.com, db->com, 3, tol);
}

// the solution c (and drift table dt) into the cache directory dir (none:
// "") under key and dkey; a failure is a warning
static void cacheStore(Buoy* B, const std::string& who, const std::string& dir,
                       const std::string& key, const std::string& dkey, const HydroCoef& c,
                       const DriftTable* dt) {
  if (dir.empty()) return;
  std::string note;
  if (radCacheStore(dir, key, c, &note) &&
      (!dt || radCacheStore(dir, dkey, driftPack(*dt, c), &note))) {
    B->radcache.write++;
  } else {
    B->cfg.warn.push_back(who.substr(8) + ": " + note);
  }
}

// panelSolve through the cache (radcache.h): a file whose key matches and
// whose payload fits it (radCacheCheck) is used as it is, else the
// solution is computed, after its memory is estimated (radmem.h), and
// stored; every cache problem is a warning, never an error
// db, dt: the drift table too (driftattach.h), cached in its own file;
// solved: this attach's solutions, an identical hull's reused (and this
// one's added)
static bool cachedSolve(Buoy* B, const std::string& who, const PanelMesh& body,
                        const PanelMesh& lid, const std::vector<double>& omega,
                        const std::vector<double>& head, HydroCoef* c, std::string* err,
                        std::vector<Solved>* solved, const DriftBody* db = nullptr,
                        DriftTable* dt = nullptr) {
  std::string dir = radCacheDir(B->cfg.rad.cache), key, note, dkey;
  if (!dir.empty()) {
    key = radCacheKey(body, lid, omega, head, *c);
    if (dt) dkey = driftCacheKey(key, *db);
    HydroCoef got, gotd;
    std::string dnote;
    if (radCacheLoad(dir, key, &got, &note)) {
      // a file whose checksum holds can still not fit its key: replaced
      note = radCacheCheck(body, omega, head, *c, got);
      // the drift table's file, else both are solved again
      bool dok = !dt || (radCacheLoad(dir, dkey, &gotd, &dnote) &&
                         driftUnpack(gotd, (int)omega.size(), (int)head.size(), dt));
      if (note.empty() && dok) {
        progressSay(who.substr(8) + ": read from the cache " + radCachePath(dir, key));
        return *c = std::move(got), B->radcache.hit++, true;
      }
      // no drift file yet (drift was off, or another process is writing
      // it): a plain miss; a drift file that cannot be used: named
      std::string bad = note.empty() ? dnote : note;
      std::string path = radCachePath(dir, note.empty() ? dkey : key);
      note = bad.empty() ? "" : "radiation cache: " + path + " " + bad + "; recomputed and "
             "rewritten";
    }
    if (!note.empty()) B->cfg.warn.push_back(who.substr(8) + ": " + note);
  }
  for (const Solved& s : *solved) {
    if (!sameProblem(s, body, lid, omega, head, *c, db)) continue;
    const size_t at = s.who.find("body ");  // (who: "mjbuoy: radiation of body ...")
    progressSay(who.substr(8) + ": the same panels as " +
                s.who.substr(at == std::string::npos ? 0 : at) + " (an identical hull): its solution");
    *c = s.c;
    if (dt) *dt = s.dt;
    B->radcache.same++;
    // stored under this hull's own key too: the next attach reads these
    // numbers, not a solve of its own that differs in the last bits
    cacheStore(B, who, dir, key, dkey, *c, dt);
    return true;
  }
  const HydroCoef in = *c;
  const int nb = body.nface(), nl = lid.nface();
  note = panelMemoryCheck(nb + nl, nb, int(omega.size()));
  if (!note.empty()) {
    *err = note + "; lower mjbuoy.radiation.panels (e.g. " + std::to_string(kDefaultPanels) +
           ": a coarsened copy of the hull is solved) or mjbuoy.radiation.refine, or turn its "
           "radiation off";
    return false;
  }
  B->radcache.miss++;
  progressSay(who.substr(8) + ": " + solveLine(body, lid, omega, head, c->depth));
  if (dt) {
    *err = panelSolveDrift(body, lid, omega, head, *db, c, dt, false);  // far field only
    if (!err->empty()) return false;
  } else if (!panelSolve(body, lid, omega, head, c, err)) {
    return false;
  }
  solved->push_back(Solved{who, body, lid, omega, head, in, *c, db != nullptr,
                           db ? *db : DriftBody(), dt ? *dt : DriftTable()});
  cacheStore(B, who, dir, key, dkey, *c, dt);
  return true;
}

// heave offset [m] of the panel pose from d's: the flat-water equilibrium
// of a free body's subtree (eqdraft.h), else 0 (a body on other joints
// is at its equilibrium along them in d, jointPose); at: the pose's name
// for messages. A free body without equilibrium is warned about
static double poseHeave(Buoy* B, const mjData* d, int root, const std::string& who,
                        std::string* at) {
  const mjModel* m = B->m;
  if (!m->body_jntnum[root] || m->jnt_type[m->body_jntadr[root]] != mjJNT_FREE) return 0;
  double dz = 0;
  std::string why;
  if (equilibriumHeave(*B, B->cfg.sea, d, root, &dz, &why)) {
    *at = "its floating equilibrium (qpos0 moved " + fmt(dz) + " m in z)";
    return dz;
  }
  *at = "the model's initial pose (qpos0; no floating equilibrium)";
  B->cfg.warn.push_back(who.substr(8) + ": no floating equilibrium on flat water (" + why +
                        "); its added mass and damping are for its wetted surface at the "
                        "model's initial pose (qpos0)");
  return 0;
}

// the slide and hinge joints between root and the world (ball and free
// joints there are held at qpos0); *held: whether there are such
static std::vector<int> chainJoints(const mjModel* m, int root, bool* held) {
  std::vector<int> j;
  *held = false;
  for (int b = root; b > 0; b = m->body_parentid[b])
    for (int k = m->body_jntadr[b]; k < m->body_jntadr[b] + m->body_jntnum[b]; k++) {
      const int t = m->jnt_type[k];
      if (t == mjJNT_SLIDE || t == mjJNT_HINGE) {
        j.push_back(k);
      } else {
        *held = true;
      }
    }
  return j;
}

// the pose of a group whose root is not free: d0 (qpos0) with its slide
// and hinge joints moved to their equilibrium on flat water (jointeq.h;
// docs/physics.md section 14, "Equilibrium along joints"), in a new
// mjData (nullptr for a free root, which poseHeave floats); at: the
// pose's name. Without an equilibrium the pose is qpos0, with a warning
// naming the body
static mjData* jointPose(Buoy* B, const mjData* d0, int root, const std::string& who,
                         std::string* at) {
  const mjModel* m = B->m;
  *at = "the model's initial pose (qpos0)";
  if (m->body_jntnum[root] && m->jnt_type[m->body_jntadr[root]] == mjJNT_FREE) return nullptr;
  mjData* d = mj_makeData(m);
  if (!d) return nullptr;
  mju_copy(d->qpos, d0->qpos, m->nq);
  bool held = false;
  std::vector<int> jnt = chainJoints(m, root, &held);
  EqWater w;
  w.vert = B->vert.data();
  w.face = B->face.data();
  w.level = B->cfg.sea.level;
  w.rho = B->cfg.sea.rho;
  w.g = B->cfg.sea.g;
  for (const Hull& h : B->hull) w.hull.push_back({h.body, h.t0, h.nt});
  std::string why = jnt.empty() ? "it has no slide or hinge joint to float along"
                                : jointEquilibrium(m, d, w, jnt);
  if (why.empty()) {
    *at = "its equilibrium along its joints";
    if (held) *at += " (its ball and free joints at qpos0)";
    return d;
  }
  mju_copy(d->qpos, d0->qpos, m->nq);
  mj_kinematics(m, d);
  mj_comPos(m, d);
  *at = "the model's initial pose (qpos0; no equilibrium along its joints)";
  B->cfg.warn.push_back(who.substr(8) + ": no equilibrium along its joints on flat water (" +
                        why + "); its added mass and damping are for its wetted surface at "
                        "the model's initial pose (qpos0)");
  return d;
}

// whether the wet panels reach the mean sea level (z = 0 in the panel
// frame, within 1e-9 of their depth): a hull with a waterline
static bool piercesSurface(const PanelMesh& p) {
  double zlo = 0, zhi = -INFINITY;
  eachEdge(p, [&](const double* a, double) { zlo = std::min(zlo, a[2]), zhi = std::max(zhi, a[2]); });
  return zhi >= 1e-9 * zlo;
}

// why A_inf of the panel solution is not positive semi-definite, and what
// to do: the panels are too coarse for the draft. A collocation point a
// draft d below the surface sees its panel's image 2 d away; a panel much
// wider than d is then integrated at one point across a 1/r^2 kernel that
// varies over d, and the diagonal fix (panel.cc rankineMatrices) carries
// that error: the solution is not resolved (a 2 x 1 m box at 2.5 mm
// draft gave A33 = -3.2e6 kg at rho 1e5)
static std::string unresolved(const PanelMesh& p, const HydroCoef& c, const RadConfig& rc) {
  double zlo = 0, wide = 0;
  eachEdge(p, [&](const double* a, double l) {
    zlo = std::min(zlo, a[2]);
    wide = std::max(wide, l);
  });
  double lo = INFINITY;
  for (int i = 0; i < 6; i++) lo = std::min(lo, c.Ainf[7 * i]);
  return "the panel solver's infinite-frequency added mass is not positive semi-definite "
         "(smallest diagonal entry " + fmt(lo) + "): its " + std::to_string(p.nface()) +
         " wet panels, up to " + fmt(wide) + " m wide, do not resolve its draft of " +
         fmt(-zlo) + " m (panels should be no wider than a few drafts); give the hull a "
         "finer mesh below the waterline or " + refineHint(rc, p.nface()) + ", or turn its "
         "radiation off";
}

// the wet panels counted against mjbuoy.radiation.panels: those of a
// hull without symmetry that take as much memory and time to solve.
// k mirror planes split the LU into 2^k systems of N / 2^k (docs/physics.md
// section 13, "Mirror symmetry"): N^3 / 4^k flops, as much as N / 4^(k/3)
// unsymmetric panels, but the influence matrices and their Green function
// integrals are N^2 / 2^k, as much as N / 2^(k/2): the larger of the two
static double solveSize(const PanelMesh& body, const PanelMesh& lid, bool useLid) {
  int n = body.nface() + (useLid ? lid.nface() : 0);
  int m = panelMirrors(body, useLid ? lid : PanelMesh());
  int k = (m & 1) + (m >> 1 & 1);
  return n * std::pow(2.0, -k / 2.0);
}

// the panels a hull's geometry asks for (docs/physics.md section 13,
// "Panel size"): no wider than kDraftPanels drafts (a panel much wider
// than the draft integrates its image's 1/r^2 kernel at one point) nor
// than a sixth of the shortest wavelength every default range holds,
// lambda = 2 pi R / kTopKRMin (6 panels per wavelength). The 90th-
// percentile edge h (panelEdge90) is halved per refine level, up to
// kAutoRefine, while the refined panels stay within the budget; body,
// lid and note become the finest such mesh. A hull the budget coarsens
// anyway is left as it is
static const double kDraftPanels = 3;
static const int kAutoRefine = 2;
static void autoRefine(const RadConfig& rc, const std::vector<float>& v,
                       const std::vector<int>& f, const double pos[3], const double* quat,
                       PanelMesh* body, PanelMesh* lid, std::string* note) {
  const int budget = rc.budget();
  if (budget > 0 && solveSize(*body, *lid, rc.lid) > budget) return;
  double zlo = 0;
  eachEdge(*body, [&](const double* a, double) { zlo = std::min(zlo, a[2]); });
  const double target = std::min(kDraftPanels * -zlo,
                                 2 * M_PI * waterplaneRadius(*body) / kTopKRMin / 6);
  double h = panelEdge90(*body);
  for (int r = rc.refine + 1; r <= kAutoRefine && h > target; r++) {
    PanelMesh b, l;
    std::string n;
    if (!hullPanels(v.data(), v.size() / 3, f.data(), f.size() / 3, pos, quat, r, &b, &l, &n))
      return;
    if (budget > 0 && solveSize(b, l, rc.lid) > budget) return;
    *body = std::move(b), *lid = std::move(l), *note = n;
    h = panelEdge90(*body);
  }
}

// a coarsened copy of the group's hull within the budget
// mjbuoy.radiation.panels (docs/physics.md section 13, "Coarsened hulls"):
// body, lid, note and *np become its own, with a warning giving the
// change; left as they are, with a warning, if it cannot be had
static void coarsenGroup(Buoy* B, const std::string& who, const std::vector<float>& v,
                         const std::vector<int>& f, const double pos[3], const double* quat,
                         PanelMesh* body, PanelMesh* lid, std::string* note, int* np) {
  const RadConfig& rc = B->cfg.rad;
  CoarseInfo ci;
  std::string cn = *note;
  if (!coarsenPanels(v.data(), v.size() / 3, f.data(), f.size() / 3, pos, quat, rc.refine,
                     rc.lid, rc.budget(), body, lid, &cn, &ci)) {
    B->cfg.warn.push_back(who.substr(8) + ": not coarsened to mjbuoy.radiation.panels = " +
                          std::to_string(rc.budget()) + ": " + cn + "; set <numeric name=\""
                          "mjbuoy.radiation.panels\" data=\"0\"/> to solve the full mesh");
    return;
  }
  *note = cn;
  *np = ci.panels;
  auto pct = [](double r) {
    char b[32];
    std::snprintf(b, sizeof b, "%+.1f%%", 100 * (r - 1));
    return std::string(b);
  };
  B->cfg.warn.push_back(who.substr(8) + ": hull coarsened for the panel solver from " +
                        std::to_string(ci.panels0) + " to " + std::to_string(ci.panels) +
                        " wet panels (" + std::to_string(ci.tri0) + " to " +
                        std::to_string(ci.tri) + " triangles; mjbuoy.radiation.panels = " +
                        std::to_string(rc.budget()) + "): displaced volume " +
                        pct(ci.vol / ci.vol0) + ", waterplane area " + pct(ci.awp / ci.awp0) +
                        " (the hydrostatics keep the full mesh); <numeric name=\"mjbuoy."
                        "radiation.panels\" data=\"0\"/> solves the full mesh (minutes, "
                        "cached)");
}

// the rollzeta share of critical roll damping added to x (docs/physics.md
// section 14, "Viscous roll damping"): B_1 = 2 zeta sqrt(C44 (I44 + A44)),
// C44 the hydrostatic stiffness of the wet panels body about the body x
// axis through the group's COM, I44 the group's inertia about that axis,
// A44 = A_inf's roll entry (about the root's COM, body axes); dz: the
// panel pose's heave (d is at qpos0, after mj_comPos)
static void rollZeta(Buoy* B, const mjData* d, int root, const PanelMesh& body,
                     const HydroCoef& c, double dz, double psi, const std::string& who,
                     RadBody* x) {
  const mjModel* m = B->m;
  const RadConfig& rc = B->cfg.rad;
  double I[6], G[3], mass, C[9];
  if (!groupInertia(m, d, root, I, G, &mass)) return;
  // the COM in the panel frame: axes turned by psi from the world's, origin
  // (x_root, y_root, sea level)
  for (int k = 0; k < 3; k++) G[k] -= d->xpos[3 * root + k];
  G[2] += d->xpos[3 * root + 2] + dz - B->cfg.sea.level;
  toPanel(psi, G, G);
  rotStiffness(body, G, c.rho * c.g, C);
  const mjtNum* R = d->xmat + 9 * root;
  const double e[3] = {R[0], R[3], R[6]};  // the body's x axis in the world
  double ep[3];
  toPanel(psi, e, ep);
  x->c44 = axisStiffness(C, ep);
  const double i44 = e[0] * e[0] * I[0] + e[1] * e[1] * I[1] + e[2] * e[2] * I[2] +
                     2 * (e[0] * e[1] * I[3] + e[0] * e[2] * I[4] + e[1] * e[2] * I[5]);
  const double it = i44 + c.Ainf[21];
  if (!(x->c44 > 0) || !(it > 0)) {
    if (rc.zetaGiven && rc.zeta > 0)
      B->cfg.warn.push_back(who.substr(8) + ": no roll restoring at its panel pose (C44 = " +
                            fmt(x->c44) + " N m/rad about its x axis), so mjbuoy.radiation."
                            "rollzeta adds no roll damping; give it mjbuoy.radiation.rolldamping");
    return;
  }
  x->roll[0] += 2 * rc.zeta * std::sqrt(x->c44 * it);
}

// the group's coefficients c (about its COM in body axes) and cx (the
// exciting force about its COM in world axes at qpos0, with diffraction
// on) to the time-domain radiation, the roll damping and the diffraction;
// imported: c is from a coefficient file, not the panel solver; Rd: the
// root's rotation at qpos0 in the panel frame, whose axes are turned by psi
// from the world's (cx's axes). "" or the error
static std::string finishGroup(Buoy* B, const mjData* d, int root, const std::string& who,
                               const PanelMesh& body, double dz, const double Rd[9],
                               HydroCoef c, const HydroCoef& cx, bool imported, double psi) {
  const mjModel* m = B->m;
  const RadConfig& rc = B->cfg.rad;
  std::string err;
  checkCoef(B, who, imported, body.nface(), &c);
  B->rad.conv = rc.conv;
  B->rad.ssAsked = rc.ssAsked;
  std::copy(rc.roll, rc.roll + 2, B->rad.roll);
  B->rad.entry = rc.entry;
  B->rad.speed = rc.speed;
  if (addedMassIndefinite(c.Ainf)) {
    if (imported)
      return who + ": the coefficient file's infinite-frequency added mass is not positive "
             "semi-definite; check its units (WAMIT: mjbuoy.radiation.ulen) and that it is "
             "for this body";
    // an unresolved wet surface, not a fault of the user's numbers
    std::string why = unresolved(body, c, rc);
    if (!(rc.given && rc.on) && !namedOn(*B, root))
      return skipGroup(B, root, who.substr(8) + " is off: " + why);
    return who + ": " + why;
  }
  err = setRadiation(m, root, c, rc.memory > 0 ? rc.memory : 0, &B->rad);
  if (!err.empty()) return err;
  // the immersion factor's reference (docs/physics.md, "Immersion factor"):
  // the group's displaced volume at the panel pose, and its hull bodies
  for (RadBody& x : B->rad.rb) {
    if (x.body != root) continue;
    x.veq = groupVolume(*B, B->cfg.sea, d, root, dz);
    rollZeta(B, d, root, body, c, dz, psi, who, &x);
    for (int hb : B->body)
      if (m->body_weldid[hb] == root) x.hb.push_back(hb);
  }
  for (std::string& n : B->rad.note) B->cfg.warn.push_back(n);
  B->rad.note.clear();
  if (rc.diffraction) err = setDiffraction(root, Rd, cx, B->wcap, &B->diff);
  if (!err.empty()) return err + " (body " + bodyLabel(m, root) + ")";
  for (DiffBody& x : B->diff.db)
    if (x.body == root) x.yaw0 = psi;
  B->coef.emplace_back(root, std::move(c));
  return "";
}

// the coefficient file of the group of root (mjbuoy.radiation.file.<body>
// naming root or one of its hull bodies), nullptr if none
static const RadConfig::File* fileOf(const Buoy& B, int root) {
  for (const RadConfig::File& f : B.cfg.rad.file)
    if (B.m->body_weldid[f.body] == root) return &f;
  return nullptr;
}

// the group's coefficients from its file (radimport.h) instead of the
// panel solver; body: its wet panels at the panel pose (roll stiffness)
static std::string importGroup(Buoy* B, const mjData* d, int root, const std::string& who,
                               const RadConfig::File& rf, const PanelMesh& body, double dz) {
  RadImport in;
  in.path = rf.path;
  std::copy(rf.origin, rf.origin + 3, in.origin);
  in.ulen = rf.ulen;
  in.rho = B->cfg.sea.rho;
  in.g = B->cfg.sea.g;
  in.depth = B->cfg.sea.depth > 0 ? B->cfg.sea.depth : 0;
  double Rd[9];
  for (int i = 0; i < 9; i++) in.R[i] = Rd[i] = d->xmat[9 * root + i];
  for (int k = 0; k < 3; k++) in.com[k] = B->m->body_ipos[3 * root + k];
  in.diffraction = B->cfg.rad.diffraction;
  in.body = &body;
  // the COM in the panel frame (world axes, origin below the root's on the
  // mean sea level): R ipos, at the height of the panel pose
  const mjtNum* ip = B->m->body_ipos + 3 * root;
  mju_rotVecMat(in.comPanel, ip, d->xmat + 9 * root);
  in.comPanel[2] += d->xpos[3 * root + 2] + dz - B->cfg.sea.level;
  HydroCoef c, cx;
  std::vector<std::string> warn;
  std::string err = importCoef(in, &c, &cx, &warn);
  for (const std::string& w : warn) B->cfg.warn.push_back(who.substr(8) + ": " + w);
  if (!err.empty()) return who + ": " + err;
  // the drift table comes from the panel solution's potentials, which a
  // coefficient file does not hold (docs/physics.md section 18)
  if (B->cfg.rad.diffraction && B->cfg.rad.drift)
    B->cfg.warn.push_back(who.substr(8) + ": has no mean wave drift: its coefficients come from "
                          "file " + rf.path + ", which holds no drift table (drift needs "
                          "mjbuoy's own panel solution: remove mjbuoy.radiation.file for it, or "
                          "set mjbuoy.radiation.drift off to silence this)");
  return finishGroup(B, d, root, who, body, dz, Rd, std::move(c), cx, true, 0);
}

// the error of a group whose hull gives no wet panels (note: why) at the
// pose at; on by default only: the body keeps running without radiation
static std::string noPanels(Buoy* B, int root, const std::string& who, const std::string& note,
                            const std::string& at) {
  const mjModel* m = B->m;
  const RadConfig& rc = B->cfg.rad;
  if (!(rc.given && rc.on) && !namedOn(*B, root)) {
    return skipGroup(B, root, who.substr(8) + " is off: " + note + " at " + at + " (mean sea "
                     "level " + fmt(B->cfg.sea.level) + " m); place the body at its "
                     "floating position in the model for added mass and radiation "
                     "damping, or set <text name=\"mjbuoy.radiation.body." +
                     bodyName(m, root) + "\" data=\"off\"/>");
  }
  return who + ": " + note + " at " + at + " (mean sea level " + fmt(B->cfg.sea.level) +
         " m); place the body at its floating position in the model, "
         "or turn radiation off for it with <text name=\"mjbuoy.radiation.body." +
         bodyName(m, root) + "\" data=\"off\"/>";
}

// skips a group of np wet panels, above the budget of radiation solves by
// default: on by default only within the cost bound (seconds at attach)
static std::string overBudget(Buoy* B, int root, const std::string& who, int np, int budget) {
  return skipGroup(B, root, who.substr(8) + " is off: " + std::to_string(np) + " wet panels, "
                   "above the " + std::to_string(budget) + " radiation solves by default; "
                   "set <numeric name=\"mjbuoy.radiation.panels\" data=\"" +
                   std::to_string(std::min(20000, (np + 99) / 100 * 100)) + "\"/> or switch "
                   "it on explicitly with <text name=\"mjbuoy.radiation\" data=\"on\"/> "
                   "(minutes, cached), or coarsen the hull below the waterline");
}

// the group's frequencies [rad/s]: mjbuoy.radiation.omega's uniform set,
// else the default for the hull's waterplane radius and panel size
static std::vector<double> groupOmega(const RadConfig& rc, const PanelMesh& body, double g) {
  std::vector<double> omega;
  if (rc.omega[2] > 0) {
    int n = (int)rc.omega[2];
    for (int i = 0; i < n; i++) omega.push_back(rc.omega[0] + (rc.omega[1] - rc.omega[0]) * i / (n - 1));
  } else {
    omega = defaultOmega(waterplaneRadius(body), panelEdge90(body), g);
  }
  return omega;
}

// the drift's Kochin function is deep water's (e^(K z)): said where the
// sea's main components feel the seabed at depth [m] (k h < 3: their profile
// and dispersion differ from deep water's by more than about e^(-2 k h) = 0.25%)
static void warnDriftDepth(Buoy* B, const std::string& who, double depth) {
  double amax = 0, khmin = 1e300, wmin = 0;
  for (const Wave& w : B->cfg.sea.waves) amax = std::max(amax, w.amp);
  for (const Wave& w : B->cfg.sea.waves)
    if (w.amp >= 0.1 * amax && w.k * depth < khmin) khmin = w.k * depth, wmin = w.omega;
  if (khmin < 3) {
    B->cfg.warn.push_back(who.substr(8) + ": its mean wave drift is deep water's (Maruo and "
                          "Newman), but at mjbuoy.sea.depth " + fmt(depth) + " m the sea's "
                          "components of " + fmt(wmin) + " rad/s have k h = " + fmt(khmin) +
                          " < 3 and feel the seabed: their drift is approximate "
                          "(docs/physics.md section 18, \"Limits\")");
  }
}

// the drift table dt next to the group's diffraction table, its moment
// about the COM p [m] (panel frame); none for a skipped group
static std::string attachDrift(Buoy* B, int root, const std::string& who, const DriftTable& dt,
                               const double p[3]) {
  bool has = false;  // a skipped group has no diffraction table
  for (const DiffBody& x : B->diff.db) has = has || x.body == root;
  if (!has) return "";
  const double ref0[3] = {0, 0, 0};
  std::string err = setDrift(root, dt, ref0, p, &B->diff);
  return err.empty() ? "" : who + ": " + err;
}

// the solved coefficients c to the root's COM and body axes, the exciting
// force about the COM in world axes, then the group's radiation and (drift)
// its drift table dt; posz: the panel frame's height of the root [m], psi
// its yaw [rad] (panelYaw)
static std::string placeGroup(Buoy* B, const mjData* d, int root, const std::string& who,
                              const PanelMesh& body, double dz, double posz, double psi,
                              HydroCoef* cp, bool drift, const DriftTable& dt) {
  const mjModel* m = B->m;
  const RadConfig& rc = B->cfg.rad;
  HydroCoef& c = *cp;
  std::string err;
  // panel frame: world axes turned by psi, origin (x_root, y_root, sea
  // level); the root's COM there is Rd ipos + (0, 0, pos z) (pos z at the
  // panel pose, with dz); body axes: the columns of Rd = Z(-psi) R
  const mjtNum* R = d->xmat + 9 * root;
  const mjtNum* ip = m->body_ipos + 3 * root;
  double p[3], Rd[9], pn[3] = {ip[0], ip[1], ip[2]};
  for (int j = 0; j < 3; j++) {
    const double col[3] = {R[j], R[3 + j], R[6 + j]};
    double t[3];
    toPanel(psi, col, t);
    for (int i = 0; i < 3; i++) Rd[3 * i + j] = t[i];
  }
  mju_rotVecMat(p, ip, Rd);
  p[2] += posz;
  // the exciting force about the COM, kept in the panel frame's axes at
  // qpos0 (any initial rotation; the step turns it with the body's yaw
  // since, diffract.h)
  HydroCoef cx;
  if (rc.diffraction) {
    cx = c;
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    err = coefTransform(&cx, p, I, p);
    if (!err.empty()) return who + ": " + err;
    cx.A.clear();
    cx.B.clear();
  }
  for (auto* v : {&c.heading, &c.Xre, &c.Xim, &c.FKre, &c.FKim}) v->clear();
  err = coefTransform(&c, p, Rd, pn);
  if (!err.empty()) return who + ": " + err;
  err = finishGroup(B, d, root, who, body, dz, Rd, std::move(c), cx, false, psi);
  if (!err.empty() || !drift) return err;
  return attachDrift(B, root, who, dt, p);
}

// the panel frame's yaw [rad]: a free root's heading at the panel pose
// (its x axis' direction in the world's xy plane), so that identical hulls
// turned about the vertical have the same panels and solve once
// (docs/physics.md section 13, "Identical hulls"); 0 for a root on other
// joints (their axes are the world's) or with a coefficient file
static double panelYaw(const Buoy& B, const mjData* d, int root) {
  const mjModel* m = B.m;
  if (!m->body_jntnum[root] || m->jnt_type[m->body_jntadr[root]] != mjJNT_FREE ||
      fileOf(B, root))
    return 0;
  const mjtNum* R = d->xmat + 9 * root;
  return std::atan2(R[3], R[0]);
}

// one rigid group's problem up to its panel solution: its pose (d, or dj
// for a jointed root), heave dz, panel frame (height posz, yaw psi), wet
// panels, frequencies, headings, the solver's input c and the drift's
// dynamics; ready false: nothing to solve (skipped, or read from a file)
struct Prep {
  std::string who;
  std::shared_ptr<mjData> dj;
  const mjData* d = nullptr;
  double dz = 0, posz = 0, psi = 0, xy[2] = {0, 0};
  PanelMesh body, lid;
  std::vector<double> omega, head;
  HydroCoef c;
  bool drift = false, ready = false;
  DriftBody db;
};

// the panels of the group of root at its pose; grouped: in a
// mjbuoy.radiation.group (world axes, no drift table). "" or the error
static std::string prepGroup(Buoy* B, const mjData* d, int root, bool grouped, Prep* p) {
  const mjModel* m = B->m;
  const RadConfig& rc = B->cfg.rad;
  std::string& who = p->who;
  who = "mjbuoy: radiation of body " + bodyLabel(m, root);
  // the pose: qpos0 lifted or lowered to its flat-water equilibrium
  // (docs/physics.md section 14, "Equilibrium draft"), or moved along its
  // joints to it ("Equilibrium along joints"); at names it
  std::string at;
  p->dj.reset(jointPose(B, d, root, who, &at), mj_deleteData);
  if (p->dj) d = p->dj.get();
  p->d = d;
  double dz = p->dz = poseHeave(B, d, root, who, &at);
  std::vector<float> v;
  std::vector<int> f;
  groupMesh(*B, d, root, &v, &f);
  // the panels in axes turned by the body's yaw: identical hulls turned
  // about the vertical get the same panels and solve once; a group's
  // bodies share the world's axes
  const double psi = p->psi = grouped ? 0 : panelYaw(*B, d, root);
  mjtNum q[4];
  const mjtNum qz[4] = {std::cos(-psi / 2), 0, 0, std::sin(-psi / 2)};
  mju_mulQuat(q, qz, d->xquat + 4 * root);
  double pos[3] = {d->xpos[3 * root], d->xpos[3 * root + 1],
                   d->xpos[3 * root + 2] + dz - B->cfg.sea.level};
  p->posz = pos[2], p->xy[0] = pos[0], p->xy[1] = pos[1];
  PanelMesh& body = p->body;
  PanelMesh& lid = p->lid;
  std::string note;
  if (!hullPanels(v.data(), v.size() / 3, f.data(), f.size() / 3, pos, q, rc.refine, &body,
                  &lid, &note))
    return noPanels(B, root, who, note, at);
  if (const RadConfig::File* rf = fileOf(*B, root))
    return importGroup(B, d, root, who, *rf, body, dz);
  if (!rc.refineGiven) autoRefine(rc, v, f, pos, q, &body, &lid, &note);
  int np = body.nface() + (rc.lid ? lid.nface() : 0);
  // the budget: an explicit mjbuoy.radiation.panels, none for a hull
  // refined on purpose (mjbuoy.radiation.refine alone), else the default
  const int budget = rc.budget();
  if (budget > 0 && solveSize(body, lid, rc.lid) > budget)
    coarsenGroup(B, who, v, f, pos, q, &body, &lid, &note, &np);
  if (budget > 0 && solveSize(body, lid, rc.lid) > budget && !(rc.given && rc.on) &&
      !namedOn(*B, root))
    return overBudget(B, root, who, np, budget);
  if (!rc.lid) {
    lid = PanelMesh();
  } else if (!lid.nface() && piercesSurface(body)) {
    // a fully submerged hull has no interior free surface, so no
    // irregular frequencies (docs/physics.md section 13): no lid needed
    B->cfg.warn.push_back(who.substr(8) + ": no interior lid (" + note +
                          "); its coefficients may be spoiled near irregular frequencies");
  }
  p->omega = groupOmega(rc, body, B->cfg.sea.g);
  HydroCoef& c = p->c;
  c.rho = B->cfg.sea.rho;
  c.g = B->cfg.sea.g;
  // finite depth: the panel solver's Green function of depth h where the
  // seabed is within reach (docs/physics.md section 13, "Finite depth")
  c.depth = B->cfg.sea.depth > 0 ? B->cfg.sea.depth : 0;
  // diffraction: a uniform heading set, interpolated at the components'
  // headings relative to the body's yaw (docs/physics.md section 15)
  for (int h = 0; rc.diffraction && h < kDiffHeadings; h++)
    p->head.push_back(2 * M_PI * h / kDiffHeadings);
  p->ready = true;
  return "";
}

// the drift's dynamics of a prepared group (mean drift: its table from the
// same solve, with the group's motions); a grouped body has none
static void prepDrift(Buoy* B, int root, bool grouped, Prep* p) {
  const RadConfig& rc = B->cfg.rad;
  if (!rc.diffraction || !rc.drift) return;
  if (grouped) {
    B->cfg.warn.push_back(p->who.substr(8) + ": has no mean wave drift: it is solved in its "
                          "mjbuoy.radiation.group, whose drift is not computed (set "
                          "mjbuoy.radiation.drift off to silence this)");
    return;
  }
  p->drift = true;
  if (p->c.depth > 0) warnDriftDepth(B, p->who, p->c.depth);
  const mjData* d = p->d;
  const double o[3] = {d->xpos[3 * root], d->xpos[3 * root + 1], B->cfg.sea.level - p->dz};
  driftDynamics(B->m, d, root, p->body, o, p->c.rho, p->c.g, &p->db, p->psi);
}

// the error or skip of a group whose panel solution failed (err)
static std::string solveFailed(Buoy* B, int root, const std::string& who,
                               const std::string& err) {
  const RadConfig& rc = B->cfg.rad;
  if (!(rc.given && rc.on) && !namedOn(*B, root))
    return skipGroup(B, root, who.substr(8) + " is off: panel solver: " + err);
  return who + ": panel solver: " + err;
}

// coefficients of one group; "" or the error
static std::string solveGroup(Buoy* B, const mjData* d, int root, std::vector<Solved>* solved) {
  Prep p;
  std::string err = prepGroup(B, d, root, false, &p);
  if (!p.ready) return err;
  prepDrift(B, root, false, &p);
  DriftTable dt;
  if (!cachedSolve(B, p.who, p.body, p.lid, p.omega, p.head, &p.c, &err, solved,
                   p.drift ? &p.db : nullptr, p.drift ? &dt : nullptr))
    return solveFailed(B, root, p.who, err);
  return placeGroup(B, p.d, root, p.who, p.body, p.dz, p.posz, p.psi, &p.c, p.drift, dt);
}

// the bodies of a mjbuoy.radiation.group solved together (radgroup.h):
// each member's own coefficients, with the others' scattering and
// diffraction, placed as a single body's, then their couplings; "" or the error
static std::string solveTogether(Buoy* B, const mjData* d, const std::vector<int>& roots) {
  std::vector<Prep> p(roots.size());
  std::vector<GroupMember> mem(roots.size());
  for (size_t k = 0; k < roots.size(); k++) {
    std::string err = prepGroup(B, d, roots[k], true, &p[k]);
    if (!err.empty()) return err;
    if (!p[k].ready) return p[k].who + ": not solved in its mjbuoy.radiation.group";
    prepDrift(B, roots[k], true, &p[k]);
    mem[k].who = p[k].who;
    mem[k].body = p[k].body, mem[k].lid = p[k].lid;
    std::copy(p[k].xy, p[k].xy + 2, mem[k].xy);
    mem[k].root = roots[k];
    const mjtNum* R = p[k].d->xmat + 9 * roots[k];
    std::copy(R, R + 9, mem[k].R);
    mju_rotVecMat(mem[k].com, B->m->body_ipos + 3 * roots[k], R);
    mem[k].com[2] += p[k].posz;
  }
  // one frequency set for the group: the first member's (its range covers
  // equal bodies; mjbuoy.radiation.omega sets it for all)
  std::vector<HydroCoef> c, cpl;
  std::string err;
  if (!groupSolve(B, mem, p[0].omega, p[0].head, p[0].c, &c, &cpl, &err))
    return p[0].who + ": panel solver of its mjbuoy.radiation.group: " + err;
  for (size_t k = 0; k < roots.size(); k++) {
    err = placeGroup(B, p[k].d, roots[k], p[k].who, p[k].body, p[k].dz, p[k].posz, 0, &c[k],
                     false, DriftTable());
    if (!err.empty()) return err;
  }
  return coupleGroup(B, d, mem, cpl);
}

// each radiating rigid group of roots alone, or with its
// mjbuoy.radiation.group (checked first); "" or the error
static std::string solveAll(Buoy* B, const mjData* d, const std::vector<int>& roots) {
  std::vector<Solved> solved;
  std::vector<std::vector<int>> together;
  std::string e = groupBodies(*B, &together);
  if (!e.empty()) return e;
  std::vector<int> done;
  for (int r : roots) {
    if (std::count(done.begin(), done.end(), r)) continue;
    const std::vector<int>* g = nullptr;
    for (const std::vector<int>& x : together)
      if (std::count(x.begin(), x.end(), r)) g = &x;
    e = g ? solveTogether(B, d, *g) : solveGroup(B, d, r, &solved);
    if (!e.empty()) return e;
    if (g) done.insert(done.end(), g->begin(), g->end());
  }
  return "";
}

// attachRadiation's work, which may throw (std::bad_alloc)
static std::string attachGroups(Buoy* B) {
  const mjModel* m = B->m;
  const RadConfig& rc = B->cfg.rad;
  for (int b : rc.onBody) {
    bool has = false;
    for (const Hull& h : B->hull)
      has = has || (m->body_weldid[h.body] == m->body_weldid[b] &&
                    groupMoves(m, m->body_weldid[b]));
    if (!has) {
      return std::string("mjbuoy: <text name=\"mjbuoy.radiation.body.") + bodyName(m, b) +
             "\"> turns radiation on for body \"" + bodyName(m, b) +
             "\", which carries no hull that can move; list its geoms in mjbuoy.hulls or "
             "remove the entry";
    }
  }
  std::vector<int> roots;
  for (const Hull& h : B->hull) {
    int r = m->body_weldid[h.body];
    if (std::find(roots.begin(), roots.end(), r) == roots.end() && groupRadiates(*B, r))
      roots.push_back(r);
  }
  // linear radiation theory is for waves that can exist: a default group
  // in a sea beyond breaking keeps Kerner's drag instead (an explicit on
  // is honoured, with a warning)
  std::string brk = breakingWave(B->cfg.sea);
  if (!brk.empty()) {
    std::vector<int> keep;
    for (int r : roots) {
      if ((rc.given && rc.on) || namedOn(*B, r)) {
        keep.push_back(r);
        continue;
      }
      skipGroup(B, r, "radiation of body " + bodyLabel(m, r) + " is off: " +
                          brk + ", where linear radiation theory does not hold; turn it on "
                          "with <text name=\"mjbuoy.radiation\" data=\"on\"/> or lower the "
                          "wave");
    }
    if (!keep.empty())
      B->cfg.warn.push_back("radiation: " + brk + "; linear radiation theory does not hold "
                            "in such a sea (docs/physics.md section 14, \"Seas beyond "
                            "breaking\")");
    roots.swap(keep);
  }
  if (roots.empty()) {
    if (rc.roll[0] > 0 || rc.roll[1] > 0) {
      B->cfg.warn.push_back("radiation: mjbuoy.radiation.rolldamping acts only on bodies with "
                            "radiation on, and no hull body has it; turn radiation on "
                            "(mjbuoy.radiation) or remove the entry");
    }
    if (rc.zetaGiven && rc.zeta > 0) {
      B->cfg.warn.push_back("radiation: mjbuoy.radiation.rollzeta acts only on bodies with "
                            "radiation on, and no hull body has it; turn radiation on "
                            "(mjbuoy.radiation) or remove the entry");
    }
    return "";
  }
  if (B->cfg.sea.kerner && rc.diffraction) {
    B->cfg.warn.push_back("radiation: mjbuoy.sea.pressure = kerner is not linear theory's "
                          "Froude-Krylov pressure, to which the diffraction force "
                          "(mjbuoy.radiation.diffraction) adds; use pressure linear, or turn "
                          "diffraction off");
  }
  // the initial pose: qpos0 (mj_makeData resets to it)
  std::unique_ptr<mjData, void (*)(mjData*)> d(mj_makeData(m), mj_deleteData);
  if (!d) return "mjbuoy: radiation: could not allocate an mjData for the initial pose";
  mj_kinematics(m, d.get());
  mj_comPos(m, d.get());  // cinert, for the groups' roll inertia (rollZeta)
  std::string e = solveAll(B, d.get(), roots);
  if (!e.empty()) return e;
  diffSea(B->cfg.sea, &B->diff);
  // each diffraction body's radiation body, for its immersion factor
  for (DiffBody& db : B->diff.db)
    for (size_t i = 0; i < B->rad.rb.size(); i++)
      if (B->rad.rb[i].body == db.body) db.ri = int(i);
  return "";
}

// no C++ exception leaves the attach: an allocation that fails despite
// the estimate (panelMemoryCheck; another process took the memory
// meanwhile) is an error naming the setting
std::string attachRadiation(Buoy* B) {
  try {
    return attachGroups(B);
  } catch (const std::bad_alloc&) {
    return "mjbuoy: radiation: out of memory at attach; lower mjbuoy.radiation.panels or "
           "mjbuoy.radiation.refine, or turn radiation off (<text name=\"mjbuoy.radiation\" "
           "data=\"off\"/>)";
  } catch (const std::exception& e) {
    return std::string("mjbuoy: radiation: failed at attach (") + e.what() + "); turn radiation "
           "off (<text name=\"mjbuoy.radiation\" data=\"off\"/>) and report the model";
  }
}

}  // namespace mjb
