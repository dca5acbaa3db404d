// coefficient files of other tools (radiation/coefio.h, docs/interchange.md):
// WAMIT's text files against hand calculation of their nondimensional
// numbers and phase convention, each format's write and read back, and a
// hemisphere driven by coefficients imported from its own panel solution
// against the hemisphere driven by the panel solution itself
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <netcdf.h>

#include "api/buoy.h"
#include "api/coefexport.h"
#include "radiation/coefio.h"
#include "radiation/coefpsd.h"
#include "radiation/radimport.h"
#include "hemisphere.h"
#include "testutil.h"

namespace {

using mjb::CoefFile;
using mjb::CoefOpt;

// a fresh directory for one test's files, removed with the test binary's
// end (every directory made)
struct TmpDirs {
  std::vector<std::string> made;
  ~TmpDirs() {
    std::error_code ec;
    for (const std::string& d : made) std::filesystem::remove_all(d, ec);
  }
};
TmpDirs tmpDirs;

std::string tmpDir() {
  char t[] = "/tmp/mjb-coefio-XXXXXX";
  const char* d = mkdtemp(t);
  if (!d) return "/nonexistent-tmp";  // the writes then fail with the path named
  tmpDirs.made.push_back(d);
  return d;
}

void writeText(const std::string& path, const std::string& s) {
  std::ofstream(path) << s;
}

// coefficients with every entry distinct and of both signs (not physical:
// what a file must carry through unchanged), rho 1025, g 9.81
CoefFile synthetic() {
  CoefFile f;
  mjb::HydroCoef& c = f.c;
  c.rho = 1025;
  c.g = 9.81;
  c.omega = {0.3, 0.71, 1.2, 2.5, 4.0};
  c.heading = {0, M_PI / 3, M_PI, 1.5 * M_PI};
  for (int w = 0; w < c.nw(); w++)
    for (int k = 0; k < 36; k++) {
      c.A.push_back(1e3 * std::sin(1.0 + k + 7 * w));
      c.B.push_back(1e2 * std::cos(2.0 + k + 5 * w));
    }
  for (int k = 0; k < 36; k++) c.Ainf[k] = 1e3 * std::sin(0.5 + 3 * k), f.C[k] = 1e4 * std::cos(k);
  for (int k = 0; k < 6 * c.nw() * c.nh(); k++) {
    c.Xre.push_back(1e4 * std::sin(0.3 * k)), c.Xim.push_back(1e4 * std::cos(0.7 * k));
    c.FKre.push_back(5e3 * std::sin(0.2 * k + 1)), c.FKim.push_back(5e3 * std::cos(0.4 * k));
  }
  f.hasAinf = f.hasX = f.hasFK = f.hasC = true;
  return f;
}

// |a - b| <= tol max(|a|, |b|, floor) for each entry
void expectNear(const std::vector<double>& a, const std::vector<double>& b, double tol,
                double floor, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t i = 0; i < a.size(); i++)
    EXPECT_LE(std::fabs(a[i] - b[i]), tol * std::max({std::fabs(a[i]), std::fabs(b[i]), floor}))
        << what << "[" << i << "]: " << a[i] << " vs " << b[i];
}

// f read back from a file: every array within tol (relative; X and FK
// relative to the force scale, the sum and difference of parts rounding
// once each)
void expectSame(const CoefFile& f, const CoefFile& g, double tol) {
  expectNear(f.c.omega, g.c.omega, tol, 0, "omega");
  expectNear(f.c.heading, g.c.heading, tol, 1, "heading");
  expectNear(f.c.A, g.c.A, tol, 0, "A");
  expectNear(f.c.B, g.c.B, tol, 0, "B");
  expectNear(std::vector<double>(f.c.Ainf, f.c.Ainf + 36),
             std::vector<double>(g.c.Ainf, g.c.Ainf + 36), tol, 0, "Ainf");
  expectNear(f.c.Xre, g.c.Xre, tol, 1e4, "Xre");
  expectNear(f.c.Xim, g.c.Xim, tol, 1e4, "Xim");
  expectNear(f.c.FKre, g.c.FKre, tol, 0, "FKre");
  expectNear(f.c.FKim, g.c.FKim, tol, 0, "FKim");
  EXPECT_EQ(g.hasAinf, f.hasAinf);
  EXPECT_EQ(g.hasX, f.hasX);
  EXPECT_EQ(g.hasFK, f.hasFK);
  EXPECT_DOUBLE_EQ(g.c.rho, f.c.rho);
  EXPECT_DOUBLE_EQ(g.c.g, f.c.g);
}

