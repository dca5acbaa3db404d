// mjbuoy-sweep: one case in its own process (the runner starts
// `mjbuoy-sweep case FILE --index I --out DIR`): build the case's scenario,
// run it, evaluate checks and statistics, write DIR/cases/<id>.json
// atomically. Exit status as mjbuoy-scenario: 0 pass, 1 fail, 2 invalid.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <sys/resource.h>

#include <nlohmann/json.hpp>

#include "atomic.h"
#include "sweep.h"

namespace swp {

using json = nlohmann::json;

// the report's header without its wall time, which differs between runs
static std::string stableHeader(const std::string& h) {
  size_t w = h.find(", wall ");
  return w == std::string::npos ? h : h.substr(0, w);
}

json caseHeader(const Sweep& s, const Case& c) {
  json j;
  j["sweep"] = s.name;
  j["id"] = c.id;
  j["index"] = c.index;
  json ax = json::object();
  for (size_t i = 0; i < s.axes.size(); i++) ax[s.axes[i].name] = s.axes[i].labels[c.at[i]];
  j["axes"] = ax;
  return j;
}

int runCase(const std::string& file, long index, const std::string& out) {
  auto t0 = std::chrono::steady_clock::now();
  Sweep s = parseSweep(file);
  if (index < 0 || index >= s.ncases) {
    std::fprintf(stderr, "mjbuoy-sweep: case %ld is not in 0 .. %ld\n", index, s.ncases - 1);
    return 2;
  }
  Case c = caseAt(s, index);
  json j = caseHeader(s, c);
  std::string xml;
  int status = 0;
  try {
    scn::Scenario sc = caseScenario(s, c, &xml);
    j["hash"] = caseHash(s, xml, caseFiles(sc));
    // test hook (tests/sweeps): this case's process dies as if killed (OOM, node failure)
    const char* crash = std::getenv("MJBUOY_SWEEP_TEST_CRASH");
    if (crash && c.id == crash) std::raise(SIGKILL);
    std::unique_ptr<scn::Sim> sim = scn::loadScenario(sc, "");
    if (!sim->warnings.empty()) std::fputs(sim->warnings.c_str(), stderr);
    Stats stats(s, sc, sim->m);
    scn::Report r;
    r.file = s.base;
    r.name = s.name + "." + c.id;
    scn::runScenario(sc, *sim, r, [&](const scn::Sample& smp) { stats.sample(smp); });
    scn::printReport(r, stdout);
    std::vector<double> v = stats.finish(r.diverged);
    json st = json::object();
    for (size_t i = 0; i < v.size(); i++) st[s.stats[i].name] = v[i];  // NaN -> null
    json checks = json::array();
    for (const scn::Result& x : r.results) {
      checks.push_back({{"label", x.label}, {"kind", x.kind}, {"pass", x.pass}, {"detail", x.detail}});
    }
    j["stats"] = st;
    j["checks"] = checks;
    j["header"] = stableHeader(r.header);
    bool div = !std::isinf(r.diverged);
    j["status"] = div ? "diverged" : r.passed() ? "pass" : "fail";
    status = r.passed() ? 0 : 1;
  } catch (const scn::Invalid& e) {
    std::fprintf(stderr, "mjbuoy-sweep: %s\n", e.what());
    if (!j.contains("hash")) j["hash"] = caseHash(s, xml, {});
    j["status"] = "invalid";
    j["error"] = e.what();
    status = 2;
  }
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  j["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  j["maxrss_kb"] = ru.ru_maxrss;
  std::string err;
  if (!atomicfile::write(resultPath(out, c.id), j.dump(1) + "\n", &err)) {
    std::fprintf(stderr, "mjbuoy-sweep: %s\n", err.c_str());
    return 3;
  }
  return status;
}

}  // namespace swp
