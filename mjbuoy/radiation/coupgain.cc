// coupgain: the explicit coupling's gain (coupgain.h)
#include "radiation/coupgain.h"

#include <cmath>

#include <Eigen/Dense>

namespace mjb {

double couplingGain(int n, const std::vector<double>& D, const std::vector<double>& O) {
  const int nm = 6 * n;
  if (n < 1 || D.size() < size_t(36 * n) || O.size() < size_t(36 * n * n)) return -1;
  Eigen::MatrixXd Dm = Eigen::MatrixXd::Zero(nm, nm), Om = Eigen::MatrixXd::Zero(nm, nm);
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++)
      for (int a = 0; a < 6; a++)
        for (int b = 0; b < 6; b++) {
          if (i == j) {
            Dm(6 * i + a, 6 * j + b) = D[36 * i + 6 * a + b];
          } else {
            Om(6 * i + a, 6 * j + b) = O[36 * (n * i + j) + 6 * a + b];
          }
        }
  if (!Dm.allFinite() || !Om.allFinite()) return -1;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(Dm);
  if (!lu.isInvertible()) return -1;
  // the step-to-step map of the acceleration error, -D^-1 O
  const Eigen::MatrixXd G = lu.solve(Om);
  Eigen::EigenSolver<Eigen::MatrixXd> es(G, false);
  if (es.info() != Eigen::Success) return -1;
  double rho = 0;
  for (int k = 0; k < nm; k++) rho = std::fmax(rho, std::abs(es.eigenvalues()[k]));
  return std::isfinite(rho) ? rho : -1;
}

}  // namespace mjb