// each format's precision (docs/interchange.md, "Precision"): Capytaine
// holds SI doubles, so A, B, A_inf, FK and the frequencies come back bit
// for bit and X = FK + (X - FK) to one rounding of the force scale; BEMIO
// divides by rho (g, omega) and WAMIT also writes 17 significant digits
// and periods: a few roundings, 1e-15 relative
TEST(CoefIO, CapytaineReadsBackBitForBit) {
  std::string dir = tmpDir(), p = dir + "/s.nc";
  CoefFile f = synthetic(), g;
  CoefOpt o;
  ASSERT_EQ(mjb::writeCoefFile(p, o, f), "");
  ASSERT_EQ(mjb::readCoefFile(p, o, &g), "");
  expectSame(f, g, 2.3e-16);
  EXPECT_EQ(g.c.A, f.c.A);
  EXPECT_EQ(g.c.B, f.c.B);
  EXPECT_EQ(g.c.omega, f.c.omega);
  EXPECT_EQ(g.c.FKre, f.c.FKre);
  EXPECT_TRUE(g.hasC);
  for (int k = 0; k < 36; k++) EXPECT_EQ(g.C[k], f.C[k]);
}

// water_depth is optional in a Capytaine dataset (deep water without it):
// a file without it reads back the same coefficients, exciting force
// included; one without wave_direction has no exciting force to read
TEST(CoefIO, CapytaineWithoutWaterDepth) {
  std::string dir = tmpDir(), p = dir + "/s.nc";
  CoefFile f = synthetic(), g;
  CoefOpt o;
  ASSERT_EQ(mjb::writeCoefFile(p, o, f), "");
  // rename a variable in place (netCDF keeps its data)
  auto rename = [&](const char* from, const char* to) {
    int id, var;
    ASSERT_EQ(nc_open(p.c_str(), NC_WRITE, &id), NC_NOERR);
    ASSERT_EQ(nc_redef(id), NC_NOERR);
    ASSERT_EQ(nc_inq_varid(id, from, &var), NC_NOERR) << from;
    ASSERT_EQ(nc_rename_var(id, var, to), NC_NOERR);
    ASSERT_EQ(nc_close(id), NC_NOERR);
  };
  rename("water_depth", "unused_depth");
  ASSERT_EQ(mjb::readCoefFile(p, o, &g), "");
  expectSame(f, g, 2.3e-16);
  EXPECT_EQ(g.c.depth, 0);
  rename("wave_direction", "unused_direction");
  CoefFile h;
  const std::string e = mjb::readCoefFile(p, o, &h);
  EXPECT_NE(e.find("wave_direction"), std::string::npos) << e;
}

TEST(CoefIO, BemioReadsBack) {
  std::string dir = tmpDir(), p = dir + "/s.h5";
  CoefFile f = synthetic(), g;
  CoefOpt o;
  ASSERT_EQ(mjb::writeCoefFile(p, o, f), "");
  ASSERT_EQ(mjb::readCoefFile(p, o, &g), "");
  expectSame(f, g, 1e-15);
  for (int k = 0; k < 36; k++) EXPECT_NEAR(g.C[k], f.C[k], 1e-15 * 1e4);
}

TEST(CoefIO, WamitReadsBack) {
  std::string dir = tmpDir();
  CoefFile f = synthetic(), g;
  CoefOpt o;
  o.ulen = 3.5;  // a length scale other than 1: each power of it goes out and back
  ASSERT_EQ(mjb::writeCoefFile(dir + "/s.1", o, f), "");
  for (const char* e : {"/s.1", "/s.3", "/s.3fk", "/s.hst"})
    EXPECT_EQ(access((dir + e).c_str(), R_OK), 0) << e;
  ASSERT_EQ(mjb::readCoefFile(dir + "/s.3", o, &g), "");  // any of the files names the set
  expectSame(f, g, 1e-15);
  for (int k = 0; k < 36; k++) EXPECT_NEAR(g.C[k], f.C[k], 1e-15 * 1e4);
}

