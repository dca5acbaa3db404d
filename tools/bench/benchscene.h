// benchscene: mjbuoy-bench --scene FILE, a model's own scene (its hulls,
// sea, wind and radiation) timed as it is: mjbuoy's forces, the full
// mj_step and the real-time factor (simulated seconds per wall second),
// alone or side by side with a baseline build (--baseline)
#ifndef MJBUOY_TOOLS_BENCHSCENE_H_
#define MJBUOY_TOOLS_BENCHSCENE_H_

#include <string>

namespace mjbtool {

struct SceneArgs {
  std::string file;     // the MJCF model
  std::string backend;  // "": the model's mjbuoy.backend
  int steps = 1000;     // timed steps per repetition
  int reps = 3;         // repetitions (the median is reported)
  std::string json;     // also write the row as JSON ("": none)
};

// the scene's table row on stdout (and JSON): hydro wall and CPU ms per step,
// full step wall ms and CPU ms of all threads (over the cores: about the
// wall time of an idle machine, which a loaded one exceeds), real-time
// factor; the exit status
int benchScene(const SceneArgs& a);

// the scene run by this bench and the bench `base`, alternating as child
// processes; the exit status (1 with a message when the baseline has no
// --scene)
int compareScene(const SceneArgs& a, const std::string& base);

// --baseline's setup: this executable's path into exe and a fresh private
// directory in $TMPDIR (or /tmp) for the children's JSON and stderr into
// dir; false after a message on stderr
bool baselineSetup(std::string* exe, std::string* dir);

}  // namespace mjbtool

#endif  // MJBUOY_TOOLS_BENCHSCENE_H_
