// benchcmp: mjbuoy-bench --baseline, two builds' benches run side by side
// as child processes of one bench, one cell and one repetition at a time,
// alternating A/B, so a speed-up is a ratio from one run on one loaded
// machine rather than a quotient of two runs minutes apart
#ifndef MJBUOY_TOOLS_BENCHCMP_H_
#define MJBUOY_TOOLS_BENCHCMP_H_

#include <string>
#include <vector>

namespace mjbtool {

// one child run's numbers (its --json): ms per step (hydro wall and CPU
// time, full step); newton iterations per
// surface solve (cpu backend), NaN when the build does not report them
struct CmpRun {
  double hydro = 0, cpu = 0, step = 0, newton = 0;
  double vertex = 0;  // cpu backend's vertex stage ms (NaN when not reported)
  int ntri = 0;  // triangles in the scene
};

// run exe once with args plus --json dir/NAME, its stdout discarded and its
// stderr kept in dir; false and err (with the child's stderr) on failure
bool benchChild(const std::string& exe, const std::vector<std::string>& args,
                const std::string& dir, CmpRun* r, std::string* err);

// can path be executed (the --baseline binary); false and err naming it
bool checkExecutable(const std::string& path, const std::string& what, std::string* err);

}  // namespace mjbtool

#endif  // MJBUOY_TOOLS_BENCHCMP_H_