// WAMIT User Manual v7, section 4: .1 "PER I J Abar Bbar", .3 "PER BETA I
// |X| arg X Re X Im X", .hst "I J C"; Abar = A / (rho L^k), Bbar = B / (rho
// L^k omega), k = 3, 4, 5 for translation-translation, -rotation,
// rotation-rotation; Xbar = X / (rho g A L^m), m = 2 (forces), 3 (moments);
// Cbar = C / (rho g L^n), n = 2, 3, 4; PER = 0 infinite frequency, PER = -1
// zero frequency; time dependence Re(X e^{+i omega t})
TEST(CoefIO, WamitHandMadeFile) {
  std::string dir = tmpDir();
  // periods 2 pi (omega 1) and pi (omega 2), listed shortest first
  writeText(dir + "/h.1",
            "   0.000000E+00   3   3   5.000000E-01\n"
            "  -1.000000E+00   3   3   9.000000E-01\n"
            "   3.141592653589793   3   3   7.000000E-01   4.000000E-01\n"
            "   6.283185307179586   3   3   6.000000E-01   2.000000E-01\n"
            "   6.283185307179586   1   5   1.000000E-01   5.000000E-02\n"
            "   6.283185307179586   5   5   3.000000E-01   1.000000E-02\n");
  // heave force 0.5 at -30 deg (WAMIT's phase: a lag behind the crest),
  // pitch moment 0.2 at +90 deg, heading 90 deg
  writeText(dir + "/h.3",
            "3.141592653589793 90 3 0.1 0 0.1 0\n"
            "3.141592653589793 90 5 0.1 0 0.1 0\n"
            "6.283185307179586 90 3 0.5 -30 0.43301270189221930 -0.25\n"
            "6.283185307179586 90 5 0.2  90 0 0.2\n");
  writeText(dir + "/h.hst", "3 3 0.25\n3 5 -0.1\n4 4 0.05\n");
  CoefOpt o;
  o.rho = 1000, o.g = 9.8, o.ulen = 2;
  CoefFile f;
  ASSERT_EQ(mjb::readCoefFile(dir + "/h.1", o, &f), "");
  const mjb::HydroCoef& c = f.c;
  ASSERT_EQ(c.nw(), 2);
  EXPECT_NEAR(c.omega[0], 1, 1e-15);  // 2 pi / 2 pi, sorted increasing
  EXPECT_NEAR(c.omega[1], 2, 1e-15);
  const double t = 1e-12;
  // A_inf33 = 0.5 rho L^3 = 0.5 1000 8 = 4000 kg
  EXPECT_NEAR(c.Ainf[14], 4000, t * 4000);
  EXPECT_TRUE(f.hasAinf);
  // omega 1: A33 = 0.6 8000 = 4800 kg, B33 = 0.2 8000 1 = 1600 kg/s;
  // A15 = 0.1 rho L^4 = 1600 kg m, B15 = 0.05 16000 = 800 kg m/s;
  // A55 = 0.3 rho L^5 = 9600 kg m^2, B55 = 0.01 32000 = 320 kg m^2/s
  EXPECT_NEAR(c.A[14], 4800, t * 4800);
  EXPECT_NEAR(c.B[14], 1600, t * 1600);
  EXPECT_NEAR(c.A[4], 1600, t * 1600);
  EXPECT_NEAR(c.B[4], 800, t * 800);
  EXPECT_NEAR(c.A[28], 9600, t * 9600);
  EXPECT_NEAR(c.B[28], 320, t * 320);
  EXPECT_EQ(c.A[24], 0);  // A51: not in the file
  // omega 2: A33 = 0.7 8000 = 5600 kg, B33 = 0.4 8000 2 = 6400 kg/s
  EXPECT_NEAR(c.A[36 + 14], 5600, t * 5600);
  EXPECT_NEAR(c.B[36 + 14], 6400, t * 6400);
  // heading 90 deg: pi / 2
  ASSERT_EQ(c.nh(), 1);
  EXPECT_NEAR(c.heading[0], M_PI / 2, 1e-15);
  // omega 1, heave: WAMIT's Re(0.5 e^{-i 30 deg} e^{+i t}) = 0.5 cos(t - 30
  // deg) per rho g L^2 = 39200 N/m; mjbuoy's Re(X e^{-i t}) is the same
  // signal for X = 0.5 e^{+i 30 deg} 39200 = 16974.097 + 9800 i
  EXPECT_NEAR(c.Xre[2], 0.5 * std::cos(M_PI / 6) * 39200, t * 39200);
  EXPECT_NEAR(c.Xim[2], 9800, t * 39200);
  // pitch: 0.2 i (leading by 90 deg) per rho g L^3 = 78400 N m/m: mjbuoy's
  // X = -0.2 i 78400 = -15680 i, Re(X e^{-i t}) = -15680 sin t = Re(0.2 i
  // 78400 e^{i t}), WAMIT's
  EXPECT_NEAR(c.Xre[4], 0, t * 78400);
  EXPECT_NEAR(c.Xim[4], -15680, t * 78400);
  for (int i = 0; i < 6; i++) {
    const double x = c.Xre[i], y = c.Xim[i];
    // the signal at t = 1 s both ways
    const double wamit[6] = {0, 0, 0.5 * std::cos(1 - M_PI / 6) * 39200, 0, -0.2 * std::sin(1) * 78400, 0};
    EXPECT_NEAR(x * std::cos(1) + y * std::sin(1), wamit[i], t * 78400) << "dof " << i;
  }
  // no .3fk: the Froude-Krylov part is unknown (zeros, hasFK false)
  EXPECT_TRUE(f.hasX);
  EXPECT_FALSE(f.hasFK);
  // .hst: C33 = 0.25 rho g L^2 = 9800 N/m, C35 = -0.1 rho g L^3 = -7840 N,
  // C44 = 0.05 rho g L^4 = 7840 N m
  EXPECT_TRUE(f.hasC);
  EXPECT_NEAR(f.C[14], 9800, t * 9800);
  EXPECT_NEAR(f.C[16], -7840, t * 7840);
  EXPECT_NEAR(f.C[21], 7840, t * 7840);
}

