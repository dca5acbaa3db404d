// mjbuoy-sim --set, --spectrum and --calm: mjbuoy.* custom entries set on
// the model in memory before it compiles (docs/mjcf.md section 10)
#ifndef MJBUOY_TOOLS_SIMSEA_H_
#define MJBUOY_TOOLS_SIMSEA_H_

#include <string>
#include <utility>
#include <vector>

#include <mujoco/mujoco.h>

namespace mjbsim {

struct Edits {
  bool calm = false;  // delete the model's waves and spectra first
  std::vector<std::pair<std::string, std::string>> set;  // name, data
  std::vector<std::string> given;  // the option that set each entry, for messages
  bool empty() const { return !calm && set.empty(); }
};

// parse --set NAME=VALUE and --spectrum [LABEL=]TYPE[:FIELD=VALUE,...]
// arguments into edits; "" or what is wrong, naming the argument
std::string parseEdits(const std::vector<std::string>& sets,
                       const std::vector<std::string>& spectra, bool calm, Edits* out);

// the MJCF text of the model file with the edits applied (the file is only
// read; mjbtool::loadModel compiles it); false with the reason in err
bool editedModel(const std::string& model, const Edits& e, std::string* xml, std::string* err);

// the same for the MJCF text of model (mjbuoy's Python Sim, which takes
// MJCF text too)
bool editedText(const std::string& model, const std::string& text, const Edits& e,
                std::string* xml, std::string* err);

// the same for the MJCF text xml, compiled as if it were the file model
// (its directory resolves mesh files and includes; mjbuoy's Python Sim)
mjModel* loadEditedText(const std::string& model, const std::string& xml, const Edits& e,
                        std::string* err);

// an mjb_attach message about an entry the edits set, prefixed with the
// option that set it
std::string blame(const Edits& e, const std::string& err);

}  // namespace mjbsim

#endif  // MJBUOY_TOOLS_SIMSEA_H_
