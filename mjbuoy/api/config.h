// configuration: the "mjbuoy.*" <custom> entries of a model, validated
#ifndef MJBUOY_CONFIG_H_
#define MJBUOY_CONFIG_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "api/radconfig.h"
#include "hull/hullset.h"
#include "sea/sea.h"
#include "sea/wind.h"
#include "util/fmt.h"

namespace mjb {

struct Config {
  Sea sea;
  std::string backend = "cpu";
  int threads = 0;                 // cpu backend threads; 0 = auto
  std::vector<int> geom;           // hull geom ids, ascending
  std::vector<HullParams> param;   // one per hull geom
  std::vector<char> radDrag;       // one per hull geom: kRadDrag bits (radiationDragDefaults)
  std::vector<std::string> warn;   // load-time warnings
  std::vector<mjbSpectrum> spec;   // spectra as given (table not kept), seaconfig.cc
  WindParams wind;                 // wind entries, seaconfig.cc
  int capacity = 0;                // mjbuoy.sea.capacity: components reserved
  RadConfig rad;                   // mjbuoy.radiation*, radconfig.cc
};

// the linear drag terms (C_PD1, C_SD1) that the radiation default set to 0
// for a hull of a radiating group (config.cc, docs/physics.md section 16)
const char kRadDrag = 1, kRadSuction = 2;

// a hull whose group gets no radiation after all (radattach.cc: dry,
// too many panels, a failed solve) takes back the default linear terms of
// bits; bits becomes 0
void restoreDrag(HullParams* p, char* bits);

// read m's custom entries into c; returns "" or the first error. radiation
// false: every mjbuoy.radiation* entry is still checked, but no body
// radiates and the hulls take the drag defaults of radiation off
// (mjb_attachWithoutRadiation)
std::string parseConfig(const mjModel* m, Config* c, bool radiation = true);

// choose backend name (cpu, gl or auto); where names the source for the error message
std::string setBackend(const char* name, const std::string& where, Config* c);

}  // namespace mjb

#endif  // MJBUOY_CONFIG_H_