TEST(CoefIO, BadFilesAreNamed) {
  std::string dir = tmpDir();
  CoefOpt o;
  CoefFile f;
  std::string e = mjb::readCoefFile(dir + "/x.csv", o, &f);
  EXPECT_NE(e.find("unknown format"), std::string::npos) << e;
  e = mjb::readCoefFile(dir + "/none.1", o, &f);
  EXPECT_NE(e.find("none.1 cannot be read"), std::string::npos) << e;
  writeText(dir + "/b.1", "6.28 3 3 0.5 0.1\n6.28 3 x 0.5 0.1\n");
  e = mjb::readCoefFile(dir + "/b.1", o, &f);
  EXPECT_NE(e.find("b.1 line 2"), std::string::npos) << e;
  writeText(dir + "/m.1", "6.28 7 7 0.5 0.1\n");  // a second body's mode
  e = mjb::readCoefFile(dir + "/m.1", o, &f);
  EXPECT_NE(e.find("modes 1 to 6"), std::string::npos) << e;
  writeText(dir + "/n.nc", "not netcdf");
  e = mjb::readCoefFile(dir + "/n.nc", o, &f);
  EXPECT_NE(e.find("n.nc"), std::string::npos) << e;
  writeText(dir + "/n.h5", "not hdf5");
  e = mjb::readCoefFile(dir + "/n.h5", o, &f);
  EXPECT_NE(e.find("n.h5 cannot be opened"), std::string::npos) << e;
  o.ulen = 0;
  e = mjb::readCoefFile(dir + "/b.1", o, &f);
  EXPECT_NE(e.find("ULEN"), std::string::npos) << e;
}

