// mjbuoy-view: an interactive viewer of an mjbuoy scene (see view.h)
#include "view.h"

#include <dlfcn.h>
#include <link.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "cliopt.h"
#include "guard.h"
#include "modelload.h"
#include "mjbuoy_version.h"
#include "outfile.h"
#include "radnotice.h"
#include "render.h"
#include "simsea.h"

namespace mjbview {
namespace {

// TIME:FILE.png
bool parseShot(const std::string& s, Options* o) {
  size_t c = s.find(':');
  char* end = nullptr;
  double t = c == std::string::npos ? -1 : std::strtod(s.c_str(), &end);
  if (c == std::string::npos || end != s.c_str() + c || !(t >= 0) || c + 1 >= s.size()) {
    std::fprintf(stderr, "mjbuoy-view: --screenshot %s: expected TIME:FILE.png, e.g. "
                 "2:shot.png\n", s.c_str());
    return false;
  }
  o->shotTime = t;
  o->shotFile = s.substr(c + 1);
  return true;
}

// the window's picture to o.shotFile, atomically (tools/common/outfile.h)
bool screenshot(View* v, mjrRect vp, double t) {
  std::vector<unsigned char> rgb((size_t)3 * vp.width * vp.height);
  mjr_readPixels(rgb.data(), nullptr, vp, &v->con);
  std::string e;
  mjbtool::OutFile out;
  if (!out.open(v->o.shotFile, "--screenshot", &e) ||
      !mjbsim::writePng(out.file(), v->o.shotFile, rgb, vp.width, vp.height, &e) ||
      !out.commit(&e)) {
    std::fprintf(stderr, "mjbuoy-view: %s\n", e.c_str());  // e names --screenshot
    return false;
  }
  std::printf("mjbuoy-view: wrote %s (%dx%d, t = %.6g s)\n", v->o.shotFile.c_str(), vp.width,
              vp.height, t);
  return true;
}

void printCamera(const View* v, const char* when) {
  const mjvCamera& c = v->cam;
  std::printf("mjbuoy-view: %s camera: lookat %.6f %.6f %.6f distance %.6f azimuth %.6f "
              "elevation %.6f fovy %g deg\n", when, c.lookat[0], c.lookat[1], c.lookat[2],
              c.distance, c.azimuth, c.elevation, v->m->vis.global.fovy);
}

// positions and orientations of every body (world body excluded), time
// first, then every actuator's control
void printBodies(const View* v, const char* when) {
  std::printf("mjbuoy-view: %s time %.9f\n", when, v->d->time);
  for (int i = 1; i < v->m->nbody; i++) {
    const mjtNum* p = v->d->xpos + 3 * i;
    const mjtNum* q = v->d->xquat + 4 * i;
    std::printf("mjbuoy-view: %s body %s pos %.9g %.9g %.9g quat %.9g %.9g %.9g %.9g\n", when,
                mj_id2name(v->m, mjOBJ_BODY, i), p[0], p[1], p[2], q[0], q[1], q[2], q[3]);
  }
  for (int a = 0; a < v->m->nu; a++) {  // the controls the last step used
    const char* name = mj_id2name(v->m, mjOBJ_ACTUATOR, a);
    std::printf("mjbuoy-view: %s ctrl %s %.9g\n", when, name ? name : std::to_string(a).c_str(),
                v->d->ctrl[a]);
  }
}

// --print-rtf: the real-time factor the physics thread kept, and the drawing's cost
void printRtf(const View* v) {
  double wall = v->rtfWall1 - v->rtfWall0, sim = v->rtfSim1 - v->rtfSim0;
  double n = std::max(1L, v->nframe);
  std::printf("mjbuoy-view: real-time factor %.3f (%.3f s simulated in %.3f s wall); %ld frames, "
              "%.1f fps, per frame %.2f ms MuJoCo's scene, %.2f ms sea\n",
              wall > 0 ? sim / wall : 0.0, sim, wall, v->nframe, wall > 0 ? v->nframe / wall : 0.0,
              1e3 * v->renderSec / n, 1e3 * v->seaSec / n);
}

void overlay(View* v, mjrRect vp, double t, bool paused, int slow, const std::string& ctrl) {
  char time[64], rate[96];
  std::snprintf(time, sizeof(time), "%.2f s%s", t, paused ? " (paused)" : "");
  std::snprintf(rate, sizeof(rate), "%.2fx%s", v->rtf, slow ? (" (slow motion 1/" +
                std::to_string((int)kSlow[slow]) + ")").c_str() : "");
  std::string titles = "Time\nReal time\nmjbuoy\nSea\nWind\nRadiation\nShowing";
  std::string vals = std::string(time) + "\n" + rate + "\n" + v->info + "\n" +
                     v->seaState + "\n" + v->windState + "\n" + v->radState + "\n" +
                     (v->forces ? "forces " : "") + (v->wet ? "wet" : "");
  if (!ctrl.empty()) {
    titles += "\nActuator";
    vals += "\n" + ctrl;
  }
  mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, vp, titles.c_str(), vals.c_str(), &v->con);
  if (v->help) {
    mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMLEFT, vp,
                "Space\nRight arrow\nBackspace\n- / +\nUp / Down\n[ / ]\n0\nF\nW\n"
                "Double-click\nCtrl + drag\nDrag / scroll\nCtrl+Q",
                "pause\nstep (paused)\nreset\nslower / faster\nactuator control up / down\n"
                "previous / next actuator\nevery control to 0\nforce arrows\nwet hull parts\n"
                "select body (right: look at)\nperturb selected body (right: move, left: turn)\n"
                "camera (left: rotate, right: move, middle: zoom)\nquit",
                &v->con);
  } else {
    mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMLEFT, vp, "H", "help", &v->con);
  }
}

