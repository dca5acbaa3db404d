// libFuzzer target: one hull triangle through the per-triangle kernels.
// Bytes -> a triangle (3 vertices [m]), its vertex heights above the water
// [m], a velocity, force coefficients and a Gerstner sea, all finite and
// inside the ranges that mjbuoy's configuration accepts (docs/mjcf.md),
// then wetTriangle (pressure.h), the hydro forces (hydro.h) and the sea
// (sea.h). Fails (trap) on any non-finite output and on a broken physics
// invariant: 0 <= wet area <= area, 0 <= integral(d dA) <= area * max depth
// (so |F| = rho g dA <= rho g area max depth along n), the centre of
// pressure on the triangle, viscous force tangential and opposing the
// flow, drag along n, slamming opposing the motion, surface height within
// the sum of amplitudes of the still level.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fuzzer/FuzzedDataProvider.h>

#include "hull/hydro.h"
#include "hull/pressure.h"
#include "sea/sea.h"

namespace {

// report what broke, then trap so libFuzzer records the input
#define REQUIRE(c)                                                        \
  do {                                                                    \
    if (!(c)) {                                                           \
      std::fprintf(stderr, "fuzz_kernel: %s:%d: %s\n", __FILE__, __LINE__, #c); \
      __builtin_trap();                                                   \
    }                                                                     \
  } while (0)

// a value in [lo, hi]; a selector byte favours the values where kernels
// divide or branch: 0, the smallest subnormal, +-1 and the range ends
double val(FuzzedDataProvider& in, double lo, double hi) {
  double v;
  switch (in.ConsumeIntegralInRange<int>(0, 9)) {
    case 0: v = 0; break;
    case 1: v = 4.9e-324; break;
    case 2: v = -4.9e-324; break;
    case 3: v = 1; break;
    case 4: v = -1; break;
    case 5: v = lo; break;
    case 6: v = hi; break;
    default: v = in.ConsumeFloatingPointInRange<double>(lo, hi);
  }
  return std::clamp(v, lo, hi);
}

// absolute slack of the force direction and sign checks [N, N m/s]: the
// special values include subnormal coefficients, whose products are
// subnormal forces that round in absolute terms (direction meaningless)
const double kTiny = 1e-290;

bool finite(const double* v, int n) {
  for (int i = 0; i < n; i++) if (!std::isfinite(v[i])) return false;
  return true;
}

double dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double norm(const double a[3]) { return std::sqrt(dot(a, a)); }

void kernels(FuzzedDataProvider& in) {
  // triangle: coordinates up to 1 km; mode 1 makes it (nearly) collinear,
  // mode 2 repeats a vertex, where the normal is ill-conditioned
  double p[3][3], h[3];
  for (auto& v : p) for (double& x : v) x = val(in, -1e3, 1e3);
  int mode = in.ConsumeIntegralInRange<int>(0, 3);
  if (mode == 1) {
    double s = val(in, -2, 2), e = val(in, -1e-6, 1e-6);
    for (int j = 0; j < 3; j++) p[2][j] = p[0][j] + s * (p[1][j] - p[0][j]) + (j == 2 ? e : 0);
  } else if (mode == 2) {
    for (int j = 0; j < 3; j++) p[2][j] = p[0][j];
  }
  for (double& x : h) x = val(in, -1e3, 1e3);

  mjb::Wet w;
  mjb::wetTriangle(p, h, &w);
  REQUIRE(std::isfinite(w.area) && std::isfinite(w.dA));
  REQUIRE(finite(w.drA, 3) && finite(w.rA, 3) && finite(w.n, 3) && finite(&w.q[0][0], 12));
  REQUIRE(w.nq == 0 || w.nq == 3 || w.nq == 4);

  double e1[3], e2[3], c[3], L = 0, dmax = 0;
  for (int j = 0; j < 3; j++) {
    e1[j] = p[1][j] - p[0][j];
    e2[j] = p[2][j] - p[0][j];
  }
  c[0] = e1[1] * e2[2] - e1[2] * e2[1];
  c[1] = e1[2] * e2[0] - e1[0] * e2[2];
  c[2] = e1[0] * e2[1] - e1[1] * e2[0];
  double area = 0.5 * norm(c);
  for (auto& v : p) for (double x : v) L = std::max(L, std::fabs(x));
  for (double x : h) dmax = std::max(dmax, -x);
  // rounding of cross products of coordinates of size L
  double tol = 1e-12 * (L * L + 1) + 1e-9 * area;
  double nn = norm(w.n);
  REQUIRE(nn == 0 || std::fabs(nn - 1) < 1e-12);
  REQUIRE(w.area >= -tol && w.area <= area + tol);
  // (1e-300: products of subnormal depths round in absolute, not relative, terms)
  REQUIRE(w.dA >= -tol * dmax - 1e-300 && w.dA <= (area + tol) * dmax * (1 + 1e-12) + 1e-300);
  if (h[0] >= 0 && h[1] >= 0 && h[2] >= 0) REQUIRE(w.area == 0 && w.dA == 0);
  if (h[0] < 0 && h[1] < 0 && h[2] < 0 && nn > 0) {
    REQUIRE(std::fabs(w.area - area) <= tol);
    if (dmax > 1e-100) REQUIRE(std::fabs(w.dA + area * (h[0] + h[1] + h[2]) / 3) <= tol * dmax * 4);
  }
  // centre of pressure drA / dA on the triangle: inside its bounding box,
  // where the integrals are well above rounding (subnormal depths are not)
  if (dmax > 1e-100 && w.dA > 1e-6 * area * dmax && area > 1e-6 * (L * L + 1)) {
    for (int j = 0; j < 3; j++) {
      double cp = w.drA[j] / w.dA;
      double lo = std::min({p[0][j], p[1][j], p[2][j]}), hi = std::max({p[0][j], p[1][j], p[2][j]});
      REQUIRE(cp >= lo - 1e-6 * (L + 1) && cp <= hi + 1e-6 * (L + 1));
    }
  }

  // hydro forces on the wet part: velocities up to 50 m/s, water and
  // hull coefficients over their accepted ranges (config.cc)
  double v[3], vprev[3], f[3];
  for (double& x : v) x = val(in, -50, 50);
  for (double& x : vprev) x = val(in, -50, 50);
  double rho = val(in, 1e-3, 1e5), nu = val(in, 1e-9, 1), len = val(in, 1e-3, 1e3);
  double A = w.area > 0 ? w.area : 0, sp = norm(v);
  double cf = mjb::ittc57(sp * len / nu);
  REQUIRE(std::isfinite(cf) && cf > 0 && cf <= mjb::ittc57(mjb::kRnMin) * (1 + 1e-12));
  double ff = val(in, 0, 3);
  mjb::viscousForce(rho, cf, ff, A, w.n, v, f);
  REQUIRE(finite(f, 3));
  double fl = norm(f), bound = 0.5 * rho * cf * ff * A * sp * sp;
  REQUIRE(fl <= bound * (1 + 1e-9) + kTiny);
  // tangential and against the tangential flow t = v - (v.n) n; t has
  // rounding of order eps |v|, large relative to |t| for flow along n
  double t[3], vn = dot(v, w.n);
  for (int j = 0; j < 3; j++) t[j] = v[j] - vn * w.n[j];
  double tl = norm(t), slack = tl > 0 ? 1e-13 * fl * (sp / tl + 1) : 0;
  REQUIRE(std::fabs(dot(f, w.n)) <= slack + kTiny);
  REQUIRE(dot(f, v) <= slack * sp + kTiny);

  double drag[3] = {val(in, 0, 1e5), val(in, 0, 1e5), val(in, 0, 8)};
  double suction[3] = {val(in, 0, 1e5), val(in, 0, 1e5), val(in, 0, 8)};
  double vr = val(in, 1e-3, 1e3);
  mjb::dragForce(drag, suction, vr, A, w.n, v, f);
  REQUIRE(finite(f, 3));
  // along n: pushes back on an advancing face, pulls on a retreating one
  double fn = dot(f, w.n);
  // componentwise, since |f|^2 underflows for forces below 1e-154 N
  for (int j = 0; j < 3; j++) REQUIRE(std::fabs(f[j] - fn * w.n[j]) <= 1e-9 * std::fabs(fn) + kTiny);
  REQUIRE(!(vn > 0) || fn <= kTiny);
  REQUIRE(!(vn < 0) || fn >= -kTiny);

  double gain = val(in, 0, 1), gmax = val(in, 1e-3, 1e4), pw = val(in, 1e-3, 16);
  double mass = val(in, 1e-3, 1e6), dt = val(in, 1e-5, 0.1);
  double shull = std::max(area, val(in, 1e-3, 1e4));
  double aprev = val(in, 0, area);
  if (A > 0) {
    float qf[3], qpf[3];
    mjb::sweptRate(A, v, qf);
    mjb::sweptRate(aprev, vprev, qpf);
    const double q[3] = {qf[0], qf[1], qf[2]}, qp[3] = {qpf[0], qpf[1], qpf[2]};
    mjb::slamForce(gain, gmax, pw, mass, shull, area, A, v, q, qp, w.n, dt, f);
    REQUIRE(finite(f, 3));
    REQUIRE(dot(f, v) <= kTiny);  // opposes the motion: never reverses it
    REQUIRE(norm(f) <= gain * mass * 2 * A / shull / dt * sp * (1 + 1e-9));
  }
}

void sea(FuzzedDataProvider& in) {
  // a Gerstner sea the configuration accepts: up to 4 waves, fold < 1
  mjb::Sea s;
  s.rho = 1000;
  s.level = val(in, -100, 100);
  s.depth = in.ConsumeBool() ? 0 : val(in, 1e-3, 1e5);
  s.current[0] = val(in, -10, 10);
  s.current[1] = val(in, -10, 10);
  int n = in.ConsumeIntegralInRange<int>(0, 4);
  double amps = 0;
  for (int i = 0; i < n; i++) {
    mjb::Wave w{};
    w.amp = val(in, 0, 20);
    w.len = val(in, 1e-2, 1e4);
    w.dir = val(in, -720, 720);
    w.phase = val(in, -720, 720);
    w.steep = val(in, 0, 1);
    s.waves.push_back(w);
    amps += w.amp;
  }
  s.derive();
  if (!(s.fold() < 1)) return;  // rejected by config.cc
  double x = val(in, -1e4, 1e4), y = val(in, -1e4, 1e4), t = val(in, 0, 1e5);
  double z = s.height(x, y, t);
  REQUIRE(std::isfinite(z));
  REQUIRE(std::fabs(z - s.level) <= amps * (1 + 1e-12) + 1e-9);
  double q[3] = {x, y, s.level + val(in, -1e3, 1e3)}, u[3];
  s.velocity(q, t, u);
  REQUIRE(finite(u, 3));
  // linear theory (docs/physics.md section 11), Wheeler-stretched to z' in
  // [-h, 0]: per wave |u|^2 = (A omega)^2 (cosh^2 cos^2 + sinh^2 sin^2) of
  // k (z' + h) over sinh^2 k h, at most (A omega coth k h)^2 (the surface in
  // finite depth); deep water e^(2 k z') (A omega)^2 <= (A omega)^2. Q plays
  // no part
  double vmax = std::hypot(s.current[0], s.current[1]);
  for (const mjb::Wave& w : s.waves) {
    vmax += w.amp * w.omega * (s.depth > 0 ? 1 / std::tanh(w.k * s.depth) : 1.0);
  }
  REQUIRE(norm(u) <= vmax * (1 + 1e-9) + 1e-12);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  if (in.ConsumeBool()) {
    kernels(in);
  } else {
    sea(in);
  }
  return 0;
}
