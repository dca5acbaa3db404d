// plot: heave, roll and pitch against time through gnuplot (see plot.h)
#include "plot.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <cerrno>
#include <fstream>
#include <string>
#include <vector>

#include "render.h"  // findProgram, shellQuote

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

// a temporary file in $TMPDIR (path in *name), removed by its owner
static int tmpFile(const char* stem, std::string* name) {
  const char* td = std::getenv("TMPDIR");
  std::string t = std::string(td && *td ? td : "/tmp") + "/" + stem + "-XXXXXX";
  std::vector<char> buf(t.begin(), t.end());
  buf.push_back(0);
  int fd = mkstemp(buf.data());
  if (fd >= 0) *name = buf.data();
  return fd;
}

bool writePlot(const std::string& png, const std::string& name, const std::string& title,
               const std::vector<double>& t, const std::vector<PlotSeries>& s, std::string* err) {
  if (!plotAvailable(err)) return false;
  std::string dat, log;
  int fd = tmpFile("mjbuoy-plot", &dat);
  FILE* f = fd < 0 ? nullptr : fdopen(fd, "w");
  if (!f) {
    if (fd >= 0) ::close(fd), std::remove(dat.c_str());
    *err = std::string("cannot create a temporary file for the plot data: ") + std::strerror(errno);
    return false;
  }
  for (size_t i = 0; i < t.size(); i++) {
    std::fprintf(f, "%.6f", t[i]);
    for (const PlotSeries& p : s) std::fprintf(f, " %.6g %.6g %.6g", p.z[i], p.roll[i], p.pitch[i]);
    std::fprintf(f, "\n");
  }
  bool ok = std::fflush(f) == 0 && !std::ferror(f);
  ok = std::fclose(f) == 0 && ok;
  if (!ok) {
    std::remove(dat.c_str());
    *err = std::string("cannot write the plot data to ") + dat + ": " + std::strerror(errno);
    return false;
  }
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
  script += "unset multiplot\nset output\n";
  int lfd = tmpFile("mjbuoy-gnuplot", &log);
  if (lfd >= 0) ::close(lfd);
  std::string cmd = shellQuote(findProgram("gnuplot") + "/gnuplot") + " >/dev/null 2>" +
                    (lfd >= 0 ? shellQuote(log) : std::string("&1"));
  FILE* g = popen(cmd.c_str(), "w");
  if (!g) {
    std::remove(dat.c_str());
    if (lfd >= 0) std::remove(log.c_str());
    *err = "cannot start gnuplot";
    return false;
  }
  std::fputs(script.c_str(), g);
  int st = pclose(g);
  std::remove(dat.c_str());
  std::string msg;
  if (lfd >= 0) {
    std::ifstream in(log);
    std::string l;
    while (std::getline(in, l)) {
      if (!l.empty()) msg = l;  // the last line says why
    }
    std::remove(log.c_str());
  }
  if (st == -1 || !WIFEXITED(st) || WEXITSTATUS(st) != 0) {
    *err = "gnuplot failed writing " + name + (msg.empty() ? "" : ": " + msg);
    return false;
  }
  return true;
}

}  // namespace mjbsim
