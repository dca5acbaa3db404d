// progress lines at attach (progress.h)
#include "api/progress.h"

#include <mutex>

namespace mjb {

namespace {
std::mutex gMu;  // models may be attached on several threads at once
mjbProgress gFn = nullptr;
void* gUser = nullptr;
}  // namespace

void progressSet(mjbProgress fn, void* user) {
  std::lock_guard<std::mutex> lk(gMu);
  gFn = fn;
  gUser = user;
}

void progressSay(const std::string& line) {
  std::lock_guard<std::mutex> lk(gMu);
  if (gFn) gFn(line.c_str(), gUser);
}

}  // namespace mjb
