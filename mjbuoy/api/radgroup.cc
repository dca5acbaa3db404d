// radgroup: hydrodynamic interaction of named groups at attach (radgroup.h)
#include "api/radgroup.h"

#include <algorithm>

#include "api/buoy.h"
#include "api/progress.h"
#include "hull/rigid.h"
#include "radiation/coupgain.h"
#include "radiation/radiation.h"
#include "radiation/radcache.h"
#include "util/fmt.h"

namespace mjb {

static const char* kField = "<text name=\"mjbuoy.radiation.group\">";

// the error naming the field, the body and the fix
static std::string groupError(const std::string& body, const std::string& why,
                              const std::string& fix) {
  return std::string("mjbuoy: ") + kField + " names body \"" + body + "\", " + why + "; " + fix;
}

// the weld root of a named body that can be grouped, else the error
static int groupRoot(const Buoy& B, const std::string& name, std::string* err) {
  const mjModel* m = B.m;
  const int b = mj_name2id(m, mjOBJ_BODY, name.c_str());
  if (b < 0) {
    *err = groupError(name, "which does not exist", "give the name of a body that carries "
                      "hulls (mjbuoy.hulls)");
    return -1;
  }
  const int r = m->body_weldid[b];
  std::vector<int> hb;
  for (const Hull& h : B.hull) hb.push_back(h.body);
  bool hull = false;
  for (int x : hb) hull = hull || m->body_weldid[x] == r;
  if (!hull || !B.cfg.rad.groupRadiates(m, hb, r)) {
    *err = groupError(name, hull ? "which has no radiation (off, or it cannot move)"
                                 : "which carries no hull",
                      hull ? "turn its radiation on (<text name=\"mjbuoy.radiation.body." + name +
                             "\" data=\"on\"/>) or remove it from the group"
                           : "list its geoms in mjbuoy.hulls or remove it from the group");
    return -1;
  }
  for (const RadConfig::File& f : B.cfg.rad.file) {
    if (m->body_weldid[f.body] != r) continue;
    *err = groupError(name, "whose coefficients come from a file (mjbuoy.radiation.file)",
                      "the panel solver solves a group together: remove the file entry or "
                      "remove the body from the group");
    return -1;
  }
  return r;
}

std::string groupBodies(const Buoy& B, std::vector<std::vector<int>>* roots) {
  roots->clear();
  std::vector<std::string> seen;  // the name that put each root in a group
  std::vector<int> seenRoot;
  for (const std::vector<std::string>& g : B.cfg.rad.group) {
    std::vector<int> rs;
    for (const std::string& n : g) {
      std::string err;
      const int r = groupRoot(B, n, &err);
      if (r < 0) return err;
      auto it = std::find(seenRoot.begin(), seenRoot.end(), r);
      if (it != seenRoot.end()) {
        const std::string& o = seen[it - seenRoot.begin()];
        return groupError(n, o == n ? "which is in two groups (or twice in one)"
                                    : "which is rigidly attached to body \"" + o + "\" named "
                                      "before it (one rigid group)",
                          "name each body in one group only");
      }
      seen.push_back(n), seenRoot.push_back(r), rs.push_back(r);
    }
    if (rs.size() < 2) {
      return groupError(g[0], "alone in its group", "a group solves 2 or more bodies together: "
                        "add the bodies it interacts with, or remove the group (a body in no "
                        "group is solved alone)");
    }
    roots->push_back(rs);
  }
  return "";
}

// member k's mesh moved into the group frame (origin at member 0's)
static PanelMesh shifted(const PanelMesh& p, const double d[2]) {
  PanelMesh q = p;
  for (size_t i = 0; i < q.vert.size(); i += 3) q.vert[i] += d[0], q.vert[i + 1] += d[1];
  return q;
}

// the cache key of member k: every member's panels in the group frame with
// its reference point there, so a moved body misses
static std::string groupKey(const std::vector<PanelMesh>& body,
                            const std::vector<PanelMesh>& lid, const std::vector<double>& ref,
                            const std::vector<double>& omega, const std::vector<double>& head,
                            const HydroCoef& in, int k) {
  // k < n: member k's own coefficients; n + n i + j: the block (i, j)
  std::string key = "mjbuoy-group " + std::to_string(k) + " of " + std::to_string(body.size());
  for (size_t j = 0; j < body.size(); j++) {
    HydroCoef r = in;
    std::copy(&ref[3 * j], &ref[3 * j] + 3, r.ref);
    key += radCacheKey(body[j], lid[j], omega, head, r);
  }
  return key;
}

// every member's coefficients from the cache; false on any miss (a file
// that does not fit its key is named in a warning)
static bool groupLoad(Buoy* B, const std::string& dir, const std::vector<GroupMember>& mem,
                      const std::vector<std::string>& key, const std::vector<double>& omega,
                      const std::vector<double>& head, const HydroCoef& in,
                      std::vector<HydroCoef>* c) {
  const size_t n = mem.size();
  for (size_t k = 0; k < key.size(); k++) {
    std::string note;
    if (k >= n && (k - n) / n == (k - n) % n) continue;  // no diagonal coupling
    const GroupMember& x = mem[k < n ? k : (k - n) / n];
    if (!radCacheLoad(dir, key[k], &(*c)[k], &note)) {
      if (!note.empty()) B->cfg.warn.push_back(x.who.substr(8) + ": " + note);
      return false;
    }
    note = radCacheCheck(x.body, omega, k < n ? head : std::vector<double>(), in, (*c)[k]);
    if (!note.empty()) {
      B->cfg.warn.push_back(x.who.substr(8) + ": radiation cache: " +
                            radCachePath(dir, key[k]) + " " + note + "; recomputed");
      return false;
    }
  }
  return true;
}

// the solved group's n own coefficients then n x n coupling blocks into all
static void groupSplit(const PanelGroupCoef& g, size_t n, std::vector<HydroCoef>* all) {
  for (size_t k = 0; k < n; k++) {
    HydroCoef& x = (*all)[k];
    panelGroupBody(g, int(k), &x);
    // member k's panel frame: origin at its own (x, y) on the sea level
    x.ref[0] = x.ref[1] = x.ref[2] = 0;
  }
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < n; j++)
      if (i != j) panelGroupBlock(g, int(i), int(j), &(*all)[n + n * i + j]);
}

