// panellu: dense complex LU and products through OpenBLAS (panellu.h)
#include "radiation/panellu.h"

#include <cstddef>
#include <vector>
#include <limits>

typedef std::complex<double> cplx;

// the Fortran ABI of BLAS and LAPACK (gfortran: a hidden length per
// character argument) and OpenBLAS's thread control
extern "C" {
void zgetrf_(const int* m, const int* n, cplx* a, const int* lda, int* ipiv, int* info);
void zgetrs_(const char* trans, const int* n, const int* nrhs, const cplx* a, const int* lda,
             const int* ipiv, cplx* b, const int* ldb, int* info, size_t ltrans);
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda,
             const int* ipiv, double* b, const int* ldb, int* info, size_t ltrans);
void zgemm_(const char* ta, const char* tb, const int* m, const int* n, const int* k,
            const cplx* alpha, const cplx* a, const int* lda, const cplx* b, const int* ldb,
            const cplx* beta, cplx* c, const int* ldc, size_t lta, size_t ltb);
int openblas_get_num_threads(void);
void openblas_set_num_threads(int n);
}

namespace mjb {

// LU with partial pivoting of A, then the solve of B, for a real or a
// complex T (getrf, getrs: the LAPACK routines of T)
template <class T, class Mat, class Getrf, class Getrs>
static bool luSolve(Mat* A, Mat* B, Getrf getrf, Getrs getrs) {
  const int n = (int)A->rows(), nrhs = (int)B->cols(), ld = n > 1 ? n : 1;
  if (!n) return true;
  std::vector<int> piv(n);
  int info = 0;
  getrf(&n, &n, A->data(), &ld, piv.data(), &info);
  if (info != 0) {
    // info > 0: U(info, info) is 0; the solve would divide by it
    B->setConstant(T(std::numeric_limits<double>::quiet_NaN()));
    return false;
  }
  if (!nrhs) return true;
  getrs("N", &n, &nrhs, A->data(), &ld, piv.data(), B->data(), &ld, &info, 1);
  return info == 0;
}

bool panelLuSolve(Eigen::MatrixXcd* A, Eigen::MatrixXcd* B) {
  return luSolve<cplx>(A, B, zgetrf_, zgetrs_);
}

bool panelLuSolve(Eigen::MatrixXd* A, Eigen::MatrixXd* B) {
  return luSolve<double>(A, B, dgetrf_, dgetrs_);
}

void panelProduct(const Eigen::Ref<const Eigen::MatrixXcd>& A, const Eigen::MatrixXcd& B,
                  Eigen::MatrixXcd* C) {
  const int m = (int)A.rows(), n = (int)B.cols(), k = (int)A.cols();
  C->resize(m, n);
  if (!m || !n) return;
  if (!k) {
    C->setZero();
    return;
  }
  const cplx one(1, 0), zero(0, 0);
  const int lda = (int)A.outerStride(), ldb = k, ldc = m;
  zgemm_("N", "N", &m, &n, &k, &one, A.data(), &lda, B.data(), &ldb, &zero, C->data(), &ldc, 1,
         1);
}

PanelBlasSerial::PanelBlasSerial() : prev_(openblas_get_num_threads()) {
  if (prev_ != 1) openblas_set_num_threads(1);
}

PanelBlasSerial::~PanelBlasSerial() {
  if (prev_ != 1) openblas_set_num_threads(prev_);
}

}  // namespace mjb
