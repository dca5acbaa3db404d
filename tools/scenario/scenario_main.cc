// mjbuoy-scenario: run scenario files and check the motion they produce.
// Exit status: 0 all checks pass, 1 a check fails, 2 a scenario is invalid
// (or an output cannot be written).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cliopt.h"

#include "guard.h"
#include "modelload.h"
#include "outfile.h"
#include "mjbuoy_version.h"
#include "scenario.h"

// the files a run reads: the scenario files, and of those that parse, their
// models and <mesh file>s
static std::vector<mjbtool::PathUse> inputs(const std::vector<std::string>& files) {
  std::vector<mjbtool::PathUse> uses;
  for (const std::string& f : files) {
    uses.push_back({f, "scenario", false});
    try {
      scn::Scenario s = scn::parseScenario(f);
      for (const std::string& mf : mjbtool::modelFiles(s.model)) {
        std::string what = mf == s.model ? "model of " + f + ":"
                                         : "file that the model of " + f + " reads:";
        uses.push_back({mf, what, false});
      }
      for (const scn::MeshFile& mf : s.meshes) uses.push_back({mf.file, "mesh of " + f + ":", false});
    } catch (const scn::Invalid&) {
      // reported when the scenario runs
    }
  }
  return uses;
}

// write the edited model of the single scenario (status 0) or say why not (2)
static int printModel(const std::string& file, const std::string& print) {
  try {
    scn::Scenario s = scn::parseScenario(file);
    std::string xml = scn::editModel(s);
    mjbtool::OutFile out;
    std::string e;
    if (!out.open(print, "--print-model", &e) ||
        std::fwrite(xml.data(), 1, xml.size(), out.file()) != xml.size() || !out.commit(&e)) {
      if (e.empty()) e = "--print-model " + print + ": write failed";
      std::fprintf(stderr, "mjbuoy-scenario: %s\n", e.c_str());
      return 2;
    }
    return 0;
  } catch (const scn::Invalid& e) {
    std::fprintf(stderr, "mjbuoy-scenario: %s\n", e.what());
    return 2;
  }
}

int main(int argc, char** argv) {
  mjbtool::installMujocoHandlers("mjbuoy-scenario");
  CLI::App app{"Run mjbuoy scenario files (docs/scenarios.md): load the model with the "
               "scenario's sea and initial state, simulate and evaluate the checks. Exit status "
               "0: all pass, 1: a check fails, 2: an invalid scenario or an output that cannot "
               "be written."};
  app.set_version_flag("--version", std::string("mjbuoy-scenario ") + MJBUOY_VERSION_STRING);
  std::vector<std::string> files;
  std::string junit, backend, print;
  app.add_option("scenario", files, "scenario XML file(s)")->required();
  app.add_option("--junit", junit, "write JUnit XML here (one <testsuite> per scenario file)");
  app.add_option("--backend", backend, "override the scenario's and the model's backend");
  app.add_option("--print-model", print,
                 "write the edited model MJCF of the (single) scenario here and exit");
  {
    int rc = mjbtool::parseArgs(app, argc, argv, 2);  // docs: invalid input exits 2
    if (rc >= 0) return rc;
  }

  if (!print.empty() && files.size() != 1) {
    std::fprintf(stderr, "mjbuoy-scenario: --print-model writes the model of one scenario, "
                 "but %zu scenario files were given; run it once per scenario\n", files.size());
    return 2;
  }
  if (!print.empty() || !junit.empty()) {
    std::vector<mjbtool::PathUse> uses = inputs(files);
    if (!print.empty()) uses.push_back({print, "--print-model", true});
    if (!junit.empty()) uses.push_back({junit, "--junit", true});
    std::string e;
    for (const mjbtool::PathUse& u : uses) {
      if (u.output && !mjbtool::checkWritable(u.path, u.what, &e)) {
        std::fprintf(stderr, "mjbuoy-scenario: %s\n", e.c_str());
        return 2;
      }
    }
    if (!mjbtool::checkDistinct(uses, &e)) {
      std::fprintf(stderr, "mjbuoy-scenario: %s\n", e.c_str());
      return 2;
    }
  }
  if (!print.empty()) return printModel(files[0], print);

  std::vector<scn::Report> reports;
  int status = 0;
  for (const std::string& f : files) {
    scn::Report r;
    r.file = f;
    r.name = std::filesystem::path(f).stem().string();
    auto t0 = std::chrono::steady_clock::now();
    try {
      scn::Scenario s = scn::parseScenario(f);
      r.name = s.name;
      std::unique_ptr<scn::Sim> sim = scn::loadScenario(s, backend);
      if (!sim->warnings.empty()) std::fputs(sim->warnings.c_str(), stderr);
      scn::runScenario(s, *sim, r);
    } catch (const scn::Invalid& e) {
      r.invalid = true;
      r.error = e.what();
      std::fprintf(stderr, "mjbuoy-scenario: %s\n", e.what());
    }
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    scn::printReport(r, stdout);
    std::fflush(stdout);
    status = std::max(status, r.invalid ? 2 : r.passed() ? 0 : 1);
    reports.push_back(std::move(r));
  }
  if (!junit.empty()) {
    mjbtool::OutFile out;
    std::string e;
    if (!out.open(junit, "--junit", &e) || !scn::writeJUnit(reports, out.file()) ||
        !out.commit(&e)) {
      if (e.empty()) e = "--junit " + junit + ": write failed";
      std::fprintf(stderr, "mjbuoy-scenario: %s\n", e.c_str());
      return 2;
    }
  }
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::fprintf(stderr, "mjbuoy-scenario: cannot write the report to stdout\n");
    return 2;
  }
  return status;
}
