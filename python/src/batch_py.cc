// mjbuoy.Batch: n independent worlds of one scene stepped on a thread pool
// (mjbuoy's util/pool.h) with the GIL released; stacked observations
#include <algorithm>
#include <cstring>
#include <string>
#include <thread>

#include "bind.h"
#include "util/pool.h"

namespace mjbpy {

namespace {

class Batch {
 public:
  Batch(std::vector<std::shared_ptr<World>> w, int threads) : w_(std::move(w)) {
    if (threads > 1) pool_ = mjb::poolMake(threads - 1);
  }
  ~Batch() {
    if (pool_) mjb::poolFree(pool_);
  }
  Batch(const Batch&) = delete;
  Batch& operator=(const Batch&) = delete;

  int n() const { return (int)w_.size(); }
  const mjModel* m() const { return w_[0]->m; }

  // step every world nstep times with its row of actions (n x nu)
  void step(const double* actions, int nstep) {
    Job job{this, actions, nstep, std::vector<std::string>(w_.size())};
    {
      py::gil_scoped_release release;
      if (!pool_ || !mjb::poolRun(pool_, &Batch::run, &job, n())) {
        for (int i = 0; i < n(); i++) run(&job, i, 0);
      }
    }
    for (int i = 0; i < n(); i++) {
      if (!job.err[i].empty()) {
        throw Error("world " + std::to_string(i) + " of the batch: " + job.err[i] +
                    "; reset(mask) it");
      }
    }
  }

  void reset(const std::vector<bool>& mask) {
    for (int i = 0; i < n(); i++) {
      if (mask[i]) mj_resetData(w_[i]->m, w_[i]->d);
    }
  }

  // rows of cols values from each world (get: the world's array)
  py::array stack(double* (*get)(const World&), int cols) const {
    py::array_t<double> a({n(), cols});
    for (int i = 0; i < n(); i++) {
      if (cols) std::memcpy(a.mutable_data(i), get(*w_[i]), sizeof(double) * cols);
    }
    return a;
  }

  py::array wrench() const {
    int nb = m()->nbody;
    py::array_t<double> a({n(), nb, 6});
    for (int i = 0; i < n(); i++) {
      const mjtNum* p = mjb_wrench(w_[i]->b, w_[i]->d);
      if (p) std::memcpy(a.mutable_data(i), p, sizeof(double) * nb * 6);
      else std::memset(a.mutable_data(i), 0, sizeof(double) * nb * 6);
    }
    return a;
  }

  const World& world(int i) const { return *w_[i]; }

 private:
  struct Job {
    Batch* self;
    const double* actions;
    int nstep;
    std::vector<std::string> err;  // per world, written by its own chunk only
  };

  static void run(void* arg, int c, int) {
    Job* job = static_cast<Job*>(arg);
    World& w = *job->self->w_[c];
    int nu = w.m->nu;
    if (nu) std::memcpy(w.d->ctrl, job->actions + (size_t)c * nu, sizeof(double) * nu);
    for (int s = 0; s < job->nstep; s++) {
      mj_step(w.m, w.d);
      if (diverged(w.d, &job->err[c])) return;
    }
  }

