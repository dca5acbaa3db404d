// mjbuoy-sweep slurm: an sbatch script that runs the sweep as a job array,
// one array task per shard (`mjbuoy-sweep run --shard $SLURM_ARRAY_TASK_ID/N`),
// after a one-task job that fills the shared radiation cache (`mjbuoy-sweep
// precompute`), both written into the output directory and submitted with
// sbatch. It assumes only sbatch and a directory that every node sees
// (absolute paths). Every value written into a script is checked against
// the form sbatch takes (#SBATCH lines are not shell, they cannot be
// quoted) or single-quoted (shell lines).
#include <cstdio>
#include <filesystem>
#include <regex>
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

// s for a message: control characters as \xNN
static std::string shown(const std::string& s) {
  std::string o;
  for (unsigned char c : s) {
    if (c < 32 || c == 127) {
      char b[8];
      std::snprintf(b, sizeof(b), "\\x%02x", c);
      o += b;
    } else {
      o += (char)c;
    }
  }
  return o;
}

// "" when value has the form, else a message naming the option and the form
static std::string checkForm(const std::string& opt, const std::string& value, const char* re,
                             const std::string& form) {
  if (std::regex_match(value, std::regex(re))) return "";
  return opt + " \"" + shown(value) + "\": expected " + form + " (values go into #SBATCH "
         "lines, which take no quoting: no spaces, newlines or shell characters)";
}

std::string checkSlurmOptions(const SlurmOptions& o, const std::string& out) {
  std::string e;
  if (!o.time.empty() &&
      !(e = checkForm("--time", o.time, R"(^([0-9]+-)?[0-9]+(:[0-9]+){0,2}$)",
                      "Slurm's MINUTES, MINUTES:SECONDS, HOURS:MINUTES:SECONDS, DAYS-HOURS, "
                      "DAYS-HOURS:MINUTES or DAYS-HOURS:MINUTES:SECONDS, e.g. 90 or 1-12:00:00"))
           .empty())
    return e;
  if (!o.mem.empty() &&
      !(e = checkForm("--mem", o.mem, R"(^[0-9]+[KMGT]?$)", "a size in MiB or with K, M, G or "
                      "T, e.g. 4000 or 4G")).empty())
    return e;
  if (!o.partition.empty() &&
      !(e = checkForm("--partition", o.partition, R"(^[A-Za-z0-9_.-]+(,[A-Za-z0-9_.-]+)*$)",
                      "partition names of letters, digits and _.- separated by commas, e.g. "
                      "compute,long")).empty())
    return e;
  if (!o.account.empty() &&
      !(e = checkForm("--account", o.account, R"(^[A-Za-z0-9_.-]+$)",
                      "an account name of letters, digits and _.-")).empty())
    return e;
  for (const std::string& x : o.extra) {
    e = checkForm("--sbatch", x, R"(^--[A-Za-z][A-Za-z0-9-]*(=[A-Za-z0-9_.,:=/@%+-]+)?$)",
                  "--NAME or --NAME=VALUE, VALUE of letters, digits and _.,:=/@%+-, e.g. "
                  "--sbatch=--qos=long");
    if (!e.empty()) return e;
  }
  // the output directory is in #SBATCH --output (where % starts a pattern)
  return checkForm("--out", out, R"(^[A-Za-z0-9_./,+@=~-]+$)",
                   "a directory path of letters, digits and _./,+@=~- (it is in the "
                   "#SBATCH --output line)");
}

// the #SBATCH lines both scripts share
static std::string header(const Sweep& s, const SlurmOptions& o, const std::string& job,
                          int cpus) {
  std::string j = "#!/bin/bash\n";
  j += "#SBATCH --job-name=mjbuoy-sweep-" + s.name + job + "\n";
  j += "#SBATCH --ntasks=1\n";
  j += "#SBATCH --cpus-per-task=" + std::to_string(cpus) + "\n";
  if (!o.time.empty()) j += "#SBATCH --time=" + o.time + "\n";
  if (!o.mem.empty()) j += "#SBATCH --mem=" + o.mem + "\n";
  if (!o.partition.empty()) j += "#SBATCH --partition=" + o.partition + "\n";
  if (!o.account.empty()) j += "#SBATCH --account=" + o.account + "\n";
  for (const std::string& e : o.extra) j += "#SBATCH " + e + "\n";
  return j;
}

