// plot: heave, roll and pitch against time through gnuplot (see plot.h)
#include "plot.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "render.h"  // findProgram, shellQuote, checkWritable

namespace mjbsim {

bool plotAvailable(std::string* err) {
  if (findProgram("gnuplot").empty()) {
    *err = "--plot needs the gnuplot program, which is not on PATH; install the Debian "
           "package gnuplot-nox (apt-get install gnuplot-nox)";
    return false;
  }
  return true;
}

// gnuplot string literal (single quotes, doubled inside)
static std::string gq(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

bool writePlot(const std::string& png, const std::string& title, const std::vector<double>& t,
               const std::vector<PlotSeries>& s, std::string* err) {
  if (!plotAvailable(err) || !checkWritable(png, err)) return false;
  char dat[] = "/tmp/mjbuoy-plot-XXXXXX";
  int fd = mkstemp(dat);
  if (fd < 0) {
    *err = "cannot create a temporary file for the plot data";
    return false;
  }
  FILE* f = fdopen(fd, "w");
  for (size_t i = 0; i < t.size(); i++) {
    std::fprintf(f, "%.6f", t[i]);
    for (const PlotSeries& p : s) std::fprintf(f, " %.6g %.6g %.6g", p.z[i], p.roll[i], p.pitch[i]);
    std::fprintf(f, "\n");
  }
  std::fclose(f);
  std::string script = "set terminal pngcairo size 1200,900 font 'sans,10'\n";
  script += "set output " + gq(png) + "\n";
  script += "set multiplot layout 3,1 title " + gq(title) + "\n";
  script += "set grid\nset key outside right top\nset lmargin 12\nset rmargin 20\n";
  const char* what[3] = {"heave z [m]", "roll [deg]", "pitch [deg]"};
  for (int k = 0; k < 3; k++) {
    script += std::string("set ylabel ") + gq(what[k]) + "\n";
    script += std::string("set xlabel ") + gq(k == 2 ? "time [s]" : "") + "\n";
    script += "plot ";
    for (size_t j = 0; j < s.size(); j++) {
      char col[64];
      std::snprintf(col, sizeof(col), "using 1:%zu", 2 + 3 * j + k);
      script += (j ? ", " : "") + gq(dat) + " " + col + " with lines lw 1.5" + (j >= 8 ? " dt 2" : "") + " title " +
                gq(s[j].name);
    }
    if (s.empty()) script += "0 title 'no bodies'";
    script += "\n";
  }
  script += "unset multiplot\n";
  std::string cmd = shellQuote(findProgram("gnuplot") + "/gnuplot") + " 2>&1";
  FILE* g = popen(cmd.c_str(), "w");
  if (!g) {
    std::remove(dat);
    *err = "cannot start gnuplot";
    return false;
  }
  std::fputs(script.c_str(), g);
  int st = pclose(g);
  std::remove(dat);
  if (st == -1 || !WIFEXITED(st) || WEXITSTATUS(st) != 0) {
    *err = "gnuplot failed writing " + png;
    return false;
  }
  return true;
}

}  // namespace mjbsim
