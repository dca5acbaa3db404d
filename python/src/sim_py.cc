// mjbuoy.Sim: one scene, its live arrays as numpy views, the sea, wrenches,
// radiation coefficients and offscreen pictures
#include <cmath>
#include <cstring>
#include <string>

#include "bind.h"
#include "render.h"

namespace mjbpy {

namespace {

class Sim {
 public:
  explicit Sim(std::shared_ptr<World> w) : w_(std::move(w)) {}

  // the world, or mjbuoy.Error once closed
  World& world() const {
    if (!w_) throw Error("this Sim is closed; create a new mjbuoy.Sim");
    return *w_;
  }
  const std::shared_ptr<World>& shared() const {
    world();
    return w_;
  }
  void close() {
    renderer_.reset();  // holds the mjbBuoy: before the world goes
    w_.reset();         // freed now, or when the last numpy view of it goes
  }
  bool closed() const { return !w_; }

  void step(int n) {
    if (n < 1) throw py::value_error("step(n): n = " + std::to_string(n) + " must be >= 1");
    std::shared_ptr<World> w = shared();
    std::string why;
    bool bad = false;
    {
      py::gil_scoped_release release;
      for (int i = 0; i < n && !bad; i++) {
        mj_step(w->m, w->d);
        bad = diverged(w->d, &why);
      }
    }
    if (bad) throw Error(w->name + ": " + why + "; reset() the Sim (or lower the timestep)");
  }

  py::array render(int width, int height, const std::string& camera) {
    World& w = world();
    if (width < 16 || width > 8192 || height < 16 || height > 8192) {
      throw py::value_error("render: width " + std::to_string(width) + " and height " +
                            std::to_string(height) + " must be 16 to 8192 pixels");
    }
    if (!renderer_ || renderer_->width() != width || renderer_->height() != height ||
        camera != camera_) {
      renderer_.reset();
      mjbsim::RenderOptions ro;
      ro.width = width;
      ro.height = height;
      ro.camera = camera;
      std::string e;
      renderer_ = mjbsim::Renderer::create(w.m, w.b, ro, &e);
      if (!renderer_) throw Error("render: " + e);
      camera_ = camera;
    }
    std::vector<unsigned char> rgb;
    std::string e;
    if (!renderer_->render(w.d, &rgb, &e)) throw Error("render: " + e);
    py::array_t<unsigned char> out({height, width, 3});
    unsigned char* o = out.mutable_data();
    size_t row = (size_t)width * 3;
    for (int r = 0; r < height; r++) {  // OpenGL's bottom row first to top row first
      std::memcpy(o + r * row, rgb.data() + (size_t)(height - 1 - r) * row, row);
    }
    return out;
  }

