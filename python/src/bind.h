// bind: what the Python module's files share (module.cc, sim_py.cc,
// batch_py.cc, sea_py.cc)
#ifndef MJBUOY_PYTHON_BIND_H_
#define MJBUOY_PYTHON_BIND_H_

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "world.h"

namespace mjbpy {

namespace py = pybind11;

// mjbuoy's own errors (bad scene, bad entry, MuJoCo reset, closed Sim):
// mjbuoy.Error in Python, a RuntimeError
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// a float64, C-contiguous copy of obj of exactly shape (-1: any length);
// TypeError for None or non-numbers, ValueError for a wrong shape, both
// naming what (the argument) and the expected shape
py::array_t<double> doubles(py::handle obj, const char* what, std::vector<py::ssize_t> shape);

// the LoadSpec of a source, backend, seed, calm and Python overrides
// (names: "mjbuoy.x.y", or "x__y" for mjbuoy.x.y; values: numbers,
// sequences of numbers, strings)
LoadSpec makeSpec(const std::string& source, py::object backend, py::object seed, bool calm,
                  py::dict overrides);

// a world loaded from spec, or mjbuoy.Error with mjbuoy's message
std::shared_ptr<World> load(const LoadSpec& spec);

// a numpy view of n x cols doubles at p (cols 0: 1-d of n), read-only unless
// writable; the array keeps w alive
py::array view(const std::shared_ptr<World>& w, double* p, int n, int cols, bool writable);

// the force family index of a part name or number (None: -1, the total)
int partIndex(py::object part);

void bindSim(py::module_& m);
void bindBatch(py::module_& m);

// sea_py.cc: mjb_setSea from Python values, the radiation coefficients
void setSea(mjbBuoy* b, py::object waves, py::object spectra, py::object current,
            py::object wind, py::object ramp);
py::dict radiationOf(const World& w, int body);

}  // namespace mjbpy

#endif  // MJBUOY_PYTHON_BIND_H_
