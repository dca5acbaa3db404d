// wind: the wind field, a mean wind at 10 m with optional gusts
// (docs/physics.md, "Irregular seas and wind"); its force on dry faces is
// hull/windload.h
#ifndef MJBUOY_WIND_H_
#define MJBUOY_WIND_H_

#include <vector>

#include "mjbuoy.h"

namespace mjb {

// wind entries of a model (docs/mjcf.md section 9)
struct WindParams {
  bool on = false;        // any mjbuoy.wind.* entry: wind forces are computed
  mjbWind w = {0, 0, mjbGUST_NONE, 128, 1};
  double rho = 1.225;     // air density [kg/m^3]
  double cd = 1.0;        // drag coefficient per projected dry area
  double cf = 0.002;      // friction coefficient per dry area
  std::vector<int> geom;  // superstructure geoms
};

struct Gust { double a, f, ph; };  // amplitude [m/s], frequency [Hz], phase [rad]

// the wind field: its entries and gust components
struct WindField {
  WindParams par;
  std::vector<Gust> gust;      // capacity reserved at attach
};

// Froya gust spectrum at 10 m [m^2/s^2 per Hz] of mean speed u0 [m/s]
double froya(double u0, double f);

// fill w->gust from w->par.w (no allocation within the 1024 reserved)
void windGusts(WindField* w);

// speed at 10 m along the mean direction at time t [m/s]
double windSpeed(const WindField& w, double t);

}  // namespace mjb

#endif  // MJBUOY_WIND_H_
