// mjbuoy-sweep run and estimate: every case runs in a child process
// (`mjbuoy-sweep case`), so a crash is contained; results already complete
// are skipped, so a run can be resumed (docs/sweeps.md)
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "api/buoy.h"
#include "atomic.h"
#include "outfile.h"
#include "radiation/radcache.h"
#include "sweep.h"

namespace swp {

namespace fs = std::filesystem;
using json = nlohmann::json;

std::string notRegular(const std::string& path) {
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return "";
  if (S_ISLNK(st.st_mode) && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) return "";
  const char* kind = S_ISFIFO(st.st_mode) ? "a FIFO" : S_ISDIR(st.st_mode) ? "a directory" :
                     S_ISSOCK(st.st_mode) ? "a socket" : S_ISLNK(st.st_mode) ? "a broken link" :
                     "not a regular file";
  return path + " is " + kind + ", not a regular file; remove it (mjbuoy-sweep writes and reads "
         "only regular files there)";
}

static bool readJson(const std::string& path, json* j) {
  if (!notRegular(path).empty()) return false;
  std::ifstream in(path);
  if (!in) return false;
  try {
    in >> *j;
    return true;
  } catch (...) {
    return false;
  }
}

// the manifest DIR/sweep.json: what merge needs to know of the sweep. Its
// content depends on the sweep only, so shards write identical files
static json manifest(const Sweep& s) {
  json j;
  j["sweep"] = s.name;
  j["file"] = s.file;
  j["base"] = s.base;
  json axes = json::array();
  for (const Axis& a : s.axes) axes.push_back({{"name", a.name}, {"set", a.path}, {"values", a.labels}});
  j["axes"] = axes;
  json stats = json::array();
  for (const Stat& t : s.stats) stats.push_back({{"name", t.name}, {"stat", t.kind_name}, {"quantity", t.quantity_name}});
  j["stats"] = stats;
  json plots = json::array();
  for (const Plot& p : s.plots) {
    plots.push_back({{"y", p.y}, {"x", p.x}, {"curves", p.curves}, {"title", p.title},
                     {"logx", p.logx}, {"logy", p.logy}});
  }
  j["plots"] = plots;
  json cases = json::array();
  std::vector<std::string> h = caseHashes(s);
  for (long i = 0; i < s.ncases; i++) cases.push_back({{"id", caseAt(s, i).id}, {"hash", h[i]}});
  j["cases"] = cases;
  return j;
}

std::vector<std::string> caseHashes(const Sweep& s) {
  std::vector<std::string> h;
  for (long i = 0; i < s.ncases; i++) {
    std::string xml;
    scn::Scenario sc = caseScenario(s, caseAt(s, i), &xml);
    h.push_back(caseHash(s, xml, caseFiles(sc)));
  }
  return h;
}

bool checkSweepOutputs(const Sweep& s, const std::vector<std::string>& outs) {
  std::vector<mjbtool::PathUse> uses = {{s.file, "sweep file", false}, {s.base, "base scenario", false}};
  try {
    std::string xml;
    for (const std::string& f : caseFiles(caseScenario(s, caseAt(s, 0), &xml))) {
      uses.push_back({f, "file the sweep's model reads:", false});
    }
  } catch (const std::exception&) {
    // an invalid case is reported where the cases are built
  }
  for (const std::string& o : outs) uses.push_back({o, "output", true});
  std::string err;
  if (mjbtool::checkDistinct(uses, &err)) return true;
  std::fprintf(stderr, "mjbuoy-sweep: %s\n", err.c_str());
  return false;
}

// the first result, log or manifest path of this shard that is not a
// regular file ("" if none)
static std::string blocked(const Sweep& s, const std::string& out, int shard, int nshards) {
  std::string why = notRegular((fs::path(out) / "sweep.json").string());
  for (long i = shard; why.empty() && i < s.ncases; i += nshards) {
    std::string id = caseAt(s, i).id;
    why = notRegular(resultPath(out, id));
    if (why.empty()) why = notRegular((fs::path(out) / "logs" / (id + ".log")).string());
  }
  return why;
}

// a result that needs no re-run: the same case definition, and not a crash
static bool complete(const std::string& path, const std::string& hash) {
  json j;
  return readJson(path, &j) && j.value("hash", "") == hash && j.value("status", "") != "crash";
}

static std::string tail(const std::string& path, size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return s.size() > n ? s.substr(s.size() - n) : s;
}

// start `self case FILE --index I --out DIR`, output to log
static pid_t spawn(const std::string& self, const Sweep& s, long index, const std::string& out,
                   const std::string& log) {
  pid_t pid = fork();
  if (pid != 0) return pid;
  int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) {
    dup2(fd, 1);
    dup2(fd, 2);
    close(fd);
  }
  std::string idx = std::to_string(index);
  execl(self.c_str(), self.c_str(), "case", s.file.c_str(), "--index", idx.c_str(), "--out",
        out.c_str(), (char*)nullptr);
  std::fprintf(stderr, "mjbuoy-sweep: cannot run %s: %s\n", self.c_str(), std::strerror(errno));
  _exit(127);
}

