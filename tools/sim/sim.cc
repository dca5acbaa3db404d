// mjbuoy-sim: run an MJCF boat scene headless and summarise it
#include <signal.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <mujoco/mujoco.h>

#include "cliopt.h"
#include "guard.h"
#include "mjbuoy.h"  // and mjbuoy_version.h
#include "modelload.h"
#include "outfile.h"
#include "plot.h"
#include "render.h"
#include "radnotice.h"
#include "seaopts.h"
#include "simsea.h"

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
      std::fprintf(stderr, "mjbuoy-sim: %3d%% (sim %.2f of %.2f s, %.1f s elapsed, about %.1f s "
                   "left, %.2fx real time)\n", 10 * tenth, t, total, el, eta, el > 0 ? t / el : 0);
    }
  }
  void done() {
    if (mode == BAR) std::fprintf(stderr, "\r\033[K");
  }
};

// CSV column name of object i: its MJCF name, or <kind><id> if unnamed
static std::string csvName(const mjModel* m, int type, int i) {
  const char* n = mj_id2name(m, type, i);
  if (n && *n) return n;
  return std::string(type == mjOBJ_JOINT ? "joint" : "sensor") + std::to_string(i);
}

// the model, its data and the attachment, freed on every way out
struct Scene {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  mjbBuoy* b = nullptr;
  ~Scene() {
    if (b && d) mjb_unbindData(b, d);
    if (d) mj_deleteData(d);
    if (b) mjb_detach(b);
    if (m) mj_deleteModel(m);
  }
};

// a still picture at simulated time t
struct Snap {
  double t;
  std::string file;
  bool done = false;
  mjbtool::OutFile out;
};

// "mjbuoy-sim: OPT: why", unless why already starts with OPT
static void fail(const char* opt, const std::string& why) {
  bool named = why.compare(0, std::strlen(opt), opt) == 0;
  std::fprintf(stderr, "mjbuoy-sim: %s%s%s\n", named ? "" : opt, named ? "" : ": ", why.c_str());
}

