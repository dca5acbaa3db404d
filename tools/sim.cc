// mjbuoy-sim: run an MJCF boat scene headless and summarise it
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <mujoco/mujoco.h>

#include "mjbuoy.h"
#include "plot.h"
#include "render.h"

// roll, pitch, yaw [deg] of rotation matrix R (row-major), marine
// convention R = Rz(yaw) Ry(pitch) Rx(roll) (intrinsic z, y', x'')
static void rpy(const mjtNum* R, double out[3]) {
  out[0] = std::atan2(R[7], R[8]) * 180 / M_PI;
  out[1] = -std::asin(std::fmax(-1.0, std::fmin(1.0, R[6]))) * 180 / M_PI;
  out[2] = std::atan2(R[3], R[0]) * 180 / M_PI;
}

// progress on stderr: a bar with ETA on a terminal, plain lines every 10%
// otherwise
struct Progress {
  enum Mode { OFF, BAR, LINES } mode = OFF;
  double total = 0;
  int lastTenth = -1;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now(), last;
  static std::string clock(double s) {
    char b[32];
    int n = (int)std::lround(std::max(0.0, s));
    std::snprintf(b, sizeof(b), "%d:%02d", n / 60, n % 60);
    return b;
  }
  void update(double t) {
    if (mode == OFF || total <= 0) return;
    auto now = std::chrono::steady_clock::now();
    double el = std::chrono::duration<double>(now - t0).count();
    double fr = std::fmin(1.0, t / total);
    double eta = fr > 0 ? el * (1 - fr) / fr : 0;
    if (mode == BAR) {
      if (fr < 1 && std::chrono::duration<double>(now - last).count() < 0.1) return;
      last = now;
      const int w = 30;
      int n = (int)(fr * w);
      std::string bar(n, '=');
      if (n < w) bar += '>' + std::string(w - n - 1, ' ');
      std::fprintf(stderr, "\r  [%s] %3d%%  sim %.2f/%.2f s  elapsed %s  ETA %s ", bar.c_str(),
                   (int)(100 * fr), t, total, clock(el).c_str(), fr > 0 ? clock(eta).c_str() : "?");
      std::fflush(stderr);
    } else {
      int tenth = (int)(10 * fr + 1e-9);
      if (tenth == lastTenth) return;
      lastTenth = tenth;
      std::fprintf(stderr, "mjbuoy-sim: %3d%% (sim %.2f of %.2f s, %.1f s elapsed, about %.1f s left)\n",
                   10 * tenth, t, total, el, eta);
    }
  }
  void done() {
    if (mode == BAR) std::fprintf(stderr, "\r\033[K");
  }
};

