// coefio: hydrodynamic coefficients read from and written to the files of
// other tools: WAMIT's .1, .3, .3fk, .hst text files, Capytaine's NetCDF and
// WEC-Sim's BEMIO HDF5 (docs/interchange.md: axes, phase, units of each)
#ifndef MJBUOY_COEFIO_H_
#define MJBUOY_COEFIO_H_

#include <string>

#include "radiation/hydrocoef.h"

namespace mjb {

// one body's coefficients as a file holds them, in mjbuoy's conventions
// (hydrocoef.h: SI units, e^{-i omega t}, force i per motion j), about the
// file's origin (c.ref = 0) in the file's axes
struct CoefFile {
  HydroCoef c;
  bool hasAinf = false;  // c.Ainf was in the file (else 0)
  bool hasX = false;     // c.Xre, c.Xim were (else empty)
  bool hasFK = false;    // c.FKre, c.FKim were (else zeros beside X)
  bool hasC = false;     // C was
  double C[36] = {0};    // hydrostatic restoring stiffness about the origin, row-major
                         //   [N/m, N/rad, N m/m, N m/rad]
  double vol = 0;        // displaced volume [m^3] (0: unknown; written by BEMIO only)
  double cg[3] = {0, 0, 0};  // centre of gravity in the file's frame [m] (BEMIO only)
};

enum CoefFormat { kCoefNone = 0, kCoefWamit, kCoefCapytaine, kCoefBemio };

// the format of a file by its name: .1 .3 .3fk .hst (or a stem ending in
// "."): WAMIT; .nc: Capytaine; .h5 .hdf5: BEMIO; else kCoefNone
CoefFormat coefFormatOf(const std::string& path);

// what a file's numbers need besides themselves
struct CoefOpt {
  double rho = 1025;  // water density [kg/m^3]: WAMIT's files are per rho
  double g = 9.81;    // gravity [m/s^2]: WAMIT's files are per g
  double ulen = 1;    // WAMIT's length scale ULEN [m]
  int body = 1;       // BEMIO: the body group (body<n>), 1-based
};

// read path (its format by coefFormatOf) into *f; "" or the error naming
// the file (and line or variable) and how to fix it. The result is checked
// (checkCoefFile)
std::string readCoefFile(const std::string& path, const CoefOpt& o, CoefFile* f);

// write f to path in its format; WAMIT writes stem.1, stem.3, stem.3fk and
// (hasC) stem.hst for path stem.<any of them>. Each file is written to a
// temporary beside it and renamed into place when complete. "" or the error
std::string writeCoefFile(const std::string& path, const CoefOpt& o, const CoefFile& f);

// sizes, finite values, increasing positive frequencies, rho and g > 0;
// "" or what is wrong, naming who
std::string checkCoefFile(const CoefFile& f, const std::string& who);

// the formats (coefio_wamit.cc, coefio_hdf5.cc, coefio_netcdf.cc)
std::string readWamit(const std::string& stem, const CoefOpt& o, CoefFile* f);
std::string writeWamit(const std::string& stem, const CoefOpt& o, const CoefFile& f);
std::string readCapytaine(const std::string& path, CoefFile* f);
std::string writeCapytaine(const std::string& path, const CoefFile& f);
std::string readBemio(const std::string& path, const CoefOpt& o, CoefFile* f);
std::string writeBemio(const std::string& path, const CoefFile& f);

// a file written atomically: a temporary beside path, renamed onto it by
// commit; the temporary is removed if commit is not reached. tmp() is
// the temporary's name (for libraries that open files themselves)
class AtomicPath {
 public:
  explicit AtomicPath(const std::string& path);
  ~AtomicPath();
  const std::string& tmp() const { return tmp_; }
  std::string commit();  // "" or the error
 private:
  std::string path_, tmp_;
  bool done_ = false;
};

}  // namespace mjb

#endif  // MJBUOY_COEFIO_H_
