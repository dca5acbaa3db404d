// vertex integration (mjbuoy.sea.integration = vertex, docs/physics.md
// "Vertex integration") in the two forms tests/vertexint_test.cc leaves
// out: Kerner's pressure with the pressure and suction drag and the
// slamming, which take the water velocity whose integrals the vertex sums
// replace, and seas of Gerstner (trochoidal) components, alone and with
// Airy ones. The reference is the exact path (the closed-form series of
// every component, tests/waveint_test.cc); the tolerance is the docs'
// interpolation bound, computed here from the mesh, the components and the
// pose alone, or, for the slamming, the error's second order in the edge
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "simdlevels.h"
#include "testutil.h"
#include "util/vmath.h"
#include "vertexmesh.h"

namespace mjbt {
namespace {

// the bench's short-crested JONSWAP (Hs 0.6 m, Tp 5 s, spreading s = 10)
// with n components
std::string jonswap(int n) {
  return "<text name=\"mjbuoy.spectrum.sea.type\" data=\"jonswap\"/>"
         "<numeric name=\"mjbuoy.spectrum.sea.hs\" data=\"0.6\"/>"
         "<numeric name=\"mjbuoy.spectrum.sea.tp\" data=\"5\"/>"
         "<numeric name=\"mjbuoy.spectrum.sea.components\" data=\"" + std::to_string(n) + "\"/>"
         "<numeric name=\"mjbuoy.spectrum.sea.direction\" data=\"20\"/>"
         "<numeric name=\"mjbuoy.spectrum.sea.spreading\" data=\"10\"/>";
}

// one free Wigley 576 (the bench's mass and inertia) on sea, with
// integration integ, radiation off, no start-up ramp (every amplitude
// whole, as the bounds take them), and the extra custom entries more
std::string wigley(const std::string& sea, const char* integ, const std::string& more = "") {
  return wigleyModel(576, sea + more + "<numeric name=\"mjbuoy.sea.ramp\" data=\"0\"/>" +
                              "<text name=\"mjbuoy.sea.integration\" data=\"" + integ +
                              "\"/>");
}

struct Pose {
  const char* name;
  double z, roll, pitch;  // COM height offset [m], roll and pitch [deg]
  double v[6];            // free joint velocity: world linear [m/s], local angular [rad/s]
};
// heave (deeper, higher), roll, and pitched so the surface cuts the ends;
// surging, sinking and rolling, so every face sees a flow of about 1 m/s
const Pose kPoses[] = {{"level", 0.03, 0, 0, {1.2, 0.2, -0.5, 0.6, 0.1, 0.2}},
                       {"down", -0.05, 0, 0, {-0.8, 0.4, 0.6, -0.5, 0.2, 0}},
                       {"roll", 0.03, 12, 0, {1.2, -0.4, -0.5, 1.0, 0, -0.2}},
                       {"pitch", 0.0, 0, 4, {0.6, 0.6, -0.7, 0, -0.3, 0.3}}};

// the pose and velocity at time t, then mj_forward: the body's wrench of
// force family part. With prev, first a call one step earlier at the
// position moved back by v dt, so the slamming history (docs/physics.md
// 4.4) holds that step's swept-volume rates
template <class S>
void place(S& s, const Pose& p, double t, int part, double w[6], bool prev = false) {
  mj_resetData(s.m, s.d);
  mjtNum qr[4], qp[4], ax[3] = {1, 0, 0}, ay[3] = {0, 1, 0};
  mju_axisAngle2Quat(qr, ax, p.roll * M_PI / 180);
  mju_axisAngle2Quat(qp, ay, p.pitch * M_PI / 180);
  mju_mulQuat(s.d->qpos + 3, qp, qr);
  for (int j = 0; j < 6; j++) s.d->qvel[j] = p.v[j];
  const double dt = s.m->opt.timestep;
  for (int k = prev ? 1 : 0; k >= 0; k--) {
    for (int j = 0; j < 3; j++) s.d->qpos[j] = (j == 2 ? p.z : 0) - k * dt * p.v[j];
    s.d->time = t - k * dt;
    mj_forward(s.m, s.d);
  }
  const mjtNum* f = mjb_wrenchPart(s.b, s.d, part) + 6;
  for (int j = 0; j < 6; j++) w[j] = f[j];
}

// the sea's components (mjb_waves): amplitude, omega, k, direction [rad],
// phase [rad], steepness Q
struct Comp {
  double a, w, k, dx, dy, ph, q;
};
std::vector<Comp> comps(const mjbBuoy* b) {
  const int n = mjb_waves(b, nullptr, 0);
  std::vector<double> v(6 * n);
  mjb_waves(b, v.data(), n);
  std::vector<Comp> c(n);
  for (int i = 0; i < n; i++) {
    const double* r = &v[6 * i];
    c[i] = {r[0], r[1], r[2], std::cos(r[3] * M_PI / 180), std::sin(r[3] * M_PI / 180),
            r[4] * M_PI / 180, r[5]};
  }
  return c;
}

// the Gerstner label a of the surface particle above (x, y) at t, by
// Newton on docs/physics.md (6.1) x(a) = a - sum Q A D sin(theta(a)),
// written here apart from the library's solve (components with Q = 0 move
// no particle); the surface height there, (6.2) over the Gerstner
// components plus the Airy ones at the point (section 11, "Components"),
// into eta
void label(const std::vector<Comp>& cs, double x, double y, double t, double a[2],
           double* eta) {
  a[0] = x, a[1] = y;
  for (int it = 0; it < 50; it++) {
    double r[2] = {a[0] - x, a[1] - y}, J[4] = {1, 0, 0, 1};
    for (const Comp& c : cs) {
      if (c.q == 0) continue;
      const double th = c.k * (c.dx * a[0] + c.dy * a[1]) - c.w * t + c.ph;
      const double s = c.q * c.a * std::sin(th), g = c.q * c.a * c.k * std::cos(th);
      r[0] -= s * c.dx, r[1] -= s * c.dy;
      J[0] -= g * c.dx * c.dx, J[1] -= g * c.dx * c.dy;
      J[2] -= g * c.dy * c.dx, J[3] -= g * c.dy * c.dy;
    }
    const double det = J[0] * J[3] - J[1] * J[2];
    const double d0 = (J[3] * r[0] - J[1] * r[1]) / det, d1 = (J[0] * r[1] - J[2] * r[0]) / det;
    a[0] -= d0, a[1] -= d1;
    if (std::fabs(d0) + std::fabs(d1) < 1e-13) break;
  }
  *eta = 0;
  for (const Comp& c : cs) {
    const double px = c.q == 0 ? x : a[0], py = c.q == 0 ? y : a[1];
    *eta += c.a * std::cos(c.k * (c.dx * px + c.dy * py) - c.w * t + c.ph);
  }
}

// one triangle's share of the bound: its area A, the largest lever arm of
// its corners about the COM, the largest corner height above the surface
// (deep water: z' = z - eta) and e[j], component j's interpolation error
// of e^L over the triangle, e^(k max z') q_j / 24 (times A its integral)
struct TriBound {
  double A, lever, hmax;
  std::vector<double> e;
};

// docs/physics.md "Vertex integration": on a triangle with corner exponents
// L_c = k (z'_c + i D . p_c) (p the physical point for an Airy component,
// the particle label for a Gerstner one), the linear interpolant of e^L
// differs from e^L by at most e^(max_c Re L_c) sum_c lambda_c |L_c -
// Lbar|^2 / 2 at the point of barycentric weights lambda, whose mean over
// the triangle is e^(k max z') q / 24, q = k^2 sum_(c<c') ((z'_c - z'_c')^2
// + (D . (p_c - p_c'))^2). Nonnegative, so its integral over the wet part
// of the triangle is at most A times that. Every triangle with a wet
// corner; z' and the labels from the exact surface (label above), so
// from the mesh, the components and the pose alone
template <class S>
std::vector<TriBound> triBounds(const S& s, const std::vector<Comp>& cs, double t) {
  const mjModel* m = s.m;
  const mjData* d = s.d;
  const int g = 0, mi = m->geom_dataid[g];
  const int v0 = m->mesh_vertadr[mi], nv = m->mesh_vertnum[mi];
  std::vector<double> x(3 * nv), h(nv), lb(2 * nv);
  for (int i = 0; i < nv; i++) {
    const float* v = m->mesh_vert + 3 * (v0 + i);
    const double vb[3] = {v[0], v[1], v[2]};
    mju_rotVecMat(&x[3 * i], vb, d->geom_xmat + 9 * g);
    for (int j = 0; j < 3; j++) x[3 * i + j] += d->geom_xpos[3 * g + j];
    double eta;
    label(cs, x[3 * i], x[3 * i + 1], t, &lb[2 * i], &eta);
    // the library's surface (mjb_seaHeight) is the one solved here
    EXPECT_NEAR(eta, mjb_seaHeight(s.b, x[3 * i], x[3 * i + 1], t), 1e-8) << "vertex " << i;
    h[i] = x[3 * i + 2] - eta;
  }
  const double* com = d->xipos + 3;
  std::vector<TriBound> out;
  for (int f = 0; f < m->mesh_facenum[mi]; f++) {
    const int* fc = m->mesh_face + 3 * (m->mesh_faceadr[mi] + f);
    if (!(h[fc[0]] <= 0 || h[fc[1]] <= 0 || h[fc[2]] <= 0)) continue;
    TriBound b;
    double e1[3], e2[3], cr[3];
    for (int j = 0; j < 3; j++) {
      e1[j] = x[3 * fc[1] + j] - x[3 * fc[0] + j];
      e2[j] = x[3 * fc[2] + j] - x[3 * fc[0] + j];
    }
    mju_cross(cr, e1, e2);
    b.A = 0.5 * mju_norm3(cr);
    b.lever = 0;
    for (int c = 0; c < 3; c++) {
      double r[3];
      for (int j = 0; j < 3; j++) r[j] = x[3 * fc[c] + j] - com[j];
      b.lever = std::max(b.lever, mju_norm3(r));
    }
    b.hmax = std::max({h[fc[0]], h[fc[1]], h[fc[2]]});
    for (const Comp& w : cs) {
      double q = 0;
      for (int c = 0; c < 3; c++) {
        for (int e = c + 1; e < 3; e++) {
          const double* pc = w.q == 0 ? &x[3 * fc[c]] : &lb[2 * fc[c]];
          const double* pe = w.q == 0 ? &x[3 * fc[e]] : &lb[2 * fc[e]];
          const double dz = h[fc[c]] - h[fc[e]];
          const double dx = w.dx * (pc[0] - pe[0]) + w.dy * (pc[1] - pe[1]);
          q += w.k * w.k * (dz * dz + dx * dx);
        }
      }
      b.e.push_back(std::exp(w.k * b.hmax) * q / 24);
    }
    out.push_back(b);
  }
  return out;
}

// the pressure-force bound: rho g sum_j A_j A e_j over the triangles
// (docs/physics.md "Vertex integration"), each force component by it, each
// torque component by it times the lever arm
void pressureBound(const std::vector<TriBound>& tb, const std::vector<Comp>& cs, double* bf,
                   double* bm) {
  *bf = *bm = 0;
  for (const TriBound& b : tb) {
    double s = 0;
    for (size_t j = 0; j < cs.size(); j++) s += kRho * kG * cs[j].a * b.A * b.e[j];
    *bf += s;
    *bm += s * b.lever;
  }
}

// Kerner's pressure (mjbuoy.sea.pressure kerner: rho g (eta - z), no
// dynamic part) with the pressure and suction drag of docs/physics.md 4.2
// at exponents f_P = f_S = 1 (viscous resistance and slamming off)
const std::string kKernerDrag =
    "<text name=\"mjbuoy.sea.pressure\" data=\"kerner\"/>"
    "<numeric name=\"mjbuoy.hull.drag\" data=\"100 400 1\"/>"
    "<numeric name=\"mjbuoy.hull.suction\" data=\"100 200 1\"/>"
    "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>"
    "<numeric name=\"mjbuoy.hull.slamming\" data=\"0 100 2\"/>";
const double kC1 = 100, kC2 = 400;  // the larger of drag's and suction's (vref = 1 m/s)

// With Kerner's pressure only the water velocity integrals use the vertex
// sums (docs/physics.md "Vertex integration"), and they reach the wrench
// through the drag (4.2). The bound, derived from that section:
//  - per triangle, the integral of the wave velocity over its wet part,
//    V = sum_j A_j omega_j (D_j Re, Im) integral e^(L_j) dA (the weights
//    carry omega; |(D Re e, Im e)| = |e|), errs by at most
//    dV = sum_j A_j omega_j A e_j (triBounds: the section's velocity bound
//    A |w_(u,j)| e^(k max z') q_j / 24);
//  - the drag takes the mean relative velocity v = v_body(c) - (current +
//    V / A_w) at the wet centroid c (wet area A_w, the same in both modes:
//    the cut and Kerner's pressure do not use the sums), so v moves by
//    dV / A_w;
//  - at f = 1 the drag is F = -(C_1 + C_2 |v|) A_w (v . n) n on both sides
//    (vref = 1), continuous through v . n = 0, with |dF/dv| <= A_w (C_1 +
//    |v| C_2 + |v . n| C_2) <= A_w (C_1 + 2 C_2 |v|) (C the larger of drag
//    and suction), so |dF| <= (C_1 + 2 C_2 vmax) dV: the wet area cancels;
//  - |v| <= |v_G| + |w| lever + sum_j A_j omega_j e^(k_j max(z'_max, 0))
//    in either mode (the exact mean over z' <= 0 at most 1 per component,
//    the interpolant at most its largest corner value);
//  - the torque c x F by the same times the lever arm.
// Asserted: the drag a sizeable part of the wrench (at least 10 % of the
// pressure force), the bound under a tenth of the drag, Kerner's
// pressure the same in both modes to rounding, and the drag within the bound
TEST(VertexForms, KernerDragWithinTheVelocityBound) {
  Scene ex(wigley(jonswap(64), "exact", kKernerDrag)),
      vx(wigley(jonswap(64), "vertex", kKernerDrag));
  ASSERT_TRUE(ex.ok()) << ex.err;
  ASSERT_TRUE(vx.ok()) << vx.err;
  const std::vector<Comp> cs = comps(ex.b);
  const int prev = mjb::simdLevel();
  for (int level : vectorLevels("vertexforms")) {
    mjb::simdSet(level);
    for (const Pose& p : kPoses) {
      for (double t : {3.1, 7.7}) {
        double pe[6], pv[6], de[6], dv[6];
        place(ex, p, t, mjbPART_PRESSURE, pe);
        place(ex, p, t, mjbPART_DRAG, de);
        place(vx, p, t, mjbPART_PRESSURE, pv);
        place(vx, p, t, mjbPART_DRAG, dv);
        const double vg = mju_norm3(p.v), wg = mju_norm3(p.v + 3);
        double bf = 0, bm = 0;
        for (const TriBound& b : triBounds(ex, cs, t)) {
          double dV = 0, uw = 0;
          for (size_t j = 0; j < cs.size(); j++) {
            dV += cs[j].a * cs[j].w * b.A * b.e[j];
            uw += cs[j].a * cs[j].w * std::exp(cs[j].k * std::max(b.hmax, 0.0));
          }
          const double lip = kC1 + 2 * kC2 * (vg + wg * b.lever + uw);
          bf += lip * dV;
          bm += lip * dV * b.lever;
        }
        const double P = mju_norm3(pe), D = mju_norm3(de);
        double err[2] = {0, 0};
        for (int j = 0; j < 6; j++) {
          EXPECT_NEAR(pv[j], pe[j], 1e-9 * P) << p.name << " t " << t << " pressure " << j;
          EXPECT_LE(std::fabs(dv[j] - de[j]), j < 3 ? bf : bm) << p.name << " t " << t << " " << j;
          err[j / 3] = std::max(err[j / 3], std::fabs(dv[j] - de[j]));
        }
        EXPECT_GT(D, 0.1 * P) << p.name << " t " << t;
        EXPECT_LT(bf, 0.1 * D) << p.name << " t " << t;
        std::printf("%s %s t %.1f: |F_p| %.1f N, |F_drag| %.1f N, drag err %.3g N (bound %.3g, "
                    "%.2g of |F_drag|), torque err %.3g N m (bound %.3g)\n", mjb::simdName(level),
                    p.name, t, P, D, err[0], bf, bf / D, err[1], bm);
      }
    }
  }
  mjb::simdSet(prev);
}

// a sea: the linear pressure wrench of vertex integration within the
// interpolation bound of the exact one at every pose, two times and every
// vector level, the bound under 5 % of the pressure force (these Gerstner
// components are steeper than the bench's JONSWAP, whose bound is under 2 %:
// tests/vertexint_test.cc); and vertex
// integration in use (not an exact fallback: its error above rounding)
void expectWithinBound(const std::string& sea, const char* what) {
  Scene ex(wigley(sea, "exact")), vx(wigley(sea, "vertex"));
  ASSERT_TRUE(ex.ok()) << ex.err;
  ASSERT_TRUE(vx.ok()) << vx.err;
  const std::vector<Comp> cs = comps(ex.b);
  const int prev = mjb::simdLevel();
  for (int level : vectorLevels("vertexforms")) {
    mjb::simdSet(level);
    for (const Pose& p : kPoses) {
      for (double t : {3.1, 7.7}) {
        double we[6], wv[6], bf, bm;
        place(ex, p, t, mjbPART_PRESSURE, we);
        place(vx, p, t, mjbPART_PRESSURE, wv);
        pressureBound(triBounds(ex, cs, t), cs, &bf, &bm);
        double err[2] = {0, 0};
        for (int j = 0; j < 6; j++) {
          EXPECT_LE(std::fabs(wv[j] - we[j]), j < 3 ? bf : bm) << p.name << " t " << t << " " << j;
          err[j / 3] = std::max(err[j / 3], std::fabs(wv[j] - we[j]));
        }
        const double F = mju_norm3(we);
        EXPECT_LT(bf, 0.05 * F) << p.name << " t " << t;
        EXPECT_GT(err[0], 1e-9 * F) << p.name << " t " << t;
        std::printf("%s %s %s t %.1f: |F| %.1f N, force err %.3g N (bound %.3g, %.2g of |F|), "
                    "torque err %.3g N m (bound %.3g)\n", what, mjb::simdName(level), p.name, t,
                    F, err[0], bf, bf / F, err[1], bm);
      }
    }
  }
  mjb::simdSet(prev);
}

// three short-crested Gerstner components of 4 to 8 m (k s from 0.1 to
// 0.3 on the Wigley's triangles), sum Q k A = 0.33 < 1 (no folding)
const std::string kGerstner =
    "<numeric name=\"mjbuoy.wave.g1\" data=\"0.12 6 20 0 0.9\"/>"
    "<numeric name=\"mjbuoy.wave.g2\" data=\"0.08 4 -30 70 1\"/>"
    "<numeric name=\"mjbuoy.wave.g3\" data=\"0.15 8 60 200 0.8\"/>";

// Gerstner components: their exponent's imaginary part is linear in the
// particle label (docs/physics.md section 11, "Dynamic part in closed
// form"), the label linear between the vertices in both modes, so the
// section's bound holds with the labels' differences D . (a_c - a_c') in
// place of the points' (docs/physics.md "Vertex integration"); the labels
// here from this file's own Newton solve of (6.1)
TEST(VertexForms, GerstnerWithinTheLabelBound) { expectWithinBound(kGerstner, "gerstner"); }

// two Gerstner components along one direction: the exact path's
// long-crested form (one polynomial in k per piece, docs/physics.md
// "Long-crested seas") as the reference
TEST(VertexForms, LongCrestedGerstnerWithinTheLabelBound) {
  expectWithinBound("<numeric name=\"mjbuoy.wave.g1\" data=\"0.12 6 20 0 0.9\"/>"
                    "<numeric name=\"mjbuoy.wave.g2\" data=\"0.08 4 20 70 1\"/>",
                    "long-crested gerstner");
}

// the bench's swell (one Gerstner component, 20 m, Q 0.5) and the same
// three Gerstner components over 32 Airy JONSWAP components: each kind's
// L differences in its own coordinate
TEST(VertexForms, GerstnerAndAiryWithinTheBound) {
  expectWithinBound("<numeric name=\"mjbuoy.wave.swell\" data=\"0.3 20 20 0 0.5\"/>" + kGerstner +
                        jonswap(32),
                    "gerstner+airy");
}

// Second order (docs/physics.md "Vertex integration": each piece's error
// is O((k s)^2) of its integrals, so the drag's through its Lipschitz
// constant, above, and the pressure's alike): the Wigley 576 with every
// edge halved once and twice (the same surface, vertexmesh.h); the error
// of force family part summed over the poses and two times falls about 4x
// per halving (asserted: at least 3x; a first-order or constant fault,
// such as a velocity or pressure sum off by a fixed fraction, does not)
void expectSecondOrder(const std::string& sea, const std::string& more, int part,
                       const char* what, bool prev = false) {
  double err[3];
  for (int r = 0; r < 3; r++) {
    const std::string xml[2] = {onTextMesh(wigley(sea, "exact", more)), onTextMesh(wigley(sea, "vertex", more))};
    const std::string obj = refinedWigley(r);
    MeshScene ex(xml[0], obj), vx(xml[1], obj);
    ASSERT_TRUE(ex.ok()) << ex.err;
    ASSERT_TRUE(vx.ok()) << vx.err;
    err[r] = 0;
    for (const Pose& p : kPoses) {
      for (double t : {3.1, 7.7}) {
        double we[6], wv[6];
        place(ex, p, t, part, we, prev);
        place(vx, p, t, part, wv, prev);
        for (int j = 0; j < 3; j++) err[r] += std::fabs(wv[j] - we[j]);
        if (r == 0 && part != mjbPART_PRESSURE) {
          // the family a sizeable part of the wrench
          double pe[6];
          place(ex, p, t, mjbPART_PRESSURE, pe, prev);
          EXPECT_GT(mju_norm3(we), 0.1 * mju_norm3(pe)) << what << " " << p.name << " t " << t;
        }
      }
    }
    std::printf("%s, %d triangles: force error %.4g N\n", what, ex.m->mesh_facenum[0], err[r]);
  }
  for (int r = 0; r + 1 < 3; r++) {
    EXPECT_GT(err[r] / err[r + 1], 3) << what << " refinement " << r;
    std::printf("%s, refinement %d -> %d: error ratio %.2f\n", what, r, r + 1,
                err[r] / err[r + 1]);
  }
}

TEST(VertexForms, KernerDragErrorFallsAsTheSquareOfTheEdge) {
  expectSecondOrder(jonswap(64), kKernerDrag, mjbPART_DRAG, "kerner drag");
}

// Kerner's slamming (4.5, 4.6; drag off) after one step of history: it
// takes the water velocity as the drag does, through the swept-volume
// rate Q = A_w v and its change over the step, piecewise smooth in v (the
// clamp, cos_t = 0), so its error falls with the velocity integrals'
// (Gamma_max 10 m/s^2, power 1: the faces of cut triangles below the
// clamp's limit, whose Gamma depends on v)
TEST(VertexForms, KernerSlamErrorFallsAsTheSquareOfTheEdge) {
  const std::string slam = "<text name=\"mjbuoy.sea.pressure\" data=\"kerner\"/>"
                           "<numeric name=\"mjbuoy.hull.drag\" data=\"0 0 1\"/>"
                           "<numeric name=\"mjbuoy.hull.suction\" data=\"0 0 1\"/>"
                           "<numeric name=\"mjbuoy.hull.viscous\" data=\"0\"/>"
                           "<numeric name=\"mjbuoy.hull.slamming\" data=\"1 10 1\"/>";
  expectSecondOrder(jonswap(64), slam, mjbPART_SLAM, "kerner slamming", true);
}

TEST(VertexForms, GerstnerErrorFallsAsTheSquareOfTheEdge) {
  expectSecondOrder("<numeric name=\"mjbuoy.wave.swell\" data=\"0.3 20 20 0 0.5\"/>" +
                        kGerstner + jonswap(32),
                    "", mjbPART_PRESSURE, "gerstner+airy");
}

}  // namespace
}  // namespace mjbt
