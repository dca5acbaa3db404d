// radimport: a rigid group's coefficients from a file of another tool
// (coefio.h) in place of the panel solver, ready for the time-domain
// radiation and the diffraction (docs/interchange.md, "In a model")
#ifndef MJBUOY_RADIMPORT_H_
#define MJBUOY_RADIMPORT_H_

#include <cmath>
#include <string>
#include <vector>

#include "radiation/coefio.h"
#include "radiation/hydrocoef.h"
#include "radiation/panel.h"

namespace mjb {

// what the model says about the file
struct RadImport {
  std::string path;               // the file (format by coefFormatOf)
  double origin[3] = {0, 0, 0};   // the file's origin in the body frame [m]; its axes: the body's
  double ulen = 1;                // WAMIT's ULEN [m]
  double rho = 1025, g = 9.81;    // the model's water
  double depth = 0;               // the model's water depth [m] (mjbuoy.sea.depth; 0: deep)
  double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // body to world rotation at qpos0 (row-major)
  double com[3] = {0, 0, 0};      // the body's COM in its frame [m]
  bool diffraction = true;        // cx wanted
  // the wet panels at the panel pose (panel frame: world axes, origin on
  // the mean sea level below the body's origin) and the COM there [m]: the
  // Froude-Krylov force of a file without one
  const PanelMesh* body = nullptr;
  double comPanel[3] = {0, 0, 0};
};

// c: A, B, A_inf about the COM in body axes (c->ref = com); cx (when
// diffraction): X and FK about the COM in world axes at qpos0, on
// kDiffHeadings uniform headings (setDiffraction's table), interpolated
// from the file's (periodic linear in heading; none farther than
// kImportGap from a file heading). A file of another density is scaled to
// the model's, with a warning; another g or another water depth than the
// model's is warned about (a file without a depth counts as deep water).
// "" or the error naming the file and the fix
std::string importCoef(const RadImport& in, HydroCoef* c, HydroCoef* cx,
                       std::vector<std::string>* warn);

// the widest gap between a file's wave headings that the diffraction table
// bridges by interpolation [rad] (30 deg: the linear interpolation's error
// of a force varying as cos(beta) is below 1 - cos(15 deg) = 3.4%)
const double kImportGap = M_PI / 6;

// the Froude-Krylov force of deep-water waves on the wet panels body, per
// unit amplitude, about the panel frame's origin in its axes, at c's
// frequencies and headings (mjbuoy's conventions, hydrocoef.h): the
// incident pressure p = rho g e^{k z} e^{i k (x cos b + y sin b)}, k =
// omega^2 / g, integrated at each panel's centroid, F = -sum p n dS,
// M = -sum p (r x n) dS (n out of the body; docs/physics.md section 15).
// Sets c's FKre, FKim
void froudeKrylov(const PanelMesh& body, HydroCoef* c);

// X and FK of c (about any point) on n uniform headings 2 pi h / n,
// from c's headings (any order, any range); false if two neighbouring
// headings are farther apart than kImportGap (*gap: the widest [rad])
bool resampleHeadings(HydroCoef* c, int n, double* gap);

}  // namespace mjb

#endif  // MJBUOY_RADIMPORT_H_