bool groupSolve(Buoy* B, const std::vector<GroupMember>& mem, const std::vector<double>& omega,
                const std::vector<double>& head, const HydroCoef& in, std::vector<HydroCoef>* c,
                std::vector<HydroCoef>* cpl, std::string* err) {
  const size_t n = mem.size();
  std::vector<PanelMesh> body, lid;
  PanelGroupCoef g;
  g.rho = in.rho, g.g = in.g, g.depth = in.depth;
  for (const GroupMember& x : mem) {
    const double d[2] = {x.xy[0] - mem[0].xy[0], x.xy[1] - mem[0].xy[1]};
    body.push_back(shifted(x.body, d));
    lid.push_back(shifted(x.lid, d));
    g.ref.insert(g.ref.end(), {d[0], d[1], 0.0});
  }
  std::vector<HydroCoef> all(n + n * n, in);
  const std::string dir = radCacheDir(B->cfg.rad.cache);
  std::vector<std::string> key;
  for (size_t k = 0; k < all.size() && !dir.empty(); k++)
    key.push_back(groupKey(body, lid, g.ref, omega, k < n ? head : std::vector<double>(), in,
                           int(k)));
  bool hit = !dir.empty() && groupLoad(B, dir, mem, key, omega, head, in, &all);
  if (hit) {
    progressSay(mem[0].who.substr(8) + " and its group: read from the cache");
    B->radcache.hit += int(n);
  } else {
    int np = 0;
    for (size_t k = 0; k < n; k++) np += body[k].nface() + lid[k].nface();
    progressSay(mem[0].who.substr(8) + " and its group: panel solver, " + std::to_string(n) +
                " bodies, " + std::to_string(np) + " panels together, " +
                std::to_string(omega.size()) + " frequencies");
    B->radcache.miss += int(n);
    if (!panelSolveGroup(body, lid, omega, head, &g, err)) return false;
    groupSplit(g, n, &all);
  }
  for (size_t k = 0; k < all.size() && !hit && !dir.empty(); k++) {
    std::string note;
    if (k >= n && (k - n) / n == (k - n) % n) continue;
    if (radCacheStore(dir, key[k], all[k], &note)) {
      B->radcache.write++;
    } else {
      B->cfg.warn.push_back(mem[0].who.substr(8) + ": " + note);
    }
  }
  c->assign(all.begin(), all.begin() + n);
  cpl->assign(all.begin() + n, all.end());
  return true;
}