// the render loop: one picture per display refresh, until closed or done
int run(View* v) {
  bool shotPending = v->o.shotTime >= 0, failed = false;
  double rtfWall = glfwGetTime(), rtfSim = 0;
  // without vsync (a virtual X server, a driver that ignores the swap
  // interval) pace the frames to the refresh rate anyway, so that drawing
  // never takes more CPU from the physics thread than the display needs
  const GLFWvidmode* mode = glfwGetVideoMode(glfwGetPrimaryMonitor());
  const double period = 1.0 / (mode && mode->refreshRate > 0 ? mode->refreshRate : 60);
  double lastSwap = glfwGetTime();
  while (!glfwWindowShouldClose(v->win)) {
    glfwPollEvents();
    double t;
    bool paused;
    int slow;
    std::string ctrl;
    {
      UiLock lk(v);
      if (v->frame) {
        int w, h;
        glfwGetFramebufferSize(v->win, &w, &h);
        v->framer.update(v->m, v->b, v->d, h > 0 ? (double)w / h : 1.6, &v->cam);
        v->frame = false;
        printCamera(v, "start");
        std::fflush(stdout);
      }
      mjv_updateScene(v->m, v->d, &v->opt, &v->pert, &v->cam, mjCAT_ALL, &v->scn);
      if (v->forces) mjbsim::addForceArrows(v->m, v->b, v->d, &v->scn);
      mjbsim::addLines(v->b, v->d, &v->scn);
      v->sea.capture(v->d);
      t = v->d->time;
      paused = v->paused;
      slow = v->slow;
      if (v->m->nu) ctrl = describeCtrl(v->m, v->act, v->ctrl[v->act]);
    }
    double now = glfwGetTime();
    if (now - rtfWall >= 0.5 || t < rtfSim) {
      v->rtf = t >= rtfSim ? (t - rtfSim) / (now - rtfWall) : 0;
      rtfWall = now;
      rtfSim = t;
    }
    mjrRect vp = {0, 0, 0, 0};
    glfwGetFramebufferSize(v->win, &vp.width, &vp.height);
    double r0 = glfwGetTime();
    mjr_render(vp, &v->scn, &v->con);
    if (v->o.printRtf) glFinish();  // MuJoCo's drawing timed apart from the sea's
    double r1 = glfwGetTime();
    v->sea.draw(v->scn, v->cam, vp, v->wet);
    if (v->o.printRtf) glFinish();  // the sea's cost, not the next call's
    v->renderSec += r1 - r0;
    v->seaSec += glfwGetTime() - r1;
    v->nframe++;
    overlay(v, vp, t, paused, slow, ctrl);
    const double eps = 1e-9 * std::fmax(1.0, v->o.shotTime);
    if (shotPending && t >= v->o.shotTime - eps) {
      shotPending = false;
      failed |= !screenshot(v, vp, t);
      UiLock lk(v);
      v->stopAt = v->o.exitAfter >= 0 ? v->o.exitAfter : 1e300;
    }
    glfwSwapBuffers(v->win);
    double wait = lastSwap + period - glfwGetTime();
    // physics behind the clock: draw at most a third of the time, leaving
    // the cores to the physics thread (the real-time factor comes first)
    const double cost = glfwGetTime() - lastSwap;
    if (!paused && v->rtf < 0.95 / kSlow[slow]) wait = std::max(wait, 2 * cost);
    if (wait > 0) std::this_thread::sleep_for(std::chrono::duration<double>(wait));
    lastSwap = glfwGetTime();
    if (!shotPending && v->o.exitAfter >= 0 && t >= v->o.exitAfter - 1e-9 * std::fmax(1.0, t)) {
      break;
    }
    if (v->o.exitAfter >= 0 && v->everDiverged) break;  // unattended: stop at the reset
  }
  return failed || v->everDiverged ? 1 : 0;
}

