// libFuzzer target: the scenario file parser of mjbuoy-scenario
// (tools/scenario/scenario_parse.cc) and, for a valid scenario, the model edit and
// load that follow (tools/scenario/scenario_model.cc; cpu backend, no simulation).
// Bytes -> scenario XML text, read as if it were the file
// tests/scenarios/checks/fuzz.xml (model paths as in the seed corpus).
// Must hold: every rejection is a scn::Invalid with a "FILE:LINE: reason"
// message; no other exception, crash or sanitizer report.
#include <cstdio>
#include <string>

#include "scenario.h"

#ifndef MJB_SCENARIO_DIR
#error "MJB_SCENARIO_DIR: the directory model paths are relative to"
#endif

namespace {

void quiet(const char*) {}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  mju_user_warning = quiet;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string file = MJB_SCENARIO_DIR "/fuzz.xml";
  std::string xml(reinterpret_cast<const char*>(data), size);
  try {
    scn::Scenario s = scn::parseScenarioText(xml, file);
    if (s.checks.empty() || !(s.duration > 0)) __builtin_trap();  // the parser's own rules
    // radiation off (appended last, so it wins over the model's and the
    // scenario's switch): the panel solve of a radiating model (the seed
    // fleet's 11 bodies) takes far longer than libFuzzer's per-input timeout
    // under the fuzz build's instrumentation, and this target is about the
    // scenario's parse, edit and load; radiation's entries are checked by
    // RadAttach.BadEntriesAreRefusedByName
    scn::Entry off;
    off.name = "mjbuoy.radiation";
    off.data = "off";
    off.text = true;
    s.entries.push_back(off);
    scn::editModel(s);
    std::unique_ptr<scn::Sim> sim = scn::loadScenario(s, "cpu");
    if (!sim->m || !sim->d || !sim->b) __builtin_trap();
  } catch (const scn::Invalid& e) {
    std::string what = e.what();
    if (what.compare(0, file.size(), file) != 0 || what.size() <= file.size() + 2) {
      std::fprintf(stderr, "fuzz_scenario: error without FILE:LINE: reason: %s\n", what.c_str());
      __builtin_trap();
    }
  }
  return 0;
}
