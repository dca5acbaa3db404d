// coarsened hulls for the panel solver (mjbuoy/radiation/panelcoarse.h,
// docs/physics.md section 13, "Coarsened hulls"): PanelCoarse.* (default
// run, seconds) checks the coarse wet surface's hydrostatics against the
// Wigley hull's closed form; PanelCoarseConverged.* (label panel, minutes)
// checks its added mass and damping against Hulme (1982) and against the
// full-resolution solution of the same hull
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "hemisphere.h"
#include "radiation/panel.h"
#include "radiation/panelcoarse.h"
#include "radiation/panelmesh.h"

namespace {

using mjb::CoarseInfo;
using mjb::HydroCoef;
using mjb::PanelMesh;

const double kRho = 1000, kG = 9.81;
const double kPos[3] = {0, 0, 0}, kQuat[4] = {1, 0, 0, 0};

// Wigley hull of models/meshes (mjbuoy-hullgen, models/README.md):
// y = B/2 (1 - (2x/L)^2)(1 - (z/T)^2), L 4, B 0.5, T 0.25 m, body frame on
// the design waterline. Closed form at the design draft: waterplane
// int B (1 - (2x/L)^2) dx = 2/3 L B, volume (2/3 L B)(2/3 T) = 4/9 L B T
const double kL = 4, kB = 0.5, kT = 0.25;
const double kAwp = 2.0 / 3.0 * kL * kB, kVol = 4.0 / 9.0 * kL * kB * kT;

struct Tri {
  std::vector<float> v;
  std::vector<int> f;
};

// a Wigley mesh file (v x y z / f a b c, 1-based)
Tri readObj(int n) {
  Tri m;
  std::ifstream in(std::string(MJB_MODELS) + "/meshes/wigley_" + std::to_string(n) + ".obj");
  EXPECT_TRUE(in.good()) << "wigley_" << n << ".obj";
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string k;
    s >> k;
    if (k == "v") {
      float x, y, z;
      s >> x >> y >> z;
      m.v.insert(m.v.end(), {x, y, z});
    } else if (k == "f") {
      for (int i = 0, a; i < 3 && s >> a; i++) m.f.push_back(a - 1);
    }
  }
  return m;
}

// tests/hemisphere.h's closed mesh (hemisphere under z = 0, collar, top)
// read back from its MJCF text
Tri hemisphereTri(int nt, int na) {
  std::string x = mjbt::hemisphereMeshXML(1, nt, na, 0.3);
  auto attr = [&](const char* a) {
    size_t b = x.find(a) + std::string(a).size() + 2;
    return std::istringstream(x.substr(b, x.find('"', b) - b));
  };
  Tri m;
  auto sv = attr("vertex");
  for (double d; sv >> d;) m.v.push_back((float)d);
  auto sf = attr("face");
  for (int i; sf >> i;) m.f.push_back(i);
  return m;
}

int wet(const PanelMesh& b, const PanelMesh& l) { return b.nface() + l.nface(); }

// the mesh's wet panels, then coarsened to budget (lid counted)
void coarse(Tri* m, int budget, PanelMesh* b, PanelMesh* l, CoarseInfo* ci) {
  std::string note;
  ASSERT_TRUE(mjb::hullPanels(m->v.data(), m->v.size() / 3, m->f.data(), m->f.size() / 3, kPos,
                              kQuat, 0, b, l, &note)) << note;
  ASSERT_TRUE(mjb::coarsenPanels(m->v.data(), m->v.size() / 3, m->f.data(), m->f.size() / 3,
                                 kPos, kQuat, 0, true, budget, b, l, &note, ci))
      << note;
}

double relErr(double a, double b) { return std::fabs(a - b) / std::fabs(b); }

// ---- default run: hydrostatics and Hulme, seconds ----

