// mjbuoy-sim: run an MJCF boat scene headless and summarise it
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <mujoco/mujoco.h>

#include "mjbuoy.h"

// roll, pitch, yaw [deg] of rotation matrix R (row-major), marine
// convention R = Rz(yaw) Ry(pitch) Rx(roll) (intrinsic z, y', x'')
static void rpy(const mjtNum* R, double out[3]) {
  out[0] = std::atan2(R[7], R[8]) * 180 / M_PI;
  out[1] = -std::asin(std::fmax(-1.0, std::fmin(1.0, R[6]))) * 180 / M_PI;
  out[2] = std::atan2(R[3], R[0]) * 180 / M_PI;
}

int main(int argc, char** argv) {
  CLI::App app{"Simulate an mjbuoy MJCF scene headless and print a summary."};
  std::string model, csv, backend;
  double duration = 10, interval = 0.01;
  app.add_option("model", model, "MJCF model file")->required()->check(CLI::ExistingFile);
  app.add_option("--duration", duration, "simulated time [s]")->check(CLI::NonNegativeNumber);
  app.add_option("--csv", csv, "write time and pose of every free body to this CSV file");
  app.add_option("--interval", interval, "CSV output interval [s]")
      ->check(CLI::PositiveNumber);
  app.add_option("--backend", backend, "override the model's mjbuoy.backend")
      ->check(CLI::IsMember({"cpu", "gl", "auto"}));
  std::vector<double> ctrl;
  app.add_option("--ctrl", ctrl, "constant controls, one per actuator in model order");
  CLI11_PARSE(app, argc, argv);

  char err[1024] = "";
  mjModel* m = mj_loadXML(model.c_str(), nullptr, err, sizeof(err));
  if (!m) {
    std::fprintf(stderr, "mjbuoy-sim: cannot load %s: %s\n", model.c_str(), err);
    return 1;
  }
  mjbBuoy* b = mjb_attach(m, backend.empty() ? nullptr : backend.c_str(), err, sizeof(err));
  if (!b) {
    std::fprintf(stderr, "mjbuoy-sim: %s: %s\n", model.c_str(), err);
    mj_deleteModel(m);
    return 1;
  }
  std::fputs(mjb_warnings(b), stderr);
  mjData* d = mj_makeData(m);
  mjb_bindData(b, d);
  if ((int)ctrl.size() > m->nu) {
    std::fprintf(stderr, "mjbuoy-sim: --ctrl has %zu values but %s has %d actuator(s)\n",
                 ctrl.size(), model.c_str(), m->nu);
    return 1;
  }
  for (size_t i = 0; i < ctrl.size(); i++) d->ctrl[i] = ctrl[i];

  // bodies with a free joint go to the CSV
  std::vector<int> free;
  for (int j = 0; j < m->njnt; j++) {
    if (m->jnt_type[j] == mjJNT_FREE) free.push_back(m->jnt_bodyid[j]);
  }
  FILE* out = nullptr;
  if (!csv.empty()) {
    out = std::fopen(csv.c_str(), "w");
    if (!out) {
      std::fprintf(stderr, "mjbuoy-sim: cannot write %s: check the directory exists "
                   "and is writable\n", csv.c_str());
      return 1;
    }
    std::fprintf(out, "time");
    for (int bd : free) {
      const char* n = m->names + m->name_bodyadr[bd];
      for (const char* c : {"x", "y", "z", "roll", "pitch", "yaw"}) {
        std::fprintf(out, ",%s.%s", n, c);
      }
    }
    std::fprintf(out, "\n");
  }

  auto row = [&]() {
    std::fprintf(out, "%.6f", d->time);
    for (int bd : free) {
      double a[3];
      rpy(d->xmat + 9 * bd, a);
      const mjtNum* x = d->xpos + 3 * bd;
      std::fprintf(out, ",%.9g,%.9g,%.9g,%.6g,%.6g,%.6g", x[0], x[1], x[2], a[0], a[1], a[2]);
    }
    std::fprintf(out, "\n");
  };

  mj_forward(m, d);
  long steps = 0;
  double next = 0;
  auto t0 = std::chrono::steady_clock::now();
  const double eps = 1e-9 * std::fmax(1.0, duration);
  while (true) {
    if (out && d->time >= next - eps) {
      row();
      next += interval;
    }
    if (d->time >= duration - eps) break;
    mj_step(m, d);
    steps++;
  }
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  mjbInfo info = mjb_info(b);
  std::printf("mjbuoy-sim: %s\n", model.c_str());
  std::printf("  backend %s on %s: %d hulls on %d bodies, %d triangles\n", info.backend,
              info.renderer, info.nhull, info.nbody, info.ntri);
  std::printf("  sim time %.3f s in %ld steps, wall %.3f s (%.1fx real time)\n", d->time,
              steps, wall, wall > 0 ? d->time / wall : 0.0);
  const char* sn[8];
  double sms[8];
  int ns = mjb_stageTimes(b, sn, sms, 8);
  if (ns) {
    std::printf("  gl stages per step:");
    for (int i = 0; i < ns; i++) std::printf(" %s %.3f ms", sn[i], sms[i]);
    std::printf("\n");
  }
  for (size_t i = 0; i < free.size() && i < 12; i++) {
    int bd = free[i];
    double a[3];
    rpy(d->xmat + 9 * bd, a);
    const mjtNum* x = d->xpos + 3 * bd;
    std::printf("  %-16s pos %8.3f %8.3f %8.3f m  roll %7.2f pitch %7.2f yaw %7.2f deg\n",
                m->names + m->name_bodyadr[bd], x[0], x[1], x[2], a[0], a[1], a[2]);
  }
  if (free.size() > 12) std::printf("  ... and %zu more free bodies\n", free.size() - 12);
  if (out) {
    std::fclose(out);
    std::printf("  wrote %s\n", csv.c_str());
  }
  mjb_unbindData(b, d);
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
  return 0;
}