// M' = T_i^T M T_j, T_k = P(-com_k) diag(R_k, R_k): the block about the
// panel-frame origins (world axes) to the COMs (body axes). A motion nu at
// the COM c is nu_o = P(o - c) nu at o, P(e) = [I -[e]x; 0 I]; a wrench
// at o is P(o - c)^T times it at c (docs/physics.md section 14, "Interaction")
static void toBodies(const GroupMember& a, const GroupMember& b, double M[36]) {
  auto T = [](const GroupMember& x, double t[36]) {
    double P[36] = {0}, e[3] = {-x.com[0], -x.com[1], -x.com[2]};
    for (int k = 0; k < 6; k++) P[7 * k] = 1;
    // -[e]x in the upper right block
    P[6 * 0 + 4] = e[2], P[6 * 0 + 5] = -e[1];
    P[6 * 1 + 3] = -e[2], P[6 * 1 + 5] = e[0];
    P[6 * 2 + 3] = e[1], P[6 * 2 + 4] = -e[0];
    double D[36] = {0};
    for (int r = 0; r < 3; r++)
      for (int c = 0; c < 3; c++) D[6 * r + c] = D[6 * (r + 3) + c + 3] = x.R[3 * r + c];
    for (int r = 0; r < 6; r++)
      for (int c = 0; c < 6; c++) {
        t[6 * r + c] = 0;
        for (int k = 0; k < 6; k++) t[6 * r + c] += P[6 * r + k] * D[6 * k + c];
      }
  };
  double Ta[36], Tb[36], MT[36];
  T(a, Ta);
  T(b, Tb);
  for (int r = 0; r < 6; r++)
    for (int c = 0; c < 6; c++) {
      MT[6 * r + c] = 0;
      for (int k = 0; k < 6; k++) MT[6 * r + c] += M[6 * r + k] * Tb[6 * k + c];
    }
  for (int r = 0; r < 6; r++)
    for (int c = 0; c < 6; c++) {
      M[6 * r + c] = 0;
      for (int k = 0; k < 6; k++) M[6 * r + c] += Ta[6 * k + r] * MT[6 * k + c];
    }
}

// the rigid-body inertia of root's weld group about rb's ref (body frame)
// in body axes, 6 x 6 row-major: [m I, -m [r]x; m [r]x, I_G - m [r]x [r]x],
// r = G - ref, I_G about the group's COM G; false when it has no mass
static bool refInertia(const mjModel* m, const mjData* d, const RadBody& rb, double M[36]) {
  double Iw[6], G[3], mass;
  if (!groupInertia(m, d, rb.body, Iw, G, &mass)) return false;
  const mjtNum* R = d->xmat + 9 * rb.body;
  const double W[9] = {Iw[0], Iw[3], Iw[4], Iw[3], Iw[1], Iw[5], Iw[4], Iw[5], Iw[2]};
  // to body axes: r = R^T (G - x) - ref, I_b = R^T I_w R
  double gw[3], r[3], WR[9], Ib[9], XX[9];
  mju_sub3(gw, G, d->xpos + 3 * rb.body);
  mju_mulMatTVec(r, R, gw, 3, 3);
  mju_subFrom3(r, rb.ref);
  mju_mulMatMat(WR, W, R, 3, 3, 3);
  mju_mulMatTMat(Ib, R, WR, 3, 3, 3);
  const double X[9] = {0, -r[2], r[1], r[2], 0, -r[0], -r[1], r[0], 0};  // [r]x
  mju_mulMatMat(XX, X, X, 3, 3, 3);
  mju_zero(M, 36);
  for (int a = 0; a < 3; a++) {
    M[6 * a + a] = mass;
    for (int b = 0; b < 3; b++) {
      M[6 * a + 3 + b] = -mass * X[3 * a + b];
      M[6 * (3 + a) + b] = mass * X[3 * a + b];
      M[6 * (3 + a) + 3 + b] = Ib[3 * a + b] - mass * XX[3 * a + b];
    }
  }
  return true;
}