// --print-sea: one line per wave component (mjb_waves), then the wind
static void printSeaTable(const mjbBuoy* b) {
  int n = mjb_waves(b, nullptr, 0);
  std::vector<double> w(6 * n);
  mjb_waves(b, w.data(), n);
  std::printf("# %d wave components\n# i amplitude_m omega_rad_s k_rad_m direction_deg "
              "phase_deg steepness\n", n);
  double m0 = 0;
  for (int i = 0; i < n; i++) {
    const double* c = &w[6 * i];
    std::printf("%d %.9g %.9g %.9g %.9g %.9g %.9g\n", i, c[0], c[1], c[2], c[3], c[4], c[5]);
    m0 += 0.5 * c[0] * c[0];
  }
  mjtNum u[2];
  mjb_windVelocity(b, 0, u);
  std::printf("# Hs = 4 sqrt(sum A^2 / 2) = %.6g m; wind at t = 0: %.6g %.6g m/s\n",
              4 * std::sqrt(m0), u[0], u[1]);
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
  std::string video, camera, plot, progress = "auto";
  double fps = 30;
  int width = 1280, height = 720;
  std::vector<std::string> snapshots;
  bool showForces = false;
  app.add_option("--render", video, "write a video of the run (H.264 MP4 through ffmpeg)");
  app.add_option("--fps", fps, "video frames per second of simulated time")
      ->check(CLI::Range(1.0, 240.0));
  app.add_option("--width", width, "picture width [pixels]")->check(CLI::Range(16, 8192));
  app.add_option("--height", height, "picture height [pixels]")->check(CLI::Range(16, 8192));
  app.add_option("--camera", camera,
                 "model camera to render from (default: a free camera following the hulls)");
  app.add_option("--snapshot", snapshots, "T:FILE.png: a still picture at simulated time T");
  app.add_flag("--show-forces", showForces, "draw each hull body's mjbuoy force as an arrow");
  bool printSea = false;
  app.add_flag("--print-sea", printSea, "print the sea's wave components and wind, then exit");
  app.add_option("--plot", plot, "plot heave, roll and pitch of the hull bodies (PNG, gnuplot)");
  app.add_option("--progress", progress,
                 "progress on stderr: auto (bar on a terminal, lines when rendering), bar, "
                 "lines or off")
      ->check(CLI::IsMember({"auto", "bar", "lines", "off"}));
  CLI11_PARSE(app, argc, argv);

  // pictures: check everything that can fail before simulating
  struct Snap {
    double t;
    std::string file;
    bool done;
  };
  std::vector<Snap> snaps;
  for (const std::string& s : snapshots) {
    size_t c = s.find(':');
    char* end = nullptr;
    double t = c == std::string::npos ? -1 : std::strtod(s.c_str(), &end);
    if (c == std::string::npos || end != s.c_str() + c || !(t >= 0) || c + 1 >= s.size()) {
      std::fprintf(stderr, "mjbuoy-sim: --snapshot %s: expected TIME:FILE.png, e.g. 1.5:still.png\n",
                   s.c_str());
      return 1;
    }
    if (t > duration + 1e-9) {
      std::fprintf(stderr, "mjbuoy-sim: --snapshot %s: time %g s is after the end of the run "
                   "(--duration %g)\n", s.c_str(), t, duration);
      return 1;
    }
    snaps.push_back(Snap{t, s.substr(c + 1), false});
    std::string e;
    if (!mjbsim::checkWritable(snaps.back().file, &e)) {
      std::fprintf(stderr, "mjbuoy-sim: --snapshot: %s\n", e.c_str());
      return 1;
    }
  }
  if (!plot.empty()) {
    std::string e;
    if (!mjbsim::plotAvailable(&e) || !mjbsim::checkWritable(plot, &e)) {
      std::fprintf(stderr, "mjbuoy-sim: %s\n", e.c_str());
      return 1;
    }
  }
  mjbsim::VideoWriter writer;
  if (!video.empty()) {
    std::string e;
    if (!mjbsim::findProgram("ffmpeg").size()) {
      writer.open(video, width, height, fps, &e);  // says which package
      std::fprintf(stderr, "mjbuoy-sim: %s\n", e.c_str());
      return 1;
    }
    if (!mjbsim::checkWritable(video, &e)) {
      std::fprintf(stderr, "mjbuoy-sim: --render: %s\n", e.c_str());
      return 1;
    }
  }

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
  if (printSea) {
    printSeaTable(b);
    mjb_detach(b);
    mj_deleteModel(m);
    return 0;
  }
  mjData* d = mj_makeData(m);
  mjb_bindData(b, d);
  if ((int)ctrl.size() > m->nu) {
    std::fprintf(stderr, "mjbuoy-sim: --ctrl has %zu values but %s has %d actuator(s)\n",
                 ctrl.size(), model.c_str(), m->nu);
    return 1;
  }
  for (size_t i = 0; i < ctrl.size(); i++) d->ctrl[i] = ctrl[i];

  std::unique_ptr<mjbsim::Renderer> renderer;
  if (!video.empty() || !snaps.empty()) {
    mjbsim::RenderOptions ro;
    ro.width = width;
    ro.height = height;
    ro.camera = camera;
    ro.showForces = showForces;
    std::string e;
    renderer = mjbsim::Renderer::create(m, b, ro, &e);
    if (!renderer) {
      std::fprintf(stderr, "mjbuoy-sim: cannot render: %s\n", e.c_str());
      return 1;
    }
    if (!video.empty() && !writer.open(video, width, height, fps, &e)) {
      std::fprintf(stderr, "mjbuoy-sim: --render: %s\n", e.c_str());
      return 1;
    }
  }
  Progress prog;
  prog.total = duration;
  bool tty = isatty(2);
  if (progress == "bar" || (progress == "auto" && tty)) prog.mode = Progress::BAR;
  if (progress == "lines" || (progress == "auto" && !tty && (renderer || !plot.empty()))) {
    prog.mode = Progress::LINES;
  }

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

  // the plot's bodies: those mjbuoy pushes on (hull bodies), else free ones
  std::vector<int> hullBodies;
  std::vector<mjbsim::PlotSeries> series;
  std::vector<double> plotT;
  if (!plot.empty()) {
    const mjtNum* w = mjb_wrench(b, d);
    for (int i = 1; w && i < m->nbody; i++) {
      bool any = false;
      for (int k = 0; k < 6; k++) any |= w[6 * i + k] != 0;
      if (any) hullBodies.push_back(i);
    }
    // bodies with a free joint too: a hull above the water at t = 0 gets no force yet
    for (int bd : free) {
      if (std::find(hullBodies.begin(), hullBodies.end(), bd) == hullBodies.end()) {
        hullBodies.push_back(bd);
      }
    }
    std::sort(hullBodies.begin(), hullBodies.end());
    for (int bd : hullBodies) series.push_back({m->names + m->name_bodyadr[bd], {}, {}, {}});
  }

  long steps = 0;
  double next = 0, nextPlot = 0;
  long frame = 0;
  std::vector<unsigned char> rgb;
  bool failed = false;
  auto t0 = std::chrono::steady_clock::now();
  const double eps = 1e-9 * std::fmax(1.0, duration);
  while (true) {
    if (out && d->time >= next - eps) {
      row();
      next += interval;
    }
    if (!plot.empty() && d->time >= nextPlot - eps) {
      plotT.push_back(d->time);
      for (size_t k = 0; k < hullBodies.size(); k++) {
        double a[3];
        rpy(d->xmat + 9 * hullBodies[k], a);
        series[k].z.push_back(d->xpos[3 * hullBodies[k] + 2]);
        series[k].roll.push_back(a[0]);
        series[k].pitch.push_back(a[1]);
      }
      nextPlot += interval;
    }
    if (renderer) {
      std::string e;
      // frames k / fps for k / fps < duration: 2 s at 30 fps are 60 frames
      if (!video.empty() && frame / fps < duration - eps && d->time >= frame / fps - eps) {
        if (!renderer->render(d, &rgb, &e) || !writer.write(rgb, &e)) {
          std::fprintf(stderr, "mjbuoy-sim: --render: %s\n", e.c_str());
          failed = true;
          break;
        }
        frame++;
      }
      for (Snap& s : snaps) {
        if (s.done || d->time < s.t - eps) continue;
        s.done = true;
        if (!renderer->render(d, &rgb, &e) ||
            !mjbsim::writePng(s.file, rgb, renderer->width(), renderer->height(), &e)) {
          std::fprintf(stderr, "mjbuoy-sim: --snapshot: %s\n", e.c_str());
          failed = true;
        }
      }
      if (failed) break;
    }
    prog.update(d->time);
    if (d->time >= duration - eps) break;
    double before = d->time;
    mj_step(m, d);
    // MuJoCo resets a diverging state (time back to 0): stop, never loop forever
    if (d->time < before) {
      std::fprintf(stderr, "mjbuoy-sim: the simulation diverged at t = %g s and MuJoCo reset "
                   "it (NaN, Inf or huge value in the state); stopping\n", before);
      return 1;
    }
    steps++;
  }
  prog.done();
  std::string verr, camLine;
  if (renderer) camLine = renderer->describeCamera();
  if (!video.empty() && !writer.close(&verr)) {
    std::fprintf(stderr, "mjbuoy-sim: --render: %s\n", verr.c_str());
    failed = true;
  }
  renderer.reset();
  if (failed) return 1;
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
  if (!video.empty()) {
    std::printf("  wrote %s (%d frames, %dx%d, %g fps)\n", video.c_str(), writer.frames(), width,
                height, fps);
  }
  for (const Snap& s : snaps) std::printf("  wrote %s (t = %g s)\n", s.file.c_str(), s.t);
  if (!camLine.empty()) std::printf("  last picture: %s\n", camLine.c_str());
  if (!plot.empty()) {
    std::string e;
    if (!mjbsim::writePlot(plot, model + ": heave, roll and pitch", plotT, series, &e)) {
      std::fprintf(stderr, "mjbuoy-sim: --plot: %s\n", e.c_str());
      return 1;
    }
    std::printf("  wrote %s\n", plot.c_str());
  }
  mjb_unbindData(b, d);
  mj_deleteData(d);
  mjb_detach(b);
  mj_deleteModel(m);
  return 0;
}
