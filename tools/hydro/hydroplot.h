// hydroplot: mjbuoy-hydro --plot, the diagonal of A(omega), B(omega) and
// K(t) of one body drawn by gnuplot (Debian package gnuplot-nox) into a PNG
#ifndef MJBUOY_TOOLS_HYDROPLOT_H_
#define MJBUOY_TOOLS_HYDROPLOT_H_

#include <string>
#include <vector>

#include "radiation/hydrocoef.h"

namespace mjbhydro {

// write png atomically (three panels: A_ii [kg, kg m^2] and B_ii [kg/s,
// kg m^2/s] against omega [rad/s], K_ii against t [s]); K holds 6 rows of
// samples dt apart. false with the reason (gnuplot missing or failing)
bool plotCoef(const std::string& png, const std::string& title, const mjb::HydroCoef& c,
              const std::vector<std::vector<double>>& K, double dt, std::string* err);

}  // namespace mjbhydro

#endif  // MJBUOY_TOOLS_HYDROPLOT_H_
