// view: mjbuoy-view, an interactive viewer of an mjbuoy scene on GLFW.
//
// Two threads: the physics thread (view_sim.cc) steps the model in real
// time, as MuJoCo's simulate does (simulated time follows the wall clock,
// scaled by the slow-motion factor; when stepping falls more than 0.1 s
// behind, the clock is re-synchronised instead of catching up, so a slow
// stretch never spirals); the main thread (view.cc) renders at the
// display's rate (vsync) and handles input (view_input.cc). They share d
// under one mutex, which the renderer holds only to copy the scene
// (mjv_updateScene, SeaPainter::capture), so physics never waits for
// drawing. The sea and the wet hull parts are drawn by seadraw.h, the same
// code as mjbuoy-sim's offscreen pictures. The gl backend's EGL context
// lives on the physics thread only while stepping; GLFW's compatibility
// context stays on the main thread.
#ifndef MJBUOY_TOOLS_VIEW_H_
#define MJBUOY_TOOLS_VIEW_H_

#include <atomic>
#include <mutex>
#include <string>
#include <vector>

#include <GLFW/glfw3.h>
#include <mujoco/mujoco.h>

#include "mjbuoy.h"
#include "seadraw.h"
#include "seaopts.h"
#include "viewtext.h"

namespace mjbview {

struct Options {
  std::string model, backend, shotFile;
  double shotTime = -1;   // --screenshot T (s); < 0: none
  double exitAfter = -1;  // --exit-after T (s); < 0: run until closed
  bool printFinal = false, forces = false, wet = false, paused = false;
  bool printRtf = false;  // --print-rtf: the real-time factor and frame costs at exit
  int width = 1280, height = 800;
  int msaa = -1;          // --msaa samples; < 0: 4, or 0 on a software renderer
  bool shadows = false;   // --shadows: MuJoCo's shadows on a software renderer too
  mjbtool::SeaArgs sea;   // --set, --spectrum, --calm (seaopts.h)
};

// slow-motion factors: simulated time runs 1/kSlow[slow] times the wall clock
const int kNSlow = 6;
const double kSlow[kNSlow] = {1, 2, 4, 8, 16, 32};

struct View {
  Options o;
  mjModel* m = nullptr;
  mjData* d = nullptr;
  mjbBuoy* b = nullptr;
  mjvCamera cam;
  mjvOption opt;
  mjvScene scn;
  mjrContext con;
  mjvPerturb pert;
  mjbsim::SeaPainter sea;
  mjbsim::HullFramer framer;
  GLFWwindow* win = nullptr;

  // shared with the physics thread, under mtx
  std::mutex mtx;
  // the drawing and input threads waiting for mtx (UiLock): the physics
  // thread lets them in between its batches of steps, as std::mutex is not
  // fair and a re-lock straight after an unlock can starve them
  std::atomic<int> uiWaiting{0};
  bool paused = false;
  int steps = 0;            // single steps requested while paused
  bool reset = false;       // reset requested
  int slow = 0;             // index into kSlow
  double stopAt = 1e300;    // physics holds at this simulated time (screenshot, exit)
  bool diverged = false;    // MuJoCo reset a diverging state
  bool everDiverged = false;  // ... at any time of the run: exit status 1
  std::atomic<bool> quit{false};
  std::vector<double> ctrl;  // actuator controls the keys set, copied to d->ctrl each step
  std::string notices;       // mjb_notices printed so far
  // the physics thread's real-time record: wall and simulated time of the
  // first step and of the latest one (--print-rtf)
  double rtfWall0 = -1, rtfSim0 = 0, rtfWall1 = 0, rtfSim1 = 0;

  // main thread only
  bool forces = false, wet = false, help = false;
  bool frame = true;  // frame the hulls on the next picture
  bool left = false, right = false, middle = false;
  double lastx = 0, lasty = 0;
  double lastPress = -10;
  int lastButton = -1;
  double rtf = 0;  // measured real-time factor
  int act = 0;     // the actuator the keys drive
  std::string info, seaState, windState, radState;
  // frame costs for --print-rtf: frames drawn, seconds in mjr_render and in the sea
  long nframe = 0;
  double renderSec = 0, seaSec = 0;
};

// mtx for the drawing and input threads: counted in uiWaiting while they
// wait, so the physics thread yields the lock to them (view_sim.cc)
class UiLock {
 public:
  explicit UiLock(View* v) : v_(v) {
    v_->uiWaiting++;
    v_->mtx.lock();
    v_->uiWaiting--;
  }
  ~UiLock() { v_->mtx.unlock(); }
  UiLock(const UiLock&) = delete;
  UiLock& operator=(const UiLock&) = delete;

 private:
  View* v_;
};

// keyboard, mouse and scroll callbacks of v->win (view_input.cc)
void installInput(View* v);

// the physics thread's loop, until v->quit (view_sim.cc)
void physics(View* v);

}  // namespace mjbview

#endif  // MJBUOY_TOOLS_VIEW_H_