// what became of a finished case process; writes a crash record when it left none
static std::string settle(const Sweep& s, const Case& c, const std::string& hash, int status,
                          const std::string& out, const std::string& log) {
  std::string path = resultPath(out, c.id);
  bool exited = WIFEXITED(status), ok = exited && WEXITSTATUS(status) <= 2;
  json j;
  if (ok && readJson(path, &j) && j.value("hash", "") == hash) return j.value("status", "?");
  j = caseHeader(s, c);
  j["hash"] = hash;
  j["status"] = "crash";
  if (WIFSIGNALED(status)) {
    j["signal"] = WTERMSIG(status);
    j["error"] = std::string("the case's process was killed by signal ") +
                 std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  } else {
    j["exit"] = exited ? WEXITSTATUS(status) : -1;
    j["error"] = "the case's process exited with status " + std::to_string(j["exit"].get<int>()) +
                 " without a result";
  }
  j["log"] = tail(log, 2000);
  std::string err;
  if (!atomicfile::write(path, j.dump(1) + "\n", &err)) std::fprintf(stderr, "mjbuoy-sweep: %s\n", err.c_str());
  return "crash";
}

int runSweep(const std::string& file, const std::string& out, int jobs, int shard, int nshards,
             const std::string& self) {
  Sweep s = parseSweep(file);
  json man = manifest(s);  // builds every case's scenario: a bad value stops here (exit 2)
  if (!checkSweepOutputs(s, {(fs::path(out) / "sweep.json").string()})) return 2;
  if (std::string why = blocked(s, out, shard, nshards); !why.empty()) {
    std::fprintf(stderr, "mjbuoy-sweep: %s\n", why.c_str());
    return 2;
  }
  json prev;
  std::string mpath = (fs::path(out) / "sweep.json").string();
  if (readJson(mpath, &prev) && prev.value("file", "") != s.file) {
    std::fprintf(stderr, "mjbuoy-sweep: %s holds the results of another sweep (%s); give another "
                 "--out, or remove that directory to start again\n", out.c_str(),
                 prev.value("file", "").c_str());
    return 2;
  }
  std::error_code ec;
  fs::create_directories(fs::path(out) / "cases", ec);
  fs::create_directories(fs::path(out) / "logs", ec);
  std::string err;
  if (!atomicfile::write(mpath, man.dump(1) + "\n", &err)) {
    std::fprintf(stderr, "mjbuoy-sweep: %s\n", err.c_str());
    return 2;
  }
  std::vector<long> pending;
  long mine = 0;
  for (long i = shard; i < s.ncases; i += nshards) {
    mine++;
    if (!complete(resultPath(out, caseAt(s, i).id), man["cases"][i]["hash"])) pending.push_back(i);
  }
  std::printf("mjbuoy-sweep: %s: %ld case(s), shard %d/%d has %ld, %zu to run (%ld complete), "
              "%d job(s)\n", s.name.c_str(), s.ncases, shard, nshards, mine, pending.size(),
              mine - (long)pending.size(), jobs);
  std::fflush(stdout);
  const char* stop = std::getenv("MJBUOY_SWEEP_TEST_STOP_AFTER");  // test hook: die after K cases
  long stop_after = stop ? std::atol(stop) : -1;

  struct Running { long index; std::chrono::steady_clock::time_point t0; };
  std::map<pid_t, Running> running;
  size_t next = 0;
  long done = 0, bad = 0;
  while (next < pending.size() || !running.empty()) {
    while (next < pending.size() && (int)running.size() < jobs) {
      long i = pending[next++];
      Case c = caseAt(s, i);
      std::string log = (fs::path(out) / "logs" / (c.id + ".log")).string();
      pid_t pid = spawn(self, s, i, out, log);
      if (pid < 0) {
        std::fprintf(stderr, "mjbuoy-sweep: fork failed: %s\n", std::strerror(errno));
        return 3;
      }
      running[pid] = {i, std::chrono::steady_clock::now()};
    }
    int status = 0;
    pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      break;
    }
    auto it = running.find(pid);
    if (it == running.end()) continue;
    Case c = caseAt(s, it->second.index);
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - it->second.t0).count();
    std::string log = (fs::path(out) / "logs" / (c.id + ".log")).string();
    std::string st = settle(s, c, man["cases"][c.index]["hash"], status, out, log);
    running.erase(it);
    done++;
    bad += st != "pass";
    std::printf("[%ld/%zu] %s: %s (%.2f s)\n", done, pending.size(), c.id.c_str(), st.c_str(), wall);
    std::fflush(stdout);
    if (stop_after >= 0 && done >= stop_after) raise(SIGKILL);
  }
  std::printf("mjbuoy-sweep: shard %d/%d: ran %ld case(s), %ld not passed; results in %s\n", shard,
              nshards, done, bad, (fs::path(out) / "cases").string().c_str());
  // the status counts this shard's cases, also those complete from before
  for (long i = shard; i < s.ncases && !bad; i += nshards) {
    json j;
    bad += !readJson(resultPath(out, caseAt(s, i).id), &j) || j.value("status", "") != "pass";
  }
  return bad ? 1 : 0;
}