#if defined(__SANITIZE_ADDRESS__)
// sanitizer builds: at exit glfwTerminate closes the X display, which
// unloads Mesa's GL driver (swrast_dri.so) with strings it allocated and
// still points to; LeakSanitizer then sees them unreachable, from an
// unloaded "<unknown module>" that no suppression can name. Keeping every
// loaded library mapped (RTLD_NODELETE) keeps those pointers visible.
int pin(struct dl_phdr_info* info, size_t, void*) {
  if (info->dlpi_name && info->dlpi_name[0]) {
    void* h = dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
    if (h) dlclose(h);
  }
  return 0;
}
void pinLibraries() { dl_iterate_phdr(pin, nullptr); }
#else
void pinLibraries() {}
#endif

// the window, its GL context (GLFW's default: a compatibility profile, which
// MuJoCo 2.2's fixed-function renderer needs), MuJoCo's scene and context
bool openWindow(View* v) {
  std::string title = "mjbuoy-view: " + v->o.model;
  glfwWindowHint(GLFW_SAMPLES, v->o.msaa < 0 ? 4 : v->o.msaa);
  v->win = glfwCreateWindow(v->o.width, v->o.height, title.c_str(), nullptr, nullptr);
  if (!v->win) return false;
  glfwMakeContextCurrent(v->win);
  // a software renderer (Mesa's llvmpipe) pays for every sample and the
  // shadow map's pass on the CPU the physics needs: there, no multisampling
  // without --msaa and no shadows without --shadows
  const char* r = (const char*)glGetString(GL_RENDERER);
  const bool software = r && (std::strstr(r, "llvmpipe") || std::strstr(r, "softpipe"));
  if (software && (v->o.msaa < 0 || !v->o.shadows)) {
    std::fprintf(stderr, "mjbuoy-view: software renderer (%s):%s%s\n", r,
                 v->o.msaa < 0 ? " no multisampling (--msaa 4 asks for it)" : "",
                 v->o.shadows ? "" : " no shadows (--shadows asks for them)");
  }
  if (software && v->o.msaa < 0) {
    glfwDestroyWindow(v->win);
    glfwWindowHint(GLFW_SAMPLES, 0);
    v->win = glfwCreateWindow(v->o.width, v->o.height, title.c_str(), nullptr, nullptr);
    if (!v->win) return false;
    glfwMakeContextCurrent(v->win);
  }
  pinLibraries();
  glfwSwapInterval(1);  // render at the display's rate
  mjv_defaultCamera(&v->cam);
  mjv_defaultOption(&v->opt);
  mjv_defaultPerturb(&v->pert);
  mjv_defaultScene(&v->scn);
  mjr_defaultContext(&v->con);
  mjv_makeScene(v->m, &v->scn, v->m->ngeom + v->m->nbody + 2000);
  if (software && !v->o.shadows) v->scn.flags[mjRND_SHADOW] = 0;
  mjr_makeContext(v->m, &v->con, mjFONTSCALE_100);
  mjr_setBuffer(mjFB_WINDOW, &v->con);
  installInput(v);
  return true;
}