// an output path that is a regular file (or new), not a device or pipe
static bool isRegularTarget(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode);
}

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
  mjbtool::installMujocoHandlers("mjbuoy-sim");
  // a failing ffmpeg closes its pipe: a write error to report, not a death by SIGPIPE
  signal(SIGPIPE, SIG_IGN);
  using mjbtool::Finite;
  using mjbtool::kInf;
  CLI::App app{"Simulate an mjbuoy MJCF scene headless and print a summary. Outputs are "
               "written to a temporary file beside them and renamed into place when the run "
               "succeeds; an output that is an input or another output is refused."};
  app.set_version_flag("--version", std::string("mjbuoy-sim ") + MJBUOY_VERSION_STRING);
  std::string model, csv, backend;
  double duration = 10, interval = 0.01;
  app.add_option("model", model, "MJCF model file")->required()->check(CLI::ExistingFile);
  app.add_option("--duration", duration, "simulated time [s]")->check(Finite(0, 1e9));
  app.add_option("--csv", csv, "write time and pose of every free body to this CSV file");
  app.add_option("--interval", interval, "CSV output interval [s]")
      ->check(Finite(0, kInf, true));
  app.add_option("--backend", backend, "override the model's mjbuoy.backend")
      ->check(CLI::IsMember({"cpu", "gl", "auto"}));
  std::vector<double> ctrl;
  app.add_option("--ctrl", ctrl, "constant controls, one per actuator in model order")
      ->check(Finite(-kInf, kInf));
  std::string video, camera, plot, progress = "auto";
  double fps = 30;
  int width = 1280, height = 720;
  std::vector<std::string> snapshots;
  bool showForces = false, showWet = false;
  app.add_option("--render", video, "write a video of the run (H.264 MP4 through ffmpeg; "
                 "FILE.mp4, or a device such as /dev/null)");
  app.add_option("--fps", fps, "video frames per second of simulated time")
      ->check(Finite(1, 240));
  app.add_option("--width", width, "picture width [pixels]")->check(Finite(16, 8192));
  app.add_option("--height", height, "picture height [pixels]")->check(Finite(16, 8192));
  app.add_option("--camera", camera,
                 "model camera to render from (default: a free camera following the hulls)");
  app.add_option("--snapshot", snapshots, "T:FILE.png: a still picture at simulated time T");
  app.add_flag("--show-forces", showForces, "draw each hull body's mjbuoy force as an arrow");
  app.add_flag("--show-wet", showWet,
               "draw the wet part of each hull (below the exact surface) in magenta");
  bool printSea = false;
  app.add_flag("--print-sea", printSea, "print the sea's wave components and wind, then exit "
               "(radiation is not solved for it unless --set mjbuoy.radiation=... asks)");
  mjbtool::SeaArgs seaArgs;  // --set, --spectrum, --calm (seaopts.h)
  mjbtool::addSeaOptions(app, &seaArgs);
  app.add_option("--plot", plot, "plot heave, roll and pitch of the hull bodies (PNG, gnuplot)");
  app.add_option("--progress", progress,
                 "progress on stderr: auto (bar on a terminal, lines when rendering), bar, "
                 "lines or off")
      ->check(CLI::IsMember({"auto", "bar", "lines", "off"}));
  {
    int rc = mjbtool::parseArgs(app, argc, argv, 1);  // docs: invalid input exits 1
    if (rc >= 0) return rc;
  }

  // everything that can fail before simulating, nothing written yet
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
    snaps.emplace_back();
    snaps.back().t = t;
    snaps.back().file = s.substr(c + 1);
  }
  {
    std::vector<mjbtool::PathUse> uses;
    if (!csv.empty()) uses.push_back({csv, "--csv", true});
    if (!plot.empty()) uses.push_back({plot, "--plot", true});
    if (!video.empty()) uses.push_back({video, "--render", true});
    for (const Snap& s : snaps) uses.push_back({s.file, "--snapshot", true});
    std::string e;
    if (!mjbtool::checkOutputs(model, uses, &e)) {
      std::fprintf(stderr, "mjbuoy-sim: %s\n", e.c_str());
      return 1;
    }
  }
  if (!plot.empty()) {
    std::string e;
    if (!mjbsim::plotAvailable(&e)) {
      std::fprintf(stderr, "mjbuoy-sim: %s\n", e.c_str());
      return 1;
    }
  }
  mjbsim::VideoWriter writer;
  if (!video.empty()) {
    // ffmpeg writes H.264 into an MP4 container (-f mp4): the name must say so
    size_t dot = video.rfind('.');
    std::string ext = dot == std::string::npos || video.find('/', dot) != std::string::npos
                          ? "" : video.substr(dot);
    if (isRegularTarget(video) && strcasecmp(ext.c_str(), ".mp4") != 0) {
      std::fprintf(stderr, "mjbuoy-sim: --render %s: the video is H.264 in an MP4 container; "
                   "give a file name ending in .mp4 (got %s)\n", video.c_str(),
                   ext.empty() ? "no extension" : ("\"" + ext + "\"").c_str());
      return 1;
    }
    if (mjbsim::findProgram("ffmpeg").empty()) {
      std::string e;
      writer.open(video, video, width, height, fps, &e);  // says which package
      std::fprintf(stderr, "mjbuoy-sim: %s\n", e.c_str());
      return 1;
    }
  }

  // the sea's table needs no panel solution (seconds to minutes cold): it
  // attaches without radiation, unless the user's --set mjbuoy.radiation asks
  const std::vector<std::string>& sets = seaArgs.sets;
  const bool radiation = !printSea || std::any_of(sets.begin(), sets.end(), [](
      const std::string& s) { return s.rfind("mjbuoy.radiation=", 0) == 0; });
  mjbsim::Edits edits;
  {
    std::string e = mjbsim::parseEdits(seaArgs.sets, seaArgs.spectra, seaArgs.calm, &edits);
    if (!e.empty()) {
      std::fprintf(stderr, "mjbuoy-sim: %s\n", e.c_str());
      return 1;
    }
  }

  Scene sc;
  char err[1024] = "";
  {
    // the edited model from memory: the file is only read
    std::string xml, e;
    if (!edits.empty() && !mjbsim::editedModel(model, edits, &xml, &e)) {
      std::fprintf(stderr, "mjbuoy-sim: %s\n", e.c_str());
      return 1;
    }
    sc.m = mjbtool::loadModel(model, edits.empty() ? nullptr : &xml, "mjbuoy-sim", &e);
    if (!sc.m) {
      std::fprintf(stderr, "mjbuoy-sim: %s\n", e.c_str());
      return 1;
    }
  }
  mjModel* m = sc.m;
  std::string why;
  if (mjbtool::runSteps(duration, m->opt.timestep, &why) < 1) {
    std::fprintf(stderr, "mjbuoy-sim: --%s\n", why.c_str());
    return 1;
  }
  if (radiation) {
    std::string plan = mjbtool::radiationPlan(m);  // the panel solve is no silent wait
    if (!plan.empty()) std::fprintf(stderr, "mjbuoy-sim: %s\n", plan.c_str());
  }
  const char* be = backend.empty() ? nullptr : backend.c_str();
  sc.b = radiation ? mjb_attach(m, be, err, sizeof(err))
                   : mjb_attachWithoutRadiation(m, be, err, sizeof(err));
  if (!sc.b) {
    std::fprintf(stderr, "mjbuoy-sim: %s: %s\n", model.c_str(), mjbsim::blame(edits, err).c_str());
    return 1;
  }
  mjbBuoy* b = sc.b;
  std::fputs(mjb_warnings(b), stderr);
  if (printSea) {
    printSeaTable(b);
    return 0;
  }
  sc.d = mj_makeData(m);
  mjData* d = sc.d;
  mjb_bindData(b, d);
  if ((int)ctrl.size() > m->nu) {
    std::fprintf(stderr, "mjbuoy-sim: --ctrl has %zu values but %s has %d actuator(s)\n",
                 ctrl.size(), model.c_str(), m->nu);
    return 1;
  }
  for (size_t i = 0; i < ctrl.size(); i++) d->ctrl[i] = ctrl[i];

  std::unique_ptr<mjbsim::Renderer> renderer;
  mjbtool::OutFile videoOut;
  if (!video.empty() || !snaps.empty()) {
    mjbsim::RenderOptions ro;
    ro.width = width;
    ro.height = height;
    ro.camera = camera;
    ro.showForces = showForces;
    ro.showWet = showWet;
    std::string e;
    renderer = mjbsim::Renderer::create(m, b, ro, &e);
    if (!renderer) {
      std::fprintf(stderr, "mjbuoy-sim: cannot render: %s\n", e.c_str());
      return 1;
    }
    if (!video.empty() && (!videoOut.open(video, "--render", &e) ||
                           !writer.open(videoOut.tmpPath(), video, width, height, fps, &e))) {
      fail("--render", e);
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
  mjbtool::OutFile csvOut;
  FILE* out = nullptr;
  if (!csv.empty()) {
    std::string e;
    if (!csvOut.open(csv, "--csv", &e)) {
      std::fprintf(stderr, "mjbuoy-sim: %s\n", e.c_str());
      return 1;
    }
    out = csvOut.file();
    std::fprintf(out, "time");
    for (int bd : free) {
      const char* n = m->names + m->name_bodyadr[bd];
      for (const char* c : {"x", "y", "z", "roll", "pitch", "yaw"}) {
        std::fprintf(out, ",%s.%s", n, c);
      }
    }
    // every other joint by name (docs/tools.md, mjbuoy-sim): slide [m], hinge [deg],
    // ball as its quaternion w, x, y, z; then every sensor by name, one
    // column per value (<sensor>.<i> when it has several)
    for (int j = 0; j < m->njnt; j++) {
      std::string n = csvName(m, mjOBJ_JOINT, j);
      if (m->jnt_type[j] == mjJNT_BALL) {
        std::fprintf(out, ",%s.qw,%s.qx,%s.qy,%s.qz", n.c_str(), n.c_str(), n.c_str(), n.c_str());
      } else if (m->jnt_type[j] != mjJNT_FREE) {
        std::fprintf(out, ",%s", n.c_str());
      }
    }
    for (int i = 0; i < m->nsensor; i++) {
      std::string n = csvName(m, mjOBJ_SENSOR, i);
      for (int k = 0; k < m->sensor_dim[i]; k++) {
        if (m->sensor_dim[i] == 1) std::fprintf(out, ",%s", n.c_str());
        else std::fprintf(out, ",%s.%d", n.c_str(), k);
      }
    }
    std::fprintf(out, "\n");
  }

  auto row = [&]() {
    // sensors as of this row's state: mj_step leaves those of the state it
    // started from
    if (m->nsensor) mj_forward(m, d);
    std::fprintf(out, "%.6f", d->time);
    for (int bd : free) {
      double a[3];
      rpy(d->xmat + 9 * bd, a);
      const mjtNum* x = d->xpos + 3 * bd;
      std::fprintf(out, ",%.9g,%.9g,%.9g,%.6g,%.6g,%.6g", x[0], x[1], x[2], a[0], a[1], a[2]);
    }
    for (int j = 0; j < m->njnt; j++) {
      const mjtNum* q = d->qpos + m->jnt_qposadr[j];
      if (m->jnt_type[j] == mjJNT_BALL) {
        std::fprintf(out, ",%.9g,%.9g,%.9g,%.9g", q[0], q[1], q[2], q[3]);
      } else if (m->jnt_type[j] == mjJNT_HINGE) {
        std::fprintf(out, ",%.9g", q[0] * 180 / M_PI);
      } else if (m->jnt_type[j] == mjJNT_SLIDE) {
        std::fprintf(out, ",%.9g", q[0]);
      }
    }
    for (int i = 0; i < m->nsensor; i++) {
      for (int k = 0; k < m->sensor_dim[i]; k++) {
        std::fprintf(out, ",%.9g", d->sensordata[m->sensor_adr[i] + k]);
      }
    }
    std::fprintf(out, "\n");
  };

  mj_forward(m, d);

  // the plot's bodies: those mjbuoy pushes on (hull bodies), else free ones
  std::vector<int> hullBodies;
  std::vector<mjbsim::PlotSeries> series;
  std::vector<double> plotT;
  mjbtool::OutFile plotOut;
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

  // a fixed number of steps: time alone could stall or go back (a MuJoCo reset)
  const long nsteps = mjbtool::stepsFor(duration, m->opt.timestep);
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
          fail("--render", e);
          failed = true;
          break;
        }
        frame++;
      }
      for (Snap& s : snaps) {
        if (s.done || (d->time < s.t - eps && steps < nsteps)) continue;
        s.done = true;
        if (!renderer->render(d, &rgb, &e) || !s.out.open(s.file, "--snapshot", &e) ||
            !mjbsim::writePng(s.out.file(), s.file, rgb, renderer->width(), renderer->height(),
                              &e)) {
          fail("--snapshot", e);
          failed = true;
        }
      }
      if (failed) break;
    }
    prog.update(d->time);
    if (steps >= nsteps) break;
    double before = d->time;
    mj_step(m, d);
    steps++;
    std::string why;
    if (mjbtool::diverged(d, &why)) {
      prog.done();
      std::fprintf(stderr, "mjbuoy-sim: the simulation diverged in the step from t = %g s: %s; "
                   "stopping, no output written (a smaller time step, a heavier hull or "
                   "milder forces may help)\n", before, why.c_str());
      return 1;
    }
  }
  prog.done();
  std::string verr, camLine;
  if (renderer) camLine = renderer->describeCamera();
  if (!video.empty() && !writer.close(&verr)) {
    fail("--render", verr);
    failed = true;
  }
  renderer.reset();
  if (failed) return 1;
  if (!plot.empty()) {
    std::string e;
    if (!plotOut.open(plot, "--plot", &e) ||
        !mjbsim::writePlot(plotOut.tmpPath(), plot, model + ": heave, roll and pitch", plotT,
                           series, &e)) {
      fail("--plot", e);
      return 1;
    }
  }
  // the run succeeded: every output into place, each write checked
  {
    std::string e;
    bool ok = !out || csvOut.commit(&e);
    ok = ok && (video.empty() || videoOut.commit(&e));
    for (Snap& s : snaps) ok = ok && s.out.commit(&e);
    ok = ok && (plot.empty() || plotOut.commit(&e));
    if (!ok) {
      std::fprintf(stderr, "mjbuoy-sim: %s\n", e.c_str());
      return 1;
    }
  }
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::fputs(mjb_notices(b, d), stderr);  // the library's run-time notices, each once
  mjbInfo info = mjb_info(b);
  std::printf("mjbuoy-sim: %s\n", model.c_str());
  std::printf("  backend %s on %s: %d hulls on %d bodies, %d triangles\n", info.backend,
              info.renderer, info.nhull, info.nbody, info.ntri);
  std::printf("  sim time %.3f s in %ld steps, wall %.3f s (%.1fx real time)\n", d->time,
              steps, wall, wall > 0 ? d->time / wall : 0.0);
  std::printf("  radiation %s\n", mjbtool::radiationState(b).c_str());
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
  if (out) std::printf("  wrote %s\n", csv.c_str());
  if (!video.empty()) {
    std::printf("  wrote %s (%d frames, %dx%d, %g fps)\n", video.c_str(), writer.frames(), width,
                height, fps);
  }
  for (const Snap& s : snaps) std::printf("  wrote %s (t = %g s)\n", s.file.c_str(), s.t);
  if (!camLine.empty()) std::printf("  last picture: %s\n", camLine.c_str());
  if (!plot.empty()) std::printf("  wrote %s\n", plot.c_str());
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::fprintf(stderr, "mjbuoy-sim: cannot write the summary to stdout\n");
    return 1;
  }
  return 0;
}
