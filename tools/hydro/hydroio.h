// hydroio: mjbuoy-hydro's coefficient files of other tools (WAMIT, Capytaine
// NetCDF, BEMIO HDF5; docs/interchange.md): a model's coefficients written
// to them, and one file converted into the others
#ifndef MJBUOY_TOOLS_HYDROIO_H_
#define MJBUOY_TOOLS_HYDROIO_H_

#include <string>
#include <vector>

#include "radiation/coefio.h"

namespace mjbhydro {

// the files a write to path makes (WAMIT: stem.1, stem.3, stem.3fk)
std::vector<std::string> outputsOf(const std::string& path);

// write f to each path (format by name); false with *err
bool writeAll(const std::vector<std::string>& paths, const mjb::CoefOpt& o,
              const mjb::CoefFile& f, std::string* err);

}  // namespace mjbhydro

#endif  // MJBUOY_TOOLS_HYDROIO_H_
