// seaopts: the --set, --spectrum and --calm options of mjbuoy-sim and
// mjbuoy-view, declared once; their values go through one validator,
// mjbsim::parseEdits (tools/sim/simsea.h), and edit the model in memory
// before it compiles (docs/mjcf.md section 10)
#ifndef MJBUOY_TOOLS_SEAOPTS_H_
#define MJBUOY_TOOLS_SEAOPTS_H_

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace mjbtool {

struct SeaArgs {
  std::vector<std::string> sets, spectra;
  bool calm = false;
};

// adds --set, --spectrum and --calm to app, their values into a
inline void addSeaOptions(CLI::App& app, SeaArgs* a) {
  app.add_option("--set", a->sets, "NAME=VALUE: set or override the mjbuoy.* custom entry NAME "
                 "(repeatable; numbers make a <numeric>, else <text>, an existing entry keeps "
                 "its kind), e.g. --set mjbuoy.spectrum.sea.hs=1; the model file is not changed")
      ->allow_extra_args(false);
  app.add_option("--spectrum", a->spectra, "[LABEL=]TYPE[:FIELD=VALUE,...]: add a spectrum "
                 "(label default cli), e.g. --spectrum jonswap:hs=1,tp=6,spreading=10")
      ->allow_extra_args(false);
  app.add_flag("--calm", a->calm, "delete the model's waves and spectra (mjbuoy.wave.*, "
               "mjbuoy.airy.*, mjbuoy.spectrum.*) before --set and --spectrum");
}

}  // namespace mjbtool

#endif  // MJBUOY_TOOLS_SEAOPTS_H_
