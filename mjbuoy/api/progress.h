// progress lines of long work at attach (mjb_setProgress, mjbuoy.h): what
// the panel solver solves and its estimated time, what the radiation cache
// answers
#ifndef MJBUOY_PROGRESS_H_
#define MJBUOY_PROGRESS_H_

#include <string>

#include "mjbuoy.h"

namespace mjb {

// the process-wide receiver (NULL: silent, the default)
void progressSet(mjbProgress fn, void* user);

// one line (no newline) to the receiver, if any
void progressSay(const std::string& line);

}  // namespace mjb

#endif  // MJBUOY_PROGRESS_H_
