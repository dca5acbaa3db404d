// hydroplot: A, B and K(t) through gnuplot (hydroplot.h)
#include "hydroplot.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "outfile.h"

namespace mjbhydro {

// gnuplot string literal (single quotes, doubled inside)
static std::string gq(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

// the tables as gnuplot data: index 0 omega A_11..A_66 B_11..B_66, index 1
// t K_11..K_66; false on a write error
static bool writeData(FILE* f, const mjb::HydroCoef& c, const std::vector<std::vector<double>>& K,
                      double dt) {
  for (int w = 0; w < c.nw(); w++) {
    std::fprintf(f, "%.9g", c.omega[w]);
    for (int i = 0; i < 6; i++) std::fprintf(f, " %.9g", c.A[36 * w + 7 * i]);
    for (int i = 0; i < 6; i++) std::fprintf(f, " %.9g", c.B[36 * w + 7 * i]);
    std::fprintf(f, "\n");
  }
  std::fprintf(f, "\n\n");
  size_t n = K.empty() ? 0 : K[0].size();
  for (size_t k = 0; k < n; k++) {
    std::fprintf(f, "%.9g", k * dt);
    for (int i = 0; i < 6; i++) std::fprintf(f, " %.9g", K[i][k]);
    std::fprintf(f, "\n");
  }
  return std::fflush(f) == 0 && !std::ferror(f);
}

// the gnuplot script drawing dat into out
static std::string script(const std::string& out, const std::string& dat,
                          const std::string& title) {
  static const char* kDof[6] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};
  std::string s = "set terminal pngcairo size 1200,1200 font 'sans,10' noenhanced\n";
  s += "set output " + gq(out) + "\nset multiplot layout 3,1 title " + gq(title) + "\n";
  s += "set grid\nset key outside right top\nset lmargin 14\nset rmargin 16\n";
  const char* yl[3] = {"added mass A_ii [kg, kg m^2]", "damping B_ii [kg/s, kg m^2/s]",
                       "retardation K_ii [N/m/s, N m/s]"};
  const char* xl[3] = {"omega [rad/s]", "omega [rad/s]", "t [s]"};
  for (int p = 0; p < 3; p++) {
    s += std::string("set xlabel ") + gq(xl[p]) + "\nset ylabel " + gq(yl[p]) + "\nplot ";
    for (int i = 0; i < 6; i++) {
      int col = p == 2 ? 2 + i : 2 + 6 * p + i;
      char u[64];
      std::snprintf(u, sizeof u, " index %d using 1:%d", p == 2 ? 1 : 0, col);
      s += (i ? ", " : "") + gq(dat) + u + " with linespoints lw 1.5 pt 7 ps 0.5 title " +
           gq(kDof[i]);
    }
    s += "\n";
  }
  return s + "unset multiplot\nset output\n";
}

bool plotCoef(const std::string& png, const std::string& title, const mjb::HydroCoef& c,
              const std::vector<std::vector<double>>& K, double dt, std::string* err) {
  const char* td = std::getenv("TMPDIR");
  std::string dat = std::string(td && *td ? td : "/tmp") + "/mjbuoy-hydroplot-XXXXXX";
  std::vector<char> buf(dat.begin(), dat.end());
  buf.push_back(0);
  int fd = mkstemp(buf.data());
  FILE* f = fd < 0 ? nullptr : fdopen(fd, "w");
  if (!f) {
    if (fd >= 0) ::close(fd), std::remove(buf.data());
    *err = std::string("cannot create a temporary file for the plot data: ") + std::strerror(errno);
    return false;
  }
  dat = buf.data();
  bool ok = writeData(f, c, K, dt);
  ok = std::fclose(f) == 0 && ok;
  mjbtool::OutFile out;
  if (!ok || !out.open(png, "--plot", err)) {
    std::remove(dat.c_str());
    if (!ok) *err = "cannot write the plot data to " + dat;
    return false;
  }
  FILE* g = popen("gnuplot >/dev/null 2>&1", "w");
  int st = -1;
  if (g) {
    std::fputs(script(out.tmpPath(), dat, title).c_str(), g);
    st = pclose(g);
  }
  std::remove(dat.c_str());
  if (st == -1 || !WIFEXITED(st) || WEXITSTATUS(st) != 0) {
    *err = (g && WIFEXITED(st) && WEXITSTATUS(st) == 127)
               ? "--plot needs the gnuplot program, which is not on PATH; install the Debian "
                 "package gnuplot-nox (apt-get install gnuplot-nox)"
               : "gnuplot failed writing " + png;
    return false;
  }
  return out.commit(err);
}

}  // namespace mjbhydro
