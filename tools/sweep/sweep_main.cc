// mjbuoy-sweep: seakeeping campaigns, sweeps of scenarios over sea states
// and designs, run locally in parallel processes or as a Slurm job array
// (docs/sweeps.md). Exit status: 0 all cases pass, 1 a case fails or
// crashed, 2 an invalid sweep or I/O error.
#include <climits>
#include <cstdio>
#include <filesystem>
#include <string>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "cliopt.h"
#include "guard.h"

#include "mjbuoy_version.h"
#include "util/cpus.h"
#include "sweep.h"

// this executable, for the case processes and the sbatch script
static std::string self(const char* argv0) {
  char buf[PATH_MAX];
  ssize_t n = readlink("/proc/self/exe", buf, sizeof(buf) - 1);
  if (n > 0) return std::string(buf, n);
  return std::filesystem::absolute(argv0).string();
}

int main(int argc, char** argv) {
  CLI::App app{"Run sweeps of mjbuoy scenarios (docs/sweeps.md): locally in parallel processes "
               "or as a Slurm job array; merge the results into CSV, JUnit and plots."};
  app.set_version_flag("--version", std::string("mjbuoy-sweep ") + MJBUOY_VERSION_STRING);
  mjbtool::installProgress("mjbuoy-sweep");
  app.require_subcommand(1);
  std::string file, out, shard = "0/1";
  int jobs = 1;
  long index = 0;
  swp::SlurmOptions so;

  CLI::App* run = app.add_subcommand("run", "run the cases (or one shard of them), one process per case");
  run->add_option("sweep", file, "sweep XML file")->required();
  run->add_option("--out", out, "output directory (results in OUT/cases)")->required();
  run->add_option("--jobs,-j", jobs, "cases run at once; 0: one per CPU of the allocation "
                  "(affinity mask, SLURM_CPUS_PER_TASK)")->check(mjbtool::Finite(0, 4096));
  run->add_option("--shard", shard, "I/N: run the cases whose index mod N is I (I from 0)");

  CLI::App* cs = app.add_subcommand("case", "run one case (what run starts per case)");
  cs->add_option("sweep", file, "sweep XML file")->required();
  cs->add_option("--index", index, "case index")->required()->check(mjbtool::Finite(0, 1e15));
  cs->add_option("--out", out, "output directory")->required();

  CLI::App* est = app.add_subcommand("estimate", "run one case, report its wall time and peak "
                                     "memory, and suggest Slurm resources");
  est->add_option("sweep", file, "sweep XML file")->required();
  est->add_option("--index", index, "the case to measure (default 0)")->check(mjbtool::Finite(0, 1e15));
  est->add_option("--shards", so.shards, "array tasks planned")->check(mjbtool::Finite(1, 1000000));
  est->add_option("--jobs", so.jobs, "cases per task at once (cpus per task)")->check(mjbtool::Finite(1, 4096));

  CLI::App* sl = app.add_subcommand("slurm", "write OUT/sweep.sbatch (a job array, one task per "
                                    "shard) and submit it with sbatch");
  sl->add_option("sweep", file, "sweep XML file")->required();
  sl->add_option("--out", out, "output directory, shared by all nodes")->required();
  sl->add_option("--shards", so.shards, "array tasks")->check(mjbtool::Finite(1, 1000000));
  sl->add_option("--jobs", so.jobs, "cases per task at once (--cpus-per-task)")->check(mjbtool::Finite(1, 4096));
  sl->add_option("--time", so.time, "sbatch --time per task (default: from case 0's measured "
                 "time, as estimate)");
  sl->add_option("--mem", so.mem, "sbatch --mem per task (default: from case 0's measured "
                 "peak memory, as estimate)");
  sl->add_option("--partition", so.partition, "sbatch --partition");
  sl->add_option("--account", so.account, "sbatch --account");
  sl->add_option("--sbatch", so.extra, "another #SBATCH option, e.g. --sbatch=--qos=long (repeatable)");
  sl->add_flag("--dry-run", so.dry_run, "print the script; do not write or submit it");

  CLI::App* pc = app.add_subcommand("precompute", "attach every case's model once, filling "
                                    "the radiation cache (the slurm job before the array)");
  pc->add_option("sweep", file, "sweep XML file")->required();

  CLI::App* ls = app.add_subcommand("list", "list the cases: index, id and axis values");
  ls->add_option("sweep", file, "sweep XML file")->required();

  CLI::App* mg = app.add_subcommand("merge", "merge OUT/cases into OUT/sweep.csv, OUT/junit.xml "
                                    "and OUT/plots");
  mg->add_option("dir", out, "output directory of run")->required();
  {
    int rc = mjbtool::parseArgs(app, argc, argv, 2);  // docs: invalid input exits 2
    if (rc >= 0) return rc;
  }

  try {
    std::string me = self(argv[0]);
    if (*run) {
      int i = 0, n = 1, used = 0;
      char slash = 0;
      // the whole text, not a prefix: 0/2/3 is not 0/2
      if (std::sscanf(shard.c_str(), "%d%c%d%n", &i, &slash, &n, &used) != 3 || slash != '/' ||
          used != (int)shard.size() || n < 1 || i < 0 || i >= n) {
        std::fprintf(stderr, "mjbuoy-sweep: --shard %s: give I/N with 0 <= I < N, e.g. 0/4\n", shard.c_str());
        return 2;
      }
      if (jobs == 0) jobs = mjb::usableCpus();
      return swp::runSweep(file, out, jobs, i, n, me);
    }
    if (*cs) return swp::runCase(file, index, out);
    if (*est) return swp::estimate(file, index, so.shards, so.jobs, me);
    if (*sl) return swp::slurm(file, out, so, me);
    if (*mg) return swp::merge(out);
    if (*ls) return swp::list(file);
    if (*pc) return swp::precompute(file);
  } catch (const scn::Invalid& e) {
    std::fprintf(stderr, "mjbuoy-sweep: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mjbuoy-sweep: %s\n", e.what());
    return 2;
  }
  return 2;
}
