// radcache: the panel solver's results kept on disk between attaches, keyed
// by everything that determines them (docs/mjcf.md section 11, "Cache")
#ifndef MJBUOY_RADCACHE_H_
#define MJBUOY_RADCACHE_H_

#include <string>
#include <vector>

#include "radiation/hydrocoef.h"
#include "radiation/panel.h"

namespace mjb {

// bump when panel.cc or green.cc change their results: older cache files
// then miss (their key holds the old number) and are recomputed
const unsigned kPanelSolverVersion = 3;  // 2: tabulated wave Green function, mirror symmetry; 3: damped lid

// environment variable naming the cache directory ("off": no cache); the
// MJCF entry mjbuoy.radiation.cache wins over it
const char* const kRadCacheEnv = "MJBUOY_RADIATION_CACHE";

// hits, misses and files written by one attach (tests and mjbuoy-hydro)
struct RadCacheStats {
  int hit = 0, miss = 0, write = 0;
  int same = 0;  // solutions of an identical hull solved earlier in the same attach
};

// the cache directory: entry (mjbuoy.radiation.cache) if given, else
// $MJBUOY_RADIATION_CACHE, else $XDG_CACHE_HOME/mjbuoy, else
// $HOME/.cache/mjbuoy; "" when off (or no HOME)
std::string radCacheDir(const std::string& entry);

// the bytes that determine panelSolve's result: solver version, rho, g,
// depth, ref of in, omega, heading, both panel meshes
std::string radCacheKey(const PanelMesh& body, const PanelMesh& lid,
                        const std::vector<double>& omega, const std::vector<double>& heading,
                        const HydroCoef& in);

// the file of key in dir
std::string radCachePath(const std::string& dir, const std::string& key);

// fill *c from the file of key in dir; false on a miss. A file that is
// corrupt, truncated, of another format or version, or of another key is
// not used: *note says so ("" for a plain miss)
bool radCacheLoad(const std::string& dir, const std::string& key, HydroCoef* c,
                  std::string* note);

// "" when c, loaded for the key of (body, omega, heading, in), holds what
// that key asks and values a body of its size can have, else why not: its
// frequencies, headings, rho, g, depth and reference point those of the
// key; its coefficients finite and within 1e3 times the scale of a body of
// the mesh's size L about ref (rho L^3, times L per rotation dof, and
// omega for B; rho g L^2 for the exciting force)
std::string radCacheCheck(const PanelMesh& body, const std::vector<double>& omega,
                          const std::vector<double>& heading, const HydroCoef& in,
                          const HydroCoef& c);

// write c as the file of key in dir (made if missing), atomically (a
// temporary file renamed into place); a file there that is not a cache
// file is left alone. false with *note on failure
bool radCacheStore(const std::string& dir, const std::string& key, const HydroCoef& c,
                   std::string* note);

}  // namespace mjb

#endif  // MJBUOY_RADCACHE_H_