// the B->rad.rb index of each root body (-1: no radiation)
static std::vector<int> radIndex(const Buoy& B, const std::vector<int>& roots) {
  std::vector<int> ri(roots.size(), -1);
  for (size_t k = 0; k < roots.size(); k++)
    for (size_t x = 0; x < B.rad.rb.size(); x++)
      if (B.rad.rb[x].body == roots[k]) ri[k] = int(x);
  return ri;
}

double groupGain(const Buoy& B, const mjData* d, const std::vector<int>& roots) {
  const int n = (int)roots.size();
  const std::vector<int> ri = radIndex(B, roots);
  std::vector<double> D(36 * n), O(36 * n * n, 0.0);
  for (int i = 0; i < n; i++) {
    if (ri[i] < 0) return -1;
    const RadBody& rb = B.rad.rb[ri[i]];
    if (!refInertia(B.m, d, rb, &D[36 * i])) return -1;
    for (int k = 0; k < 36; k++) D[36 * i + k] += rb.A[k];
  }
  for (const RadCouple& c : B.rad.cp)
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++)
        if (c.i == ri[i] && c.j == ri[j]) std::copy(c.A, c.A + 36, &O[36 * (n * i + j)]);
  return couplingGain(n, D, O);
}

// warns when the group's explicit added-mass coupling keeps kCoupleGainWarn
// or more of a step's acceleration error (groupGain; docs/physics.md
// section 14, "Interaction")
static void warnGain(Buoy* B, const mjData* d, const std::vector<GroupMember>& mem,
                     const std::vector<int>& roots) {
  const double g = groupGain(*B, d, roots);
  if (g < kCoupleGainWarn) return;
  std::string who;
  for (size_t i = 0; i < mem.size(); i++)
    who += std::string(i ? ", " : "") + "\"" + (B->m->names + B->m->name_bodyadr[mem[i].root]) +
           "\"";
  B->cfg.warn.push_back(
      "mjbuoy.radiation.group of bodies " + who + ": the coupling's added mass against the "
      "bodies' own inertia and added mass gives the explicit coupling a gain of " + fmt(g) +
      " (it carries that share of a step's acceleration error into the next, alternating; " +
      (g >= 1 ? "at 1 or more the motion grows step by step" : "it dies out slowly") +
      "): place the bodies further apart or group fewer (docs/physics.md section 14, "
      "\"Interaction\")");
}

std::string coupleGroup(Buoy* B, const mjData* d, const std::vector<GroupMember>& mem,
                        const std::vector<HydroCoef>& cpl) {
  const size_t n = mem.size();
  std::vector<int> roots;
  for (const GroupMember& x : mem) roots.push_back(x.root);
  const std::vector<int> ri = radIndex(*B, roots);
  const double tmem = B->cfg.rad.memory > 0 ? B->cfg.rad.memory : 0;
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < n; j++) {
      if (i == j) continue;
      if (ri[i] < 0 || ri[j] < 0) return mem[i].who + ": its group's coupling has no radiation";
      HydroCoef h = cpl[n * i + j];
      toBodies(mem[i], mem[j], h.Ainf);
      for (int w = 0; w < h.nw(); w++) {
        toBodies(mem[i], mem[j], &h.A[36 * w]);
        toBodies(mem[i], mem[j], &h.B[36 * w]);
      }
      std::string err = setCouple(ri[i], ri[j], h, tmem, B->m->opt.timestep, &B->rad);
      if (!err.empty()) return mem[i].who + ": " + err;
    }
  warnGain(B, d, mem, roots);
  return "";
}

}  // namespace mjb
