// benchscene: mjbuoy-bench --scene (see benchscene.h)
#include "benchscene.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <vector>

#include <mujoco/mujoco.h>

#include "benchcmp.h"
#include "guard.h"
#include "mjbuoy.h"
#include "modelload.h"
#include "outfile.h"
#include "radnotice.h"

namespace mjbtool {
namespace {

using Clock = std::chrono::steady_clock;

// the callback mjbuoy installed, timed: wall and CPU time of all threads
mjfGeneric sinner = nullptr;
double shydro = 0, scpu = 0;

double cpuNow() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

void timedPassive(const mjModel* m, mjData* d) {
  double c0 = cpuNow();
  auto t0 = Clock::now();
  sinner(m, d);
  shydro += std::chrono::duration<double>(Clock::now() - t0).count();
  scpu += cpuNow() - c0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Row {
  std::string backend, radiation;
  int nhull = 0, ntri = 0;
  double dt = 0, hydro = 0, cpu = 0, step = 0;  // timestep [s]; ms per step
  double stepCpu = 0;  // CPU ms per step of the whole process, all threads
  double rtf() const { return dt * 1e3 / step; }  // simulated s per wall s
};

// attach, warm up (5 steps), time reps x steps; false with the message printed
bool measure(const SceneArgs& a, Row* row) {
  std::string e;
  mjModel* m = loadModel(a.file, nullptr, "mjbuoy-bench", &e);
  if (!m) {
    std::fprintf(stderr, "mjbuoy-bench: --scene: %s\n", e.c_str());
    return false;
  }
  std::string plan = radiationPlan(m);
  if (!plan.empty()) std::fprintf(stderr, "mjbuoy-bench: %s\n", plan.c_str());
  char err[1024] = "";
  mjbBuoy* b = mjb_attach(m, a.backend.empty() ? nullptr : a.backend.c_str(), err, sizeof(err));
  if (!b) {
    std::fprintf(stderr, "mjbuoy-bench: --scene %s: %s\n", a.file.c_str(), err);
    mj_deleteModel(m);
    return false;
  }
  std::fputs(mjb_warnings(b), stderr);
  mjData* d = mj_makeData(m);
  mjb_bindData(b, d);
  row->radiation = radiationState(b);
  mjbInfo info = mjb_info(b);
  row->backend = info.backend;
  row->nhull = info.nhull;
  row->ntri = info.ntri;
  row->dt = m->opt.timestep;
  sinner = mjcb_passive;
  mjcb_passive = timedPassive;
  for (int i = 0; i < 5; i++) mj_step(m, d);
  std::vector<double> full, hydro, cpu, stepCpu;
  std::string why;
  for (int r = 0; r < a.reps && why.empty(); r++) {
    shydro = scpu = 0;
    auto t0 = Clock::now();
    double c0 = cpuNow();
    for (int i = 0; i < a.steps; i++) mj_step(m, d);
    stepCpu.push_back((cpuNow() - c0) * 1e3 / a.steps);
    full.push_back(std::chrono::duration<double>(Clock::now() - t0).count() * 1e3 / a.steps);
    hydro.push_back(shydro * 1e3 / a.steps);
    cpu.push_back(scpu * 1e3 / a.steps);
    diverged(d, &why);  // a reset state is no measurement
  }
  mjcb_passive = sinner;
  std::fputs(mjb_notices(b, d), stderr);
  mjb_unbindData(b, d);
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
  if (!why.empty()) {
    std::fprintf(stderr, "mjbuoy-bench: --scene %s diverged: %s\n", a.file.c_str(), why.c_str());
    return false;
  }
  row->hydro = median(hydro);
  row->cpu = median(cpu);
  row->step = median(full);
  row->stepCpu = median(stepCpu);
  return true;
}

bool writeJson(const SceneArgs& a, const Row& r) {
  OutFile of;
  std::string e;
  if (!of.open(a.json, "--json", &e)) {
    std::fprintf(stderr, "mjbuoy-bench: %s\n", e.c_str());
    return false;
  }
  std::fprintf(of.file(), "[\n  {\"scene\": \"%s\", \"backend\": \"%s\", \"hulls\": %d, "
               "\"triangles\": %d, \"timestep_s\": %.9g, \"hydro_ms\": %.6f, "
               "\"hydro_cpu_ms\": %.6f, \"step_ms\": %.6f, \"step_cpu_ms\": %.6f, "
               "\"rtf\": %.6f}\n]\n",
               a.file.c_str(), r.backend.c_str(), r.nhull, r.ntri, r.dt, r.hydro, r.cpu, r.step,
               r.stepCpu, r.rtf());
  if (!of.commit(&e)) {
    std::fprintf(stderr, "mjbuoy-bench: %s\n", e.c_str());
    return false;
  }
  return true;
}

}  // namespace

int benchScene(const SceneArgs& a) {
  Row r;
  if (!measure(a, &r)) return 1;
  std::printf("| scene | backend | hulls | triangles | radiation | hydro ms/step | "
              "hydro CPU ms/step | step ms | step CPU ms | timestep ms | real-time factor |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|\n"
              "| %s | %s | %d | %d | %s | %.3f | %.3f | %.3f | %.3f | %.3g | %.2f |\n",
              a.file.c_str(), r.backend.c_str(), r.nhull, r.ntri, r.radiation.c_str(), r.hydro,
              r.cpu, r.step, r.stepCpu, r.dt * 1e3, r.rtf());
  if (!a.json.empty() && !writeJson(a, r)) return 1;
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::fprintf(stderr, "mjbuoy-bench: cannot write the table to stdout\n");
    return 1;
  }
  return 0;
}

bool baselineSetup(std::string* exe, std::string* dir) {
  char buf[4096];
  ssize_t n = readlink("/proc/self/exe", buf, sizeof(buf) - 1);
  if (n <= 0) {
    std::fprintf(stderr, "mjbuoy-bench: --baseline: cannot find this executable\n");
    return false;
  }
  buf[n] = 0;
  *exe = buf;
  const char* td = std::getenv("TMPDIR");
  std::string tmpl = std::string(td && *td ? td : "/tmp") + "/mjbuoy-bench-XXXXXX";
  if (!mkdtemp(&tmpl[0])) {
    std::fprintf(stderr, "mjbuoy-bench: --baseline: cannot create a directory like %s: %s\n",
                 tmpl.c_str(), std::strerror(errno));
    return false;
  }
  *dir = tmpl;
  return true;
}

int compareScene(const SceneArgs& a, const std::string& base) {
  std::string self, tmp;
  if (!baselineSetup(&self, &tmp)) return 1;
  const char* exe = self.c_str();
  const char* dir = tmp.c_str();
  std::vector<std::string> args = {"--scene", a.file, "--steps", std::to_string(a.steps),
                                   "--reps", "1"};
  if (!a.backend.empty()) args.insert(args.end(), {"--backend", a.backend});
  std::vector<double> ha, hb, sa, sb, rs;
  int rc = 0;
  for (int r = 0; r < a.reps && !rc; r++) {
    CmpRun x, y;
    std::string e;
    if (!benchChild(exe, args, dir, &x, &e)) {
      std::fprintf(stderr, "mjbuoy-bench: %s\n", e.c_str());
      rc = 1;
    } else if (!benchChild(base, args, dir, &y, &e)) {
      if (e.find("--scene") != std::string::npos && e.find("not expected") != std::string::npos) {
        std::fprintf(stderr, "mjbuoy-bench: --baseline %s has no --scene option: a side-by-side "
                     "run of a scene needs both builds to support it; run this bench with "
                     "--scene alone, and time the baseline build with its mjbuoy-sim "
                     "--duration\n", base.c_str());
      } else {
        std::fprintf(stderr, "mjbuoy-bench: --baseline: %s\n", e.c_str());
      }
      rc = 1;
    } else {
      ha.push_back(x.hydro);
      hb.push_back(y.hydro);
      sa.push_back(x.step);
      sb.push_back(y.step);
      rs.push_back(y.step / x.step);
    }
  }
  std::remove((std::string(dir) + "/cell.json").c_str());
  std::remove((std::string(dir) + "/stderr.txt").c_str());
  rmdir(dir);
  if (rc) return rc;
  std::printf("| scene | hydro ms | baseline hydro ms | step ms | baseline step ms | "
              "baseline/this step |\n|---|---|---|---|---|---|\n"
              "| %s | %.3f | %.3f | %.3f | %.3f | %.2f |\n", a.file.c_str(), median(ha),
              median(hb), median(sa), median(sb), median(rs));
  return std::fflush(stdout) != 0 ? 1 : 0;
}

}  // namespace mjbtool