 private:
  std::shared_ptr<World> w_;
  std::unique_ptr<mjbsim::Renderer> renderer_;
  std::string camera_;
};

// the id of name among MuJoCo objects of type, or KeyError listing them
int idOf(const mjModel* m, int type, int count, const char* kind, const char* kinds,
         const std::string& name) {
  int id = mj_name2id(m, type, name.c_str());
  if (id >= 0) return id;
  std::string list;
  for (int i = 0; i < count && i < 20; i++) {
    const char* n = mj_id2name(m, type, i);
    list += std::string(i ? ", " : "") + (n ? n : "(unnamed)");
  }
  if (count > 20) list += ", ...";
  throw py::key_error(std::string("no ") + kind + " named \"" + name + "\"; " + kinds +
                      " in the model: " + (count ? list : "none"));
}

// a body given by name or id
int bodyOf(const mjModel* m, py::object body) {
  if (py::isinstance<py::str>(body)) {
    return idOf(m, mjOBJ_BODY, m->nbody, "body", "bodies", body.cast<std::string>());
  }
  int id = body.cast<int>();
  if (id < 0 || id >= m->nbody) {
    throw py::value_error("body id " + std::to_string(id) + " is out of range 0 to " +
                          std::to_string(m->nbody - 1));
  }
  return id;
}

// copy value (shape of the view) into a view: the setter of sim.qpos & co.
void assign(py::array target, py::object value, const char* what) {
  std::vector<py::ssize_t> shape(target.shape(), target.shape() + target.ndim());
  py::array_t<double> v = doubles(value, what, shape);
  if (v.size()) std::memcpy(target.mutable_data(), v.data(), v.size() * sizeof(double));
}

py::array copyRows(const double* p, int n, int cols) {
  py::array_t<double> a({n, cols});
  if (n > 0 && cols > 0) std::memcpy(a.mutable_data(), p, sizeof(double) * n * cols);
  return a;
}

// the node count of mooring line `line` of w: IndexError for no such line,
// mjbuoy.Error before the first step or forward (what names the method)
int checkLine(World& w, int line, const char* what) {
  const int nl = mjb_lineCount(w.b);
  if (line < 0 || line >= nl) {
    throw py::index_error(std::string(what) + ": line " + std::to_string(line) +
                          " out of range: the model has " + std::to_string(nl) +
                          " mooring line(s), 0 to " + std::to_string(nl - 1));
  }
  int n = mjb_lineNodes(w.b, w.d, line, nullptr, 0);
  if (n == 0) throw Error(std::string(what) + ": no line state yet; step() or forward() first");
  return n;
}

}  // namespace

void bindSim(py::module_& mod) {
  py::class_<Sim> c(mod, "Sim", R"(One MuJoCo scene with mjbuoy attached.

Sim(source, backend=None, seed=None, calm=False, **overrides)

source: an MJCF file path, or MJCF text starting with '<' (mesh files then
resolve from the working directory). backend: "cpu", "gl", "auto" or None
(the model's mjbuoy.backend). seed: every wave spectrum k of the scene gets
the seed seed + k (mjbuoy.spectrum.<label>.seed). calm: delete the model's
waves and spectra first (mjbuoy-sim --calm). overrides: mjbuoy.* custom
entries set before the model compiles, as mjbuoy-sim --set NAME=VALUE:
pass **{"mjbuoy.spectrum.sea.hs": 1.5}, or spectrum__sea__hs=1.5 ("__" for
"."). Units are SI (m, kg, s, N, rad) throughout.)");
  c.def(py::init([](const std::string& source, py::object backend, py::object seed, bool calm,
                    py::kwargs kw) {
          py::dict overrides;
          for (auto kv : kw) overrides[kv.first] = kv.second;
          return new Sim(load(makeSpec(source, backend, seed, calm, overrides)));
        }),
        py::arg("source"), py::kw_only(), py::arg("backend") = py::none(),
        py::arg("seed") = py::none(), py::arg("calm") = false);
  c.def("close", &Sim::close,
        "Free the scene now (numpy views still held keep its memory until they go). Any "
        "later use raises mjbuoy.Error.");
  c.def_property_readonly("closed", &Sim::closed);
  c.def("__enter__", [](py::object self) { return self; });
  c.def("__exit__", [](Sim& s, py::args) { s.close(); });
  c.def("step", &Sim::step, py::arg("n") = 1,
        "Advance n steps of timestep seconds (mj_step), the GIL released. Raises mjbuoy.Error if "
        "MuJoCo reset a diverged state.");
  c.def("forward", [](Sim& s) { World& w = s.world(); mj_forward(w.m, w.d); },
        "Compute the derived quantities (body_xpos, sensordata, the wrench) without stepping.");
  c.def("reset", [](Sim& s) { World& w = s.world(); mj_resetData(w.m, w.d); },
        "Reset the state to the model's initial one (mj_resetData; mjbuoy's state starts clean).");
  c.def_property("time", [](Sim& s) { return s.world().d->time; },
                 [](Sim& s, double t) {
                   if (!std::isfinite(t)) throw py::value_error("time must be finite [s]");
                   s.world().d->time = t;
                 },
                 "simulated time [s]");
  c.def_property("timestep", [](Sim& s) { return s.world().m->opt.timestep; },
                 [](Sim& s, double dt) {
                   if (!(dt > 0 && dt < 1)) {
                     throw py::value_error("timestep " + std::to_string(dt) +
                                           " must be > 0 and < 1 [s]");
                   }
                   s.world().m->opt.timestep = dt;
                 },
                 "integration step [s] (mjModel.opt.timestep)");

  // live arrays: (name, pointer, rows, cols, writable)
  struct Arr {
    const char* name;
    double* (*ptr)(const World&);
    int (*rows)(const mjModel*);
    int cols;
    bool writable;
    const char* doc;
  };
  static const Arr arrs[] = {
      {"qpos", [](const World& w) { return w.d->qpos; }, [](const mjModel* m) { return m->nq; },
       0, true, "joint positions (nq,) [m, rad; free joints: position, unit quaternion w x y z]"},
      {"qvel", [](const World& w) { return w.d->qvel; }, [](const mjModel* m) { return m->nv; },
       0, true, "joint velocities (nv,) [m/s, rad/s]"},
      {"ctrl", [](const World& w) { return w.d->ctrl; }, [](const mjModel* m) { return m->nu; },
       0, true, "actuator controls (nu,) [actuator units, e.g. N for a motor of gear 1]"},
      {"act", [](const World& w) { return w.d->act; }, [](const mjModel* m) { return m->na; }, 0,
       true, "actuator activations (na,)"},
      {"xfrc_applied", [](const World& w) { return w.d->xfrc_applied; },
       [](const mjModel* m) { return m->nbody; }, 6, true,
       "user force [N] and torque [N m] on each body, world frame, at its centre of mass "
       "(nbody, 6); mjbuoy never writes it"},
      {"sensordata", [](const World& w) { return w.d->sensordata; },
       [](const mjModel* m) { return m->nsensordata; }, 0, false,
       "sensor outputs (nsensordata,), read-only; use sensor_range(name) for one sensor"},
      {"body_xpos", [](const World& w) { return w.d->xpos; },
       [](const mjModel* m) { return m->nbody; }, 3, false,
       "body frame positions, world frame (nbody, 3) [m], read-only; from the last forward/step"},
      {"body_xquat", [](const World& w) { return w.d->xquat; },
       [](const mjModel* m) { return m->nbody; }, 4, false,
       "body orientations as unit quaternions w x y z (nbody, 4), read-only"},
  };
  for (const Arr& a : arrs) {
    const Arr* p = &a;
    auto get = [p](Sim& s) {
      const std::shared_ptr<World>& w = s.shared();
      return view(w, p->ptr(*w), p->rows(w->m), p->cols, p->writable);
    };
    if (a.writable) {
      c.def_property(a.name, get,
                     [p, get](Sim& s, py::object v) { assign(get(s), v, p->name); }, a.doc);
    } else {
      c.def_property_readonly(a.name, get, a.doc);
    }
  }
  c.def_property_readonly("nq", [](Sim& s) { return s.world().m->nq; });
  c.def_property_readonly("nv", [](Sim& s) { return s.world().m->nv; });
  c.def_property_readonly("nu", [](Sim& s) { return s.world().m->nu; });
  c.def_property_readonly("na", [](Sim& s) { return s.world().m->na; });
  c.def_property_readonly("nbody", [](Sim& s) { return s.world().m->nbody; },
                          "bodies, the world body 0 included");
  c.def_property_readonly("nsensordata", [](Sim& s) { return s.world().m->nsensordata; });

  c.def("body_id", [](Sim& s, const std::string& n) {
          const mjModel* m = s.world().m;
          return idOf(m, mjOBJ_BODY, m->nbody, "body", "bodies", n);
        }, py::arg("name"),
        "index of a body in body_xpos, xfrc_applied, wrench(); KeyError if none");
  c.def("joint_id", [](Sim& s, const std::string& n) {
          const mjModel* m = s.world().m;
          return idOf(m, mjOBJ_JOINT, m->njnt, "joint", "joints", n);
        }, py::arg("name"), "index of a joint");
  c.def("joint_qpos_range", [](Sim& s, const std::string& n) {
          const mjModel* m = s.world().m;
          int j = idOf(m, mjOBJ_JOINT, m->njnt, "joint", "joints", n);
          static const int nq[4] = {7, 4, 1, 1};  // free, ball, slide, hinge
          int a = m->jnt_qposadr[j];
          return py::make_tuple(a, a + nq[m->jnt_type[j]]);
        }, py::arg("name"), "(start, stop) of a joint's entries in qpos");
  c.def("actuator_id", [](Sim& s, const std::string& n) {
          const mjModel* m = s.world().m;
          return idOf(m, mjOBJ_ACTUATOR, m->nu, "actuator", "actuators", n);
        }, py::arg("name"), "index of an actuator in ctrl");
  c.def("sensor_id", [](Sim& s, const std::string& n) {
          const mjModel* m = s.world().m;
          return idOf(m, mjOBJ_SENSOR, m->nsensor, "sensor", "sensors", n);
        }, py::arg("name"), "index of a sensor");
  c.def("sensor_range", [](Sim& s, const std::string& n) {
          const mjModel* m = s.world().m;
          int i = idOf(m, mjOBJ_SENSOR, m->nsensor, "sensor", "sensors", n);
          return py::make_tuple(m->sensor_adr[i], m->sensor_adr[i] + m->sensor_dim[i]);
        }, py::arg("name"), "(start, stop) of a sensor's values in sensordata");

  c.def("wrench", [](Sim& s, py::object part) {
          World& w = s.world();
          int k = partIndex(part);
          const mjtNum* p = k < 0 ? mjb_wrench(w.b, w.d) : mjb_wrenchPart(w.b, w.d, k);
          if (!p) throw Error("no wrench for this state yet; step() or forward() first");
          return copyRows(p, w.m->nbody, 6);
        }, py::arg("part") = py::none(),
        "mjbuoy's wrench on each body from the last step (nbody, 6): world-frame force [N], "
        "then torque about the body's centre of mass [N m] (a copy). part: None for the total, "
        "or one force family of mjbuoy.PARTS (\"pressure\", \"viscous\", \"drag\", \"slam\", "
        "\"damping\", \"wind\").");
  c.def_property_readonly("line_count", [](Sim& s) { return mjb_lineCount(s.world().b); },
                          "number of mooring lines (mjb_lineCount)");
  c.def("line_nodes", [](Sim& s, int line) {
          World& w = s.world();
          int n = checkLine(w, line, "line_nodes");
          py::array_t<double> a({n, 3});
          mjb_lineNodes(w.b, w.d, line, a.mutable_data(), n);
          return a;
        }, py::arg("line"),
        "node positions of mooring line `line` (nseg + 1, 3), world frame [m], anchor first "
        "(mjb_lineNodes, a copy)");
  c.def("line_tensions", [](Sim& s, int line) {
          World& w = s.world();
          checkLine(w, line, "line_tensions");
          int n = mjb_lineTensions(w.b, w.d, line, nullptr, 0);
          py::array_t<double> a(n);
          mjb_lineTensions(w.b, w.d, line, a.mutable_data(), n);
          return a;
        }, py::arg("line"),
        "segment tensions of mooring line `line` (nseg,) [N], anchor first, after the last "
        "step (mjb_lineTensions, a copy)");
  c.def("line_wrench", [](Sim& s) {
          World& w = s.world();
          if (mjb_lineCount(w.b) == 0) throw Error("line_wrench: the model has no mooring lines");
          const mjtNum* p = mjb_lineWrench(w.b, w.d);
          if (!p) throw Error("no line wrench for this state yet; step() or forward() first");
          return copyRows(p, w.m->nbody, 6);
        },
        "the mooring lines' wrench on each body (nbody, 6) from the last step: world-frame "
        "force [N], torque about the body's centre of mass [N m] (mjb_lineWrench, a copy); "
        "not part of wrench()");
  c.def_property_readonly("seabed", [](Sim& s) -> py::object {
          mjtNum z = 0;
          if (!mjb_seabed(s.world().b, &z)) return py::none();
          return py::float_(z);
        }, "height z [m] of the seabed (world frame), None without one (mjb_seabed)");
  c.def("notices", [](Sim& s) { World& w = s.world(); return std::string(mjb_notices(w.b, w.d)); },
        "run-time notices (bodies or force families left out as non-finite), one a line");
  c.def_property_readonly("warnings", [](Sim& s) { return std::string(mjb_warnings(s.world().b)); },
                          "load-time warnings of mjb_attach, one a line");
  c.def_property_readonly("info", [](Sim& s) {
          mjbInfo i = mjb_info(s.world().b);
          py::dict d;
          d["nhull"] = i.nhull;
          d["nbody"] = i.nbody;
          d["ntri"] = i.ntri;
          d["nvert"] = i.nvert;
          d["backend"] = i.backend;
          d["renderer"] = i.renderer;
          return d;
        }, "sizes and backend of the attached scene (mjb_info)");

  c.def("sea_height", [](Sim& s, py::object x, py::object y, py::object t) -> py::object {
          World& w = s.world();
          py::module_ np = py::module_::import("numpy");
          if (x.is_none() || y.is_none()) throw py::type_error("sea_height: x and y are None");
          py::object tt = t.is_none() ? py::float_(w.d->time) : t;
          py::tuple b;
          try {
            b = np.attr("broadcast_arrays")(np.attr("asarray")(x, "float64"),
                                            np.attr("asarray")(y, "float64"),
                                            np.attr("asarray")(tt, "float64"));
          } catch (py::error_already_set& e) {
            throw py::type_error(std::string("sea_height: x, y and t must be numbers or arrays "
                                             "of broadcastable shapes: ") + e.what());
          }
          using arr = py::array_t<double, py::array::c_style | py::array::forcecast>;
          arr xa(b[0]), ya(b[1]), ta(b[2]);
          py::array_t<double> out(std::vector<py::ssize_t>(xa.shape(), xa.shape() + xa.ndim()));
          for (py::ssize_t i = 0; i < xa.size(); i++) {
            out.mutable_data()[i] = mjb_seaHeight(w.b, xa.data()[i], ya.data()[i], ta.data()[i]);
          }
          if (xa.ndim() == 0) return py::float_(out.data()[0]);
          return std::move(out);
        }, py::arg("x"), py::arg("y"), py::arg("t") = py::none(),
        "the exact sea surface height eta(x, y, t) [m] at points x, y [m] and times t [s] "
        "(numbers or arrays, broadcast; t None: the Sim's time)");
  c.def("waves", [](Sim& s) {
          World& w = s.world();
          int n = mjb_waves(w.b, nullptr, 0);
          py::array_t<double> a({n, 6});
          if (n) mjb_waves(w.b, a.mutable_data(), n);
          return a;
        }, "the sea's linear components (n, 6): amplitude [m], omega [rad/s], wave number k "
           "[rad/m], direction [deg], phase [deg], steepness Q");
  c.def("wind_velocity", [](Sim& s, py::object t) {
          World& w = s.world();
          mjtNum v[2];
          mjb_windVelocity(w.b, t.is_none() ? w.d->time : t.cast<double>(), v);
          py::array_t<double> a(2);
          a.mutable_data()[0] = v[0];
          a.mutable_data()[1] = v[1];
          return a;
        }, py::arg("t") = py::none(), "wind speed vector at 10 m at time t (None: now) [m/s]");
  c.def("set_sea", [](Sim& s, py::object waves, py::object spectra, py::object current,
                      py::object wind, py::object ramp) {
          setSea(s.world().b, waves, spectra, current, wind, ramp);
        },
        py::kw_only(), py::arg("waves") = py::none(), py::arg("spectra") = py::none(),
        py::arg("current") = py::none(), py::arg("wind") = py::none(),
        py::arg("ramp") = py::none(),
        R"(Replace the sea between steps (mjb_setSea); density, level and depth stay the model's.

waves: (n, 5) rows of amplitude [m], wavelength [m], direction [deg], phase
[deg], steepness Q (as mjbuoy.wave.<label>). spectra: a list of dicts with
keys type ("pm", "jonswap", "table"), hs [m], tp [s], wind [m/s], gamma,
table ((n, 2) omega [rad/s], S [m^2 s/rad]), dir [deg], spread, n, wmin,
wmax [rad/s], seed; missing keys keep mjb_defaultSpectrum's values.
current: (2,) [m/s]. wind: a dict with speed [m/s], dir [deg], gust ("none"
or "froya"), ngust, seed. ramp: the start-up ramp [s] from t = 0 (as
mjbuoy.sea.ramp, 0 = off); not given keeps the model's. What is not given
is calm (no waves, no current, no wind). Raises mjbuoy.Error with
mjbuoy's message if a value is out of range (the sea is then unchanged).)");
  c.def("radiation", [](Sim& s, py::object body) {
          World& w = s.world();
          return radiationOf(w, bodyOf(w.m, body));
        }, py::arg("body"),
        "the panel solver's coefficients of a body (name or id) about its centre of mass, body "
        "axes: dict of omega (nw,) [rad/s], A (nw, 6, 6) added mass, B (nw, 6, 6) radiation "
        "damping, Ainf (6, 6), heading (nh,) [rad], X (nw, nh, 6) complex exciting force per "
        "unit amplitude [N/m, N m/m] about the COM in world axes at qpos0 (nh = 0 with "
        "mjbuoy.radiation.diffraction off), FK (its Froude-Krylov part), rho, g, depth. Needs "
        "mjbuoy.radiation on.");
  c.def("render", &Sim::render, py::arg("width") = 640, py::arg("height") = 480,
        py::arg("camera") = "",
        "an RGB picture (height, width, 3) uint8, top row first, of the scene and the sea "
        "(MuJoCo's renderer on a headless EGL context). camera: a model camera name, or \"\" "
        "for a free camera following the hulls.");
}

}  // namespace mjbpy
