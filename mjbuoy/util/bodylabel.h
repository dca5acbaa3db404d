// bodylabel: a body as messages name it
#ifndef MJBUOY_UTIL_BODYLABEL_H_
#define MJBUOY_UTIL_BODYLABEL_H_

#include <cstddef>
#include <cstdio>
#include <string>

#include <mujoco/mujoco.h>

namespace mjb {

// body b for a message: its name in quotes ("\"hull\""), or its id when the
// model gives it none ("3 (no name)"), into buf of n chars (no allocation:
// the per-step notices use it)
inline const char* bodyLabel(const mjModel* m, int b, char* buf, size_t n) {
  const char* name = m->names + m->name_bodyadr[b];
  if (*name) {
    std::snprintf(buf, n, "\"%s\"", name);
  } else {
    std::snprintf(buf, n, "%d (no name)", b);
  }
  return buf;
}

// bodyLabel as a string (attach and parse time)
inline std::string bodyLabel(const mjModel* m, int b) {
  char buf[256];
  return bodyLabel(m, b, buf, sizeof buf);
}

}  // namespace mjb

#endif  // MJBUOY_UTIL_BODYLABEL_H_
