// coefpsd: radiation damping made positive semi-definite (coefpsd.h)
#include "radiation/coefpsd.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

#include "util/fmt.h"

namespace mjb {

double projectDamping(HydroCoef* c, const std::string& who, std::vector<std::string>* warn) {
  typedef Eigen::Matrix<double, 6, 6, Eigen::RowMajor> Mat6;
  double big = 0;
  for (double b : c->B) big = std::max(big, std::fabs(b));
  if (!(big > 0)) return 0;
  double worst = 0, wworst = 0;
  int nneg = 0;
  for (int f = 0; f < c->nw(); f++) {
    Eigen::Map<Mat6> B(&c->B[36 * f]);
    // the radiated power nu^T B nu >= 0 for every motion (Newman 1977,
    // sec. 6.13): B is symmetric positive semi-definite
    Mat6 S = 0.5 * (B + B.transpose());
    Eigen::SelfAdjointEigenSolver<Mat6> es(S);
    Eigen::Matrix<double, 6, 1> lam = es.eigenvalues();
    // an eigenvalue above -1e-13 |B|max is zero to the solver's rounding
    // (a few eps ||S||): left alone, so that a projected B (the
    // reconstruction's own rounding) passes unchanged a second time, as
    // when mjbuoy's coefficients are written to a file and read back
    if (lam.minCoeff() >= -1e-13 * big) {
      B = S;
      continue;
    }
    Mat6 V = es.eigenvectors();
    Mat6 neg = V * lam.cwiseMin(0.0).asDiagonal() * V.transpose();
    Mat6 P = V * lam.cwiseMax(0.0).asDiagonal() * V.transpose();
    B = 0.5 * (P + P.transpose());
    const double r = neg.cwiseAbs().maxCoeff() / big;
    if (r > 1e-6) nneg++;
    if (r > worst) worst = r, wworst = c->omega[f];
  }
  if (worst > kPsdWarn && warn) {
    char pct[32];
    std::snprintf(pct, sizeof(pct), "%.3g", 100 * worst);
    std::string w = who + ": the panel solver's damping B is not positive semi-definite at " +
                    std::to_string(nneg) + " frequencies (worst at omega " + fmt(wworst) +
                    " rad/s: a part " + std::string(pct) + "% of the largest |B| would feed " +
                    "energy into the body); its negative eigenvalues are set to 0";
    if (worst > kPsdCoarse) {
      w += ". The panel mesh is too coarse: raise mjbuoy.radiation.refine (each step splits "
           "every triangle in 4) or give the hull a finer mesh";
    }
    warn->push_back(w);
  }
  return worst;
}

}  // namespace mjb