// a damping matrix made positive semi-definite (coefpsd.h) passes the
// projection unchanged a second time, as mjbuoy's own coefficients do when
// read back from a file: the projection's rounding (its eigenvalues at
// -1e-16 |B|) is not taken for a negative part
TEST(CoefIO, ProjectedDampingIsAFixedPoint) {
  // diag(3, 2, 1, 0.5, -0.2, 0) turned by rotations in the 1-5 and 2-4
  // planes, at 50 angles: the zero eigenvalues come out of the solver at
  // +-1e-16 |B|, of either sign
  for (int n = 0; n < 50; n++) {
    mjb::HydroCoef c;
    c.omega = {1};
    double d[6] = {3, 2, 1, 0.5, -0.2, 0}, ca = std::cos(0.1 + 0.07 * n), sa = std::sin(0.1 + 0.07 * n);
    c.B.assign(36, 0);
    double Q[36] = {0};
    for (int i = 0; i < 6; i++) Q[7 * i] = 1;
    Q[0] = Q[28] = ca, Q[4] = -sa, Q[24] = sa;
    Q[7] = Q[21] = ca, Q[9] = -sa, Q[19] = sa;
    for (int i = 0; i < 6; i++)
      for (int j = 0; j < 6; j++)
        for (int k = 0; k < 6; k++) c.B[6 * i + j] += Q[6 * i + k] * d[k] * Q[6 * j + k];
    mjb::projectDamping(&c, "test", nullptr);
    std::vector<double> once = c.B;
    // the negative eigenvalue -0.2 is gone: trace 6.5 (3 + 2 + 1 + 0.5)
    double tr = 0;
    for (int i = 0; i < 6; i++) tr += once[7 * i];
    EXPECT_NEAR(tr, 6.5, 1e-12);
    mjb::projectDamping(&c, "test", nullptr);
    EXPECT_EQ(c.B, once) << "angle " << n;
  }
}

// resampling onto the diffraction table's headings: a force cos(beta) +
// i sin(2 beta) known every 15 deg is linear-interpolated to within the
// interpolation bound h^2 / 8 max|f''| = (pi/12)^2 / 8 4 = 0.034 (h the
// spacing, f'' of sin(2 beta) at most 4), exact where the headings meet
TEST(CoefIO, HeadingResample) {
  mjb::HydroCoef c;
  c.omega = {1};
  for (int h = 0; h < 24; h++) c.heading.push_back(-M_PI + 2 * M_PI * h / 24);  // -180..165 deg
  for (double b : c.heading)
    for (int i = 0; i < 6; i++) {
      c.Xre.push_back(std::cos(b)), c.Xim.push_back(std::sin(2 * b));
      c.FKre.push_back(0), c.FKim.push_back(0);
    }
  double gap;
  ASSERT_TRUE(mjb::resampleHeadings(&c, 36, &gap));
  EXPECT_NEAR(gap, M_PI / 12, 1e-12);
  ASSERT_EQ(c.nh(), 36);
  for (int h = 0; h < 36; h++) {
    double b = 2 * M_PI * h / 36;
    EXPECT_NEAR(c.Xre[6 * h], std::cos(b), (M_PI / 12) * (M_PI / 12) / 8 * 1) << h;
    EXPECT_NEAR(c.Xim[6 * h], std::sin(2 * b), (M_PI / 12) * (M_PI / 12) / 8 * 4) << h;
    if (h % 3 == 0) {
      EXPECT_NEAR(c.Xre[6 * h], std::cos(b), 1e-12) << h;  // 30 deg steps meet
    }
  }
  // one heading is not all round the body
  mjb::HydroCoef one;
  one.omega = {1};
  one.heading = {0};
  one.Xre = one.Xim = one.FKre = one.FKim = std::vector<double>(6, 1);
  EXPECT_FALSE(mjb::resampleHeadings(&one, 36, &gap));
  EXPECT_NEAR(gap, 2 * M_PI, 1e-12);
}

