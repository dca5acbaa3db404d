// the CPU allocation (util/cpus.h) and the cpu backend's automatic thread
// count: a process that a batch scheduler (taskset, Slurm, cgroups) gives
// fewer CPUs than the node has runs that many threads, not one per core
#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "api/buoy.h"
#include "mjbuoy.h"
#include "util/cpus.h"

namespace {

// the kernel's own list of the CPUs this process may use ("0-3,6"), from
// /proc/self/status: an independent reading of the affinity mask
int allowedFromProc() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("Cpus_allowed_list:", 0) != 0) continue;
    std::istringstream s(line.substr(18));
    std::string part;
    int n = 0;
    while (std::getline(s, part, ',')) {
      size_t dash = part.find('-');
      int a = std::stoi(part), b = dash == std::string::npos ? a : std::stoi(part.substr(dash + 1));
      n += b - a + 1;
    }
    return n;
  }
  return -1;
}

// one Wigley hull of 7740 triangles, past the 2000 above which the
// automatic thread count uses several threads (api/glue.cc); radiation off
// (only the thread count matters here)
std::string wigley() {
  return "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" MJB_MODELS
         "/meshes/wigley_7744.obj\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"h0\"/>"
         "<text name=\"mjbuoy.radiation\" data=\"off\"/></custom><worldbody>"
         "<body pos=\"0 0 0.03\"><freejoint/><inertial pos=\"0 0 -0.08\" mass=\"176.2\" "
         "diaginertia=\"6.02 237.28 238.6\"/><geom name=\"h0\" type=\"mesh\" mesh=\"w\" "
         "contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>";
}

int autoThreads() {
  std::string xml = wigley();
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "w.xml", (int)xml.size());
  std::copy(xml.begin(), xml.end(), (char*)vfs.filedata[mj_findFileVFS(&vfs, "w.xml")]);
  char err[1024] = "";
  mjModel* m = mj_loadXML("w.xml", &vfs, err, sizeof(err));
  mj_deleteVFS(&vfs);
  EXPECT_NE(m, nullptr) << err;
  if (!m) return -1;
  mjbBuoy* b = mjb_attach(m, "cpu", err, sizeof(err));
  EXPECT_NE(b, nullptr) << err;
  int n = b ? mjb::buoyOf(b)->nthreads : -1;
  if (b) mjb_detach(b);
  mj_deleteModel(m);
  return n;
}

TEST(Cpus, CountsTheAffinityMask) {
  unsetenv("SLURM_CPUS_PER_TASK");
  EXPECT_EQ(mjb::usableCpus(), allowedFromProc());
}

TEST(Cpus, OneAllowedCpuMeansOneThread) {
  cpu_set_t old;
  ASSERT_EQ(sched_getaffinity(0, sizeof(old), &old), 0);
  unsetenv("SLURM_CPUS_PER_TASK");
  // this hull splits among the allowed CPUs, at most its 4 chunks of 1935
  // triangles (mjb::hullChunks; api/glue.cc caps the count at 8 too)
  EXPECT_EQ(autoThreads(), std::min(CPU_COUNT(&old), 4));
  int first = 0;
  while (!CPU_ISSET(first, &old)) first++;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof(one), &one), 0);  // as `taskset -c FIRST`
  EXPECT_EQ(allowedFromProc(), 1);
  EXPECT_EQ(mjb::usableCpus(), 1);
  EXPECT_EQ(autoThreads(), 1);
  sched_setaffinity(0, sizeof(old), &old);
}

TEST(Cpus, SlurmsAllocationBoundsTheCount) {
  cpu_set_t old;
  ASSERT_EQ(sched_getaffinity(0, sizeof(old), &old), 0);
  setenv("SLURM_CPUS_PER_TASK", "1", 1);
  EXPECT_EQ(mjb::usableCpus(), 1);
  EXPECT_EQ(autoThreads(), 1);
  setenv("SLURM_CPUS_PER_TASK", "not a number", 1);  // ignored, not trusted
  EXPECT_EQ(mjb::usableCpus(), CPU_COUNT(&old));
  unsetenv("SLURM_CPUS_PER_TASK");
}

}  // namespace
