// guard: divergence and MuJoCo's messages in the tools (see guard.h)
#include "guard.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cliopt.h"
#include "mjbuoy.h"

namespace mjbtool {

static const char* g_tool = "mjbuoy";
static std::string g_last;
static int g_count = 0;

static void onWarning(const char* msg) {
  g_last = msg;
  while (!g_last.empty() && (g_last.back() == '.' || g_last.back() == '\n')) g_last.pop_back();
  if (++g_count <= 20) {
    std::fprintf(stderr, "%s: MuJoCo warning: %s\n", g_tool, msg);
  } else if (g_count == 21) {
    std::fprintf(stderr, "%s: further MuJoCo warnings not shown\n", g_tool);
  }
}

static void onError(const char* msg) {
  std::fprintf(stderr, "%s: MuJoCo error: %s\n", g_tool, msg);
  std::exit(3);  // MuJoCo's state is undefined after an error
}

static void onProgress(const char* line, void* tool) {
  std::fprintf(stderr, "%s: %s\n", (const char*)tool, line);
}

void installProgress(const char* tool) { mjb_setProgress(onProgress, (void*)tool); }

void installMujocoHandlers(const char* tool) {
  g_tool = tool;
  mju_user_warning = onWarning;
  mju_user_error = onError;
  installProgress(tool);
}

std::string lastMujocoWarning() { return g_last; }

bool diverged(const mjData* d, std::string* why) {
  const int kinds[3] = {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC};
  const char* names[3] = {"bad qpos", "bad qvel", "bad qacc"};
  for (int k = 0; k < 3; k++) {
    if (d->warning[kinds[k]].number > 0) {
      if (why) {
        *why = "MuJoCo reset the state: " +
               (g_last.empty() ? std::string(names[k]) + " (NaN, Inf or a huge value)" : g_last);
      }
      return true;
    }
  }
  return false;
}

long stepsFor(double duration, double dt) {
  double n = duration / dt;
  if (!(n < kMaxSteps)) return -1;  // NaN, Inf or beyond a long's exact range
  double r = std::round(n);
  return (long)(std::fabs(n - r) < 1e-6 ? r : std::ceil(n));
}

long runSteps(double duration, double dt, std::string* why) {
  long n = stepsFor(duration, dt);
  if (n >= 1) return n;
  if (n == 0 || duration <= 0) {
    *why = "duration = " + bound(duration) + " s is less than one time step (" + bound(dt) +
           " s): the run would take 0 steps; give a duration of at least one time step";
  } else {
    *why = "duration = " + bound(duration) + " s at a time step of " + bound(dt) +
           " s is more than " + bound(kMaxSteps) + " steps; give a shorter duration";
  }
  return 0;
}

}  // namespace mjbtool
