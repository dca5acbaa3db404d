// mjbuoy-scenario: run scenario files and check the motion they produce.
// Exit status: 0 all checks pass, 1 a check fails, 2 a scenario is invalid.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "mjbuoy_version.h"
#include "scenario.h"

int main(int argc, char** argv) {
  CLI::App app{"Run mjbuoy scenario files (docs/scenarios.md): load the model with the "
               "scenario's sea and initial state, simulate and evaluate the checks. Exit status "
               "0: all pass, 1: a check fails, 2: an invalid scenario."};
  app.set_version_flag("--version", std::string("mjbuoy-scenario ") + MJBUOY_VERSION_STRING);
  std::vector<std::string> files;
  std::string junit, backend, print;
  app.add_option("scenario", files, "scenario XML file(s)")->required();
  app.add_option("--junit", junit, "write JUnit XML here (one <testsuite> per scenario file)");
  app.add_option("--backend", backend, "override the scenario's and the model's backend");
  app.add_option("--print-model", print,
                 "write the edited model MJCF of the (single) scenario here and exit");
  CLI11_PARSE(app, argc, argv);

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
      if (!print.empty()) {
        std::string xml = scn::editModel(s);
        FILE* out = std::fopen(print.c_str(), "w");
        if (!out) {
          std::fprintf(stderr, "mjbuoy-scenario: cannot write %s\n", print.c_str());
          return 2;
        }
        std::fputs(xml.c_str(), out);
        std::fclose(out);
        return 0;
      }
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
  if (!junit.empty() && !scn::writeJUnit(reports, junit)) {
    std::fprintf(stderr, "mjbuoy-scenario: cannot write %s: check the directory exists and is "
                 "writable\n", junit.c_str());
    return 2;
  }
  return status;
}