// the Froude-Krylov force on a box L x B x T (centred on the z axis, top
// at the waterline) in a wave along +x, k = omega^2 / g, against the
// integral of the incident pressure rho g e^{k z} e^{i k x} over its
// faces: heave (the bottom) rho g B e^{-k T} 2 sin(k L / 2) / k, surge
// (the two ends) -2 i rho g B (1 - e^{-k T}) / k sin(k L / 2). The
// centroid rule on panels h long integrates e^{i k x} to the exact over
// sinc(k h / 2) and e^{k z} to the exact over sinh(k h / 2) / (k h / 2)
// (each panel's exact integral h e^{i k x_c} sin(k h / 2) / (k h / 2)):
// 4.2e-4 off at k h = 0.1, and exactly that
TEST(CoefIO, FroudeKrylovOfABox) {
  const double L = 2, Bw = 1, T = 0.5, h = 0.1, rho = 1025, g = 9.81;
  mjb::PanelMesh p;
  // a grid of quads from corner o along u and v, normal u x v out of the box
  auto grid = [&](const double o[3], const double u[3], const double v[3], int nu, int nv) {
    int v0 = p.vert.size() / 3;
    for (int i = 0; i <= nu; i++)
      for (int j = 0; j <= nv; j++)
        for (int k = 0; k < 3; k++) p.vert.push_back(o[k] + u[k] * i / nu + v[k] * j / nv);
    for (int i = 0; i < nu; i++)
      for (int j = 0; j < nv; j++) {
        int a = v0 + i * (nv + 1) + j;
        p.face.insert(p.face.end(), {a, a + nv + 1, a + nv + 2, a + 1});
      }
  };
  const double x0 = -L / 2, y0 = -Bw / 2;
  {  // bottom, normal -z: u along y, v along x
    double o[3] = {x0, y0, -T}, u[3] = {0, Bw, 0}, v[3] = {L, 0, 0};
    grid(o, u, v, int(Bw / h), int(L / h));
  }
  {  // end x = L/2, normal +x: u along y, v along z
    double o[3] = {L / 2, y0, -T}, u[3] = {0, Bw, 0}, v[3] = {0, 0, T};
    grid(o, u, v, int(Bw / h), int(T / h));
  }
  {  // end x = -L/2, normal -x: u along z, v along y
    double o[3] = {-L / 2, y0, -T}, u[3] = {0, 0, T}, v[3] = {0, Bw, 0};
    grid(o, u, v, int(T / h), int(Bw / h));
  }
  mjb::HydroCoef c;
  c.rho = rho, c.g = g;
  c.omega = {std::sqrt(g * 1.0)};  // k = 1
  c.heading = {0};
  mjb::froudeKrylov(p, &c);
  const double k = 1, f3 = rho * g * Bw * std::exp(-k * T) * 2 * std::sin(k * L / 2) / k;
  const double f1 = -2 * rho * g * Bw * (1 - std::exp(-k * T)) / k * std::sin(k * L / 2);
  const double s = std::sin(k * h / 2) / (k * h / 2), sh = std::sinh(k * h / 2) / (k * h / 2);
  EXPECT_NEAR(c.FKre[2], f3 / s, 1e-12 * f3);
  EXPECT_NEAR(c.FKim[2], 0, 1e-12 * f3);
  EXPECT_NEAR(c.FKre[0], 0, 1e-12 * f3);
  EXPECT_NEAR(c.FKim[0], f1 / sh, 1e-12 * f3);
}

// the floating hemisphere of tests/hemisphere.h (COM 0.3 m below its
// frame's origin) in a wave from 30 deg, with radiation and diffraction;
// its full mesh is solved (panels 0), as the import's roll stiffness
// (rollzeta) is of the full wet mesh; drift off: the files carry no drift
// table (docs/physics.md section 18)
std::string hemiXML(const std::string& extra) {
  return mjbt::floatingHemisphereXML(
      1, mjbt::kRho, std::string(mjbt::kNoDragEntries) +
                         "<numeric name=\"mjbuoy.airy.w\" data=\"0.05 9 30 0\"/>"
                         "<numeric name=\"mjbuoy.radiation.panels\" data=\"0\"/>"
                         "<text name=\"mjbuoy.radiation.drift\" data=\"off\"/>"
                         "<text name=\"mjbuoy.radiation\" data=\"on\"/>" + extra);
}

