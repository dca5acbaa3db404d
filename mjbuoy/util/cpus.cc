// cpus: the CPU allocation of this process (see cpus.h)
#include "util/cpus.h"

#ifdef __linux__
#include <sched.h>
#endif

#include <cstdlib>
#include <thread>

namespace mjb {

int usableCpus() {
  int n = 0;
#ifdef __linux__
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) n = CPU_COUNT(&set);
#endif
  if (n < 1) n = (int)std::thread::hardware_concurrency();
  // Slurm binds tasks to their CPUs only with task/affinity or cgroups; the
  // variable holds the allocation either way
  if (const char* s = std::getenv("SLURM_CPUS_PER_TASK")) {
    char* end = nullptr;
    long k = std::strtol(s, &end, 10);
    if (end != s && *end == 0 && k >= 1 && k < n) n = (int)k;
  }
  return n < 1 ? 1 : n;
}

}  // namespace mjb
