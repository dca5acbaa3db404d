// diffraction excitation (docs/physics.md section 15): per wave component
// of the sea, the part D = X - FK of the panel solver's exciting force that
// the per-triangle pressure (hydrostatic plus Froude-Krylov) leaves out
#ifndef MJBUOY_DIFFRACT_H_
#define MJBUOY_DIFFRACT_H_

#include <memory>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "radiation/hydrocoef.h"
#include "sea/sea.h"

namespace mjb {

// headings solved at attach: uniform 2 pi h / n, h = 0..n-1 (10 deg apart)
const int kDiffHeadings = 36;

// a read-only table of doubles, one copy held by every body whose table is
// bitwise the same (identical hulls: one copy in the cache while stepping)
class SharedTable {
 public:
  SharedTable& operator=(std::vector<double> v) {
    if (v.empty()) p_.reset();
    else p_ = std::make_shared<const std::vector<double>>(std::move(v));
    d_ = p_ ? p_->data() : nullptr;
    return *this;
  }
  // hold o's table if it is bitwise v (same results); whether it is
  bool share(const SharedTable& o, const std::vector<double>& v);
  operator const std::vector<double>&() const { return p_ ? *p_ : none(); }
  const double* data() const { return d_; }
  size_t size() const { return p_ ? p_->size() : 0; }
  bool empty() const { return d_ == nullptr; }
  double operator[](size_t i) const { return d_[i]; }

 private:
  static const std::vector<double>& none();
  std::shared_ptr<const std::vector<double>> p_;
  const double* d_ = nullptr;  // p_'s data, one load while stepping
};

// one rigid group's table, about its COM
struct DiffBody {
  int body;                // MuJoCo body id (the group's top body)
  double R0[9];            // its rotation at qpos0 (table from body, row-major)
  double yaw0 = 0;         // the table's axes: the world's turned by yaw0 [rad] about z
  HydroCoef c;             // X and FK about the COM in the table's axes
  SharedTable D;           // X - FK, (re, im) per (omega, heading, dof): 2 ((w nh + h) 6 + dof)
  std::vector<int> iw;     // per sea component: table row at or below its omega;
                           //   -1 below the first (D linear from 0), -2 above the last (none)
  std::vector<double> tw;  // weight of the next row
  int ri = -1;             // its body's index in Radiation::rb (immersion factor)
  SharedTable T;           // mean drift (driftstep.h): Fx, Fy, Mz per (omega, heading); empty: off
  std::vector<double> Tfar;  // the total (far-field) drift, same layout; T = Tfar - the step's own
};

struct Diffraction {
  std::vector<DiffBody> db;
};

// add body's table from c (about its COM, world axes at qpos0, headings
// uniform as kDiffHeadings), R0 its rotation at qpos0; per-component
// arrays reserved for wcap components. "" or the error
std::string setDiffraction(int body, const double R0[9], const HydroCoef& c, size_t wcap,
                           Diffraction* df);

// each component's table row and weight for every body (when the sea is
// set: at attach and by mjb_setSea); allocates nothing while
// sea.waves.size() stays within the wcap given to setDiffraction
void diffSea(const Sea& sea, Diffraction* df);

// frequency row and weight of omega [rad/s] in a table of frequencies
void diffRow(const std::vector<double>& omega, double omega1, int* iw, double* tw);

// periodic Catmull-Rom weights of heading beta [rad] on n uniform headings
void headingWeights(double beta, int n, int idx[4], double w[4]);

// the table weights at row (iw, tw) (diffRow) and heading beta [rad]: up to
// 8 entries, each a (row, heading) offset row nh + h and its weight, the 4
// headings of each row of non-zero weight; below the table only row 0,
// weighted tw (linear from 0 at omega = 0); none above it (iw -2)
struct TableWeights {
  int n = 0;     // entries
  int off[8];    // row nh + heading index
  double f[8];   // row weight times heading weight
};
void tableWeights(int nh, int iw, double tw, double beta, TableWeights* out);

// D of b at row (iw, tw) and heading beta [rad] (table axes): re, im per dof
void diffAt(const DiffBody& b, int iw, double tw, double beta, double re[6], double im[6]);

// the wrench of body b at its COM x [m] (world) and time t [s], in the
// table's axes turned by psi [rad]: F (N, N m) set to the diffraction force
// plus the mean and slowly varying drift (driftstep.h), in one pass over
// the components sharing each one's table weights and phase
void diffractionWrench(const DiffBody& b, const Sea& sea, const double x[3], double psi,
                       double t, double F[6]);

// in mjcb_passive: each body's diffraction wrench [N, N m] in world axes,
// about its COM (d->xipos), 6 per body in w: sum over components of
// Re(a_j D(omega_j, beta_j - psi) e^{-i omega_j t}) turned by the body's
// rotation since qpos0 (psi its yaw). A non-finite wrench is left out (zero) and named
// once in notices (told: per body)
void diffractionStep(const Diffraction& df, const Sea& sea, const mjModel* m, const mjData* d,
                     double* w, char* told, std::string* notices);

}  // namespace mjb

#endif  // MJBUOY_DIFFRACT_H_
