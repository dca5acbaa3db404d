// tabulated wave Green function (greentab.h, docs/physics.md section 13)
#include "radiation/greentab.h"

#include <atomic>
#include <cmath>
#include <mutex>
#include <new>
#include <thread>

namespace mjb {

namespace {

const double kPi = 3.14159265358979323846;
const double kRhoMin = 1e-3;  // below: direct (cheap there, and rare)
const double kRhoA = 2;       // polar grid below, (X, Y) grid above
const double kH = 0.05;       // (X, Y) grid step
const double kHs = 0.02;      // polar steps in ln rho and theta
const int kNt = 96;           // theta intervals over [0, pi/2]
const double kXcap = 100, kYcap = 40;  // largest tabulated range

std::mutex gMutex;
std::shared_ptr<const GreenTable> gTable;
std::atomic<bool> gUse{true};

// runs f(i) for i in [0, n) on two threads (interleaved rows)
template <class Fn>
void rows(int n, Fn f) {
  auto run = [&](int t, int nt) {
    for (int i = t; i < n; i += nt) f(i);
  };
  try {
    std::thread th(run, 1, 2);
    run(0, 2);
    th.join();
  } catch (...) {
    run(0, 1);  // no second thread: all rows here
  }
}

// 4-point Lagrange weights at t in node units from the stencil's first node
void lagrange4(double t, double w[4]) {
  double a = t, b = t - 1, c = t - 2, d = t - 3;
  w[0] = -b * c * d / 6;
  w[1] = a * c * d / 2;
  w[2] = -a * b * d / 2;
  w[3] = a * b * c / 6;
}

// first node of the stencil about u (node units) on n nodes, and weights
int stencil(double u, int n, double w[4]) {
  int i = (int)std::floor(u) - 1;
  if (i < 0) i = 0;
  if (i > n - 4) i = n - 4;
  lagrange4(u - i, w);
  return i;
}

double interp(const std::vector<double>& v, int stride, int i, int j, const double* wi,
              const double* wj) {
  double s = 0;
  for (int b = 0; b < 4; b++) {
    const double* r = &v[(j + b) * stride + i];
    s += wj[b] * (wi[0] * r[0] + wi[1] * r[1] + wi[2] * r[2] + wi[3] * r[3]);
  }
  return s;
}

GreenTable* build(double xmax, double ymax) {
  GreenTable* t = new (std::nothrow) GreenTable;
  if (!t) return nullptr;
  try {
    t->h = kH;
    t->nx = (int)std::ceil(xmax / kH) + 4;
    t->ny = (int)std::ceil(ymax / kH) + 4;
    t->xmax = (t->nx - 4) * kH;
    t->ymax = (t->ny - 4) * kH;
    t->F.resize((size_t)t->nx * t->ny);
    t->FX.resize((size_t)t->nx * t->ny);
    t->J0.resize(t->nx);
    t->J1.resize(t->nx);
    t->s0 = std::log(kRhoMin) - 2 * kHs;
    t->hs = kHs;
    t->ns = (int)std::ceil((std::log(kRhoA) - t->s0) / kHs) + 3;
    t->nt = kNt + 1;
    t->ht = 0.5 * kPi / kNt;
    t->pF.resize((size_t)t->ns * t->nt);
    t->pFX.resize((size_t)t->ns * t->nt);
  } catch (...) {
    delete t;
    return nullptr;
  }
  for (int i = 0; i < t->nx; i++) {
    double y0, y1, x = i * kH;
    if (i == 0) {
      t->J0[i] = 1, t->J1[i] = 0;
    } else {
      bessel01(x, &t->J0[i], &t->J1[i], &y0, &y1);
    }
  }
  rows(t->ny, [t](int j) {
    for (int i = 0; i < t->nx; i++) {
      WaveF f = greenWave(i * kH, j * kH);
      // the origin node (F infinite) is in no stencil: points there have
      // rho >= kRhoA; kept finite all the same
      if (i == 0 && j == 0) f.F = f.FX = 0;
      t->F[(size_t)j * t->nx + i] = f.F;
      t->FX[(size_t)j * t->nx + i] = f.FX;
    }
  });
  rows(t->nt, [t](int j) {
    double th = j * t->ht, c = std::cos(th), s = std::sin(th);
    if (j == t->nt - 1) c = 0, s = 1;
    for (int i = 0; i < t->ns; i++) {
      double r = std::exp(t->s0 + i * t->hs);
      WaveF f = greenWave(r * c, r * s);
      t->pF[(size_t)j * t->ns + i] = f.F;
      t->pFX[(size_t)j * t->ns + i] = r * f.FX;
    }
  });
  return t;
}

}  // namespace

void greenTableUse(bool on) { gUse = on; }

std::shared_ptr<const GreenTable> greenTable(double xmax, double ymax) {
  if (!gUse) return nullptr;
  // ranges rounded up (fewer rebuilds) and capped
  xmax = std::fmin(kXcap, 8 * std::ceil(std::fmax(xmax, kRhoA) / 8));
  ymax = std::fmin(kYcap, 4 * std::ceil(std::fmax(ymax, kRhoA) / 4));
  std::lock_guard<std::mutex> l(gMutex);
  if (gTable && gTable->xmax >= xmax && gTable->ymax >= ymax) return gTable;
  if (gTable) xmax = std::fmax(xmax, gTable->xmax), ymax = std::fmax(ymax, gTable->ymax);
  GreenTable* t = build(xmax, ymax);
  if (t) gTable.reset(t);
  return gTable;
}

WaveF greenWaveTab(const GreenTable* t, double X, double Y) {
  double rho = std::sqrt(X * X + Y * Y);
  if (!t || rho < kRhoMin || X > t->xmax || Y > t->ymax) return greenWave(X, Y);
  WaveF r;
  double wi[4], wj[4];
  int i = stencil(X / t->h, t->nx, wi);
  r.J0 = wi[0] * t->J0[i] + wi[1] * t->J0[i + 1] + wi[2] * t->J0[i + 2] + wi[3] * t->J0[i + 3];
  r.J1 = wi[0] * t->J1[i] + wi[1] * t->J1[i + 1] + wi[2] * t->J1[i + 2] + wi[3] * t->J1[i + 3];
  if (rho < kRhoA) {
    int is = stencil((std::log(rho) - t->s0) / t->hs, t->ns, wi);
    int it = stencil(std::atan2(Y, X) / t->ht, t->nt, wj);
    r.F = interp(t->pF, t->ns, is, it, wi, wj);
    r.FX = interp(t->pFX, t->ns, is, it, wi, wj) / rho;
  } else {
    int j = stencil(Y / t->h, t->ny, wj);
    r.F = interp(t->F, t->nx, i, j, wi, wj);
    r.FX = interp(t->FX, t->nx, i, j, wi, wj);
  }
  r.FY = -r.F - 1 / rho;
  return r;
}

}  // namespace mjb
