// coefexport: a radiating body's coefficients as a coefficient file holds
// them (radiation/coefio.h; docs/interchange.md), for mjbuoy-hydro --write
#ifndef MJBUOY_COEFEXPORT_H_
#define MJBUOY_COEFEXPORT_H_

#include <string>

#include "api/buoy.h"
#include "radiation/coefio.h"

namespace mjb {

// body's A, B, A_inf and, with diffraction on, X and FK (36 uniform
// headings), about its COM in its body axes: the file's origin is the COM
// (read back with mjbuoy.radiation.fileorigin.<body> = its COM in the body
// frame); vol: its displaced volume at the panel pose. "" or why not
std::string exportCoef(const Buoy& B, int body, CoefFile* f);

}  // namespace mjb

#endif  // MJBUOY_COEFEXPORT_H_
