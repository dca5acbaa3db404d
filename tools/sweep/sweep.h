// mjbuoy-sweep: a sweep file is a base scenario plus axes that set scenario
// fields (docs/sweeps.md). Each case is the base scenario with one value of
// every axis, run in its own process; its checks and named statistics go to
// one JSON result file. This header holds the parsed sweep and the parts:
// parse and expansion (sweep_parse.cc), statistics (sweep_stats.cc), one
// case (sweep_case.cc), the runner and estimate (sweep_run.cc), merge
// (sweep_merge.cc) and the Slurm script (sweep_slurm.cc).
#ifndef MJBUOY_TOOLS_SWEEP_H_
#define MJBUOY_TOOLS_SWEEP_H_

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "scenario.h"

namespace swp {

// <axis>: sets one attribute of the base scenario to each of its values
struct Axis {
  std::string name;
  std::string path;            // as written: elem[key=value]@attr, elem@attr or @attr
  std::string elem, key, keyval, attr;  // elem "" = the <scenario> root
  std::vector<std::string> labels;  // the values as listed or computed
  std::vector<std::string> texts;   // the attribute text: format with {} replaced
  int line = 0;
};

// one dimension of the product: an axis, or a <zip> of equal-length axes
struct Dim {
  std::string name;       // its part of the case id
  std::vector<int> axes;  // indices into Sweep::axes
  int size = 0;
  int line = 0;
};

enum class StatKind { MEAN, STD, SIG, MAX, MIN, RMS, TZ, AMP, PHASE, RAO, PERIOD };

// <stat>: a named statistic of one body's quantity over a window
struct Stat {
  std::string name;
  StatKind kind = StatKind::MEAN;
  std::string kind_name;
  std::string body;
  scn::Quantity quantity = scn::Quantity::Z;
  std::string quantity_name;
  int part = -1;
  std::string part_name;
  std::string sensor;  // sensor="NAME" instead of body and quantity
  int index = 0;       // value of a multi-dimensional sensor
  double from = 0, to = 0;  // to <= 0: the case's duration
  bool has_to = false;
  double period = 0;  // frequency of amp, phase, rao, period: 2 pi / period, or
  std::string wave;   // the wave mjbuoy.wave.<wave> of the case's model
  int line = 0;
};

// <plot>: y (a statistic) against x (an axis or statistic), a curve per
// value of curves (an axis, optional)
struct Plot {
  std::string y, x, curves, title;
  bool logx = false, logy = false;
  int line = 0;
};

struct Sweep {
  std::string file;   // absolute path of the sweep file
  std::string given;  // the path as given, for errors
  std::string name;   // default: the file stem
  std::string base;   // absolute path of the base scenario
  std::string base_text;  // its contents
  int base_line = 0;  // line of the scenario attribute
  std::vector<Axis> axes;
  std::vector<Dim> dims;
  std::vector<Stat> stats;
  std::vector<Plot> plots;
  long ncases = 1;
  int line = 1;
};

struct Case {
  long index = 0;
  std::string id;        // e.g. "period-03.amp-1" (docs/sweeps.md)
  std::vector<int> at;   // value index per axis
};

// parse and check a sweep file, and parse the base scenario (throws
// scn::Invalid "FILE:LINE: reason")
Sweep parseSweep(const std::string& file);

// case number index (0 .. ncases - 1), first dimension slowest
Case caseAt(const Sweep& s, long index);

// the case's scenario: the base with the axes' values set (throws
// scn::Invalid naming the sweep file's line, the case and the reason).
// xml: the edited scenario text, hashed to tell a result's case
scn::Scenario caseScenario(const Sweep& s, const Case& c, std::string* xml);

// the files a case reads: its model and every file the model reads
// (mjbtool::modelFiles), and the scenario's <mesh file>s
std::vector<std::string> caseFiles(const scn::Scenario& sc);

// a hash of everything that decides a case's result: its scenario text (the
// overrides), the statistics, the mjbuoy version and the content of files
// (caseFiles) (hex, 16 digits)
std::string caseHash(const Sweep& s, const std::string& xml, const std::vector<std::string>& files);

// evaluates the statistics of a case from the samples of its run
class Stats {
 public:
  // resolves bodies and wave frequencies (throws scn::Invalid at the stat's line)
  Stats(const Sweep& s, const scn::Scenario& sc, const mjModel* m);
  void sample(const scn::Sample& smp);
  // one value per stat (NaN when undefined: too few samples, diverged early)
  std::vector<double> finish(double diverged) const;

 private:
  struct Series {
    int body = -1;
    double omega = 0, from = 0, to = 0;
    std::vector<double> t, v, eta;
  };
  const Sweep& s_;
  std::vector<Series> series_;
  double dt_;
};

// the value of one statistic from its samples (sweep_stats.cc)
double statValue(StatKind k, const std::vector<double>& t, const std::vector<double>& v,
                 const std::vector<double>& eta, double omega);

// subcommands (sweep_*.cc); each returns the process exit status
int runCase(const std::string& file, long index, const std::string& out);
int runSweep(const std::string& file, const std::string& out, int jobs, int shard,
             int nshards, const std::string& self);
int estimate(const std::string& file, long index, int shards, int jobs,
             const std::string& self);
int merge(const std::string& dir);
// attach every case's model once, filling the radiation cache (run before
// a Slurm array so that its tasks read instead of solving)
int precompute(const std::string& file);
// one case run in a temporary directory: its cost
struct Cost {
  std::string id;
  double wall = 0, cpu = 0, rss = 0;  // s, s, MiB (peak)
  uintmax_t bytes = 0, logb = 0;      // result and log
};
// 0, else the exit status (the reason printed)
int measureCase(const Sweep& s, long index, const std::string& self, Cost* cost);
// sbatch --time [min] and --mem [MiB] for a task of ceil(ncases / shards)
// cases, jobs at once: twice the measured time plus a minute, 1.5 times the
// peak memory of jobs cases
void suggest(const Sweep& s, const Cost& c, int shards, int jobs, long* minutes, long* mem);
int list(const std::string& file);
struct SlurmOptions {
  int shards = 1, jobs = 1;
  std::string time, mem, partition, account;
  std::vector<std::string> extra;  // more #SBATCH lines, e.g. "--qos=long"
  bool dry_run = false;
};
int slurm(const std::string& file, const std::string& out, const SlurmOptions& o,
          const std::string& self);
// "" when every value the scripts hold has the form sbatch takes, else a
// message naming the option and the form (sweep_slurm.cc)
std::string checkSlurmOptions(const SlurmOptions& o, const std::string& out);

// where a case's result lives
std::string resultPath(const std::string& dir, const std::string& id);

// outs (files the command writes) are none of the sweep's inputs: the sweep
// file, the base scenario, the model and the files it reads (case 0's);
// false with the message printed
bool checkSweepOutputs(const Sweep& s, const std::vector<std::string>& outs);

// "" when path is a regular file or absent, else why it cannot be a result,
// log or manifest (a FIFO would block the reader forever)
std::string notRegular(const std::string& path);

// the hash of every case (the manifest's "cases"), from the files as they are now
std::vector<std::string> caseHashes(const Sweep& s);

// a case's result without its outcome: sweep, id, index, axis values
nlohmann::json caseHeader(const Sweep& s, const Case& c);

}  // namespace swp

#endif  // MJBUOY_TOOLS_SWEEP_H_