// motion of a body driven by the coefficients of its own panel solution,
// written to a file and read back through mjbuoy.radiation.file.<body>,
// against the body driven by the panel solution: the same coefficients
// make the same motion. Capytaine's file holds them bit for bit, and the
// motion is the same bit for bit; BEMIO's and WAMIT's hold them to 1e-15
// relative, and the free body's surge, sway and yaw, which nothing
// restores, carry that rounding on: 9e-12 m after 10 s (of 0.8 m drift)
void importMovesIdentically(const char* name, double tol) {
  mjbt::Scene own(hemiXML(""));
  ASSERT_TRUE(own.ok()) << own.err;
  const mjb::Buoy* B = mjb::buoyOf(own.b);
  int body = own.body("hemi");
  CoefFile f;
  ASSERT_EQ(mjb::exportCoef(*B, body, &f), "");
  EXPECT_TRUE(f.hasX && f.hasFK);
  std::string path = tmpDir() + "/" + name;
  CoefOpt o;
  o.rho = mjbt::kRho;
  o.g = B->cfg.sea.g;
  ASSERT_EQ(mjb::writeCoefFile(path, o, f), "");
  // the file's origin is the COM: 0 0 -0.3 in the body frame
  mjbt::Scene imp(hemiXML("<text name=\"mjbuoy.radiation.file.hemi\" data=\"" + path + "\"/>"
                          "<numeric name=\"mjbuoy.radiation.fileorigin.hemi\" data=\"0 0 -0.3\"/>"));
  ASSERT_TRUE(imp.ok()) << imp.err;
  // the import used the file, not the panel solver: no cache lookup
  const mjb::Buoy* Bi = mjb::buoyOf(imp.b);
  EXPECT_EQ(Bi->radcache.hit + Bi->radcache.miss, 0);
  ASSERT_EQ(Bi->coef.size(), 1u);
  // 10 s of waves and the radiation memory
  const int n = 2000;
  std::vector<double> a = mjbt::stepRecord(own.m, own.d, own.b, n);
  std::vector<double> b = mjbt::stepRecord(imp.m, imp.d, imp.b, n);
  ASSERT_EQ(a.size(), b.size());
  double worst = 0;
  for (int s = 0; s < n; s++)
    for (int k = 0; k < own.m->nq; k++) {
      size_t i = s * (own.m->nq + 6 * own.m->nbody) + k;
      worst = std::max(worst, std::fabs(a[i] - b[i]));
    }
  EXPECT_LE(worst, tol) << name;
  // the motion is not trivially still: heave of centimetres
  double zmin = 1e9, zmax = -1e9;
  for (int s = 0; s < n; s++) {
    double z = a[s * (own.m->nq + 6 * own.m->nbody) + 2];
    zmin = std::min(zmin, z), zmax = std::max(zmax, z);
  }
  EXPECT_GT(zmax - zmin, 0.02);
  std::printf("%s: largest qpos difference %.3g over %d steps\n", name, worst, n);
}

TEST(CoefImport, CapytaineMovesIdentically) { importMovesIdentically("hemi.nc", 0); }
TEST(CoefImport, BemioMovesIdentically) { importMovesIdentically("hemi.h5", 1e-10); }
TEST(CoefImport, WamitMovesIdentically) { importMovesIdentically("hemi.1", 1e-10); }

// a WAMIT set without its .3fk file: the diffraction force is the file's
// exciting force less the hull panels' own Froude-Krylov force, by the
// panel solver's centroid rule, so the body moves as the panel solver's to
// the file's rounding, as WamitMovesIdentically
TEST(CoefImport, WamitWithoutFroudeKrylovUsesTheHulls) {
  mjbt::Scene own(hemiXML(""));
  ASSERT_TRUE(own.ok()) << own.err;
  CoefFile f;
  ASSERT_EQ(mjb::exportCoef(*mjb::buoyOf(own.b), own.body("hemi"), &f), "");
  std::string dir = tmpDir();
  CoefOpt o;
  o.rho = mjbt::kRho;
  ASSERT_EQ(mjb::writeCoefFile(dir + "/h.1", o, f), "");
  ASSERT_EQ(std::remove((dir + "/h.3fk").c_str()), 0);
  mjbt::Scene imp(hemiXML("<text name=\"mjbuoy.radiation.file.hemi\" data=\"" + dir + "/h.1\"/>"
                          "<numeric name=\"mjbuoy.radiation.fileorigin.hemi\" data=\"0 0 -0.3\"/>"));
  ASSERT_TRUE(imp.ok()) << imp.err;
  EXPECT_NE(std::string(mjb_warnings(imp.b)).find("holds no Froude-Krylov force"),
            std::string::npos) << mjb_warnings(imp.b);
  const int n = 2000;
  std::vector<double> a = mjbt::stepRecord(own.m, own.d, own.b, n);
  std::vector<double> b = mjbt::stepRecord(imp.m, imp.d, imp.b, n);
  double worst = 0;
  for (int s = 0; s < n; s++)
    for (int k = 0; k < own.m->nq; k++) {
      size_t i = s * (own.m->nq + 6 * own.m->nbody) + k;
      worst = std::max(worst, std::fabs(a[i] - b[i]));
    }
  EXPECT_LE(worst, 1e-10);
  std::printf("without .3fk: largest qpos difference %.3g over %d steps\n", worst, n);
}

