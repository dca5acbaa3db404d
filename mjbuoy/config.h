// configuration: the "mjbuoy.*" <custom> entries of a model, validated
#ifndef MJBUOY_CONFIG_H_
#define MJBUOY_CONFIG_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "sea.h"

namespace mjb {

// per-hull coefficients; defaults in kHullDefault (config.cc)
struct HullParams {
  double damp[2];  // simple damping: linear [N s/m], angular [N m s/rad]
};

struct Config {
  Sea sea;
  std::string backend = "cpu";
  std::vector<int> geom;           // hull geom ids, ascending
  std::vector<HullParams> param;   // one per hull geom
  std::vector<std::string> warn;   // load-time warnings
};

// read m's custom entries into c; returns "" or the first error
std::string parseConfig(const mjModel* m, Config* c);

// choose backend name (cpu); where names the source for the error message
std::string setBackend(const char* name, const std::string& where, Config* c);

}  // namespace mjb

#endif  // MJBUOY_CONFIG_H_
