// coefio_wamit: WAMIT's numeric output files (coefio.h; docs/interchange.md).
// WAMIT (Lee and Newman, WAMIT User Manual v7, chapter 4) writes
//   .1   PER I J Abar_ij Bbar_ij   (PER = 0: infinite frequency, PER = -1:
//        zero frequency, both without Bbar)
//   .3   PER BETA I |Xbar_i| arg(Xbar_i)[deg] Re(Xbar_i) Im(Xbar_i)   (also .3fk)
//   .hst I J Cbar_ij
// with PER the period [s], BETA the heading [deg], and the nondimensional
//   Abar = A / (rho L^k), Bbar = B / (rho L^k omega), Xbar = X / (rho g L^m),
//   Cbar = C / (rho g L^n), k = 3 + [i > 3] + [j > 3], m = 2 + [i > 3],
//   n = 2 + [i > 3] + [j > 3] (modes 1..6; L = ULEN)
// for time dependence Re(X e^{+i omega t}): mjbuoy's X (e^{-i omega t}) is
// its complex conjugate
#include <cerrno>
#include <cstdarg>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <vector>

#include "radiation/coefio.h"
#include "util/fmt.h"

namespace mjb {

// L^p of the modes (1-based i, j; j = 0: a force)
static double lpow(double L, int i, int j) {
  int p = (j ? 3 + (i > 3) + (j > 3) : 2 + (i > 3));
  return std::pow(L, p);
}

// the numeric lines of a text file; false if it cannot be opened. Each
// line's numbers go into rows[k], its line number into at[k]; a token that
// is not a number makes *bad its line
static bool numLines(const std::string& path, std::vector<std::vector<double>>* rows,
                     std::vector<int>* at, int* bad) {
  FILE* f = std::fopen(path.c_str(), "r");
  if (!f) return false;
  char buf[4096];
  int ln = 0;
  *bad = 0;
  while (std::fgets(buf, sizeof buf, f)) {
    ln++;
    std::vector<double> r;
    char* p = buf;
    for (;;) {
      while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') p++;
      if (!*p) break;
      char* q;
      errno = 0;
      double v = std::strtod(p, &q);
      if (q == p || errno == ERANGE) {
        if (!*bad) *bad = ln;
        break;
      }
      r.push_back(v);
      p = q;
    }
    if (!r.empty()) rows->push_back(r), at->push_back(ln);
  }
  bool ok = !std::ferror(f);
  std::fclose(f);
  return ok;
}

static std::string where(const std::string& path, int line) {
  return "WAMIT file " + path + " line " + std::to_string(line);
}

// a mode index 1..6 of one body
static bool mode(double v) { return v >= 1 && v <= 6 && v == std::floor(v); }

// .1 into f: frequencies, A, B, A_inf
static std::string read1(const std::string& path, const CoefOpt& o, CoefFile* f) {
  std::vector<std::vector<double>> rows;
  std::vector<int> at;
  int bad;
  if (!numLines(path, &rows, &at, &bad))
    return "WAMIT file " + path + " cannot be read: " + std::strerror(errno);
  if (bad) return where(path, bad) + ": not a number; a .1 line is PER I J A [B]";
  std::map<double, std::vector<double>> ab;  // omega -> 72 (A, B)
  for (size_t r = 0; r < rows.size(); r++) {
    const std::vector<double>& x = rows[r];
    if (x.size() < 4 || x.size() > 5)
      return where(path, at[r]) + ": " + std::to_string(x.size()) + " numbers; a .1 line is "
             "PER I J A [B]";
    if (!mode(x[1]) || !mode(x[2]))
      return where(path, at[r]) + ": mode " + fmt(x[1]) + ", " + fmt(x[2]) + "; mjbuoy reads "
             "one body's modes 1 to 6 (a file of several bodies or generalized modes: split it)";
    int i = (int)x[1], j = (int)x[2];
    double per = x[0], L = lpow(o.ulen, i, j);
    if (per == 0) {
      f->c.Ainf[6 * (i - 1) + j - 1] = x[3] * o.rho * L;
      f->hasAinf = true;
      continue;
    }
    if (per < 0) continue;  // zero frequency: not used
    if (x.size() != 5) return where(path, at[r]) + ": no damping column at period " + fmt(per);
    double w = 2 * M_PI / per;
    std::vector<double>& v = ab[w];
    v.resize(72);
    v[6 * (i - 1) + j - 1] = x[3] * o.rho * L;
    v[36 + 6 * (i - 1) + j - 1] = x[4] * o.rho * L * w;
  }
  for (auto& p : ab) {
    f->c.omega.push_back(p.first);
    f->c.A.insert(f->c.A.end(), p.second.begin(), p.second.begin() + 36);
    f->c.B.insert(f->c.B.end(), p.second.begin() + 36, p.second.end());
  }
  if (f->c.omega.empty()) return "WAMIT file " + path + " holds no finite period above 0";
  return "";
}

// .3 or .3fk into re, im (and the headings when empty); false: no file
static std::string read3(const std::string& path, const CoefOpt& o, CoefFile* f,
                         std::vector<double>* re, std::vector<double>* im, bool* found) {
  std::vector<std::vector<double>> rows;
  std::vector<int> at;
  int bad;
  *found = numLines(path, &rows, &at, &bad);
  if (!*found) return "";
  if (bad) return where(path, bad) + ": not a number; a .3 line is PER BETA I |X| arg(X) Re Im";
  HydroCoef& c = f->c;
  std::map<double, int> head;  // heading [rad] -> index
  for (size_t r = 0; r < rows.size(); r++) {
    if (rows[r].size() != 7)
      return where(path, at[r]) + ": " + std::to_string(rows[r].size()) + " numbers; a .3 "
             "line is PER BETA I |X| arg(X) Re(X) Im(X)";
    head[rows[r][1] * M_PI / 180];
  }
  if (c.heading.empty()) {
    for (auto& h : head) c.heading.push_back(h.first);
  } else if (head.size() != c.heading.size()) {
    return "WAMIT file " + path + " has other wave headings than its .3 file";
  }
  int nh = 0;
  for (auto& h : head) h.second = nh++;
  re->assign(6 * c.omega.size() * nh, 0);
  im->assign(re->size(), 0);
  std::vector<char> seen(c.omega.size() * nh, 0);
  for (size_t r = 0; r < rows.size(); r++) {
    const std::vector<double>& x = rows[r];
    if (!(x[0] > 0)) continue;  // zero or infinite frequency: no exciting force
    if (!mode(x[2]))
      return where(path, at[r]) + ": mode " + fmt(x[2]) + "; mjbuoy reads one body's modes 1 to 6";
    double w = 2 * M_PI / x[0];
    size_t iw = 0;
    while (iw < c.omega.size() && c.omega[iw] != w) iw++;
    if (iw == c.omega.size())
      return where(path, at[r]) + ": period " + fmt(x[0]) + " s is not in the .1 file";
    int ih = head[x[1] * M_PI / 180], i = (int)x[2];
    double s = o.rho * o.g * lpow(o.ulen, i, 0);
    size_t k = 6 * (iw * nh + ih) + i - 1;
    (*re)[k] = x[5] * s;
    (*im)[k] = -x[6] * s;  // e^{+i omega t} to e^{-i omega t}: conjugate
    seen[iw * nh + ih] = 1;
  }
  for (size_t k = 0; k < seen.size(); k++)
    if (!seen[k])
      return "WAMIT file " + path + " has no exciting force at omega " +
             fmt(c.omega[k / nh]) + " rad/s, heading " + fmt(c.heading[k % nh] * 180 / M_PI) +
             " deg; every period of the .1 file needs every heading";
  return "";
}

// .hst into f->C
static std::string readHst(const std::string& path, const CoefOpt& o, CoefFile* f) {
  std::vector<std::vector<double>> rows;
  std::vector<int> at;
  int bad;
  if (!numLines(path, &rows, &at, &bad)) return "";
  if (bad) return where(path, bad) + ": not a number; a .hst line is I J C";
  for (size_t r = 0; r < rows.size(); r++) {
    const std::vector<double>& x = rows[r];
    if (x.size() != 3 || !mode(x[0]) || !mode(x[1]))
      return where(path, at[r]) + ": a .hst line is I J C with modes 1 to 6";
    int i = (int)x[0], j = (int)x[1];
    // n = 2 + [i > 3] + [j > 3] = k - 1
    f->C[6 * (i - 1) + j - 1] = x[2] * o.rho * o.g * lpow(o.ulen, i, j) / o.ulen;
  }
  f->hasC = true;
  return "";
}

std::string readWamit(const std::string& stem, const CoefOpt& o, CoefFile* f) {
  std::string e = read1(stem + "1", o, f);
  bool found = false, fk = false;
  if (e.empty()) e = read3(stem + "3", o, f, &f->c.Xre, &f->c.Xim, &found);
  if (e.empty() && found) e = read3(stem + "3fk", o, f, &f->c.FKre, &f->c.FKim, &fk);
  if (e.empty()) e = readHst(stem + "hst", o, f);
  f->hasX = found;
  f->hasFK = fk;
  if (found && !fk) f->c.FKre.assign(f->c.Xre.size(), 0), f->c.FKim.assign(f->c.Xre.size(), 0);
  return e;
}

// one file through its temporary
static std::string writeText(const std::string& path, const std::string& text) {
  AtomicPath ap(path);
  FILE* f = std::fopen(ap.tmp().c_str(), "w");
  if (!f) return "cannot write " + path + ": " + std::strerror(errno);
  bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  ok = (std::fclose(f) == 0) && ok;
  if (!ok) return "cannot write " + path + ": " + std::strerror(errno);
  return ap.commit();
}

static void line(std::string* s, const char* fmtstr, ...) __attribute__((format(printf, 2, 3)));
static void line(std::string* s, const char* fmtstr, ...) {
  char b[256];
  va_list a;
  va_start(a, fmtstr);
  std::vsnprintf(b, sizeof b, fmtstr, a);
  va_end(a);
  *s += b;
}

// the .3 text of re, im
static std::string text3(const CoefOpt& o, const HydroCoef& c, const std::vector<double>& re,
                         const std::vector<double>& im) {
  std::string s;
  for (int w = c.nw() - 1; w >= 0; w--)
    for (int h = 0; h < c.nh(); h++)
      for (int i = 1; i <= 6; i++) {
        size_t k = 6 * ((size_t)w * c.nh() + h) + i - 1;
        double sc = o.rho * o.g * lpow(o.ulen, i, 0);
        double xr = re[k] / sc, xi = -im[k] / sc;
        line(&s, "%.17g %.17g %d %.17g %.17g %.17g %.17g\n", 2 * M_PI / c.omega[w],
             c.heading[h] * 180 / M_PI, i, std::hypot(xr, xi), std::atan2(xi, xr) * 180 / M_PI,
             xr, xi);
      }
  return s;
}

std::string writeWamit(const std::string& stem, const CoefOpt& o, const CoefFile& f) {
  const HydroCoef& c = f.c;
  std::string s;
  for (int i = 1; f.hasAinf && i <= 6; i++)
    for (int j = 1; j <= 6; j++)
      line(&s, "0 %d %d %.17g\n", i, j, c.Ainf[6 * (i - 1) + j - 1] / (o.rho * lpow(o.ulen, i, j)));
  // longest period first, as WAMIT lists increasing frequencies
  for (int w = c.nw() - 1; w >= 0; w--)
    for (int i = 1; i <= 6; i++)
      for (int j = 1; j <= 6; j++) {
        double L = o.rho * lpow(o.ulen, i, j);
        size_t k = 36 * (size_t)w + 6 * (i - 1) + j - 1;
        line(&s, "%.17g %d %d %.17g %.17g\n", 2 * M_PI / c.omega[w], i, j, c.A[k] / L,
             c.B[k] / (L * c.omega[w]));
      }
  std::string e = writeText(stem + "1", s);
  if (e.empty() && f.hasX) e = writeText(stem + "3", text3(o, c, c.Xre, c.Xim));
  if (e.empty() && f.hasX && f.hasFK) e = writeText(stem + "3fk", text3(o, c, c.FKre, c.FKim));
  if (e.empty() && f.hasC) {
    s.clear();
    for (int i = 1; i <= 6; i++)
      for (int j = 1; j <= 6; j++)
        line(&s, "%d %d %.17g\n", i, j,
             f.C[6 * (i - 1) + j - 1] * o.ulen / (o.rho * o.g * lpow(o.ulen, i, j)));
    e = writeText(stem + "hst", s);
  }
  return e;
}

}  // namespace mjb