  std::vector<std::shared_ptr<World>> w_;
  mjb::Pool* pool_ = nullptr;
};

py::tuple observe(const Batch& b, bool withWrench) {
  const mjModel* m = b.m();
  py::array q = b.stack([](const World& w) { return w.d->qpos; }, m->nq);
  py::array v = b.stack([](const World& w) { return w.d->qvel; }, m->nv);
  py::array s = b.stack([](const World& w) { return w.d->sensordata; }, m->nsensordata);
  if (withWrench) return py::make_tuple(q, v, s, b.wrench());
  return py::make_tuple(q, v, s);
}

}  // namespace

void bindBatch(py::module_& mod) {
  py::class_<Batch> c(mod, "Batch", R"(n independent copies of one scene, stepped in parallel.

Batch(source, n, seeds=None, backend=None, calm=False, threads=None, **overrides)

seeds: None (every world as the model says), one int for all, or n ints:
world i then steps exactly as mjbuoy.Sim(source, seed=seeds[i], ...), bit
for bit (spectrum k gets seeds[i] + k). threads: worker threads (None: one
per core, at most n). overrides: as for mjbuoy.Sim, the same for every
world; mjbuoy.threads defaults to 1 (the worlds, not the hulls, run in
parallel).)");
  c.def(py::init([](const std::string& source, int n, py::object seeds, py::object backend,
                    bool calm, py::object threads, py::kwargs kw) {
          if (n < 1 || n > 65536) {
            throw py::value_error("n = " + std::to_string(n) + " worlds must be 1 to 65536");
          }
          py::dict overrides;
          for (auto kv : kw) overrides[kv.first] = kv.second;
          // the pool runs the worlds in parallel: each world's cpu backend
          // on one thread (its results do not depend on its thread count,
          // docs/robustness.md), unless the caller says otherwise
          if (!overrides.contains("threads") && !overrides.contains("mjbuoy.threads")) {
            overrides["threads"] = 1;
          }
          // one int (Python's or a numpy scalar: __index__, not a sequence) for all
          auto isInt = [](py::handle h) {
            return PyIndex_Check(h.ptr()) && !PySequence_Check(h.ptr());
          };
          auto asInt = [](py::handle h) {
            PyObject* i = PyNumber_Index(h.ptr());
            if (!i) throw py::error_already_set();
            return py::reinterpret_steal<py::object>(i);
          };
          std::vector<py::object> seed(n, seeds);
          if (!seeds.is_none() && isInt(seeds)) seed.assign(n, asInt(seeds));
          if (!seeds.is_none() && !isInt(seeds)) {
            py::list l;
            try {
              l = py::list(seeds);
            } catch (py::error_already_set&) {
              throw py::type_error("seeds: give None, an int or a sequence of n ints");
            }
            if ((int)l.size() != n) {
              throw py::value_error("seeds has " + std::to_string(l.size()) + " values for n = " +
                                    std::to_string(n) + " worlds; give one seed per world");
            }
            for (int i = 0; i < n; i++) {
              if (!isInt(l[i])) {
                throw py::type_error("seeds[" + std::to_string(i) + "] is not an int");
              }
              seed[i] = asInt(l[i]);
            }
          }
          std::vector<std::shared_ptr<World>> w;
          for (int i = 0; i < n; i++) {
            w.push_back(load(makeSpec(source, backend, seed[i], calm, overrides)));
          }
          int hw = std::max(1, (int)std::thread::hardware_concurrency());
          int nt = threads.is_none() ? std::min(n, hw) : threads.cast<int>();
          if (nt < 1 || nt > 256) throw py::value_error("threads must be 1 to 256");
          return new Batch(std::move(w), nt);
        }),
        py::arg("source"), py::arg("n"), py::kw_only(), py::arg("seeds") = py::none(),
        py::arg("backend") = py::none(), py::arg("calm") = false,
        py::arg("threads") = py::none());
  c.def_property_readonly("n", &Batch::n, "number of worlds");
  c.def_property_readonly("nq", [](Batch& b) { return b.m()->nq; });
  c.def_property_readonly("nv", [](Batch& b) { return b.m()->nv; });
  c.def_property_readonly("nu", [](Batch& b) { return b.m()->nu; });
  c.def_property_readonly("nbody", [](Batch& b) { return b.m()->nbody; });
  c.def_property_readonly("nsensordata", [](Batch& b) { return b.m()->nsensordata; });
  c.def_property_readonly("timestep", [](Batch& b) { return b.m()->opt.timestep; },
                          "integration step [s]");
  c.def_property_readonly("time", [](Batch& b) {
          py::array_t<double> t(b.n());
          for (int i = 0; i < b.n(); i++) t.mutable_data()[i] = b.world(i).d->time;
          return t;
        }, "each world's simulated time (n,) [s]");
  c.def("step", [](Batch& b, py::object actions, int nstep, bool wrench) {
          if (nstep < 1) {
            throw py::value_error("nstep = " + std::to_string(nstep) + " must be >= 1");
          }
          int nu = b.m()->nu;
          py::array_t<double> a;
          if (!(actions.is_none() && nu == 0)) a = doubles(actions, "actions", {b.n(), nu});
          b.step(a.size() ? a.data() : nullptr, nstep);
          return observe(b, wrench);
        }, py::arg("actions"), py::arg("nstep") = 1, py::arg("wrench") = false,
        "Set each world's ctrl to its row of actions (n, nu) and advance nstep steps on the "
        "thread pool. Returns (qpos (n, nq), qvel (n, nv), sensordata (n, nsensordata)), and "
        "wrench (n, nbody, 6) [N, N m] last when wrench=True; copies. Raises mjbuoy.Error "
        "naming a world MuJoCo reset (diverged).");
  c.def("reset", [](Batch& b, py::object mask) {
          std::vector<bool> m(b.n(), true);
          if (!mask.is_none()) {
            py::array_t<double> a = doubles(mask, "mask", {b.n()});
            for (int i = 0; i < b.n(); i++) m[i] = a.at(i) != 0;
          }
          b.reset(m);
          return observe(b, false);
        }, py::arg("mask") = py::none(),
        "Reset the worlds where mask (n,) is true (None: all) to the initial state; returns "
        "the observation tuple of step().");
  c.def("observe", [](Batch& b, bool wrench) { return observe(b, wrench); },
        py::arg("wrench") = false, "the observation tuple of step() without stepping");
}

}  // namespace mjbpy
