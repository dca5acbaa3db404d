// radmem: the panel solver's memory estimate (radmem.h)
#include "radiation/radmem.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <thread>

namespace mjb {

double panelSolveBytes(double n, double nb, int nconc) {
  return 16 * n * n + 16 * nb * n + 32 * nb * nb + 80.0 * nconc * n * n;
}

int panelConcurrency(int nw) {
  int nt = (int)std::thread::hardware_concurrency();
  nt = nt < 1 ? 1 : (nt > 8 ? 8 : nt);
  return std::max(1, std::min(nt, nw));
}

// the first number of a one-line file, or -1 ("max" and missing: -1)
static double fileNumber(const char* path) {
  FILE* f = std::fopen(path, "r");
  if (!f) return -1;
  double v = -1;
  if (std::fscanf(f, "%lf", &v) != 1) v = -1;
  std::fclose(f);
  return v;
}

// MemAvailable of /proc/meminfo [bytes], or -1
static double memAvailable() {
  FILE* f = std::fopen("/proc/meminfo", "r");
  if (!f) return -1;
  char line[256];
  double kb = -1;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "MemAvailable: %lf kB", &kb) == 1) break;
  std::fclose(f);
  return kb >= 0 ? 1024 * kb : -1;
}

double memoryAvailable(std::string* what) {
  double best = INFINITY;
  what->clear();
  auto take = [&](double v, const char* name) {
    if (v >= 0 && v < best) best = v, *what = name;
  };
  take(memAvailable(), "the system's available memory (MemAvailable)");
  const double cmax = fileNumber("/sys/fs/cgroup/memory.max");
  const double ccur = fileNumber("/sys/fs/cgroup/memory.current");
  if (cmax >= 0 && ccur >= 0) take(std::max(0.0, cmax - ccur), "the cgroup's memory.max");
  rlimit r;
  if (getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY) {
    const double used = fileNumber("/proc/self/statm") * sysconf(_SC_PAGESIZE);
    take(std::max(0.0, double(r.rlim_cur) - std::max(0.0, used)),
         "the address-space limit (ulimit -v)");
  }
  return best;
}

std::string panelMemoryCheck(int n, int nb, int nw) {
  const int nc = panelConcurrency(nw);
  const double need = panelSolveBytes(n, nb, nc);
  std::string what;
  const double have = memoryAvailable(&what);
  if (need <= have) return "";
  char b[512];
  std::snprintf(b, sizeof b, "its %d wet panels (%d unknowns with the lid) need about %.3g GB "
                "for the panel solution (%d frequencies at a time), more than the %.3g GB of %s",
                nb, n, need / 1e9, nc, have / 1e9, what.c_str());
  return b;
}

}  // namespace mjb
