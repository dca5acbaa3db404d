// the closed-form wave pressure and velocity integrals (docs/physics.md,
// "Pressure", "Cost"; mjbuoy/sea/waveint.h) against independent references:
// Gauss-Legendre quadrature in long double, the divided-difference
// recursion, and Radon's degree-5 rule on fine subdivisions; the vector
// paths against the scalar one
#include <cfloat>
#include <cmath>
#include <complex>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sea/sea.h"
#include "testutil.h"
#include "util/vmath.h"
#include "sea/waveint.h"
#include "hull/wavepress.h"

namespace mjbt {
namespace {

using cld = std::complex<long double>;

// S = integral over the unit simplex of e^(l1 u1 + l2 u2), T_c the same
// weighted by barycentric l_c (l0 = 1 - l1 - l2)
struct ST {
  cld S, T[3];
};

// Gauss-Legendre nodes and weights on [0, 1], n points, long double (Newton
// on P_n from the Chebyshev guess; Abramowitz & Stegun 25.4.29)
void gauss(int n, std::vector<long double>* x, std::vector<long double>* w) {
  x->resize(n);
  w->resize(n);
  const long double pi = 3.141592653589793238462643383279502884L;
  for (int i = 0; i < n; i++) {
    long double z = std::cos(pi * (i + 0.75L) / (n + 0.5L)), dp = 1;
    for (int it = 0; it < 100; it++) {
      long double p0 = 1, p1 = z;
      for (int k = 2; k <= n; k++) {
        long double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      long double dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-22L) break;
    }
    (*x)[i] = 0.5L * (1 - z);
    (*w)[i] = 1 / ((1 - z * z) * dp * dp);  // 2 / ((1 - z^2) P'^2) on [-1, 1], halved
  }
}

// the simplex as the collapsed square l1 = s, l2 = (1 - s) r, dl = (1 - s)
// ds dr, with 24 x 24 Gauss points: exact for polynomial degree 47, so for
// |u| <= 4 the error is below 4^48 / 48! < 1e-32 of e^|u|
ST gaussST(cld u1, cld u2) {
  static std::vector<long double> x, w;
  if (x.empty()) gauss(24, &x, &w);
  ST r{0, {0, 0, 0}};
  for (size_t i = 0; i < x.size(); i++) {
    for (size_t j = 0; j < x.size(); j++) {
      long double l1 = x[i], l2 = (1 - x[i]) * x[j], l0 = 1 - l1 - l2;
      long double ww = w[i] * w[j] * (1 - x[i]);
      cld e = std::exp(l1 * u1 + l2 * u2) * ww;
      r.S += e;
      r.T[0] += l0 * e;
      r.T[1] += l1 * e;
      r.T[2] += l2 * e;
    }
  }
  return r;
}

// divided differences of exp by the recursion (Hermite-Genocchi: S =
// exp[0, u1, u2], T_c = exp[u_c, 0, u1, u2]); nodes must be well separated
cld dd2(cld a, cld b) { return (std::exp(a) - std::exp(b)) / (a - b); }
cld dd3(cld a, cld b, cld c) { return (dd2(a, b) - dd2(b, c)) / (a - c); }
cld dd3aab(cld a, cld b) { return (std::exp(a) - dd2(a, b)) / (a - b); }  // exp[a, a, b]
cld dd4aabc(cld a, cld b, cld c) { return (dd3aab(a, b) - dd3(a, b, c)) / (a - c); }
ST directST(cld u1, cld u2) {
  const cld z = 0;
  return ST{dd3(z, u1, u2), {dd4aabc(z, u1, u2), dd4aabc(u1, z, u2), dd4aabc(u2, z, u1)}};
}

// the library's answer for one component: the series kernel of the given
// level (or subdivision for |u| > kRMax) with e^L0 = 1 (real parts) and
// e^L0 = -i (imaginary parts)
ST libST(cld u1, cld u2, int level) {
  ST r;
  if (std::max(std::abs(u1), std::abs(u2)) > mjb::kRMax) {
    double S[2], T[3][2];
    mjb::subdivided(0, 1, 0, double(u1.real()), double(u1.imag()), double(u2.real()),
                    double(u2.imag()), S, T);
    r.S = cld(S[0], S[1]);
    for (int c = 0; c < 3; c++) r.T[c] = cld(T[c][0], T[c][1]);
    return r;
  }
  // one component, k = 1 along x: u_c = dz_c + i dx_c
  const double k = 1, kdx = 1, kdy = 0, gm = 0, one = 1, zero = 0;
  double out[2][7];
  for (int part = 0; part < 2; part++) {
    const double er = part ? 0 : 1, ei = part ? -1 : 0;
    mjb::KernIn in{&k, &kdx, &kdy, &gm, &one, &zero, &zero, &one, &er, &ei,
                   {double(u1.real()), double(u2.real())},
                   {{double(u1.imag()), 0}, {double(u2.imag()), 0}},
                   {{0, 0}, {0, 0}}, 1, std::max(std::abs(double(u1.real())) + std::abs(double(u1.imag())),
                                                 std::abs(double(u2.real())) + std::abs(double(u2.imag()))),
                   1};
    for (double& o : out[part]) o = 0;
    if (level == mjb::kSimdScalar) mjb::seriesScalar(in, 0, 1, out[part]);
    if (level == mjb::kSimdAvx2) mjb::seriesAvx2(in, 0, 1, out[part]);
    if (level == mjb::kSimdAvx512) mjb::seriesAvx512(in, 0, 1, out[part]);
  }
  r.S = cld(out[0][0], out[1][0]);
  for (int c = 0; c < 3; c++) r.T[c] = cld(out[0][1 + c], out[1][1 + c]);
  return r;
}

// the integrals of e^L over a triangle and their barycentric moments, by
// the series and by subdivision, against long-double references, to 1e-14
// of the integrand's largest size on the piece max(1, |e^u1|, |e^u2|):
// coincident corners (S = 1/2, T_c = 1/6 exactly), nearly coincident ones
// (1e-12 to 1e-6 apart: where the direct formula sum e^Li / prod(Li - Lj)
// loses everything), moderate and wide separations (series up to |u| = 4),
// and |u| to 25 (subdivided; against the recursion, exact there). The
// vector levels cut the series where the first term left out is below
// 2^-kSeriesBitsV of the leading term (1/2 for S, 1/6 for T_c) and the
// later ones shrink at least by half (waveint.cc): within 2^-kSeriesBitsV
// of the leading term 1/2, plus the same 1e-14 of round-off
TEST(WaveInt, DividedDifferencesOfExpAgainstReferences) {
  const std::vector<std::pair<cld, cld>> close = {
      {0, 0},
      {cld(1e-12L, 0), cld(0, 2e-12L)},
      {cld(1e-6L, 0), cld(1e-6L, 1e-9L)},
      {cld(0.1L, 0.2L), cld(0.1L + 1e-10L, 0.2L)},
      {cld(-0.3L, 0.05L), cld(0, 0.7L)},
      {cld(1, 1), cld(-1, 0.5L)},
      {cld(3.9L, 0), cld(0, 3.9L)},
      {cld(-3.9L, 0.1L), cld(0.2L, -2)},
      {cld(2.5L, -1), cld(2.5L, -1 + 1e-8L)}};
  const std::vector<std::pair<cld, cld>> wide = {
      {cld(12, 5), cld(-3, 20)}, {cld(-30, 0), cld(0, 25)}, {cld(0, 9), cld(0, -7)}};
  const int prev = mjb::simdLevel(), best = mjb::simdSet(mjb::kSimdAvx512);
  mjb::simdSet(prev);
  for (int level = 0; level <= best; level++) {
    long double worst = 0;
    for (int pass = 0; pass < 2; pass++) {
      for (const auto& u : pass ? wide : close) {
        ST ref = pass ? directST(u.first, u.second) : gaussST(u.first, u.second);
        ST got = libST(u.first, u.second, level);
        long double sc = std::max({1.0L, std::abs(std::exp(u.first)), std::abs(std::exp(u.second))});
        worst = std::max(worst, std::abs(got.S - ref.S) / sc);
        for (int c = 0; c < 3; c++) worst = std::max(worst, std::abs(got.T[c] - ref.T[c]) / sc);
        // the truncation is relative to the leading term, below 1, the round-off to sc
        const long double cut = level == mjb::kSimdScalar || pass ? 0
                                : std::ldexp(1.0L, -mjb::kSeriesBitsV);
        EXPECT_LT(std::abs(got.S - ref.S), 1e-14L * sc + cut) << mjb::simdName(level) << " " << u.first << u.second;
        for (int c = 0; c < 3; c++) {
          EXPECT_LT(std::abs(got.T[c] - ref.T[c]), 1e-14L * sc + cut)
              << mjb::simdName(level) << " " << c << " " << u.first << u.second;
        }
      }
    }
    std::printf("[waveint] %s: largest error %.2Le of the integrand's size\n", mjb::simdName(level),
                worst);
  }
  // the exact values at coincident corners
  ST z = libST(0, 0, mjb::kSimdScalar);
  EXPECT_EQ(z.S, cld(0.5L, 0));
  for (int c = 0; c < 3; c++) EXPECT_NEAR(double(z.T[c].real()), 1.0 / 6, 1e-17);
}


// a sea of kind: 0 deep, three Airy components; 1 deep, Gerstner + Airy;
// 2 finite depth 5 m, Gerstner + Airy
mjb::Sea testSea(int kind) {
  mjb::Sea s;
  auto airy = [&](double a, double len, double dir, double ph) {
    mjb::Wave w{a, len, dir, ph, 0, 0, 0, 0, 0, 0};
    w.kind = 1;
    s.waves.push_back(w);
  };
  airy(0.2, 6, 0, 0);
  if (kind == 0) {
    airy(0.1, 9, 70, 40);
    airy(0.05, 4, -30, 100);
  } else {
    s.waves.push_back(mjb::Wave{0.15, 9, 40, 30, 0.6, 0, 0, 0, 0, 0});
  }
  if (kind == 2) s.depth = 5;
  s.derive();
  return s;
}

// the integrand at point r of the triangle whose surface (height above the
// level, Gerstner label) is sf, linear between its corners as the cut
// assumes: p_d [Pa] and the wave velocity [m/s] of linear theory
// (Sea::dynamicSC and velocitySC, checked against Dean & Dalrymple in
// wavepress_test.cc), each component's phase computed directly
void integrand(const mjb::Sea& sea, const mjb::WaveNow* wn, const mjb::Surf& sf,
               const double r[3], double* p, double v[3]) {
  double eta, l[2];
  sf.at(r, &eta, l);
  std::vector<double> sc(2 * sea.waves.size());
  for (size_t i = 0; i < sea.order.size(); i++) {
    const bool ger = int(i) < sea.ng;
    const double x = ger ? l[0] : r[0], y = ger ? l[1] : r[1];
    const double th = wn[i].k * (wn[i].dx * x + wn[i].dy * y) - wn[i].wt + wn[i].ph;
    sc[2 * i] = std::sin(th);
    sc[2 * i + 1] = std::cos(th);
  }
  *p = sea.dynamicSC(wn, sc.data(), r[2] - sea.level, eta);
  sea.velocitySC(wn, sc.data(), r[2] - sea.level, eta, v);
}

// area of triangle a b c [m^2]: half the length of the edges' cross product
double triArea(const double* a, const double* b, const double* c) {
  double u[3], v[3];
  for (int j = 0; j < 3; j++) {
    u[j] = b[j] - a[j];
    v[j] = c[j] - a[j];
  }
  const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2],
               z = u[0] * v[1] - u[1] * v[0];
  return 0.5 * std::sqrt(x * x + y * y + z * z);
}

// Radon's degree-5 rule (Stroud 1971, T2:5-1) on 4^lev sub-triangles:
// P = integral p_d dA, R = integral p_d r dA, V = integral u dA
struct Ref {
  double P = 0, R[3] = {0, 0, 0}, V[3] = {0, 0, 0};
};

void radon(const mjb::Sea& sea, const mjb::WaveNow* wn, const mjb::Surf& sf, const double* a,
           const double* b, const double* c, int lev, Ref* out) {
  if (lev > 0) {
    double ab[3], bc[3], ca[3];
    for (int j = 0; j < 3; j++) {
      ab[j] = 0.5 * (a[j] + b[j]);
      bc[j] = 0.5 * (b[j] + c[j]);
      ca[j] = 0.5 * (c[j] + a[j]);
    }
    radon(sea, wn, sf, a, ab, ca, lev - 1, out);
    radon(sea, wn, sf, ab, b, bc, lev - 1, out);
    radon(sea, wn, sf, ca, bc, c, lev - 1, out);
    radon(sea, wn, sf, ab, bc, ca, lev - 1, out);
    return;
  }
  static const double s15 = std::sqrt(15.0), ka = (6 - s15) / 21, kb = (6 + s15) / 21;
  static const double wa = (155 - s15) / 1200, wb = (155 + s15) / 1200;
  const double bar[7][3] = {{1.0 / 3, 1.0 / 3, 1.0 / 3}, {ka, ka, 1 - 2 * ka}, {ka, 1 - 2 * ka, ka},
                            {1 - 2 * ka, ka, ka},        {kb, kb, 1 - 2 * kb}, {kb, 1 - 2 * kb, kb},
                            {1 - 2 * kb, kb, kb}};
  const double wt[7] = {9.0 / 40, wa, wa, wa, wb, wb, wb};
  const double A = triArea(a, b, c);
  for (int i = 0; i < 7; i++) {
    double r[3], p, vel[3];
    for (int j = 0; j < 3; j++) r[j] = bar[i][0] * a[j] + bar[i][1] * b[j] + bar[i][2] * c[j];
    integrand(sea, wn, sf, r, &p, vel);
    out->P += wt[i] * A * p;
    for (int j = 0; j < 3; j++) {
      out->R[j] += wt[i] * A * p * r[j];
      out->V[j] += wt[i] * A * vel[j];
    }
  }
}

// pieceIntegrals for triangle q (relative to a zero COM, fully below the
// surface) with its inputs as the cpu backend makes them: corners' labels,
// heights and phases from Sea::solve, Wheeler's z' from their exact
// surface, e^L at corner 0 per component in WaveTab's order
void closedForm(const mjb::Sea& sea, const mjb::WaveNow* wn, const double q[3][3],
                mjb::Surf* sf, Ref* out) {
  const size_t nw = sea.waves.size();
  mjb::WaveTab tab;
  tab.reserve(nw);
  tab.fill(sea, wn);
  std::vector<double> sc(2 * nw), tmp(2 * nw), sc0(2 * nw), E(4 * nw);
  double zs[3], lab[3][2];
  for (int c = 0; c < 3; c++) {
    double a[2] = {q[c][0], q[c][1]};
    double z = sea.solve(wn, q[c][0], q[c][1], a, sc.data(), tmp.data());
    for (int j = 0; j < 3; j++) sf->p[c][j] = q[c][j];
    sf->eta[c] = z - sea.level;
    sf->lab[c][0] = lab[c][0] = a[0];
    sf->lab[c][1] = lab[c][1] = a[1];
    zs[c] = mjb::stretch(sea.depth, q[c][2] - sea.level, z - sea.level);
    if (c == 0) sc0 = sc;
  }
  for (int j = 0; j < tab.n; j++) {
    const int i = tab.perm[j];
    const double e1 = std::exp(tab.k[j] * zs[0]), e2 = std::exp(-tab.k[j] * (zs[0] + 2 * sea.depth));
    E[j] = e1 * sc0[2 * i + 1];
    E[nw + j] = e1 * sc0[2 * i];
    E[2 * nw + j] = e2 * sc0[2 * i + 1];
    E[3 * nw + j] = e2 * sc0[2 * i];
  }
  const double* const E0[4] = {E.data(), E.data() + nw, E.data() + 2 * nw, E.data() + 3 * nw};
  const double area = triArea(q[0], q[1], q[2]);
  mjb::pieceIntegrals(tab, sea, E0, sc0.data(), q, zs, lab, area, true, &out->P, out->R, out->V);
}

// force, moment and velocity integrals over one wet piece, closed form
// against Radon's rule on 4^7 sub-triangles under the same surface (linear
// between the corners; the rule's own error there is below 2e-6 (k s /
// 128)^6, 1e-13 at k s = 6), for a tilted triangle of side s with k s from
// 0.25 to 6 (k of the 6 m component; past k s = 4 the series gives way to
// subdivision): deep water the integrand is the same, agreement to 1e-12 of
// rho g sum A area (force), times the largest |r| (moment), sum A omega area
// (velocity). Finite depth: the closed form takes Wheeler's z' = (z - eta)
// h / (h + eta) linear between the corners; its interpolation error is
// below s^2 / 6 max|z''| (Waldron 1998) with, along the plane, |z''| <=
// 2 G (1 + G) h / b^2 + 2 |z - eta| G^2 h / b^3 (G the surface slope on the
// plane, b = h + min eta), and |d p_d / d z'| <= rho g A k per component,
// |d u / d z'| <= A omega k coth(k h): the bound asserted
TEST(WaveInt, PieceIntegralsAgainstFineSubdivision) {
  const double t = 1.3, k6 = 2 * M_PI / 6;
  for (int kind = 0; kind < 3; kind++) {
    mjb::Sea sea = testSea(kind);
    std::vector<mjb::WaveNow> wn(sea.waves.size());
    sea.now(t, wn.data());
    double sA = 0, sAo = 0, sAk = 0, sAok = 0;
    for (const mjb::Wave& w : sea.waves) {
      sA += w.amp;
      sAo += w.amp * w.omega;
      sAk += w.amp * w.k;
      sAok += w.amp * w.omega * w.k / (sea.depth > 0 ? std::tanh(w.k * sea.depth) : 1);
    }
    for (double ks : {0.25, 1.0, 3.0, 6.0}) {
      const double sd = ks / k6;
      const double q[3][3] = {{0.3, -0.2, -0.45},
                              {0.3 + sd, 0.1 * sd, -0.45 - 0.3 * sd},
                              {0.3 + 0.4 * sd, 0.9 * sd - 0.2, -0.45 - 0.5 * sd}};
      mjb::Surf sf;
      Ref cf, rf;
      closedForm(sea, wn.data(), q, &sf, &cf);
      radon(sea, wn.data(), sf, q[0], q[1], q[2], 7, &rf);
      double u[3], v[3], rmax = 0, s2 = 0;
      for (int j = 0; j < 3; j++) {
        u[j] = q[1][j] - q[0][j];
        v[j] = q[2][j] - q[0][j];
      }
      const double area = triArea(q[0], q[1], q[2]);
      for (int c = 0; c < 3; c++) {
        rmax = std::max(rmax, std::sqrt(q[c][0] * q[c][0] + q[c][1] * q[c][1] + q[c][2] * q[c][2]));
        double d2 = 0;
        for (int j = 0; j < 3; j++) d2 += std::pow(q[(c + 1) % 3][j] - q[c][j], 2);
        s2 = std::max(s2, d2);
      }
      double bf = 1e-12, bv = 1e-12;
      if (sea.depth > 0) {
        // the surface slope on the plane (eta linear there) and the bound on
        // the interpolated z' of the comment above
        const double du2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
        const double dv2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        const double uv = u[0] * v[0] + u[1] * v[1] + u[2] * v[2], det = du2 * dv2 - uv * uv;
        const double e1 = sf.eta[1] - sf.eta[0], e2 = sf.eta[2] - sf.eta[0];
        const double G = std::sqrt((e1 * e1 * dv2 - 2 * e1 * e2 * uv + e2 * e2 * du2) / det);
        const double h = sea.depth;
        double b = h + std::min({sf.eta[0], sf.eta[1], sf.eta[2]}), ze = 0;
        for (int c = 0; c < 3; c++) ze = std::max(ze, std::fabs(q[c][2] - sf.eta[c]));
        const double dz = s2 / 6 * (2 * G * (1 + G) * h / (b * b) + 2 * ze * G * G * h / (b * b * b));
        bf += sAk * dz / sA;
        bv += sAok * dz / sAo;
      }
      const double fs = kRho * kG * sA * area, vs = sAo * area;
      double ef = std::fabs(cf.P - rf.P) / fs, em = 0, ev = 0;
      for (int j = 0; j < 3; j++) {
        em = std::max(em, std::fabs(cf.R[j] - rf.R[j]) / (fs * rmax));
        ev = std::max(ev, std::fabs(cf.V[j] - rf.V[j]) / vs);
      }
      std::printf("[waveint] sea %d k s %.2f: force %.1e moment %.1e velocity %.1e (bounds %.1e, "
                  "%.1e)\n", kind, ks, ef, em, ev, bf, bv);
      EXPECT_LT(ef, bf) << kind << " " << ks;
      EXPECT_LT(em, bf) << kind << " " << ks;
      EXPECT_LT(ev, bv) << kind << " " << ks;
    }
  }
}

// libmvec's sin, cos and exp (AVX2, AVX-512) against glibc's scalar ones on
// 4096 arguments each: libmvec is within 4 ulp of the true value and
// glibc's scalar functions within 1 (glibc manual, "Errors in Math
// Functions"), so they differ by at most 5 ulp of the result
TEST(WaveInt, VectorFunctionsWithinTheirUlpBounds) {
  const int prev = mjb::simdLevel(), best = mjb::simdSet(mjb::kSimdAvx512);
  const int n = 4096;
  std::vector<double> x(n), e(n), s(n), c(n), y(n);
  for (int i = 0; i < n; i++) {
    x[i] = -200 + 400.0 * i / n + 1e-3 * std::sin(i);  // phases [rad]
    e[i] = -700 + 710.0 * i / n;                       // exponents
  }
  auto ulp = [](double v) { return std::nextafter(std::fabs(v), INFINITY) - std::fabs(v); };
  for (int level = mjb::kSimdAvx2; level <= best; level++) {
    mjb::simdSet(level);
    mjb::vSinCos(n, x.data(), s.data(), c.data());
    mjb::vExp(n, e.data(), y.data());
    int bad = 0;
    for (int i = 0; i < n; i++) {
      const double rs = std::sin(x[i]), rc = std::cos(x[i]), re = std::exp(e[i]);
      bad += std::fabs(s[i] - rs) > 5 * ulp(rs);
      bad += std::fabs(c[i] - rc) > 5 * ulp(rc);
      bad += std::fabs(y[i] - re) > 5 * ulp(re);
    }
    EXPECT_EQ(bad, 0) << mjb::simdName(level);
    // not the scalar functions under another name: some results differ
    int diff = 0;
    for (int i = 0; i < n; i++) diff += c[i] != std::cos(x[i]) || y[i] != std::exp(e[i]);
    std::printf("[waveint] %s: %d of %d results differ from glibc scalar, all within 5 ulp\n",
                mjb::simdName(level), diff, 2 * n);
  }
  mjb::simdSet(prev);
}

// boats of 576 triangles on a 64-component JONSWAP sea plus a Gerstner
// swell, linear pressure, with mjbuoy.threads = threads
std::string jonswapFleet(int threads) {
  std::ostringstream s;
  s << "<mujoco><option timestep=\"0.002\"/><asset><mesh name=\"w\" file=\"" << MJB_MODELS
    << "/meshes/wigley_576.obj\"/></asset><custom><text name=\"mjbuoy.hulls\" data=\"h*\"/>"
    << "<numeric name=\"mjbuoy.wave.swell\" data=\"0.2 20 20 0 0.5\"/>"
    << "<text name=\"mjbuoy.spectrum.sea.type\" data=\"jonswap\"/>"
    << "<numeric name=\"mjbuoy.spectrum.sea.hs\" data=\"0.6\"/>"
    << "<numeric name=\"mjbuoy.spectrum.sea.tp\" data=\"5\"/>"
    << "<numeric name=\"mjbuoy.spectrum.sea.components\" data=\"64\"/>"
    << "<numeric name=\"mjbuoy.spectrum.sea.spreading\" data=\"10\"/>"
    << "<numeric name=\"mjbuoy.threads\" data=\"" << threads << "\"/></custom><worldbody>";
  for (int i = 0; i < 4; i++) {
    s << "<body pos=\"" << 6 * i << " " << 2 * i << " 0.03\" euler=\"0 " << 3 * i << " " << 20 * i
      << "\"><freejoint/><inertial pos=\"0 0 -0.08\" mass=\"176.2\" diaginertia=\"6.02 237.28 238.6\"/>"
      << "<geom name=\"h" << i << "\" type=\"mesh\" mesh=\"w\" contype=\"0\" conaffinity=\"0\"/>"
      << "</body>";
  }
  s << "</worldbody></mujoco>";
  return s.str();
}

// all wrench parts of every body after 20 steps
std::vector<double> parts(Scene& s) {
  mj_resetData(s.m, s.d);
  for (int i = 0; i < 20; i++) mj_step(s.m, s.d);
  std::vector<double> out;
  for (int p = 0; p < mjbNPART; p++) {
    const mjtNum* w = mjb_wrenchPart(s.b, s.d, p);
    out.insert(out.end(), w, w + 6 * s.m->nbody);
  }
  return out;
}

// the whole cpu pipeline on each vector level against the scalar one:
// every transcendental differs by at most 5 ulp (above), so heights and
// pressures by at most 5 ulp of rho g (sum |A| + the hull's depth) per
// component summed; over a hull's wetted surface S (< 3 m^2 here) and 65
// components the wrench differs by below 65 * 5 * 2^-52 rho g (sum |A| + 1 m)
// S, and 20 steps of motion (rounding-level changes in the state) keep it
// there. Each level repeats itself bit for bit, with 1 or 2 threads
TEST(WaveInt, VectorPathsAgreeWithScalarAndRepeat) {
  const int prev = mjb::simdLevel(), best = mjb::simdSet(mjb::kSimdAvx512);
  Scene one(jonswapFleet(1)), two(jonswapFleet(2));
  ASSERT_TRUE(one.ok() && two.ok()) << one.err << two.err;
  const int nw = mjb_waves(one.b, nullptr, 0);
  std::vector<double> wv(6 * nw);
  mjb_waves(one.b, wv.data(), nw);
  double sA = 0;
  for (int i = 0; i < nw; i++) sA += std::fabs(wv[6 * i]);
  EXPECT_EQ(nw, 65);
  const double tol = 65 * 5 * std::ldexp(1.0, -52) * kRho * kG * (sA + 1) * 3;
  mjb::simdSet(mjb::kSimdScalar);
  const std::vector<double> ref = parts(one);
  double largest = 0;
  for (int level = mjb::kSimdScalar; level <= best; level++) {
    mjb::simdSet(level);
    std::vector<double> a = parts(one), b = parts(one), c = parts(two);
    EXPECT_EQ(a, b) << mjb::simdName(level);
    EXPECT_EQ(a, c) << mjb::simdName(level);
    double worst = 0;
    for (size_t i = 0; i < a.size(); i++) worst = std::max(worst, std::fabs(a[i] - ref[i]));
    largest = std::max(largest, worst);
    std::printf("[waveint] %s: wrench parts differ from scalar by %.2e N (N m), bound %.2e\n",
                mjb::simdName(level), worst, tol);
    EXPECT_LT(worst, tol) << mjb::simdName(level);
  }
  mjb::simdSet(prev);
}

}  // namespace
}  // namespace mjbt
