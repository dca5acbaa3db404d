// mjbuoy-scenario: the simulation loop. Every step is one sample for the
// checks. After mj_step with Euler or implicit, d->xpos, d->xmat, d->cvel,
// d->energy, d->qacc and mjbuoy's wrench all describe the state at the start
// of that step (time t - dt), so they are sampled at that time and the final
// state is sampled after one mj_forward. RK4 leaves an intermediate stage in
// those fields, so there every step is followed by mj_forward.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "scenario.h"

namespace scn {

static std::string g_warning;  // last MuJoCo warning text
static void onWarning(const char* msg) { g_warning = msg; }

void runScenario(const Scenario& s, Sim& sim, Report& r,
                 const std::function<void(const Sample&)>& observe) {
  const mjModel* m = sim.m;
  mjData* d = sim.d;
  const double dt = m->opt.timestep;
  std::vector<std::unique_ptr<Evaluator>> evals;
  for (const Check& c : s.checks) evals.push_back(makeEvaluator(c, m, dt));
  auto sample = [&](double t) {
    Sample smp{m, d, sim.b, t};
    for (auto& e : evals) e->sample(smp);
    if (observe) observe(smp);
  };
  auto bad = [&]() {
    for (int w : {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC}) {
      if (d->warning[w].number > 0) return true;
    }
    return false;
  };

  void (*prev)(const char*) = mju_user_warning;
  mju_user_warning = onWarning;  // MuJoCo would print and write MUJOCO_LOG.TXT
  g_warning.clear();
  const bool rk4 = m->opt.integrator == mjINT_RK4;
  const double eps = 1e-6 * dt;
  double diverged = kInf;
  std::string why;
  long steps = 0;
  auto t0 = std::chrono::steady_clock::now();
  mj_forward(m, d);
  if (rk4) sample(d->time);
  while (d->time < s.duration - eps) {
    double t = d->time;
    mj_step(m, d);
    steps++;
    if (bad()) {
      diverged = t;
      why = "MuJoCo reset the state: " + (g_warning.empty() ? "bad qpos, qvel or qacc" : g_warning);
      break;
    }
    if (rk4) {
      mj_forward(m, d);
      sample(d->time);
    } else {
      sample(t);
    }
  }
  if (!rk4 && std::isinf(diverged)) {
    mj_forward(m, d);
    sample(d->time);
  }
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  mju_user_warning = prev;

  r.diverged = diverged;
  for (auto& e : evals) r.results.push_back(e->finish(diverged, why));
  if (!std::isinf(diverged)) {
    Result res;
    res.label = "simulation";
    res.kind = "simulation";
    res.pass = false;
    res.detail = "diverged at t = " + num(diverged) + " s: " + why;
    r.results.push_back(res);
  }
  mjbInfo info = mjb_info(sim.b);
  double simt = std::isinf(diverged) ? d->time : diverged;
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "model %s, backend %s on %s: %d hull(s) on %d body(ies), %d triangles; "
                "%s s simulated in %ld steps of %s s, wall %.2f s (%.1fx real time)",
                s.model_attr.c_str(), info.backend, info.renderer, info.nhull, info.nbody,
                info.ntri, num(simt).c_str(), steps, num(dt).c_str(), wall,
                wall > 0 ? simt / wall : 0.0);
  r.header = buf;
}

}  // namespace scn
