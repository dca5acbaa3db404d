// single-triangle cutting against hand integration. Every triangle lies in
// the plane y = 0 with water at z = 0 (so h = z, depth d = -z); expected
// values are the integrals of d, d x and d z over the wet region, done by
// hand in the comments.
#include <cmath>

#include <gtest/gtest.h>

#include "hull/pressure.h"

namespace mjb {
namespace {

struct Hand {
  double area, dA, cx, cz;  // wet area, integral(d dA), centre of pressure x, z
  double ny;                // outward normal y
};

void check(const double p[3][3], const Hand& e) {
  double h[3] = {p[0][2], p[1][2], p[2][2]};
  Wet w;
  wetTriangle(p, h, &w);
  EXPECT_NEAR(w.area, e.area, 1e-14);
  EXPECT_NEAR(w.dA, e.dA, 1e-14);
  EXPECT_NEAR(w.n[0], 0, 1e-15);
  EXPECT_NEAR(w.n[1], e.ny, 1e-15);
  EXPECT_NEAR(w.n[2], 0, 1e-15);
  if (e.dA > 0) {
    EXPECT_NEAR(w.drA[0] / w.dA, e.cx, 1e-14);
    EXPECT_NEAR(w.drA[1] / w.dA, 0, 1e-14);
    EXPECT_NEAR(w.drA[2] / w.dA, e.cz, 1e-14);
  }
}

TEST(WetTriangle, FullyWetOneVertexOnSurface) {
  // region x >= 0, z >= -2, x + z <= 0; area 2, normal (2,0,0)x(0,0,2) = -4 y
  // int d dA = int_{-2}^0 z^2 dz = 8/3; int d x dA = int -z^3/2 dz = 2;
  // int d z dA = int z^3 dz = -4  =>  cop (3/4, -3/2)
  double p[3][3] = {{0, 0, -2}, {2, 0, -2}, {0, 0, 0}};
  check(p, {2, 8.0 / 3, 0.75, -1.5, -1});
}

TEST(WetTriangle, TwoUnderWater) {
  // the same triangle raised by 1: wet trapezoid z in [-1, 0], x in [0, 1 - z]
  // area 3/2; int d dA = int_0^1 u (1 + u) du = 5/6;
  // int d x dA = int u (1 + u)^2 / 2 du = 17/24; int d z dA = -7/12
  double p[3][3] = {{0, 0, -1}, {2, 0, -1}, {0, 0, 1}};
  check(p, {1.5, 5.0 / 6, 17.0 / 20, -7.0 / 10, -1});
}

TEST(WetTriangle, OneUnderWater) {
  // normal (2,0,0)x(0,0,-2) = +4 y; wet part z in [-1, 0], x in [0, z + 1]
  // area 1/2; int d dA = int u (1 - u) du = 1/6; int d x dA = 1/24;
  // int d z dA = -1/12  =>  cop (1/4, -1/2)
  double p[3][3] = {{0, 0, 1}, {2, 0, 1}, {0, 0, -1}};
  check(p, {0.5, 1.0 / 6, 0.25, -0.5, 1});
}

TEST(WetTriangle, MiddleVertexOnSurface) {
  // h = -1, 0, +1: wet part z in [-1, 0], x in [0, 2 (z + 1)]
  // area 1; int d dA = 2 int u (1 - u) du = 1/3; int d x dA = 1/6;
  // int d z dA = -1/6  =>  cop (1/2, -1/2)
  double p[3][3] = {{0, 0, -1}, {2, 0, 0}, {0, 0, 1}};
  check(p, {1, 1.0 / 3, 0.5, -0.5, -1});
  // same polygon, any vertex order of the same winding
  double q[3][3] = {{2, 0, 0}, {0, 0, 1}, {0, 0, -1}};
  check(q, {1, 1.0 / 3, 0.5, -0.5, -1});
}

TEST(WetTriangle, TwoVerticesOnSurface) {
  // the wet half of the previous case as its own triangle: same integrals
  double p[3][3] = {{0, 0, -1}, {2, 0, 0}, {0, 0, 0}};
  check(p, {1, 1.0 / 3, 0.5, -0.5, -1});
}

TEST(WetTriangle, DryAndOnSurface) {
  double dry[3][3] = {{0, 0, 1}, {2, 0, 1}, {0, 0, 3}};
  check(dry, {0, 0, 0, 0, -1});
  double touch[3][3] = {{0, 0, 0}, {2, 0, 0}, {0, 0, 2}};  // edge on the surface
  check(touch, {0, 0, 0, 0, -1});
  double flat[3][3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};   // lies on the surface
  double h[3] = {0, 0, 0};
  Wet w;
  wetTriangle(flat, h, &w);
  EXPECT_EQ(w.dA, 0);
}

TEST(WetTriangle, HorizontalUnderside) {
  // bottom face at depth 2, normal -z: force rho g 2 A up, cop at centroid
  double p[3][3] = {{0, 0, -2}, {0, 3, -2}, {3, 0, -2}};
  double h[3] = {-2, -2, -2};
  Wet w;
  wetTriangle(p, h, &w);
  EXPECT_NEAR(w.n[2], -1, 1e-15);
  EXPECT_NEAR(w.area, 4.5, 1e-14);
  EXPECT_NEAR(w.dA, 9, 1e-13);
  EXPECT_NEAR(w.drA[0] / w.dA, 1, 1e-14);
  EXPECT_NEAR(w.drA[1] / w.dA, 1, 1e-14);
}

TEST(WetTriangle, ReversedWindingFlipsNormal) {
  double p[3][3] = {{0, 0, -1}, {0, 0, 1}, {2, 0, -1}};
  check(p, {1.5, 5.0 / 6, 17.0 / 20, -7.0 / 10, 1});
}

TEST(WetTriangle, DegenerateGivesZeros) {
  double line[3][3] = {{0, 0, -1}, {1, 0, -2}, {2, 0, -3}};
  double point[3][3] = {{1, 1, -1}, {1, 1, -1}, {1, 1, -1}};
  for (auto* p : {line, point}) {
    double h[3] = {p[0][2], p[1][2], p[2][2]};
    Wet w;
    wetTriangle(p, h, &w);
    EXPECT_EQ(w.area, 0);
    EXPECT_EQ(w.dA, 0);
    for (int j = 0; j < 3; j++) {
      EXPECT_EQ(w.drA[j], 0);
      EXPECT_FALSE(std::isnan(w.n[j]));
    }
  }
}

TEST(WetTriangle, TinyHeightsNoNan) {
  // heights of opposite sign near the double limit: cut points stay finite
  double p[3][3] = {{0, 0, -1e-300}, {2, 0, 1e-300}, {0, 0, 5e-324}};
  double h[3] = {-1e-300, 1e-300, 5e-324};
  Wet w;
  wetTriangle(p, h, &w);
  EXPECT_TRUE(std::isfinite(w.area));
  EXPECT_TRUE(std::isfinite(w.dA));
  EXPECT_GE(w.area, 0);
  EXPECT_LE(w.area, 2);
}

}  // namespace
}  // namespace mjb
