// view_sim: mjbuoy-view's physics thread (see view.h)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <thread>

#include "guard.h"
#include "view.h"

namespace mjbview {
namespace {

double wallClock() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

// one step with the mouse perturbation: it goes through xfrc_applied, which
// the viewer owns (mjbuoy never writes it)
void stepOnce(View* v) {
  mju_zero(v->d->xfrc_applied, 6 * v->m->nbody);
  if (v->m->nu) mju_copy(v->d->ctrl, v->ctrl.data(), v->m->nu);  // the keys' controls
  mjv_applyPerturbPose(v->m, v->d, &v->pert, 0);  // mocap bodies only
  mjv_applyPerturbForce(v->m, v->d, &v->pert);
  double before = v->d->time;
  mj_step(v->m, v->d);
  // the real-time record: the first step's wall and simulated time, and the latest
  double now = wallClock();
  if (v->rtfWall0 < 0) {
    v->rtfWall0 = now;
    v->rtfSim0 = before;
  }
  v->rtfWall1 = now;
  v->rtfSim1 = v->d->time;
  // the library's run-time notices (a non-finite state, force family...), each once
  const char* n = mjb_notices(v->b, v->d);
  if (std::strlen(n) > v->notices.size()) {
    std::fprintf(stderr, "%s", n + v->notices.size());
    v->notices = n;
  }
  std::string why;
  // MuJoCo's reset, as every tool tells it (guard.h)
  if ((v->d->time < before || mjbtool::diverged(v->d, &why)) && !v->diverged) {
    v->diverged = v->everDiverged = true;
    std::fprintf(stderr, "mjbuoy-view: the simulation diverged at t = %g s: %s; the exit status "
                 "will be 1\n", before, why.empty() ? "MuJoCo reset the state" : why.c_str());
  }
}

}  // namespace

void physics(View* v) {
  const double kMisalign = 0.1;    // resync when stepping lags the clock by this [s]
  const double kHold = 1.0 / 60;   // longest hold of the lock [s]
  double syncWall = 0, syncSim = 0;
  bool synced = false;
  int slow = -1;
  while (!v->quit) {
    bool stepped = false;
    {
      std::lock_guard<std::mutex> lk(v->mtx);
      mjModel* m = v->m;
      mjData* d = v->d;
      const double eps = 1e-9 * std::fmax(1.0, v->stopAt);
      if (v->reset) {
        mj_resetData(m, d);
        mj_forward(m, d);
        v->notices.clear();  // mj_resetData clears them too
        v->rtfWall0 = -1;
        v->reset = false;
        v->diverged = false;
        synced = false;
      }
      bool atStop = d->time >= v->stopAt - eps;
      if (v->paused) {
        if (v->steps > 0 && !atStop) {
          stepOnce(v);
          v->steps--;
          stepped = true;
        } else if (v->pert.active) {
          mjv_applyPerturbPose(m, d, &v->pert, 1);  // paused: move the body itself
          mj_forward(m, d);
        }
        synced = false;
      } else if (!atStop) {
        double now = wallClock();
        double k = kSlow[v->slow];
        if (!synced || slow != v->slow ||
            (now - syncWall) - (d->time - syncSim) * k > kMisalign) {
          // start, slow-motion change, or too far behind: follow the clock from here
          syncWall = now;
          syncSim = d->time;
          synced = true;
          slow = v->slow;
          stepOnce(v);
          stepped = true;
        }
        while ((d->time - syncSim) * k < wallClock() - syncWall && wallClock() - now < kHold &&
               d->time < v->stopAt - eps) {
          double before = d->time;
          stepOnce(v);
          stepped = true;
          if (d->time < before) {
            synced = false;
            break;
          }
        }
      }
    }
    // let the drawing and input threads take the lock (a yield alone can
    // re-lock before they wake: 2 frames in 20 s while the physics lagged);
    // sleep when ahead of the clock
    if (stepped) {
      const double t0 = wallClock();
      while (v->uiWaiting.load() > 0 && wallClock() - t0 < kHold) {
        std::this_thread::sleep_for(std::chrono::microseconds(50));
      }
      std::this_thread::yield();
    } else {
      std::this_thread::sleep_for(std::chrono::microseconds(v->paused ? 2000 : 500));
    }
  }
}

}  // namespace mjbview
