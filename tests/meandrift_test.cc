// mean wave drift from the panel solution (docs/physics.md section 18):
// the near field (Pinkster 1980, direct pressure integration) against the
// far field (Maruo 1960), and a restrained deep-draft vertical cylinder
// against Havelock's (1940) analytic drift on a vertical cylinder
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "radiation/drift.h"
#include "radiation/driftstep.h"
#include "radiation/panelmesh.h"

namespace {

using mjb::DriftBody;
using mjb::DriftTable;
using mjb::HydroCoef;
using mjb::PanelMesh;

const double kPi = 3.14159265358979323846;
const double kRho = 1025, kG = 9.81;

// Havelock, T. H. (1940) "The pressure of water waves upon a fixed
// obstacle", Proc. R. Soc. Lond. A 175:409-421: a vertical circular
// cylinder of radius a through the whole (deep) water column in a wave of
// amplitude A, wave number k. Its surface elevation (MacCamy & Fuchs 1954,
// deep water) is zeta = A c(theta), c = sum eps_n i^n 2i / (pi x H_n'(x))
// cos(n theta), x = k a; on the wall phi_r = 0 and phi ~ e^{kz}, so the
// mean pressure integration gives
//   F / (rho g A^2 a) = int [-|c|^2 / 8 + |c'|^2 / (8 x^2)] cos(theta) dtheta
// (waterline term -rho g/4 |zeta|^2 plus the velocity term rho/4 |grad
// phi|^2 integrated over depth): independent of the panel solver. It tends
// to the reflection limit 2/3 for short waves (Faltinsen 1990, "Sea loads
// on ships and offshore structures", eq. 5.23: (1/2) rho g A^2 (4a/3))
double havelock(double x) {
  int N = (int)x + 30, nt = 720;
  std::vector<std::complex<double>> an(N);
  std::complex<double> in(1, 0);
  // H_n'(x) = (H_{n-1} - H_{n+1}) / 2, H_{-1} = -H_1
  auto H = [&](int m) {
    double s = m < 0 ? -1 : 1;
    m = std::abs(m);
    return s * std::complex<double>(std::cyl_bessel_j(m, x), std::cyl_neumann(m, x));
  };
  for (int n = 0; n < N; n++) {
    std::complex<double> hd = 0.5 * (H(n - 1) - H(n + 1));
    an[n] = (n ? 2.0 : 1.0) * in * std::complex<double>(0, 2) / (kPi * x * hd);
    in *= std::complex<double>(0, 1);
  }
  double f = 0;
  for (int t = 0; t < nt; t++) {
    double th = 2 * kPi * t / nt;
    std::complex<double> c = 0, cd = 0;
    for (int n = 0; n < N; n++) {
      c += an[n] * std::cos(n * th);
      cd += -an[n] * double(n) * std::sin(n * th);
    }
    f += (-std::norm(c) / 8 + std::norm(cd) / (8 * x * x)) * std::cos(th);
  }
  return f * 2 * kPi / nt;
}

TEST(MeanDrift, HavelockReference) {
  // the reference itself: short waves reach the reflection limit 2/3
  // (Faltinsen 1990 eq. 5.23); long waves pass with little drift
  EXPECT_NEAR(havelock(80), 2.0 / 3, 0.005);
  EXPECT_LT(havelock(0.25), 0.1);
}

// omegas of the wave numbers kR for radius R (deep water, omega^2 = g k)
std::vector<double> omegas(const std::vector<double>& kR, double R) {
  std::vector<double> w;
  for (double k : kR) w.push_back(std::sqrt(kG * k / R));
  return w;
}

// a restrained deep-draft cylinder (draft 5 R: e^{-kT} < 0.01 at kR >= 1,
// the wave does not reach under it) against Havelock's wall-to-bottom
// cylinder, far and near field, head and beam seas
TEST(MeanDrift, FixedCylinderHavelock) {
  const double R = 1, T = 5;
  PanelMesh body, lid;
  mjb::cylinderMesh(R, T, 40, 4, 48, &body, &lid);
  std::vector<double> kR = {1.0, 1.5, 2.0};
  HydroCoef c;
  c.rho = kRho;
  c.g = kG;
  DriftBody fixed;
  DriftTable dt;
  std::vector<double> head = {0, kPi / 2};
  ASSERT_EQ(mjb::panelSolveDrift(body, lid, omegas(kR, R), head, fixed, &c, &dt), "");
  for (size_t w = 0; w < kR.size(); w++) {
    double ref = havelock(kR[w]), s = kRho * kG * R;
    double far = dt.far[3 * (2 * w)] / s, near = dt.near[3 * (2 * w)] / s;
    double fary = dt.far[3 * (2 * w + 1) + 1] / s;
    std::printf("kR %.2f Havelock %.4f far %.4f near %.4f far(beam, y) %.4f\n", kR[w], ref, far,
                near, fary);
    EXPECT_NEAR(far, ref, 0.05 * ref);
    EXPECT_NEAR(near, ref, 0.05 * ref);
    EXPECT_NEAR(fary, ref, 0.05 * ref);
    // a fixed body's Froude-Krylov drift is zero: |eta_I| is constant on the
    // closed waterline and |grad phi_I|^2 depends on z alone, so both
    // integrate to 0 (divergence theorem; docs/physics.md section 18)
    double fk = std::hypot(dt.fk[3 * (2 * w)], dt.fk[3 * (2 * w) + 1]) / s;
    EXPECT_LT(fk, 0.01 * ref) << "kR " << kR[w];
  }
}

// rigid-body mass matrix about the origin of a body of mass m, COM (0, 0,
// zg), principal inertia I about its COM
void massMatrix(double m, double zg, const double I[3], double* M) {
  for (int i = 0; i < 36; i++) M[i] = 0;
  for (int k = 0; k < 3; k++) M[7 * k] = m;
  M[4] = M[24] = m * zg;
  M[9] = M[19] = -m * zg;
  M[21] = I[0] + m * zg * zg;
  M[28] = I[1] + m * zg * zg;
  M[35] = I[2];
}

// a freely floating hemisphere (COM at its centre of buoyancy): the near
// field (Pinkster 1980, with its motion terms) against the far field
// (Maruo 1960), both from the same first-order solution, within 5%
TEST(MeanDrift, FreeHemisphereNearFar) {
  const double R = 1;
  PanelMesh body, lid;
  mjb::hemisphereMesh(R, 16, 48, &body, &lid);
  DriftBody b;
  b.free = true;
  double m = kRho * 2 * kPi / 3, zg = -3 * R / 8, I[3] = {0.4 * m, 0.4 * m, 0.4 * m};
  massMatrix(m, zg, I, b.M);
  // hydrostatics of a hemisphere: heave rho g pi R^2; roll and pitch rho g
  // (I_wp + V (z_B - z_G)) = rho g pi R^4 / 4 with z_G = z_B
  b.C[14] = kRho * kG * kPi * R * R;
  b.C[21] = b.C[28] = kRho * kG * kPi * R * R * R * R / 4;
  std::vector<double> kR = {0.7, 0.9, 1.2, 1.6, 2.0};
  HydroCoef c;
  c.rho = kRho;
  c.g = kG;
  DriftTable dt;
  ASSERT_EQ(mjb::panelSolveDrift(body, lid, omegas(kR, R), {0.0}, b, &c, &dt), "");
  for (size_t w = 0; w < kR.size(); w++) {
    double s = kRho * kG * R, far = dt.far[3 * w] / s, near = dt.near[3 * w] / s;
    std::printf("kR %.2f far %.4f near %.4f\n", kR[w], far, near);
    EXPECT_GT(far, 0);
    EXPECT_NEAR(near, far, 0.05 * far);
  }
}

// the yaw moment: a restrained elliptic cylinder (semi-axes 2 R and R,
// draft 2 R) in waves 30 deg off its long axis feels a mean yaw moment;
// the far field (Newman 1967) and the near field (Pinkster 1980, r x the
// pressure terms) from the same solution agree within 5%
TEST(MeanDrift, FixedEllipseYawNearFar) {
  const double R = 1;
  PanelMesh body, lid;
  mjb::cylinderMesh(R, 2 * R, 20, 4, 64, &body, &lid);
  for (size_t v = 0; v < body.vert.size(); v += 3) body.vert[v] *= 2;
  for (size_t v = 0; v < lid.vert.size(); v += 3) lid.vert[v] *= 2;
  HydroCoef c;
  c.rho = kRho;
  c.g = kG;
  DriftTable dt;
  std::vector<double> kR = {0.8, 1.5};
  ASSERT_EQ(mjb::panelSolveDrift(body, lid, omegas(kR, R), {kPi / 6}, DriftBody(), &c, &dt), "");
  for (size_t w = 0; w < kR.size(); w++) {
    double s = kRho * kG * R * R;
    double far = dt.far[3 * w + 2] / s, near = dt.near[3 * w + 2] / s;
    std::printf("kR %.2f yaw far %.4f near %.4f (Fx far %.4f near %.4f)\n", kR[w], far, near,
                dt.far[3 * w] / (s / R), dt.near[3 * w] / (s / R));
    EXPECT_GT(std::fabs(far), 0.01);
    EXPECT_NEAR(near, far, 0.05 * std::fabs(far));
  }
}

// Newman's (1974) approximation: the O(N) factorised sum of the step's
// pass (diffractionWrench, with a zero diffraction table so that its
// wrench is the drift alone) against the direct double sum sum_ij A_i A_j
// (T_i + T_j) / 2 cos(theta_i - theta_j) over component pairs, and one
// component's steady mean A^2 T
TEST(MeanDrift, NewmanSumMatchesPairs) {
  mjb::Diffraction df;
  mjb::DiffBody b;
  b.body = 1;
  b.c.omega = {1, 2, 3};
  for (int h = 0; h < mjb::kDiffHeadings; h++)
    b.c.heading.push_back(2 * kPi * h / mjb::kDiffHeadings);
  std::vector<double> T;
  for (int w = 0; w < 3; w++)
    for (int h = 0; h < mjb::kDiffHeadings; h++) {
      double be = b.c.heading[h];
      T.push_back((1 + w) * 100 * std::cos(be));
      T.push_back((2 - w) * 50 * std::sin(be));
      T.push_back(30 + 10 * w * std::cos(2 * be));
    }
  b.T = std::move(T);
  b.D = std::vector<double>(12 * 3 * mjb::kDiffHeadings, 0.0);
  df.db.push_back(b);
  mjb::Sea sea;
  const double amp[3] = {0.5, 0.3, 0.2}, om[3] = {1.3, 1.5, 2.4}, dir[3] = {0, 20, -35},
               ph[3] = {0.1, 2.0, 4.0};
  for (int j = 0; j < 3; j++) {
    mjb::Wave w{};
    w.amp = amp[j], w.omega = om[j], w.k = om[j] * om[j] / kG, w.dir = dir[j], w.ph = ph[j];
    w.dx = std::cos(dir[j] * kPi / 180), w.dy = std::sin(dir[j] * kPi / 180), w.kind = 1;
    sea.waves.push_back(w);
  }
  mjb::diffSea(sea, &df);
  const mjb::DiffBody& d = df.db[0];
  const double x[3] = {0.7, -0.4, 0}, psi = 0.2;
  for (double t : {0.0, 3.1, 17.9}) {
    double F[6] = {0, 0, 0, 0, 0, 0}, want[3] = {0, 0, 0}, Ti[3][3], th[3];
    mjb::diffractionWrench(d, sea, x, psi, t, F);
    for (int i = 0; i < 3; i++) {
      const mjb::Wave& w = sea.waves[i];
      mjb::driftAt(d, d.iw[i], d.tw[i], w.dir * kPi / 180 - psi, Ti[i]);
      th[i] = w.k * (w.dx * x[0] + w.dy * x[1]) + w.ph - w.omega * t;
    }
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
          want[k] += amp[i] * amp[j] * 0.5 * (Ti[i][k] + Ti[j][k]) * std::cos(th[i] - th[j]);
    EXPECT_NEAR(F[0], want[0], 1e-9 * std::fabs(want[0]) + 1e-12);
    EXPECT_NEAR(F[1], want[1], 1e-9 * std::fabs(want[1]) + 1e-12);
    EXPECT_NEAR(F[5], want[2], 1e-9 * std::fabs(want[2]) + 1e-12);
  }
  // one component: the steady mean drift, A^2 T, at any time
  sea.waves.resize(1);
  double T0[3], F1[6] = {0, 0, 0, 0, 0, 0}, F2[6] = {0, 0, 0, 0, 0, 0};
  mjb::driftAt(d, d.iw[0], d.tw[0], -psi, T0);
  mjb::diffractionWrench(d, sea, x, psi, 0.0, F1);
  mjb::diffractionWrench(d, sea, x, psi, 5.3, F2);
  EXPECT_NEAR(F1[0], amp[0] * amp[0] * T0[0], 1e-9 * std::fabs(T0[0]));
  EXPECT_NEAR(F2[0], F1[0], 1e-9 * std::fabs(T0[0]));
  // the heading interpolation: T at beta = 0 of row 0 is its table entry
  double Tr[3];
  mjb::driftAt(d, 0, 0, 0, Tr);
  EXPECT_NEAR(Tr[0], 100, 1e-9);
}

}  // namespace
