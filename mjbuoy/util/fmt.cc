// fmt: numbers and MJCF entries as mjbuoy's messages print them
#include "util/fmt.h"

#include <sstream>

namespace mjb {

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string tag(const char* kind, const char* name) {
  return std::string("<") + kind + " name=\"" + name + "\">";
}

}  // namespace mjb