int list(const std::string& file) {
  Sweep s = parseSweep(file);
  manifest(s);  // every case must be valid
  for (long i = 0; i < s.ncases; i++) {
    Case c = caseAt(s, i);
    std::printf("%ld %s", i, c.id.c_str());
    for (size_t a = 0; a < s.axes.size(); a++) {
      std::printf(" %s=%s", s.axes[a].name.c_str(), s.axes[a].texts[c.at[a]].c_str());
    }
    std::printf("\n");
  }
  return 0;
}

int measureCase(const Sweep& s, long index, const std::string& self, Cost* cost) {
  if (index < 0 || index >= s.ncases) {
    std::fprintf(stderr, "mjbuoy-sweep: case %ld is not in 0 .. %ld\n", index, s.ncases - 1);
    return 2;
  }
  manifest(s);  // every case must be valid
  char tmpl[] = "/tmp/mjbuoy-sweep-estimate.XXXXXX";
  if (!mkdtemp(tmpl)) {
    std::fprintf(stderr, "mjbuoy-sweep: cannot make a temporary directory\n");
    return 3;
  }
  std::string dir = tmpl;
  fs::create_directories(fs::path(dir) / "cases");
  Case c = caseAt(s, index);
  auto t0 = std::chrono::steady_clock::now();
  pid_t pid = spawn(self, s, index, dir, dir + "/case.log");
  int status = 0;
  struct rusage ru;
  wait4(pid, &status, 0, &ru);
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::error_code ec;
  uintmax_t bytes = fs::file_size(resultPath(dir, c.id), ec);
  if (ec) bytes = 0;
  uintmax_t logb = fs::file_size(dir + "/case.log", ec);
  if (ec) logb = 0;
  json res;
  readJson(resultPath(dir, c.id), &res);
  fs::remove_all(dir, ec);
  if (res.value("status", "") == "invalid" || res.value("status", "") == "diverged") {
    std::fprintf(stderr, "mjbuoy-sweep: case %s is %s: %s\n", c.id.c_str(),
                 res.value("status", "").c_str(), res.value("error", "").c_str());
    return 2;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) > 2) {
    std::fprintf(stderr, "mjbuoy-sweep: case %s did not finish (status %d)\n", c.id.c_str(), status);
    return 1;
  }
  cost->wall = wall;
  cost->cpu = ru.ru_utime.tv_sec + ru.ru_stime.tv_sec + 1e-6 * (ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  cost->rss = ru.ru_maxrss / 1024.0;  // MiB
  cost->bytes = bytes;
  cost->logb = logb;
  cost->id = c.id;
  return 0;
}