// the panel volume and waterplane formulas against the closed form on the
// full 7744-triangle mesh (resolution error only), then the coarse copies
// of the 2800- and 7744-triangle hulls: within the 400-panel budget, and
// their wet volume and waterplane area within 2% of the Wigley closed form
// (the hull a panel solution must represent; the coarse mesh's vertices
// are the fine mesh's, so it is inscribed in the hull, and 2% in volume
// is about 1% in added mass, below the solver's own 3%)
TEST(PanelCoarse, WigleyHydrostatics) {
  for (int n : {2800, 7744}) {
    Tri m = readObj(n);
    PanelMesh b, l;
    CoarseInfo ci;
    coarse(&m, 400, &b, &l, &ci);
    std::printf("[coarse] wigley %d: %d -> %d wet panels, %d -> %d triangles, volume %.5f -> "
                "%.5f (%.5f), waterplane %.5f -> %.5f (%.5f), err %.4f\n", n, ci.panels0,
                ci.panels, ci.tri0, ci.tri, ci.vol0, ci.vol, kVol, ci.awp0, ci.awp, kAwp, ci.err);
    EXPECT_GT(ci.panels0, 400);
    EXPECT_LE(wet(b, l), 400);
    EXPECT_EQ(ci.panels, wet(b, l));
    EXPECT_LT(relErr(ci.vol0, kVol), 0.005) << n;
    EXPECT_LT(relErr(ci.awp0, kAwp), 0.005) << n;
    EXPECT_LT(relErr(ci.vol, kVol), 0.02) << n;
    EXPECT_LT(relErr(ci.awp, kAwp), 0.02) << n;
    EXPECT_GT(l.nface(), 0) << "the coarse waterplane keeps its lid";
  }
}

// a budget the hull is already within leaves nothing to do for the
// caller (radattach calls coarsenPanels only above the budget); a budget
// no simplification reaches is refused with the inputs unchanged
TEST(PanelCoarse, UnreachableBudgetLeavesTheHull) {
  Tri m = readObj(576);
  Tri m0 = m;
  PanelMesh b, l;
  std::string note;
  ASSERT_TRUE(mjb::hullPanels(m.v.data(), m.v.size() / 3, m.f.data(), m.f.size() / 3, kPos,
                              kQuat, 0, &b, &l, &note));
  int n0 = wet(b, l);
  CoarseInfo ci;
  EXPECT_FALSE(mjb::coarsenPanels(m.v.data(), m.v.size() / 3, m.f.data(), m.f.size() / 3, kPos,
                                  kQuat, 0, true, 2, &b, &l, &note, &ci));
  EXPECT_NE(note.find("could not be simplified"), std::string::npos) << note;
  EXPECT_EQ(wet(b, l), n0);
  EXPECT_EQ(m.f, m0.f);
  EXPECT_EQ(m.v, m0.v);
}

HydroCoef solve(const PanelMesh& b, const PanelMesh& l, const std::vector<double>& om,
                double* sec) {
  HydroCoef h;
  h.rho = kRho;
  h.g = kG;
  std::string err;
  auto t0 = std::chrono::steady_clock::now();
  EXPECT_TRUE(mjb::panelSolve(b, l, om, {}, &h, &err)) << err;
  *sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return h;
}

// Hulme, A. (1982) "The wave forces acting on a floating hemisphere
// undergoing forced periodic oscillations", J. Fluid Mech. 121:443-463,
// Tables 1 (heave) and 2 (surge), as in tests/panel_test.cc: kR,
// A / (rho 2/3 pi R^3), B / (rho 2/3 pi R^3 omega)
struct Hulme {
  double kR, A33, B33, A11, B11;
};
const Hulme kHulme[] = {{0.5, 0.5861, 0.3391, 0.6439, 0.0987},
                        {1.0, 0.4284, 0.2484, 0.5740, 0.3535},
                        {2.0, 0.3884, 0.1031, 0.2493, -1}};

// a 32 x 64 hemisphere (4224 triangles, 4096 wet panels with its lid)
// coarsened to 400 wet panels, lid on as at attach: within 5% of Hulme's
// published values. The 16 x 32 hemisphere with its lid (768 panels) is
// within 1.5% at these kR (docs/physics.md section 13); the coarse copy,
// inscribed in the sphere (2.2% less volume) with irregular triangles, is
// allowed the resolution error of a regular mesh of about its size plus
// that volume (the 12 x 24 one, 288 panels, is 1.5 to 2.2% low in A33
// and B33; 3% is asserted for it) (seconds)
TEST(PanelCoarse, HemisphereHulme) {
  Tri m = hemisphereTri(32, 64);
  PanelMesh b, l;
  CoarseInfo ci;
  coarse(&m, 400, &b, &l, &ci);
  std::vector<double> om;
  for (const Hulme& h : kHulme) om.push_back(std::sqrt(h.kR * kG));
  double sec;
  HydroCoef c = solve(b, l, om, &sec);
  const double M = kRho * 2.0 / 3.0 * M_PI;
  std::printf("[coarse] hemisphere 32 x 64: %d -> %d wet panels, volume %+.2f%%, %.1f s\n",
              ci.panels0, ci.panels, 100 * (ci.vol / (2 * M_PI / 3) - 1), sec);
  for (int w = 0; w < c.nw(); w++) {
    const Hulme& h = kHulme[w];
    double a33 = c.A[36 * w + 14] / M, b33 = c.B[36 * w + 14] / (M * om[w]);
    double a11 = c.A[36 * w] / M, b11 = c.B[36 * w] / (M * om[w]);
    std::printf("[coarse] kR %.1f: A33 %.4f (%.4f) B33 %.4f (%.4f) A11 %.4f (%.4f) B11 %.4f "
                "(%.4f)\n", h.kR, a33, h.A33, b33, h.B33, a11, h.A11, b11, h.B11);
    EXPECT_LT(relErr(a33, h.A33), 0.05) << "kR " << h.kR;
    EXPECT_LT(relErr(b33, h.B33), 0.05) << "kR " << h.kR;
    EXPECT_LT(relErr(a11, h.A11), 0.05) << "kR " << h.kR;
    if (h.B11 > 0) {
      EXPECT_LT(relErr(b11, h.B11), 0.05) << "kR " << h.kR;
    }
  }
}

