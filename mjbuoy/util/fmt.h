// fmt: numbers and MJCF entries as mjbuoy's messages print them
#ifndef MJBUOY_UTIL_FMT_H_
#define MJBUOY_UTIL_FMT_H_

#include <string>

namespace mjb {

// a number as messages print it (10 significant digits)
std::string fmt(double v);

// an entry as MJCF writes it, <kind name="name">
std::string tag(const char* kind, const char* name);

}  // namespace mjb

#endif  // MJBUOY_UTIL_FMT_H_