static std::string runtimeCheck(const std::string& self) {
  // a node without mjbuoy's libraries (MuJoCo, GL, ...) fails here, saying
  // which, not in every case
  std::string j = "if ! mjb_v=$(" + sq(self) + " --version 2>&1); then\n";
  j += "  echo \"mjbuoy-sweep: \"" + sq(self) + "\" does not run on $(hostname): $mjb_v\" >&2\n";
  j += "  ldd " + sq(self) + " 2>&1 | grep 'not found' | sed 's/^/  missing: /' >&2\n";
  j += "  echo 'mjbuoy-sweep: install the runtime libraries above on the compute nodes "
       "(docs/dependencies.md), or load the module that provides them' >&2\n";
  j += "  exit 2\nfi\n";
  return j;
}

static std::string cacheLine(const std::string& out) {
  // one radiation cache for the whole array, unless the user set one
  return "if [ -z \"${MJBUOY_RADIATION_CACHE:-}\" ]; then\n  export MJBUOY_RADIATION_CACHE=" +
         sq(out + "/radcache") + "\nfi\n";
}

static std::string arrayScript(const Sweep& s, const std::string& out, const SlurmOptions& o,
                               const std::string& self) {
  std::string j = header(s, o, "", o.jobs);
  j += "#SBATCH --array=0-" + std::to_string(o.shards - 1) + "\n";
  j += "#SBATCH --output=" + out + "/slurm/%A_%a.out\n";
  j += "# mjbuoy-sweep " + s.name + ": " + std::to_string(s.ncases) + " case(s) in " +
       std::to_string(o.shards) + " array task(s) (docs/sweeps.md)\n";
  j += runtimeCheck(self) + cacheLine(out);
  j += "# a case already complete is skipped: resubmitting resumes the sweep; --jobs 0 runs as\n"
       "# many cases at once as the task has CPUs (its affinity, SLURM_CPUS_PER_TASK)\n";
  j += "exec " + sq(self) + " run " + sq(s.file) + " --out " + sq(out) + " --jobs 0 --shard \"${"
       "SLURM_ARRAY_TASK_ID}/" + std::to_string(o.shards) + "\"\n";
  return j;
}

static std::string precomputeScript(const Sweep& s, const std::string& out,
                                    const SlurmOptions& o, const std::string& self) {
  std::string j = header(s, o, "-precompute", 1);
  j += "#SBATCH --output=" + out + "/slurm/precompute_%j.out\n";
  j += "# mjbuoy-sweep " + s.name + ": the radiation solutions of every case, once, into the "
       "shared cache before the array starts\n";
  j += runtimeCheck(self) + cacheLine(out);
  j += "exec " + sq(self) + " precompute " + sq(s.file) + "\n";
  return j;
}

// run argv; its stdout in *text; false with a message printed
static bool runProgram(const std::vector<std::string>& args, std::string* text) {
  int fd[2];
  if (pipe(fd) != 0) return false;
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, fd[1], 1);
  posix_spawn_file_actions_addclose(&fa, fd[0]);
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid;
  int rc = posix_spawnp(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  close(fd[1]);
  if (rc != 0) {
    close(fd[0]);
    std::fprintf(stderr, "mjbuoy-sweep: cannot run %s (is Slurm's client installed? Debian: "
                 "slurm-client)\n", argv[0]);
    return false;
  }
  char buf[4096];
  ssize_t n;
  while ((n = read(fd[0], buf, sizeof(buf))) > 0) text->append(buf, n);
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "mjbuoy-sweep: %s failed (status %d)\n", argv[0],
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    return false;
  }
  return true;
}

