// plot: heave, roll and pitch of the hull bodies against time, drawn by the
// gnuplot program (Debian package gnuplot-nox) into a PNG (mjbuoy-sim --plot)
#ifndef MJBUOY_TOOLS_PLOT_H_
#define MJBUOY_TOOLS_PLOT_H_

#include <string>
#include <vector>

namespace mjbsim {

struct PlotSeries {
  std::string name;                      // body name
  std::vector<double> z, roll, pitch;    // m, deg, deg; one per time
};

// checks that gnuplot is on PATH (false with the package to install)
bool plotAvailable(std::string* err);

// writes the PNG file png (1200 x 900; name in messages): three panels
// sharing the time axis; false with gnuplot's reason
bool writePlot(const std::string& png, const std::string& name, const std::string& title,
               const std::vector<double>& t,
               const std::vector<PlotSeries>& s, std::string* err);

}  // namespace mjbsim

#endif  // MJBUOY_TOOLS_PLOT_H_
