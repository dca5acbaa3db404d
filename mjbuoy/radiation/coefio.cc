// coefio: format dispatch, checks and atomic files (coefio.h)
#include "radiation/coefio.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "util/fmt.h"

namespace mjb {

static bool endsWith(const std::string& s, const char* e) {
  size_t n = std::strlen(e);
  return s.size() >= n && !s.compare(s.size() - n, n, e);
}

CoefFormat coefFormatOf(const std::string& path) {
  for (const char* e : {".1", ".3", ".3fk", ".hst", "."})
    if (endsWith(path, e) && path.size() > std::strlen(e)) return kCoefWamit;
  if (endsWith(path, ".nc")) return kCoefCapytaine;
  if (endsWith(path, ".h5") || endsWith(path, ".hdf5")) return kCoefBemio;
  return kCoefNone;
}

// the WAMIT stem of path: "dir/spar." for dir/spar.1, .3, .3fk, .hst or dir/spar.
static std::string wamitStem(const std::string& path) {
  for (const char* e : {".3fk", ".hst", ".1", ".3"})
    if (endsWith(path, e)) return path.substr(0, path.size() - std::strlen(e) + 1);
  return path;
}

static const char* kFormats = "WAMIT (.1, .3, .3fk, .hst), Capytaine NetCDF (.nc) or BEMIO "
                              "HDF5 (.h5, .hdf5)";

std::string readCoefFile(const std::string& path, const CoefOpt& o, CoefFile* f) {
  *f = CoefFile();
  f->c.rho = o.rho;
  f->c.g = o.g;
  std::string e;
  switch (coefFormatOf(path)) {
    case kCoefWamit:
      if (!(o.ulen > 0) || !std::isfinite(o.ulen))
        return "WAMIT length scale ULEN = " + fmt(o.ulen) + " m must be > 0";
      e = readWamit(wamitStem(path), o, f);
      break;
    case kCoefCapytaine: e = readCapytaine(path, f); break;
    case kCoefBemio: e = readBemio(path, o, f); break;
    default:
      return "coefficient file " + path + ": unknown format; give a file of " + kFormats;
  }
  if (e.empty()) e = checkCoefFile(*f, "coefficient file " + path);
  return e;
}

std::string writeCoefFile(const std::string& path, const CoefOpt& o, const CoefFile& f) {
  std::string e = checkCoefFile(f, "coefficients to write to " + path);
  if (!e.empty()) return e;
  switch (coefFormatOf(path)) {
    case kCoefWamit:
      if (!(o.ulen > 0) || !std::isfinite(o.ulen))
        return "WAMIT length scale ULEN = " + fmt(o.ulen) + " m must be > 0";
      return writeWamit(wamitStem(path), o, f);
    case kCoefCapytaine: return writeCapytaine(path, f);
    case kCoefBemio: return writeBemio(path, f);
    default:
      return "coefficient file " + path + ": unknown format; name a file of " + kFormats;
  }
}

static bool finite(const double* x, size_t n) {
  for (size_t i = 0; i < n; i++)
    if (!std::isfinite(x[i])) return false;
  return true;
}

std::string checkCoefFile(const CoefFile& f, const std::string& who) {
  const HydroCoef& c = f.c;
  size_t nw = c.omega.size(), nx = 6 * nw * c.heading.size();
  if (!nw) return who + ": no frequency above 0 and below infinity";
  if (!(c.rho > 0) || !(c.g > 0) || !std::isfinite(c.rho) || !std::isfinite(c.g))
    return who + ": rho = " + fmt(c.rho) + " kg/m^3 and g = " + fmt(c.g) +
           " m/s^2 must be finite and > 0";
  for (size_t i = 0; i < nw; i++)
    if (!(c.omega[i] > 0) || !std::isfinite(c.omega[i]) || (i && !(c.omega[i] > c.omega[i - 1])))
      return who + ": frequency " + std::to_string(i + 1) + " = " + fmt(c.omega[i]) +
             " rad/s; the frequencies must be finite, > 0 and distinct";
  if (c.A.size() != 36 * nw || c.B.size() != 36 * nw)
    return who + ": added mass and damping must hold 36 values per frequency";
  if (f.hasX && (c.Xre.size() != nx || c.Xim.size() != nx || c.FKre.size() != nx ||
                 c.FKim.size() != nx))
    return who + ": the exciting force must hold 6 values per frequency and heading";
  if (!finite(c.A.data(), c.A.size()) || !finite(c.B.data(), c.B.size()) ||
      !finite(c.Ainf, 36) || !finite(f.C, 36))
    return who + ": an added mass, damping or stiffness is not finite";
  for (const auto* v : {&c.heading, &c.Xre, &c.Xim, &c.FKre, &c.FKim})
    if (!finite(v->data(), v->size()))
      return who + ": a wave heading or exciting force is not finite";
  return "";
}

AtomicPath::AtomicPath(const std::string& path) : path_(path) {
  size_t s = path.rfind('/');
  std::string dir = s == std::string::npos ? "" : path.substr(0, s + 1);
  std::string base = s == std::string::npos ? path : path.substr(s + 1);
  tmp_ = dir + "." + base + "." + std::to_string(::getpid()) + ".tmp";
}

AtomicPath::~AtomicPath() {
  if (!done_) ::unlink(tmp_.c_str());
}

std::string AtomicPath::commit() {
  if (::rename(tmp_.c_str(), path_.c_str()) != 0)
    return "cannot write " + path_ + ": " + std::strerror(errno);
  done_ = true;
  return "";
}

}  // namespace mjb
