// benchcmp: one child bench run and its --json read back (benchcmp.h)
#include "benchcmp.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace mjbtool {

// the number after "key": in a bench JSON, NaN if absent
static double field(const std::string& js, const char* key) {
  std::string k = std::string("\"") + key + "\": ";
  size_t p = js.find(k);
  if (p == std::string::npos) return NAN;
  return std::strtod(js.c_str() + p + k.size(), nullptr);
}

static std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

bool benchChild(const std::string& exe, const std::vector<std::string>& args,
                const std::string& dir, CmpRun* r, std::string* err) {
  const std::string js = dir + "/cell.json", log = dir + "/stderr.txt";
  std::remove(js.c_str());
  std::vector<std::string> all = {exe};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back("--json");
  all.push_back(js);
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(&a[0]);
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  pid_t pid;
  int e = posix_spawn(&pid, exe.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (e != 0) {
    *err = exe + ": cannot run it: " + std::strerror(e);
    return false;
  }
  int st = 0;
  while (waitpid(pid, &st, 0) < 0) {
    if (errno != EINTR) {
      *err = exe + ": waitpid: " + std::strerror(errno);
      return false;
    }
  }
  std::string out = slurp(js);
  r->hydro = field(out, "hydro_ms");
  r->step = field(out, "step_ms");
  r->cpu = field(out, "hydro_cpu_ms");
  r->ntri = int(field(out, "triangles"));
  r->newton = field(out, "newton_per_solve");
  r->vertex = field(out, "vertex_ms");
  if (!WIFEXITED(st) || WEXITSTATUS(st) != 0 || !std::isfinite(r->hydro)) {
    std::string cmd;
    for (const std::string& a : all) cmd += (cmd.empty() ? "" : " ") + a;
    *err = "the run `" + cmd + "` failed (exit status " +
           std::to_string(WIFEXITED(st) ? WEXITSTATUS(st) : -1) + "): " + slurp(log);
    return false;
  }
  return true;
}

bool checkExecutable(const std::string& path, const std::string& what, std::string* err) {
  struct stat sb;
  if (stat(path.c_str(), &sb) != 0 || !S_ISREG(sb.st_mode) || access(path.c_str(), X_OK) != 0) {
    *err = what + " " + path + ": not an executable file; give the mjbuoy-bench binary of "
           "the build to compare with (e.g. other-build/tools/mjbuoy-bench)";
    return false;
  }
  return true;
}

}  // namespace mjbtool
