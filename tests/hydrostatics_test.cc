// exact hydrostatics: pressure integration through the whole MuJoCo path
// against an independent tetrahedral clipping of the same closed mesh
#include <random>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "testutil.h"
#include "tetclip.h"

namespace mjbt {
namespace {

using Eigen::Matrix3d;
using Eigen::Quaterniond;

// non-convex closed test mesh: torus, radii R and r, nu x nv quads
void torus(double R, double r, int nu, int nv, std::vector<Vector3d>* v, std::vector<int>* f) {
  for (int i = 0; i < nu; i++) {
    for (int j = 0; j < nv; j++) {
      double a = 2 * M_PI * i / nu, b = 2 * M_PI * j / nv;
      v->emplace_back((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a),
                      r * std::sin(b));
    }
  }
  for (int i = 0; i < nu; i++) {
    for (int j = 0; j < nv; j++) {
      int a = i * nv + j, b = ((i + 1) % nu) * nv + j;
      int c = ((i + 1) % nu) * nv + (j + 1) % nv, d = i * nv + (j + 1) % nv;
      f->insert(f->end(), {a, b, c, a, c, d});
    }
  }
}

std::string meshXML(const std::vector<Vector3d>& v, const std::vector<int>& f) {
  std::ostringstream s;
  s.precision(17);
  s << "<mesh name=\"torus\" vertex=\"";
  for (const Vector3d& p : v) s << p.x() << " " << p.y() << " " << p.z() << " ";
  s << "\" face=\"";
  for (int i : f) s << i << " ";
  s << "\"/>";
  return s.str();
}

TEST(Hydrostatics, TorusAtRandomPosesMatchesTetrahedralClipping) {
  std::vector<Vector3d> v;
  std::vector<int> f;
  torus(1.0, 0.3, 32, 16, &v, &f);
  // radiation off: hydrostatics only (and the torus, heavier than the water
  // it displaces, has no floating draft to solve the panels at)
  Scene s("<mujoco><asset>" + meshXML(v, f) + "</asset>"
          "<custom><text name=\"mjbuoy.hulls\" data=\"hull\"/><text name=\"mjbuoy.radiation\" data=\"off\"/>"
          "<numeric name=\"mjbuoy.sea.level\" data=\"0.2\"/></custom>"
          "<worldbody><body name=\"b\"><freejoint/>"
          "<geom name=\"hull\" type=\"mesh\" mesh=\"torus\" contype=\"0\" conaffinity=\"0\"/>"
          "</body></worldbody></mujoco>");
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_STREQ(mjb_warnings(s.b), "");
  const int g = 0, b = s.body("b");
  std::vector<int> fc = faces(s.m, g);

  // total volume from the same clipping with the plane far above
  mj_forward(s.m, s.d);
  double vtot = submerged(worldVerts(s.m, s.d, g), fc, 1e9).vol;
  ASSERT_NEAR(vtot, 2 * M_PI * M_PI * 1.0 * 0.09, 0.05 * vtot);  // faceted: ~3% less
  const double fscale = kRho * kG * vtot, tscale = fscale * 1.3;

  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> U(-1, 1);
  int partial = 0;
  for (int k = 0; k < 1000; k++) {
    Quaterniond q = Quaterniond::UnitRandom();
    double* qp = s.d->qpos;
    qp[0] = 5 * U(rng);
    qp[1] = 5 * U(rng);
    qp[2] = 0.2 + 0.6 * U(rng);
    qp[3] = q.w(); qp[4] = q.x(); qp[5] = q.y(); qp[6] = q.z();
    mj_forward(s.m, s.d);

    VolumeMoment vm = submerged(worldVerts(s.m, s.d, g), fc, 0.2);
    if (vm.vol > 0.01 * vtot && vm.vol < 0.99 * vtot) partial++;
    Vector3d F(0, 0, kRho * kG * vm.vol);
    Vector3d com(s.d->xipos + 3 * b);
    Vector3d T = vm.vol > 0 ? Vector3d((vm.centroid() - com).cross(F)) : Vector3d::Zero();
    const mjtNum* w = s.wrench(b);
    for (int j = 0; j < 3; j++) {
      ASSERT_NEAR(w[j], F[j], 1e-9 * fscale) << "pose " << k << " force " << j;
      ASSERT_NEAR(w[3 + j], T[j], 1e-9 * tscale) << "pose " << k << " torque " << j;
    }
  }
  EXPECT_GT(partial, 500);  // the poses exercise the cutting
}

TEST(Hydrostatics, TwoHullsOnOneBodyAddUp) {
  // a box primitive (tessellated by mjbuoy) and a box mesh of the same size:
  // the clipped volume of the 12-triangle box stands in for both
  const double hx = 0.6, hy = 0.3, hz = 0.2;
  std::vector<Vector3d> v;
  for (int i = 0; i < 8; i++) {
    v.emplace_back(i & 1 ? hx : -hx, i & 2 ? hy : -hy, i & 4 ? hz : -hz);
  }
  std::vector<int> f = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                        2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  std::ostringstream mesh;
  mesh << "<mesh name=\"boxmesh\" vertex=\"";
  for (const Vector3d& p : v) mesh << p.x() << " " << p.y() << " " << p.z() << " ";
  mesh << "\" face=\"";
  for (int i : f) mesh << i << " ";
  mesh << "\"/>";
  // radiation off: hydrostatics only (the panel solver would warn about
  // the two boxes' coarse, lidless panels)
  Scene s("<mujoco><asset>" + mesh.str() + "</asset>"
          "<custom><text name=\"mjbuoy.hulls\" data=\"a b\"/><text name=\"mjbuoy.radiation\" data=\"off\"/></custom>"
          "<worldbody><body name=\"b\"><freejoint/>"
          "<geom name=\"a\" type=\"box\" size=\"0.6 0.3 0.2\" pos=\"0 1 0\" euler=\"0 0 30\"/>"
          "<geom name=\"b\" type=\"mesh\" mesh=\"boxmesh\" pos=\"0 -1 0\"/>"
          "</body></worldbody></mujoco>");
  ASSERT_TRUE(s.ok()) << s.err;
  EXPECT_STREQ(mjb_warnings(s.b), "");
  EXPECT_EQ(mjb_info(s.b).nhull, 2);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 200; k++) {
    Quaterniond q(Eigen::AngleAxisd(0.4 * U(rng), Vector3d::UnitX()) *
                  Eigen::AngleAxisd(0.4 * U(rng), Vector3d::UnitY()) *
                  Eigen::AngleAxisd(3 * U(rng), Vector3d::UnitZ()));
    double* qp = s.d->qpos;
    qp[0] = U(rng); qp[1] = U(rng); qp[2] = 0.3 * U(rng);
    qp[3] = q.w(); qp[4] = q.x(); qp[5] = q.y(); qp[6] = q.z();
    mj_forward(s.m, s.d);
    Vector3d F = Vector3d::Zero(), T = Vector3d::Zero();
    Vector3d com(s.d->xipos + 3 * 1);
    for (int g = 0; g < 2; g++) {
      // the box primitive: our 12 triangles at its pose; the mesh geom:
      // MuJoCo's re-centred, re-aligned copy of the same solid
      std::vector<Vector3d> w = worldVerts(s.m, s.d, 1);
      std::vector<int> fg = faces(s.m, 1);
      if (g == 0) {
        Vector3d x(s.d->geom_xpos);
        Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> R(s.d->geom_xmat);
        w.clear();
        for (const Vector3d& p : v) w.push_back(x + R * p);
        fg = f;
      }
      VolumeMoment vm = submerged(w, fg, 0);
      Vector3d fb(0, 0, kRho * kG * vm.vol);
      F += fb;
      if (vm.vol > 0) T += (vm.centroid() - com).cross(fb);
    }
    const mjtNum* w = s.wrench(1);
    double sc = kRho * kG * 8 * hx * hy * hz;
    for (int j = 0; j < 3; j++) {
      ASSERT_NEAR(w[j], F[j], 1e-9 * sc) << "pose " << k;
      ASSERT_NEAR(w[3 + j], T[j], 1e-9 * sc) << "pose " << k;
    }
  }
}

}  // namespace
}  // namespace mjbt
