// vertex integration (mjbuoy.sea.integration = vertex, docs/physics.md
// "Vertex integration") against the exact closed-form series (the
// reference: the exact integral of linear theory's e^L over each piece,
// tests/waveint_test.cc), within the interpolation bound computed here from
// the mesh, the components and the pose alone
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "simdlevels.h"
#include "testutil.h"
#include "util/expkern.h"
#include "util/sincoskern.h"
#include "util/vmath.h"
#include "vertexmesh.h"

namespace mjbt {
namespace {

// the bench's short-crested JONSWAP (Hs 0.6 m, Tp 5 s, 64 components,
// spreading s = 10), or its long-crested form
std::string jonswap(bool spread) {
  return std::string("<text name=\"mjbuoy.spectrum.sea.type\" data=\"jonswap\"/>"
                     "<numeric name=\"mjbuoy.spectrum.sea.hs\" data=\"0.6\"/>"
                     "<numeric name=\"mjbuoy.spectrum.sea.tp\" data=\"5\"/>"
                     "<numeric name=\"mjbuoy.spectrum.sea.components\" data=\"64\"/>"
                     "<numeric name=\"mjbuoy.spectrum.sea.direction\" data=\"20\"/>") +
         (spread ? "<numeric name=\"mjbuoy.spectrum.sea.spreading\" data=\"10\"/>" : "");
}

// one free Wigley hull (mesh wigley_<tris>.obj, the bench's mass and
// inertia) on sea, with integration integ ("" leaves it out), radiation off
std::string wigley(int tris, const std::string& sea, const char* integ) {
  if (!*integ) return wigleyModel(tris, sea);
  return wigleyModel(tris, sea + "<text name=\"mjbuoy.sea.integration\" data=\"" + integ +
                               "\"/>");
}

struct Pose {
  const char* name;
  double z, roll, pitch;  // COM height offset [m], roll and pitch [deg]
};
// heave (deeper, higher), roll, and pitched so the surface cuts the ends
const Pose kPoses[] = {{"level", 0.03, 0, 0}, {"down", -0.05, 0, 0}, {"roll", 0.03, 12, 0},
                       {"pitch", 0.0, 0, 4}};

// the pose at time t, then mj_forward: the pressure wrench of body 1
template <class S>
void place(S& s, const Pose& p, double t, double w[6]) {
  mj_resetData(s.m, s.d);
  mjtNum qr[4], qp[4], ax[3] = {1, 0, 0}, ay[3] = {0, 1, 0};
  mju_axisAngle2Quat(qr, ax, p.roll * M_PI / 180);
  mju_axisAngle2Quat(qp, ay, p.pitch * M_PI / 180);
  s.d->qpos[2] = p.z;
  mju_mulQuat(s.d->qpos + 3, qp, qr);
  s.d->time = t;
  mj_forward(s.m, s.d);
  const mjtNum* f = mjb_wrenchPart(s.b, s.d, mjbPART_PRESSURE) + 6;
  for (int j = 0; j < 6; j++) w[j] = f[j];
}

// docs/physics.md "Vertex integration": on a triangle with corner exponents
// L_c (deep water: L = k z' + i k D.x, z' = z - eta, the height above the
// surface), the linear interpolant of e^L differs from e^L by at most
// e^(max_c Re L_c) sum_c lambda_c |L_c - Lbar|^2 / 2 at the point of
// barycentric weights lambda, whose mean over the triangle is
// sum_(c<c') |L_c - L_c'|^2 / 12; so component j's pressure-force error
// over the wet part is at most rho g a_j A e^(k_j max z') q_j / 24, q_j =
// k_j^2 sum_(c<c') |(dz', D_j.dx)|^2; force components by that sum, torque
// components by it times the largest lever arm. Every triangle with a wet
// corner counts whole (A >= its wet area). From the mesh, the waves
// (mjb_waves) and the surface (mjb_seaHeight) alone. Plus the vertex
// kernels (docs/physics.md "Vertex integration", reduced-cost phases and
// exponentials): each cos and sin within eps = kSinCosFastEps, e^(k z')
// within eps_e = kExpFastEps relative, so the surface within d_eta = eps
// sum |a_j| and the pressure at a vertex within rho g (d_eta + sum_j a_j
// e^(k_j max z') (eps + eps_e + k_j d_eta)), times A (and the lever arm)
// per triangle with a wet corner
template <class S>
void bound(const S& s, double t, double* bf, double* bm) {
  const mjModel* m = s.m;
  const mjData* d = s.d;
  std::vector<double> wv(6 * 64);
  const int nw = mjb_waves(s.b, wv.data(), 64);
  const int g = 0, mi = m->geom_dataid[g];
  const int v0 = m->mesh_vertadr[mi], nv = m->mesh_vertnum[mi];
  std::vector<double> x(3 * nv), h(nv);
  for (int i = 0; i < nv; i++) {
    const float* v = m->mesh_vert + 3 * (v0 + i);
    const double vb[3] = {v[0], v[1], v[2]};
    mju_rotVecMat(&x[3 * i], vb, d->geom_xmat + 9 * g);
    for (int j = 0; j < 3; j++) x[3 * i + j] += d->geom_xpos[3 * g + j];
    h[i] = x[3 * i + 2] - mjb_seaHeight(s.b, x[3 * i], x[3 * i + 1], t);
  }
  const double* com = d->xipos + 3;
  const double eps = mjb::kSinCosFastEps;
  double suma = 0;
  for (int w = 0; w < nw; w++) suma += std::fabs(wv[6 * w]);
  const double deta = eps * suma;
  *bf = *bm = 0;
  for (int f = 0; f < m->mesh_facenum[mi]; f++) {
    const int* fc = m->mesh_face + 3 * (m->mesh_faceadr[mi] + f);
    if (!(h[fc[0]] <= 0 || h[fc[1]] <= 0 || h[fc[2]] <= 0)) continue;
    double e1[3], e2[3], cr[3], lever = 0;
    for (int j = 0; j < 3; j++) {
      e1[j] = x[3 * fc[1] + j] - x[3 * fc[0] + j];
      e2[j] = x[3 * fc[2] + j] - x[3 * fc[0] + j];
    }
    mju_cross(cr, e1, e2);
    const double A = 0.5 * mju_norm3(cr);
    for (int c = 0; c < 3; c++) {
      double r[3];
      for (int j = 0; j < 3; j++) r[j] = x[3 * fc[c] + j] - com[j];
      lever = std::max(lever, mju_norm3(r));
    }
    const double hmax = std::max({h[fc[0]], h[fc[1]], h[fc[2]]});
    for (int w = 0; w < nw; w++) {
      const double a = wv[6 * w], k = wv[6 * w + 2], b = wv[6 * w + 3] * M_PI / 180;
      double q = 0;
      for (int c = 0; c < 3; c++) {
        for (int e = c + 1; e < 3; e++) {
          const double dz = h[fc[c]] - h[fc[e]];
          const double dx = std::cos(b) * (x[3 * fc[c]] - x[3 * fc[e]]) +
                            std::sin(b) * (x[3 * fc[c] + 1] - x[3 * fc[e] + 1]);
          q += k * k * (dz * dz + dx * dx);
        }
      }
      const double ej = kRho * kG * a * A * std::exp(k * hmax) * q / 24;
      const double ek = kRho * kG * A * (std::fabs(a) * std::exp(k * hmax) *
                                          (eps + mjb::kExpFastEps + k * deta));
      *bf += ej + ek;
      *bm += (ej + ek) * lever;
    }
    *bf += kRho * kG * deta * A;
    *bm += kRho * kG * deta * A * lever;
  }
}

// Each pose of a Wigley 576 in the 64-component short-crested JONSWAP:
// every force and torque component of vertex integration within the bound
// of the exact result, and the bound small against the pressure force; on
// every vector level this cpu has
TEST(VertexInt, WigleyWithinTheInterpolationBound) {
  Scene ex(wigley(576, jonswap(true), "exact")), vx(wigley(576, jonswap(true), "vertex"));
  ASSERT_TRUE(ex.ok()) << ex.err;
  ASSERT_TRUE(vx.ok()) << vx.err;
  const int prev = mjb::simdLevel();
  for (int level : vectorLevels("vertexint")) {
    mjb::simdSet(level);
    for (const Pose& p : kPoses) {
      for (double t : {3.1, 7.7}) {
        double we[6], wv[6], bf, bm;
        place(ex, p, t, we);
        place(vx, p, t, wv);
        bound(ex, t, &bf, &bm);
        double err[2] = {0, 0};
        for (int j = 0; j < 6; j++) {
          EXPECT_LE(std::fabs(wv[j] - we[j]), j < 3 ? bf : bm) << p.name << " t " << t << " " << j;
          err[j / 3] = std::max(err[j / 3], std::fabs(wv[j] - we[j]));
        }
        const double F = mju_norm3(we);
        EXPECT_LT(bf, 0.02 * F) << p.name;
        std::printf("%s %s t %.1f: |F| %.1f N, force err %.3g N (bound %.3g, %.2g of |F|), "
                    "torque err %.3g N m (bound %.3g)\n", mjb::simdName(level), p.name, t, F,
                    err[0], bf, bf / F, err[1], bm);
      }
    }
  }
  mjb::simdSet(prev);
}

// Second order (docs/physics.md "Vertex integration": the error is
// O((k s)^2)): the Wigley 576 refined 1, 2 and 4 times along every edge
// (the same surface); the force error summed over the poses and two times
// falls about 4x per halving (asserted: at least 3x); deep water (one
// exponent family) and 3 m (two, Wheeler's stretching)
void expectSecondOrder(const std::string& sea) {
  double err[3];
  for (int r = 0; r < 3; r++) {
    const std::string xml[2] = {onTextMesh(wigley(576, sea, "exact")), onTextMesh(wigley(576, sea, "vertex"))};
    const std::string obj = refinedWigley(r);
    MeshScene ex(xml[0], obj), vx(xml[1], obj);
    ASSERT_TRUE(ex.ok()) << ex.err;
    ASSERT_TRUE(vx.ok()) << vx.err;
    err[r] = 0;
    for (const Pose& p : kPoses) {
      for (double t : {3.1, 7.7}) {
        double we[6], wv[6];
        place(ex, p, t, we);
        place(vx, p, t, wv);
        for (int j = 0; j < 3; j++) err[r] += std::fabs(wv[j] - we[j]);
      }
    }
    std::printf("%d triangles: force error %.4g N\n", ex.m->mesh_facenum[0], err[r]);
  }
  for (int r = 0; r + 1 < 3; r++) {
    EXPECT_GT(err[r] / err[r + 1], 3) << "refinement " << r;
    std::printf("refinement %d -> %d: error ratio %.2f\n", r, r + 1, err[r] / err[r + 1]);
  }
}

TEST(VertexInt, ErrorFallsAsTheSquareOfTheEdge) { expectSecondOrder(jonswap(true)); }

TEST(VertexInt, ErrorFallsAsTheSquareOfTheEdgeAtFiniteDepth) {
  expectSecondOrder(jonswap(true) + "<numeric name=\"mjbuoy.sea.depth\" data=\"3\"/>");
}

// one long wave (100 m, k s about 0.01): vertex integration within the
// bound of exact; flat water: no dynamic pressure, the same bits
TEST(VertexInt, LongWaveWithinTheBoundFlatWaterTheSame) {
  const std::string lw = "<numeric name=\"mjbuoy.airy.long\" data=\"0.3 100 20 0\"/>";
  Scene ex(wigley(576, lw, "exact")), vx(wigley(576, lw, "vertex"));
  ASSERT_TRUE(ex.ok()) << ex.err;
  ASSERT_TRUE(vx.ok()) << vx.err;
  for (const Pose& p : kPoses) {
    double we[6], wv[6], bf, bm;
    place(ex, p, 2.3, we);
    place(vx, p, 2.3, wv);
    bound(ex, 2.3, &bf, &bm);
    for (int j = 0; j < 6; j++) EXPECT_LE(std::fabs(wv[j] - we[j]), j < 3 ? bf : bm) << p.name;
    EXPECT_LT(bf, 1e-3 * mju_norm3(we)) << p.name;
  }
  Scene fe(wigley(576, "", "exact")), fv(wigley(576, "", "vertex"));
  ASSERT_TRUE(fe.ok()) << fe.err;
  ASSERT_TRUE(fv.ok()) << fv.err;
  for (const Pose& p : kPoses) {
    double we[6], wv[6];
    place(fe, p, 1, we);
    place(fv, p, 1, wv);
    for (int j = 0; j < 6; j++) EXPECT_EQ(wv[j], we[j]) << p.name;
  }
}

// a value other than exact or vertex is refused naming the entry, the
// value and the accepted ones; the gl backend refuses vertex naming the fix
TEST(VertexInt, BadValueAndGlAreRefused) {
  Scene bad(wigley(576, jonswap(true), "fast"));
  EXPECT_FALSE(bad.ok());
  for (const char* w : {"mjbuoy.sea.integration", "\"fast\"", "\"exact\"", "\"vertex\""}) {
    EXPECT_NE(bad.err.find(w), std::string::npos) << w << " in: " << bad.err;
  }
  std::string err;
  mjModel* m = loadXML(wigley(576, jonswap(true), "vertex"), &err);
  ASSERT_TRUE(m) << err;
  char e[1024] = "";
  mjbBuoy* b = mjb_attach(m, "gl", e, sizeof e);
  EXPECT_EQ(b, nullptr);
  const std::string es = e;
  for (const char* w : {"mjbuoy.sea.integration", "vertex", "backend cpu", "exact"}) {
    EXPECT_NE(es.find(w), std::string::npos) << w << " in: " << es;
  }
  mjb_detach(b);
  mj_deleteModel(m);
}

// heave and roll RMS of a free Wigley 576 over 20 s in the JONSWAP sea
void motionRms(const char* integ, double* heave, double* roll) {
  Scene s(wigley(576, jonswap(true), integ));
  ASSERT_TRUE(s.ok()) << s.err;
  mj_resetData(s.m, s.d);
  s.d->qpos[2] = 0.03;
  const int n = int(20 / s.m->opt.timestep);
  double sz = 0, szz = 0, sr = 0;
  for (int i = 0; i < n; i++) {
    mj_step(s.m, s.d);
    const double* q = s.d->qpos + 3;
    const double z = s.d->qpos[2], r = std::atan2(2 * (q[0] * q[1] + q[2] * q[3]),
                                                  1 - 2 * (q[1] * q[1] + q[2] * q[2]));
    sz += z;
    szz += z * z;
    sr += r * r;
  }
  *heave = std::sqrt(szz / n - (sz / n) * (sz / n));
  *roll = std::sqrt(sr / n);
}

// Motion: over 20 s in the JONSWAP sea the heave and roll RMS of vertex
// integration stay within 2 % of exact's. The pressure-force error is
// below the bound, itself below 2 % of the pressure force at every pose
// (WigleyWithinTheInterpolationBound); the motion responds linearly to
// the force at these amplitudes, so its RMS moves by no more than that
TEST(VertexInt, MotionMatchesExact) {
  double he, re, hv, rv;
  motionRms("exact", &he, &re);
  motionRms("vertex", &hv, &rv);
  std::printf("heave RMS %.5f / %.5f m, roll RMS %.5f / %.5f rad (exact / vertex)\n", he, hv, re,
              rv);
  EXPECT_NEAR(hv, he, 0.02 * he);
  EXPECT_NEAR(rv, re, 0.02 * re);
}

}  // namespace
}  // namespace mjbt
