// mjbuoy-sweep slurm: an sbatch script that runs the sweep as a job array,
// one array task per shard (`mjbuoy-sweep run --shard $SLURM_ARRAY_TASK_ID/N`),
// written into the output directory and submitted with sbatch. It assumes
// only sbatch and a directory that every node sees (absolute paths).
#include <cstdio>
#include <filesystem>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "atomic.h"
#include "sweep.h"

extern char** environ;

namespace swp {

namespace fs = std::filesystem;

// single-quoted for the shell
static std::string sq(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

static std::string script(const Sweep& s, const std::string& out, const SlurmOptions& o,
                          const std::string& self) {
  std::string j = "#!/bin/bash\n";
  j += "# mjbuoy-sweep " + s.name + ": " + std::to_string(s.ncases) + " case(s) in " +
       std::to_string(o.shards) + " array task(s) (docs/sweeps.md)\n";
  j += "#SBATCH --job-name=mjbuoy-sweep-" + s.name + "\n";
  j += "#SBATCH --array=0-" + std::to_string(o.shards - 1) + "\n";
  j += "#SBATCH --output=" + out + "/slurm/%A_%a.out\n";
  j += "#SBATCH --ntasks=1\n";
  j += "#SBATCH --cpus-per-task=" + std::to_string(o.jobs) + "\n";
  if (!o.time.empty()) j += "#SBATCH --time=" + o.time + "\n";
  if (!o.mem.empty()) j += "#SBATCH --mem=" + o.mem + "\n";
  if (!o.partition.empty()) j += "#SBATCH --partition=" + o.partition + "\n";
  if (!o.account.empty()) j += "#SBATCH --account=" + o.account + "\n";
  for (const std::string& e : o.extra) j += "#SBATCH " + e + "\n";
  j += "# a case already complete is skipped: resubmitting resumes the sweep\n";
  j += "exec " + sq(self) + " run " + sq(s.file) + " --out " + sq(out) + " --jobs " +
       std::to_string(o.jobs) + " --shard \"${SLURM_ARRAY_TASK_ID}/" + std::to_string(o.shards) + "\"\n";
  return j;
}

int slurm(const std::string& file, const std::string& outdir, const SlurmOptions& o,
          const std::string& self) {
  Sweep s = parseSweep(file);
  std::string out = fs::absolute(outdir).lexically_normal().string();
  while (out.size() > 1 && out.back() == '/') out.pop_back();
  std::string text = script(s, out, o, self);
  if (o.dry_run) {
    std::fputs(text.c_str(), stdout);
    return 0;
  }
  std::error_code ec;
  fs::create_directories(fs::path(out) / "slurm", ec);  // sbatch does not create the log directory
  if (ec) {
    std::fprintf(stderr, "mjbuoy-sweep: cannot create %s/slurm: %s\n", out.c_str(), ec.message().c_str());
    return 2;
  }
  std::string path = out + "/sweep.sbatch", err;
  if (!atomicfile::write(path, text, &err)) {
    std::fprintf(stderr, "mjbuoy-sweep: %s\n", err.c_str());
    return 2;
  }
  std::printf("mjbuoy-sweep: wrote %s; submitting with sbatch\n", path.c_str());
  std::fflush(stdout);
  const char* argv[] = {"sbatch", path.c_str(), nullptr};
  pid_t pid;
  if (posix_spawnp(&pid, "sbatch", nullptr, nullptr, (char* const*)argv, environ) != 0) {
    std::fprintf(stderr, "mjbuoy-sweep: cannot run sbatch (is Slurm's client installed? Debian: "
                 "slurm-client); the script is %s\n", path.c_str());
    return 2;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "mjbuoy-sweep: sbatch failed (status %d); the script is %s\n",
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1, path.c_str());
    return 2;
  }
  std::printf("mjbuoy-sweep: when the array is done: mjbuoy-sweep merge %s\n", out.c_str());
  return 0;
}

}  // namespace swp