void suggest(const Sweep& s, const Cost& c, int shards, int jobs, long* minutes, long* mem) {
  long per = (s.ncases + shards - 1) / shards;
  double task = std::ceil((double)per / jobs) * c.wall;
  // twice the measured time plus a minute: machines and cases vary
  *minutes = (long)std::ceil((2 * task + 60) / 60);
  // half again the peak of jobs cases at once, in 64 MiB steps
  *mem = (long)std::ceil(1.5 * c.rss * jobs / 64) * 64;
}

int estimate(const std::string& file, long index, int shards, int jobs, const std::string& self) {
  Sweep s = parseSweep(file);
  Cost c;
  if (int st = measureCase(s, index, self, &c)) return st;
  long minutes, mem;
  suggest(s, c, shards, jobs, &minutes, &mem);
  long per = (s.ncases + shards - 1) / shards;
  std::printf("case %s: wall %.3f s, cpu %.3f s, peak RSS %.1f MiB, result %ju B, log %ju B\n",
              c.id.c_str(), c.wall, c.cpu, c.rss, c.bytes, c.logb);
  std::printf("sweep %s: %ld case(s): about %.1f core-hours, output about %.1f MB (results and logs)\n",
              s.name.c_str(), s.ncases, c.wall * s.ncases / 3600,
              (c.bytes + c.logb) * (double)s.ncases / 1e6);
  std::printf("with --shards %d and --jobs %d: %ld case(s) per task, about %.0f s each\n", shards,
              jobs, per, std::ceil((double)per / jobs) * c.wall);
  std::printf("suggested: --time %ld --mem %ldM --jobs %d (time in minutes)\n", minutes, mem, jobs);
  return 0;
}

int precompute(const std::string& file) {
  Sweep s = parseSweep(file);
  manifest(s);  // every case must be valid
  long hit = 0, miss = 0;
  std::string dir;
  for (long i = 0; i < s.ncases; i++) {
    std::string xml;
    scn::Scenario sc = caseScenario(s, caseAt(s, i), &xml);
    std::unique_ptr<scn::Sim> sim = scn::loadScenario(sc, "");  // attach: solves or reads
    const mjb::Buoy* B = mjb::buoyOf(sim->b);
    hit += B->radcache.hit;
    miss += B->radcache.miss;
    dir = mjb::radCacheDir(B->cfg.rad.cache);
  }
  std::printf("mjbuoy-sweep: precompute %s: %ld case(s), radiation cache %s: %ld body(ies) read, "
              "%ld computed\n", s.name.c_str(), s.ncases, dir.empty() ? "off" : dir.c_str(), hit,
              miss);
  return 0;
}

}  // namespace swp
