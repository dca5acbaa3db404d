// the mjbuoy Python module (_mjbuoy): mjbuoy.Sim, mjbuoy.Batch, mjbuoy.Error;
// docs/python.md
#include <cmath>
#include <cstring>

#include "bind.h"

namespace mjbpy {

py::array_t<double> doubles(py::handle obj, const char* what, std::vector<py::ssize_t> shape) {
  auto shapeText = [](const std::vector<py::ssize_t>& s) {
    std::string t = "(";
    for (size_t i = 0; i < s.size(); i++) {
      t += (i ? ", " : "") + (s[i] < 0 ? std::string("any") : std::to_string(s[i]));
    }
    return t + (s.size() == 1 ? ",)" : ")");
  };
  if (obj.is_none()) {
    throw py::type_error(std::string(what) + ": got None; expected an array of shape " +
                         shapeText(shape) + " of numbers");
  }
  py::module_ np = py::module_::import("numpy");
  py::array a;
  try {
    a = np.attr("asarray")(obj);
  } catch (py::error_already_set&) {
    throw py::type_error(std::string(what) + ": cannot read it as an array of numbers");
  }
  char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b') {
    throw py::type_error(std::string(what) + ": dtype " + py::str(a.dtype()).cast<std::string>() +
                         " is not numeric; give floats (float64)");
  }
  bool ok = a.ndim() == (py::ssize_t)shape.size();
  for (size_t i = 0; ok && i < shape.size(); i++) ok = shape[i] < 0 || a.shape(i) == shape[i];
  if (!ok) {
    std::vector<py::ssize_t> got(a.shape(), a.shape() + a.ndim());
    throw py::value_error(std::string(what) + ": shape " + shapeText(got) + ", expected " +
                          shapeText(shape));
  }
  py::array_t<double, py::array::c_style | py::array::forcecast> out(a);
  // a copy even when a is already float64 and contiguous: the caller's
  // array may change while the GIL is released
  py::array_t<double> copy(std::vector<py::ssize_t>(out.shape(), out.shape() + out.ndim()));
  if (out.size()) std::memcpy(copy.mutable_data(), out.data(), out.size() * sizeof(double));
  const double* p = copy.data();
  for (py::ssize_t i = 0; i < copy.size(); i++) {
    if (!std::isfinite(p[i])) {
      throw py::value_error(std::string(what) + ": element " + std::to_string(i) + " is " +
                            std::to_string(p[i]) + "; give finite numbers");
    }
  }
  return copy;
}

static std::string entryValue(py::handle v, const std::string& name) {
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "1" : "0";
  if (py::isinstance<py::int_>(v)) return py::str(v).cast<std::string>();
  if (py::isinstance<py::float_>(v)) {
    return py::str(py::reinterpret_borrow<py::object>(v)).cast<std::string>();
  }
  try {
    py::array_t<double> a = doubles(v, name.c_str(), {-1});
    std::string s;
    for (py::ssize_t i = 0; i < a.size(); i++) {
      s += (i ? " " : "") + py::str(py::float_(a.at(i))).cast<std::string>();
    }
    return s;
  } catch (py::error_already_set&) {
    throw;
  } catch (std::exception&) {
    throw py::type_error("override " + name + ": give a number, a sequence of numbers or a "
                         "string (as the data of its <numeric> or <text> entry)");
  }
}

LoadSpec makeSpec(const std::string& source, py::object backend, py::object seed, bool calm,
                  py::dict overrides) {
  LoadSpec s;
  s.source = source;
  if (!backend.is_none()) s.backend = backend.cast<std::string>();
  if (!seed.is_none()) {
    long long v = seed.cast<long long>();
    if (v < 0) throw py::value_error("seed " + std::to_string(v) + " is negative; give 0 to 2^53");
    s.seeded = true;
    s.seed = (unsigned long long)v;
  }
  s.calm = calm;
  for (auto kv : overrides) {
    std::string key = py::str(kv.first).cast<std::string>();
    std::string name = key;
    if (name.rfind("mjbuoy.", 0) != 0) {
      // keyword form: spectrum__sea__hs=1 is mjbuoy.spectrum.sea.hs
      std::string dotted;
      for (size_t i = 0; i < key.size(); i++) {
        if (key.compare(i, 2, "__") == 0) {
          dotted += '.';
          i++;
        } else {
          dotted += key[i];
        }
      }
      name = "mjbuoy." + dotted;
    }
    s.set.push_back(name + "=" + entryValue(kv.second, name));
  }
  return s;
}

static std::string pythonic(std::string e) {
  // parseEdits names the option as mjbuoy-sim's --set
  for (size_t p; (p = e.find("--set ")) != std::string::npos;) e.replace(p, 6, "override ");
  return e;
}

std::shared_ptr<World> load(const LoadSpec& spec) {
  std::string err;
  std::unique_ptr<World> w;
  {
    py::gil_scoped_release release;
    w = loadWorld(spec, &err);
  }
  if (!w) throw Error(pythonic(err));
  return std::shared_ptr<World>(std::move(w));
}

py::array view(const std::shared_ptr<World>& w, double* p, int n, int cols, bool writable) {
  py::capsule owner(new std::shared_ptr<World>(w),
                    [](void* q) { delete static_cast<std::shared_ptr<World>*>(q); });
  std::vector<py::ssize_t> shape = {n}, strides = {(py::ssize_t)sizeof(double)};
  if (cols) {
    shape = {n, cols};
    strides = {(py::ssize_t)(cols * sizeof(double)), (py::ssize_t)sizeof(double)};
  }
  py::array a(py::dtype::of<double>(), shape, strides, p, owner);
  if (!writable) a.attr("flags").attr("writeable") = false;
  return a;
}

int partIndex(py::object part) {
  static const char* names[mjbNPART] = {"pressure", "viscous", "drag", "slam", "damping", "wind"};
  if (part.is_none()) return -1;
  if (py::isinstance<py::str>(part)) {
    std::string s = part.cast<std::string>();
    for (int i = 0; i < mjbNPART; i++) {
      if (s == names[i]) return i;
    }
    throw py::value_error("part \"" + s + "\" is not a force family; accepted: pressure, "
                          "viscous, drag, slam, damping, wind");
  }
  int i = part.cast<int>();
  if (i < 0 || i >= mjbNPART) {
    throw py::value_error("part " + std::to_string(i) + " is out of range 0 to " +
                          std::to_string(mjbNPART - 1));
  }
  return i;
}

}  // namespace mjbpy

PYBIND11_MODULE(_mjbuoy, m) {
  namespace py = pybind11;
  m.doc() = "mjbuoy: buoyancy and hydrodynamics of floating bodies for MuJoCo (C library "
            "bindings; see docs/python.md)";
  mjbpy::installWarningHandler();
  py::register_exception<mjbpy::Error>(m, "Error", PyExc_RuntimeError);
  m.attr("__version__") = mjb_versionString();
  m.attr("PARTS") = py::make_tuple("pressure", "viscous", "drag", "slam", "damping", "wind");
  mjbpy::bindSim(m);
  mjbpy::bindBatch(m);
}
