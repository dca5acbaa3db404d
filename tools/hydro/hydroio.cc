// hydroio: coefficient files in mjbuoy-hydro (hydroio.h)
#include "hydroio.h"

namespace mjbhydro {

std::vector<std::string> outputsOf(const std::string& path) {
  if (mjb::coefFormatOf(path) != mjb::kCoefWamit) return {path};
  std::string stem = path.substr(0, path.rfind('.') + 1);
  return {stem + "1", stem + "3", stem + "3fk"};
}

bool writeAll(const std::vector<std::string>& paths, const mjb::CoefOpt& o,
              const mjb::CoefFile& f, std::string* err) {
  for (const std::string& p : paths) {
    *err = mjb::writeCoefFile(p, o, f);
    if (!err->empty()) return false;
  }
  return true;
}

}  // namespace mjbhydro
