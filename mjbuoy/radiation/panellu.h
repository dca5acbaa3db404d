// panellu: the panel solver's dense complex LU and products through
// OpenBLAS (Debian's libopenblas0, kernels chosen for the CPU at load
// time; docs/physics.md section 13, "Progress and cost estimate")
#ifndef MJBUOY_PANELLU_H_
#define MJBUOY_PANELLU_H_

#include <complex>

#include <Eigen/Dense>

namespace mjb {

// solves A X = B in place (A: its LU factors, B: X) by LU with partial
// pivoting (LAPACK zgetrf, zgetrs); false for an exactly singular A, whose
// B is then set to NaN so that the coefficients report it
bool panelLuSolve(Eigen::MatrixXcd* A, Eigen::MatrixXcd* B);
// the same for a real A and B (dgetrf, dgetrs)
bool panelLuSolve(Eigen::MatrixXd* A, Eigen::MatrixXd* B);

// C = A B (BLAS zgemm); A: a matrix or a block of one's rows; C is resized
void panelProduct(const Eigen::Ref<const Eigen::MatrixXcd>& A, const Eigen::MatrixXcd& B,
                  Eigen::MatrixXcd* C);

// OpenBLAS on one thread while alive (the frequencies are the solver's
// parallelism, and one thread makes every frequency's result independent
// of the others'); the previous thread count is restored
class PanelBlasSerial {
 public:
  PanelBlasSerial();
  ~PanelBlasSerial();
  PanelBlasSerial(const PanelBlasSerial&) = delete;
  PanelBlasSerial& operator=(const PanelBlasSerial&) = delete;

 private:
  int prev_;
};

}  // namespace mjb

#endif  // MJBUOY_PANELLU_H_
