// mjbuoy-scenario: the simulation loop. Every step is one sample for the
// checks. After mj_step with Euler or implicit, d->xpos, d->xmat, d->cvel,
// d->energy, d->qacc and mjbuoy's wrench all describe the state at the start
// of that step (time t - dt), so they are sampled at that time and the final
// state is sampled after one mj_forward. RK4 leaves an intermediate stage in
// those fields, so there every step is followed by mj_forward.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "guard.h"
#include "scenario.h"

namespace scn {

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
  const bool rk4 = m->opt.integrator == mjINT_RK4;
  double diverged = kInf;
  std::string why;
  long steps = 0;
  auto t0 = std::chrono::steady_clock::now();
  mj_forward(m, d);
  if (rk4) sample(d->time);
  // a fixed number of steps (mjbtool::stepsFor): time alone could stall
  const long nsteps = mjbtool::stepsFor(s.duration, dt);
  while (steps < nsteps) {
    double t = d->time;
    mj_step(m, d);
    steps++;
    if (mjbtool::diverged(d, &why)) {
      diverged = t;
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