// the model with the edits of --set, --spectrum and --calm (the validator
// mjbuoy-sim uses), attached; the panel solve announced first; false after
// saying why
bool loadScene(View* v) {
  char err[1024] = "";
  mjbsim::Edits edits;  // --set, --spectrum, --calm: the validator mjbuoy-sim uses
  {
    std::string e = mjbsim::parseEdits(v->o.sea.sets, v->o.sea.spectra, v->o.sea.calm, &edits);
    std::string xml;
    if (e.empty() && !edits.empty()) mjbsim::editedModel(v->o.model, edits, &xml, &e);
    if (e.empty()) v->m = mjbtool::loadModel(v->o.model, edits.empty() ? nullptr : &xml, "", &e);
    if (!v->m) {
      std::fprintf(stderr, "mjbuoy-view: %s\n", e.c_str());
      return false;
    }
  }
  {
    std::string plan = mjbtool::radiationPlan(v->m);  // the panel solve is no silent wait
    if (!plan.empty()) std::fprintf(stderr, "mjbuoy-view: %s\n", plan.c_str());
  }
  const char* be = v->o.backend.empty() ? nullptr : v->o.backend.c_str();
  v->b = mjb_attach(v->m, be, err, sizeof(err));
  if (!v->b) {
    std::fprintf(stderr, "mjbuoy-view: %s: %s\n", v->o.model.c_str(),
                 mjbsim::blame(edits, err).c_str());
    mj_deleteModel(v->m);
    return false;
  }
  std::fputs(mjb_warnings(v->b), stderr);
  return true;
}

int parse(int argc, char** argv, Options* o) {
  CLI::App app{"Interactive viewer of an mjbuoy MJCF scene (GLFW window)."};
  app.set_version_flag("--version", std::string("mjbuoy-view ") + MJBUOY_VERSION_STRING);
  std::string shot;
  app.add_option("model", o->model, "MJCF model file")->required()->check(CLI::ExistingFile);
  app.add_option("--backend", o->backend, "override the model's mjbuoy.backend (default: the "
                 "model's, else cpu)")->check(CLI::IsMember({"cpu", "gl", "auto"}));
  app.add_option("--screenshot", shot, "T:FILE.png: write the window's picture at simulated "
                 "time T (atomically)");
  app.add_option("--exit-after", o->exitAfter, "close after simulated time T [s]")
      ->check(mjbtool::Finite(0, 1e9));
  app.add_flag("--print-final", o->printFinal,
               "print the camera and every body's position and orientation at start and exit");
  app.add_flag("--show-forces", o->forces, "start with force arrows on (key F)");
  app.add_flag("--show-wet", o->wet, "start with the wet hull parts coloured (key W)");
  app.add_flag("--paused", o->paused, "start paused (key Space)");
  app.add_flag("--print-rtf", o->printRtf, "print the real-time factor the physics thread "
               "kept (simulated s per wall s, first step to last) and the mean drawing cost "
               "per frame at exit");
  mjbtool::addSeaOptions(app, &o->sea);
  app.add_flag("--shadows", o->shadows, "MuJoCo's shadows on a software renderer too (such "
               "as Mesa's llvmpipe, where they are off by default: a pass on the CPU)");
  app.add_option("--msaa", o->msaa, "multisampling samples per pixel (default 4, 0 on a "
                 "software renderer such as Mesa's llvmpipe)")->check(mjbtool::Finite(0, 16));
  app.add_option("--width", o->width, "window width [pixels]")->check(mjbtool::Finite(64, 8192));
  app.add_option("--height", o->height, "window height [pixels]")->check(mjbtool::Finite(64, 8192));
  int rc = mjbtool::parseArgs(app, argc, argv, 2);  // docs: invalid input exits 2
  if (rc >= 0) return rc;
  if (!shot.empty() && !parseShot(shot, o)) return 2;
  if (o->shotTime >= 0 && o->exitAfter >= 0 && o->shotTime > o->exitAfter + 1e-9) {
    std::fprintf(stderr, "mjbuoy-view: --screenshot at %g s is after --exit-after %g s\n",
                 o->shotTime, o->exitAfter);
    return 2;
  }
  return -1;
}

}  // namespace
}  // namespace mjbview