// --time and --mem not given: from one case's measured cost (estimate)
static int defaults(const Sweep& s, SlurmOptions* o, const std::string& self) {
  if (!o->time.empty() && !o->mem.empty()) return 0;
  Cost c;
  std::fprintf(stderr, "mjbuoy-sweep: measuring case 0 for the defaults of --time and --mem\n");
  if (int st = measureCase(s, 0, self, &c)) return st;
  long minutes, mem;
  suggest(s, c, o->shards, o->jobs, &minutes, &mem);
  std::fprintf(stderr, "mjbuoy-sweep: case %s: wall %.3f s, peak RSS %.1f MiB:%s%s\n",
               c.id.c_str(), c.wall, c.rss,
               o->time.empty() ? (" --time " + std::to_string(minutes)).c_str() : "",
               o->mem.empty() ? (" --mem " + std::to_string(mem) + "M").c_str() : "");
  if (o->time.empty()) o->time = std::to_string(minutes);
  if (o->mem.empty()) o->mem = std::to_string(mem) + "M";
  return 0;
}

int slurm(const std::string& file, const std::string& outdir, const SlurmOptions& opt,
          const std::string& self) {
  Sweep s = parseSweep(file);
  SlurmOptions o = opt;
  std::string out = fs::absolute(outdir).lexically_normal().string();
  while (out.size() > 1 && out.back() == '/') out.pop_back();
  std::string bad = checkSlurmOptions(o, out);
  if (!bad.empty()) {
    std::fprintf(stderr, "mjbuoy-sweep: %s\n", bad.c_str());
    return 2;
  }
  if (int st = defaults(s, &o, self)) return st;
  std::string pre = precomputeScript(s, out, o, self), arr = arrayScript(s, out, o, self);
  if (o.dry_run) {
    std::printf("%s\n# ---- then, after it succeeds (--dependency=afterok) ----\n%s", pre.c_str(),
                arr.c_str());
    return 0;
  }
  std::error_code ec;
  fs::create_directories(fs::path(out) / "slurm", ec);  // sbatch does not create the log directory
  if (ec) {
    std::fprintf(stderr, "mjbuoy-sweep: cannot create %s/slurm: %s\n", out.c_str(), ec.message().c_str());
    return 2;
  }
  std::string ppath = out + "/precompute.sbatch", path = out + "/sweep.sbatch", err;
  if (!checkSweepOutputs(s, {ppath, path})) return 2;
  if (!atomicfile::write(ppath, pre, &err) || !atomicfile::write(path, arr, &err)) {
    std::fprintf(stderr, "mjbuoy-sweep: %s\n", err.c_str());
    return 2;
  }
  std::printf("mjbuoy-sweep: wrote %s and %s; submitting with sbatch\n", ppath.c_str(), path.c_str());
  std::fflush(stdout);
  std::string id, text;
  if (!runProgram({"sbatch", "--parsable", ppath}, &id)) {
    std::fprintf(stderr, "mjbuoy-sweep: the scripts are %s and %s\n", ppath.c_str(), path.c_str());
    return 2;
  }
  id = id.substr(0, id.find_first_of(";\n"));
  if (!std::regex_match(id, std::regex("^[0-9]+$"))) {
    std::fprintf(stderr, "mjbuoy-sweep: sbatch --parsable printed \"%s\", not a job id\n", shown(id).c_str());
    return 2;
  }
  std::printf("mjbuoy-sweep: radiation precompute is job %s\n", id.c_str());
  if (!runProgram({"sbatch", "--dependency=afterok:" + id, path}, &text)) {
    std::fprintf(stderr, "mjbuoy-sweep: the script is %s\n", path.c_str());
    return 2;
  }
  std::fputs(text.c_str(), stdout);
  std::printf("mjbuoy-sweep: when the array is done: mjbuoy-sweep merge %s\n", out.c_str());
  return 0;
}

}  // namespace swp
