// coefpsd: radiation damping projected onto the positive semi-definite
// cone at attach (docs/physics.md section 14, "Damping that feeds energy")
#ifndef MJBUOY_COEFPSD_H_
#define MJBUOY_COEFPSD_H_

#include <string>
#include <vector>

#include "radiation/hydrocoef.h"

namespace mjb {

// a larger removed part (relative to the largest |B|) means the panel mesh
// is too coarse
const double kPsdCoarse = 0.1;
// a smaller one is projected without a warning: it is within the panel
// method's discretisation error, the bound below which a negative B_ii
// (radattach.cc, checkCoef) is not warned about either; radiation is on by
// default, and such noise on a plain hull is not the user's to fix
const double kPsdWarn = 0.01;

// replace each frequency's B by the nearest (Frobenius) positive
// semi-definite matrix: symmetric part, negative eigenvalues set to 0.
// Returns the largest removed part (max |entry|) over the largest |B|;
// when it exceeds kPsdWarn, appends a warning naming who (the body), the
// frequency and that size to warn
double projectDamping(HydroCoef* c, const std::string& who, std::vector<std::string>* warn);

}  // namespace mjb

#endif  // MJBUOY_COEFPSD_H_