// ---- label panel: convergence against the full mesh, 10-30 s ----

// the Wigley hull's 2800- and 7744-triangle meshes coarsened to 400 wet
// panels against the full-resolution solution of the 2800-triangle mesh
// (2016 panels with its lid, solved here without coarsening: the
// independent reference; the 576-triangle mesh's own 374 panels agree
// with it within 0.6% in every entry below, so it is converged), lid on in
// both as at attach; heave and pitch (the hull's large motions in head
// seas), omega 3, 5, 7 rad/s (K L / 2 = 1.8 to 10, about the heave
// resonance near 6 rad/s). Tolerance: added mass 4%, damping 6%, what
// the hull's own regular mesh of comparable size gets (the 256-triangle
// mesh, 224 panels, printed: A33 -2.6%, B33 -5.4%, B55 -5.7% at its
// worst); the 2800 and 7744 meshes share no vertex layout with the
// reference beyond the hull shape (printed; docs/physics.md section 13)
TEST(PanelCoarseConverged, WigleyAgainstFullResolution) {
  const std::vector<double> om = {3, 5, 7};
  Tri ref = readObj(2800);
  PanelMesh rb, rl;
  std::string note;
  ASSERT_TRUE(mjb::hullPanels(ref.v.data(), ref.v.size() / 3, ref.f.data(), ref.f.size() / 3,
                              kPos, kQuat, 0, &rb, &rl, &note)) << note;
  double sec;
  HydroCoef r = solve(rb, rl, om, &sec);
  std::printf("[coarse] wigley 2800 full: %d wet panels, %.1f s\n", wet(rb, rl), sec);
  const double M = kRho * kVol, L2 = kL * kL;
  // normalized A33, B33, A55, B55 of c at w
  auto coef = [&](const HydroCoef& c, int w, double* o) {
    o[0] = c.A[36 * w + 14] / M;
    o[1] = c.B[36 * w + 14] / (M * om[w]);
    o[2] = c.A[36 * w + 28] / (M * L2);
    o[3] = c.B[36 * w + 28] / (M * L2 * om[w]);
  };
  for (int n : {256, 576, 2800, 7744}) {
    Tri m = readObj(n);
    PanelMesh b, l;
    CoarseInfo ci;
    if (n > 600) {
      coarse(&m, 400, &b, &l, &ci);
    } else {
      ASSERT_TRUE(mjb::hullPanels(m.v.data(), m.v.size() / 3, m.f.data(), m.f.size() / 3, kPos,
                                  kQuat, 0, &b, &l, &note));
      ci.panels0 = ci.panels = wet(b, l);
    }
    HydroCoef c = solve(b, l, om, &sec);
    std::printf("[coarse] wigley %d %s: %d -> %d wet panels, %.1f s\n", n,
                n > 600 ? "coarsened" : "own mesh", ci.panels0, ci.panels, sec);
    for (int w = 0; w < c.nw(); w++) {
      double x[4], y[4];
      coef(c, w, x);
      coef(r, w, y);
      std::printf("[coarse]   omega %.0f: A33 %.4f (%.4f) B33 %.4f (%.4f) A55 %.5f (%.5f) B55 "
                  "%.5f (%.5f)\n", om[w], x[0], y[0], x[1], y[1], x[2], y[2], x[3], y[3]);
      const char* name[4] = {"A33", "B33", "A55", "B55"};
      for (int k = 0; n > 600 && k < 4; k++)
        EXPECT_LT(relErr(x[k], y[k]), k % 2 ? 0.06 : 0.04) << n << " omega " << om[w] << " "
                                                              << name[k];
    }
  }
}

}  // namespace