// a file's water depth is compared with the model's: one of another depth
// (here 40 m against deep water) is named with both depths; the same depth
// is silent. A file has no drift table: with drift on, that is said
TEST(CoefImport, FileOfAnotherDepthIsNamed) {
  mjbt::Scene own(hemiXML(""));
  ASSERT_TRUE(own.ok()) << own.err;
  CoefFile f;
  ASSERT_EQ(mjb::exportCoef(*mjb::buoyOf(own.b), own.body("hemi"), &f), "");
  f.c.depth = 40;
  std::string dir = tmpDir();
  CoefOpt o;
  ASSERT_EQ(mjb::writeCoefFile(dir + "/h.nc", o, f), "");
  const std::string file = "<text name=\"mjbuoy.radiation.file.hemi\" data=\"" + dir +
                           "/h.nc\"/><numeric name=\"mjbuoy.radiation.fileorigin.hemi\" "
                           "data=\"0 0 -0.3\"/>";
  mjbt::Scene deep(hemiXML(file));
  ASSERT_TRUE(deep.ok()) << deep.err;
  const std::string w = mjb_warnings(deep.b);
  EXPECT_NE(w.find("is for water 40 m deep, the model's sea for deep water (mjbuoy.sea.depth)"),
            std::string::npos) << w;
  mjbt::Scene same(hemiXML(file + "<numeric name=\"mjbuoy.sea.depth\" data=\"40\"/>"));
  ASSERT_TRUE(same.ok()) << same.err;
  EXPECT_EQ(std::string(mjb_warnings(same.b)).find("m deep"), std::string::npos)
      << mjb_warnings(same.b);
  // a file holds no drift table: with drift on (the default) that is said
  EXPECT_EQ(std::string(mjb_warnings(same.b)).find("has no mean wave drift"), std::string::npos);
  std::string on = hemiXML(file + "<numeric name=\"mjbuoy.sea.depth\" data=\"40\"/>");
  const std::string off = "<text name=\"mjbuoy.radiation.drift\" data=\"off\"/>";
  ASSERT_NE(on.find(off), std::string::npos);
  on.erase(on.find(off), off.size());
  mjbt::Scene drift(on);
  ASSERT_TRUE(drift.ok()) << drift.err;
  EXPECT_NE(std::string(mjb_warnings(drift.b)).find("has no mean wave drift"), std::string::npos)
      << mjb_warnings(drift.b);
}

TEST(CoefImport, EntriesAreChecked) {
  mjbt::Scene s(hemiXML("<numeric name=\"mjbuoy.radiation.ulen.hemi\" data=\"2\"/>"));
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.err.find("needs a coefficient file for body \"hemi\""), std::string::npos) << s.err;
  mjbt::Scene t(hemiXML("<text name=\"mjbuoy.radiation.file.nobody\" data=\"x.nc\"/>"));
  EXPECT_NE(t.err.find("body \"nobody\", which does not exist"), std::string::npos) << t.err;
  mjbt::Scene u(hemiXML("<text name=\"mjbuoy.radiation.file.hemi\" data=\"/nonexistent/x.nc\"/>"));
  EXPECT_FALSE(u.ok());
  EXPECT_NE(u.err.find("/nonexistent/x.nc"), std::string::npos) << u.err;
  mjbt::Scene v(hemiXML("<text name=\"mjbuoy.radiation.file.hemi\" data=\"x.nc\"/>"
                        "<numeric name=\"mjbuoy.radiation.fileorigin.hemi\" data=\"0 0\"/>"));
  EXPECT_NE(v.err.find("expected 3"), std::string::npos) << v.err;
}

}  // namespace
