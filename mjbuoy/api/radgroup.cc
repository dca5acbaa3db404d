// radgroup: hydrodynamic interaction of named groups at attach (radgroup.h)
#include "api/radgroup.h"

#include <algorithm>

#include "api/buoy.h"
#include "api/progress.h"
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
  for (size_t k = 0; k < mem.size(); k++) {
    std::string note;
    if (!radCacheLoad(dir, key[k], &(*c)[k], &note)) {
      if (!note.empty()) B->cfg.warn.push_back(mem[k].who.substr(8) + ": " + note);
      return false;
    }
    note = radCacheCheck(mem[k].body, omega, head, in, (*c)[k]);
    if (!note.empty()) {
      B->cfg.warn.push_back(mem[k].who.substr(8) + ": radiation cache: " +
                            radCachePath(dir, key[k]) + " " + note + "; recomputed");
      return false;
    }
  }
  return true;
}

bool groupSolve(Buoy* B, const std::vector<GroupMember>& mem, const std::vector<double>& omega,
                const std::vector<double>& head, const HydroCoef& in, std::vector<HydroCoef>* c,
                std::string* err) {
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
  c->assign(n, in);
  const std::string dir = radCacheDir(B->cfg.rad.cache);
  std::vector<std::string> key;
  for (size_t k = 0; k < n && !dir.empty(); k++)
    key.push_back(groupKey(body, lid, g.ref, omega, head, in, int(k)));
  if (!dir.empty() && groupLoad(B, dir, mem, key, omega, head, in, c)) {
    progressSay(mem[0].who.substr(8) + " and its group: read from the cache");
    B->radcache.hit += int(n);
    return true;
  }
  int np = 0;
  for (size_t k = 0; k < n; k++) np += body[k].nface() + lid[k].nface();
  progressSay(mem[0].who.substr(8) + " and its group: panel solver, " + std::to_string(n) +
              " bodies, " + std::to_string(np) + " panels together, " +
              std::to_string(omega.size()) + " frequencies");
  B->radcache.miss += int(n);
  if (!panelSolveGroup(body, lid, omega, head, &g, err)) return false;
  for (size_t k = 0; k < n; k++) {
    HydroCoef& x = (*c)[k];
    panelGroupBody(g, int(k), &x);
    // member k's panel frame: origin at its own (x, y) on the sea level
    x.ref[0] = x.ref[1] = x.ref[2] = 0;
    std::string note;
    if (dir.empty()) continue;
    if (radCacheStore(dir, key[k], x, &note)) {
      B->radcache.write++;
    } else {
      B->cfg.warn.push_back(mem[k].who.substr(8) + ": " + note);
    }
  }
  return true;
}

}  // namespace mjb
