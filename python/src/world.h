// world: one loaded and attached scene (mjModel, mjData, mjbBuoy) for the
// Python module; the Sim and every world of a Batch hold one
#ifndef MJBUOY_PYTHON_WORLD_H_
#define MJBUOY_PYTHON_WORLD_H_

#include <memory>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "mjbuoy.h"

namespace mjbpy {

// what to load: a file or MJCF text, the backend, the mjbuoy.* entries to
// set (as mjbuoy-sim --set NAME=VALUE) and the sea seed
struct LoadSpec {
  std::string source;            // file path or MJCF text (starts with '<')
  std::string backend;           // "" (the model's), "cpu", "gl" or "auto"
  std::vector<std::string> set;  // NAME=VALUE
  bool calm = false;             // delete the model's sea components first (--calm)
  bool seeded = false;           // seed given: spectrum k gets seed + k
  unsigned long long seed = 0;
};

// the scene; frees everything (unbind, detach, data, model) when destroyed
struct World {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  mjbBuoy* b = nullptr;
  std::string name;  // the file, or "MJCF text", for messages
  ~World();
};

// the scene of spec, loaded, attached and bound; null with the reason in err
std::unique_ptr<World> loadWorld(const LoadSpec& spec, std::string* err);

// MuJoCo's warnings to a buffer instead of MUJOCO_LOG.TXT (thread-safe);
// installed once by the module
void installWarningHandler();

// did MuJoCo reset d's state in the last steps (bad qpos, qvel or qacc);
// why: what and MuJoCo's last warning
bool diverged(const mjData* d, std::string* why);

// the spectrum labels of the MJCF (file or text) and of the set entries,
// in order (each mjbuoy.spectrum.<label>.type); "" or the reason in err
std::vector<std::string> spectrumLabels(const LoadSpec& spec, std::string* err);

}  // namespace mjbpy

#endif  // MJBUOY_PYTHON_WORLD_H_