using mjbview::View;

int main(int argc, char** argv) {
  mjbtool::installMujocoHandlers("mjbuoy-view");
  View v;
  int rc = mjbview::parse(argc, argv, &v.o);
  if (rc >= 0) return rc;
  if (!v.o.shotFile.empty()) {
    std::string e;  // check before simulating, touching nothing
    if (!mjbtool::checkOutputs(v.o.model, {{v.o.shotFile, "--screenshot", true}}, &e)) {
      std::fprintf(stderr, "mjbuoy-view: %s\n", e.c_str());
      return 1;
    }
  }
  if (!mjbview::loadScene(&v)) return 1;
  std::string e;
  if (!v.sea.init(v.m, v.b, &e)) {
    std::fprintf(stderr, "mjbuoy-view: %s: %s\n", v.o.model.c_str(), e.c_str());
    mjb_detach(v.b);
    mj_deleteModel(v.m);
    return 1;
  }
  if (!glfwInit()) {
    std::fprintf(stderr, "mjbuoy-view: cannot open a window: no display (set DISPLAY, or run "
                 "headless under xvfb-run)\n");
    mjb_detach(v.b);
    mj_deleteModel(v.m);
    return 1;
  }
  v.d = mj_makeData(v.m);
  mjb_bindData(v.b, v.d);
  mj_forward(v.m, v.d);
  mjbInfo info = mjb_info(v.b);
  char buf[512];
  std::snprintf(buf, sizeof(buf), "%s on %s, %d hull%s on %d bod%s, %d triangles", info.backend,
                info.renderer, info.nhull, info.nhull == 1 ? "" : "s", info.nbody,
                info.nbody == 1 ? "y" : "ies", info.ntri);
  v.info = buf;
  v.seaState = mjbview::describeSea(v.m);
  v.windState = mjbview::describeWind(v.m);
  v.radState = mjbtool::radiationState(v.b);
  v.ctrl.assign(v.m->nu, 0);
  std::printf("mjbuoy-view: %s: %s; sea: %s; wind: %s; radiation: %s\n", v.o.model.c_str(), buf,
              v.seaState.c_str(), v.windState.c_str(), v.radState.c_str());
  v.forces = v.o.forces;
  v.wet = v.o.wet;
  v.paused = v.o.paused;
  v.stopAt = v.o.shotTime >= 0 ? v.o.shotTime : v.o.exitAfter >= 0 ? v.o.exitAfter : 1e300;

  if (!mjbview::openWindow(&v)) {
    std::fprintf(stderr, "mjbuoy-view: cannot create an OpenGL window\n");
    glfwTerminate();
    mjb_unbindData(v.b, v.d);
    mj_deleteData(v.d);
    mjb_detach(v.b);
    mj_deleteModel(v.m);
    return 1;
  }
  if (v.o.printFinal) mjbview::printBodies(&v, "start");

  std::thread sim(mjbview::physics, &v);
  rc = mjbview::run(&v);
  v.quit = true;
  sim.join();

  if (v.o.printRtf) mjbview::printRtf(&v);
  if (v.o.printFinal) {
    mjbview::printCamera(&v, "final");
    mjbview::printBodies(&v, "final");
  }
  std::fflush(stdout);
  mjr_freeContext(&v.con);
  mjv_freeScene(&v.scn);
  glfwDestroyWindow(v.win);
  glfwTerminate();
  mjb_unbindData(v.b, v.d);
  mj_deleteData(v.d);
  mjb_detach(v.b);
  mj_deleteModel(v.m);
  return rc;
}
