// waveint: closed-form integrals of linear wave pressure and velocity over
// a wet piece (docs/physics.md, "Pressure"); the series kernels are in
// waveint_kern.h, the scalar one compiled here
#include "sea/waveint.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include "util/vmath.h"
#include "sea/waveint_kern.h"

namespace mjb {

// the largest radius N terms serve, N <= kNMax, when the first term left
// out, m = N, of the widest sum (T_c: C(N+2, 2) monomials of size r^N over
// (N+3)!, leading term 1/6) must be below 2^-bits of the leading term; the
// terms after it shrink by at least half while r <= kRMax and N >= 8, or
// r <= 1 (their ratio r (N+3)/((N+1)(N+4)))
static void radii(int bits, double* rm) {
  rm[0] = 0;
  long double fact = 6;  // (N+3)!
  for (int N = 1; N <= kNMax; N++) {
    fact *= N + 3;
    long double c = std::ldexp(1.0L, -bits) * fact / (3.0L * (N + 1) * (N + 2));
    rm[N] = double(std::pow(c, 1.0L / N));
  }
}

// the bound on S's omitted tail after N terms at radius r: |h_m| <= (m+1)
// r^m (m+1 monomials of size r^m), so |S - S_N| <= sum_(m>=N) (m+1) r^m /
// (m+2)!; summed to m = N + 60, where the terms' ratio r (m+2) / ((m+1)
// (m+3)) is below 1/15 for r <= kRMax, the rest a geometric series
static double tailS(int N, double r) {
  long double t = std::pow((long double)r, N) * (N + 1), s = 0;
  for (int m = N + 2; m >= 2; m--) t /= m;  // (m+2)! at m = N
  for (int m = N; m <= N + 60; m++) {
    s += t;
    t *= r * (m + 2) / ((long double)(m + 1) * (m + 3));
  }
  return double(s + t * 15 / 14);
}

// the largest r <= kRMax with tailS(N, r) <= 2^-b (bisection; tailS rises
// with r), rounded down so the radius is never too large
static void radiiTail(int b, double* rm) {
  rm[0] = 0;
  const double tol = std::ldexp(1.0, -b);
  for (int N = 1; N <= kNMax; N++) {
    double lo = 0, hi = kRMax;
    if (tailS(N, hi) <= tol) {
      rm[N] = hi;
      continue;
    }
    for (int it = 0; it < 60; it++) {
      const double mid = 0.5 * (lo + hi);
      (tailS(N, mid) <= tol ? lo : hi) = mid;
    }
    rm[N] = lo;
  }
}

// 1/(m+2)!, 1/(m+3)!, and the largest radius N terms serve: the scalar
// reference's (seriesTerms), the vector lanes' (kSeriesRv) and the loose
// series' (kSeriesRb)
struct Tables {
  double f2[kNMax], f3[kNMax], rm[kNMax + 1], rv[kNMax + 1];
  double rb[kSeriesBitsV][kNMax + 1];
  Tables() {
    long double a = 0.5L, b = 1.0L / 6;
    for (int m = 0; m < kNMax; m++) {
      f2[m] = double(a);
      f3[m] = double(b);
      a /= m + 3;
      b /= m + 4;
    }
    radii(54, rm);
    radii(kSeriesBitsV, rv);
    for (int b = 1; b < kSeriesBitsV; b++) radiiTail(b, rb[b]);
  }
};
static const Tables kTab;
const double* kInvF2 = kTab.f2;
const double* kInvF3 = kTab.f3;
const double* kSeriesR = kTab.rm;
const double* kSeriesRv = kTab.rv;
const double* kSeriesRb = &kTab.rb[0][0];

int seriesTerms(double r) {
  int N = 1;
  while (N < kNMax && !(r <= kTab.rm[N])) N++;
  return N;
}

void seriesScalar(const KernIn& in, int j0, int j1, double out[7]) {
  seriesRange<1>(in, j0, j1, out);
}

void seriesSums(const KernIn& in, int j0, int j1, double out[7]) {
  switch (simdLevel()) {
    case kSimdAvx512: seriesAvx512(in, j0, j1, out); return;
    case kSimdAvx2: seriesAvx2(in, j0, j1, out); return;
  }
  seriesScalar(in, j0, j1, out);
}

void WaveTab::reserve(size_t cap) {
  perm.resize(cap);
  for (auto* v : {&k, &kdx, &kdy, &gm, &wp[0], &wux[0], &wuy[0], &wz[0], &wp[1], &wux[1],
                  &wuy[1], &wz[1]}) {
    v->assign(cap, 0);
  }
}

void WaveTab::fill(const Sea& sea, const WaveNow* w) {
  n = sea.order.size();
  finite = sea.depth > 0;
  depth = sea.depth;
  for (int i = 0; i < n; i++) perm[i] = i;
  // ascending k, ties by index: the same order on every call
  std::sort(perm.begin(), perm.begin() + n, [w](int a, int b) {
    return w[a].k < w[b].k || (w[a].k == w[b].k && a < b);
  });
  ident = true;
  for (int j = 0; j < n; j++) ident = ident && perm[j] == j;
  // (directions compared exactly: a spectrum's long-crested components
  // share the one cos and sin)
  lc = n >= 2;
  for (int j = 1; j < n && lc; j++) {
    lc = w[j].dx == w[0].dx && w[j].dy == w[0].dy && (j < sea.ng) == (0 < sea.ng);
  }
  ldx = n > 0 ? w[0].dx : 0;
  ldy = n > 0 ? w[0].dy : 0;
  lgm = 0 < sea.ng ? 1 : 0;
  for (int j = 0; j < n; j++) {
    const WaveNow& c = w[perm[j]];
    k[j] = c.k;
    kdx[j] = c.k * c.dx;
    kdy[j] = c.k * c.dy;
    gm[j] = perm[j] < sea.ng ? 1 : 0;
    if (!finite) {
      // deep: every profile is e^(k z')
      wp[0][j] = c.amp;
      wux[0][j] = c.ao * c.dx;
      wuy[0][j] = c.ao * c.dy;
      wz[0][j] = c.ao;
      continue;
    }
    // cosh(k(z'+h))/cosh(kh) = (e^(kz') + e^(-k(z'+2h)))/(1 + e^(-2kh)),
    // cosh/sinh(kh) and sinh/sinh(kh) the same over 1 - e^(-2kh) (with
    // the second exponent subtracted for sinh): Dean & Dalrymple ch. 4
    const double D = c.k * depth, e2 = std::exp(-2 * D), sd = -std::expm1(-2 * D);
    wp[0][j] = wp[1][j] = c.amp / (1 + e2);
    wux[0][j] = wux[1][j] = c.ao * c.dx / sd;
    wuy[0][j] = wuy[1][j] = c.ao * c.dy / sd;
    wz[0][j] = c.ao / sd;
    wz[1][j] = -c.ao / sd;
  }
}

using cplx = std::complex<double>;

// S and T_c of one component by the series about corner 0 (e0 = e^L0)
static void leaf(cplx e0, cplx u1, cplx u2, cplx* S, cplx T[3]) {
  const int N = seriesTerms(std::max(std::abs(u1), std::abs(u2)));
  cplx p = 1, h = 1, g = 1, f = 1, s = kInvF2[0], t0 = kInvF3[0], t1 = t0, t2 = t0;
  for (int m = 1; m < N; m++) {
    p *= u2;
    h = u1 * h + p;
    g = u1 * g + h;
    f = u2 * f + h;
    s += kInvF2[m] * h;
    t0 += kInvF3[m] * h;
    t1 += kInvF3[m] * g;
    t2 += kInvF3[m] * f;
  }
  *S = e0 * s;
  T[0] = e0 * t0;
  T[1] = e0 * t1;
  T[2] = e0 * t2;
}

// the four halves: corner 0's exponent offset (in u1, u2 halves), the
// children's u1, u2 signs, and each child corner's barycentrics in the parent
static const double kOff[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
static const double kSgn[4] = {1, 1, 1, -1};
static const double kBar[4][3][3] = {
    {{1, 0, 0}, {.5, .5, 0}, {.5, 0, .5}},
    {{.5, .5, 0}, {0, 1, 0}, {0, .5, .5}},
    {{.5, 0, .5}, {0, .5, .5}, {0, 0, 1}},
    {{0, .5, .5}, {.5, 0, .5}, {.5, .5, 0}}};

static void subRec(double L0r, cplx ph, cplx u1, cplx u2, int depth, cplx* S, cplx T[3]) {
  if (std::max(std::abs(u1), std::abs(u2)) <= kRMax || depth >= 8) {
    leaf(std::exp(L0r) * ph, u1, u2, S, T);
    return;
  }
  *S = 0;
  T[0] = T[1] = T[2] = 0;
  const cplx h1 = 0.5 * u1, h2 = 0.5 * u2;
  for (int c = 0; c < 4; c++) {
    const cplx o = kOff[c][0] * h1 + kOff[c][1] * h2;
    cplx s, t[3];
    subRec(L0r + o.real(), ph * std::exp(cplx(0, o.imag())), kSgn[c] * h1, kSgn[c] * h2,
           depth + 1, &s, t);
    *S += 0.25 * s;
    for (int a = 0; a < 3; a++) {
      for (int b = 0; b < 3; b++) T[b] += 0.25 * kBar[c][a][b] * t[a];
    }
  }
}

void subdivided(double L0r, double phr, double phi, double u1r, double u1i, double u2r,
                double u2i, double S[2], double T[3][2]) {
  cplx s, t[3];
  subRec(L0r, cplx(phr, phi), cplx(u1r, u1i), cplx(u2r, u2i), 0, &s, t);
  S[0] = s.real();
  S[1] = s.imag();
  for (int c = 0; c < 3; c++) {
    T[c][0] = t[c].real();
    T[c][1] = t[c].imag();
  }
}

// first j with k[j] > x (k ascending)
static int above(const WaveTab& t, double x) {
  return std::upper_bound(t.k.begin(), t.k.begin() + t.n, x) - t.k.begin();
}

void pieceIntegrals(const WaveTab& t, const Sea& sea, const double* const E0[4],
                    const double* sc0, const double q[3][3], const double zs[3],
                    const double lab[3][2], double area, bool moments, double* P,
                    double Pr[3], double V[3]) {
  KernIn in;
  in.k = t.k.data();
  in.kdx = t.kdx.data();
  in.kdy = t.kdy.data();
  in.gm = t.gm.data();
  double rho = 0;
  for (int c = 0; c < 2; c++) {
    in.dz[c] = zs[c + 1] - zs[0];
    double hp = 0, hl = 0;
    for (int j = 0; j < 2; j++) {
      in.dp[c][j] = q[c + 1][j] - q[0][j];
      in.dl[c][j] = lab[c + 1][j] - lab[0][j];
      hp += in.dp[c][j] * in.dp[c][j];
      hl += in.dl[c][j] * in.dl[c][j];
    }
    // |u_c| = k |(dz, D . dx)| <= k sqrt(dz^2 + |dx|^2)
    rho = std::max(rho, std::sqrt(in.dz[c] * in.dz[c] + std::max(hp, hl)));
  }
  in.rho = rho;
  in.mom = moments;
  const double zmax = std::max({zs[0], zs[1], zs[2]}), zmin = std::min({zs[0], zs[1], zs[2]});
  // past this k the piece is too coarse for the series: subdivided
  const int jfb = rho > 0 ? above(t, kRMax / rho) : t.n;
  double out[7] = {0, 0, 0, 0, 0, 0, 0};
  for (int f = 0; f < (t.finite ? 2 : 1); f++) {
    // components whose largest exponent on the piece is below -40
    // (e^-40 < 5e-18) add nothing in double: past jsk
    const double zx = f == 0 ? -zmax : zmin + 2 * t.depth;
    const int jsk = zx > 0 ? above(t, 40 / zx) : t.n;
    in.wp = t.wp[f].data();
    in.wux = t.wux[f].data();
    in.wuy = t.wuy[f].data();
    in.wz = t.wz[f].data();
    in.e0r = E0[2 * f];
    in.e0i = E0[2 * f + 1];
    in.sgn = f == 0 ? 1 : -1;
    seriesSums(in, 0, std::min(jfb, jsk), out);
    for (int j = jfb; j < jsk; j++) {
      double u[2][2], S[2], T[3][2];
      for (int c = 0; c < 2; c++) {
        double X = in.dp[c][0] + t.gm[j] * (in.dl[c][0] - in.dp[c][0]);
        double Y = in.dp[c][1] + t.gm[j] * (in.dl[c][1] - in.dp[c][1]);
        u[c][0] = in.sgn * in.dz[c] * t.k[j];
        u[c][1] = t.kdx[j] * X + t.kdy[j] * Y;
      }
      const int i = t.perm[j];
      const double L0r = f == 0 ? t.k[j] * zs[0] : -t.k[j] * (zs[0] + 2 * t.depth);
      subdivided(L0r, sc0[2 * i + 1], sc0[2 * i], u[0][0], u[0][1], u[1][0], u[1][1], S, T);
      out[0] += in.wp[j] * S[0];
      for (int c = 0; c < 3; c++) out[1 + c] += in.wp[j] * T[c][0];
      out[4] += in.wux[j] * S[0];
      out[5] += in.wuy[j] * S[0];
      out[6] += in.wz[j] * S[1];
    }
  }
  const double a2 = 2 * area, rg = sea.rho * sea.g;
  *P += rg * a2 * out[0];
  for (int j = 0; j < 3; j++) {
    Pr[j] += rg * a2 * (out[1] * q[0][j] + out[2] * q[1][j] + out[3] * q[2][j]);
    V[j] += a2 * out[4 + j];
  }
}

}  // namespace mjb
