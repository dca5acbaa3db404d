// diffraction excitation (diffract.h, docs/physics.md section 15)
#include "radiation/diffract.h"
#include "radiation/driftstep.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "util/bodylabel.h"

namespace mjb {

const std::vector<double>& SharedTable::none() {
  static const std::vector<double> e;
  return e;
}

bool SharedTable::share(const SharedTable& o, const std::vector<double>& v) {
  if (o.empty() || o.size() != v.size() ||
      std::memcmp(o.data(), v.data(), v.size() * sizeof(double)) != 0)
    return false;
  *this = o;
  return true;
}

std::string setDiffraction(int body, const double R0[9], const HydroCoef& c, size_t wcap,
                           Diffraction* df) {
  const int nw = c.nw(), nh = c.nh();
  const size_t nx = 6 * (size_t)nw * nh;
  if (nw < 1 || nh != kDiffHeadings || c.Xre.size() != nx || c.Xim.size() != nx ||
      c.FKre.size() != nx || c.FKim.size() != nx) {
    return "mjbuoy: diffraction: the exciting-force table needs " +
           std::to_string(kDiffHeadings) + " headings and 6 values per frequency and heading";
  }
  for (int h = 0; h < nh; h++) {
    if (std::fabs(c.heading[h] - 2 * M_PI * h / nh) > 1e-12) {
      return "mjbuoy: diffraction: the headings must be uniform from 0";
    }
  }
  DiffBody b;
  b.body = body;
  std::memcpy(b.R0, R0, sizeof(b.R0));
  b.c = c;
  std::vector<double> D(2 * nx);
  for (size_t i = 0; i < nx; i++) {
    D[2 * i] = c.Xre[i] - c.FKre[i];
    D[2 * i + 1] = c.Xim[i] - c.FKim[i];
    if (!std::isfinite(D[2 * i]) || !std::isfinite(D[2 * i + 1])) {
      return "mjbuoy: diffraction: the exciting force is not finite";
    }
  }
  // an identical hull's table, if any, else its own
  bool shared = false;
  for (const DiffBody& o : df->db)
    if (o.body != body && (shared = b.D.share(o.D, D))) break;
  if (!shared) b.D = std::move(D);
  b.iw.reserve(wcap);
  b.tw.reserve(wcap);
  for (DiffBody& o : df->db) {
    if (o.body == body) {
      o = std::move(b);
      return "";
    }
  }
  df->db.push_back(std::move(b));
  return "";
}

void diffRow(const std::vector<double>& omega, double w, int* iw, double* tw) {
  const int n = omega.size();
  if (!(w > 0) || n == 0 || w > omega[n - 1]) {
    *iw = -2;  // beyond the table (or a still component): no force
    *tw = 0;
  } else if (w < omega[0]) {
    *iw = -1;  // D -> 0 as omega -> 0: linear from 0 to the first row
    *tw = w / omega[0];
  } else {
    int i = 0;
    while (i < n - 2 && omega[i + 1] <= w) i++;
    *iw = i;
    *tw = n > 1 ? (w - omega[i]) / (omega[i + 1] - omega[i]) : 0;
  }
}

void diffSea(const Sea& sea, Diffraction* df) {
  const size_t n = sea.waves.size();
  for (DiffBody& b : df->db) {
    b.iw.resize(n);  // within the capacity reserved at attach
    b.tw.resize(n);
    for (size_t j = 0; j < n; j++) {
      const Wave& w = sea.waves[j];
      if (w.amp == 0) {
        b.iw[j] = -2;
        b.tw[j] = 0;
      } else {
        diffRow(b.c.omega, w.omega, &b.iw[j], &b.tw[j]);
      }
    }
  }
}

// periodic Catmull-Rom weights (headingWeights), inlined in the step's pass:
// u = beta n / 2 pi splits into floor(u) and s = u - floor(u) (exact), the
// index floor(u) mod n; no division. A non-finite beta gives NaN weights at
// index 0 (the step reports the force)
__attribute__((always_inline)) static inline void headingAt(double beta, int n, int idx[4],
                                                            double w[4]) {
  const double u = beta * n / (2 * M_PI);
  const double fl = std::floor(u);
  double s = u - fl;
  int i = 0;
  if (std::fabs(fl) < 0x1p52) {  // else u is not finite (beta is): s NaN
    long long q = (long long)fl;  // exact
    q += q < 0 ? n : q >= n ? -n : 0;  // a heading less a yaw: within one turn
    if (q < 0 || q >= n) {  // more than a turn off
      q %= n;
      if (q < 0) q += n;
    }
    i = (int)q;
  } else {
    s = NAN;
  }
  const double s2 = s * s, s3 = s2 * s;
  w[0] = 0.5 * (-s3 + 2 * s2 - s);
  w[1] = 0.5 * (3 * s3 - 5 * s2 + 2);
  w[2] = 0.5 * (-3 * s3 + 4 * s2 + s);
  w[3] = 0.5 * (s3 - s2);
  // i - 1 + k in [-1, n + 1]: wrapped by one period
  for (int k = 0; k < 4; k++) {
    const int h = i - 1 + k;
    idx[k] = h < 0 ? h + n : h >= n ? h - n : h;
  }
}

void headingWeights(double beta, int n, int idx[4], double w[4]) { headingAt(beta, n, idx, w); }

// tableWeights, inlined in the step's pass
__attribute__((always_inline)) static inline void weightsAt(int nh, int iw, double tw,
                                                            double beta, TableWeights* out) {
  out->n = 0;
  if (iw == -2) return;
  int idx[4];
  double hw[4];
  headingAt(beta, nh, idx, hw);
  const int r0 = iw < 0 ? 0 : iw;
  const double w0 = iw < 0 ? tw : 1 - tw, w1 = iw < 0 ? 0 : tw;
  for (int r = 0; r < 2; r++) {
    const double wr = r ? w1 : w0;
    if (wr == 0) continue;
    for (int k = 0; k < 4; k++) {
      out->off[out->n] = (r0 + r) * nh + idx[k];
      out->f[out->n++] = wr * hw[k];
    }
  }
}

void tableWeights(int nh, int iw, double tw, double beta, TableWeights* out) {
  weightsAt(nh, iw, tw, beta, out);
}

// sum of the weighted table entries: (re, im) per dof, 12 contiguous values
static inline void blendD(const double* D, const TableWeights& tw, double acc[12]) {
  for (int k = 0; k < 12; k++) acc[k] = 0;
  for (int i = 0; i < tw.n; i++) {
    const double* p = D + 12 * (size_t)tw.off[i];
    const double f = tw.f[i];
    for (int k = 0; k < 12; k++) acc[k] += f * p[k];
  }
}

void diffAt(const DiffBody& b, int iw, double tw, double beta, double re[6], double im[6]) {
  TableWeights w;
  tableWeights(b.c.nh(), iw, tw, beta, &w);
  double acc[12];
  blendD(b.D.data(), w, acc);
  for (int k = 0; k < 6; k++) {
    re[k] = acc[2 * k];
    im[k] = acc[2 * k + 1];
  }
}

// components per block of phases on the stack
static const int kBlock = 64;

void diffractionWrench(const DiffBody& b, const Sea& sea, const double x[3], double psi,
                       double t, double F[6]) {
  for (int k = 0; k < 6; k++) F[k] = 0;
  const size_t n = sea.waves.size() < b.iw.size() ? sea.waves.size() : b.iw.size();
  const double r = sea.gain(t);  // the start-up ramp on every amplitude (sea.h)
  const int nh = b.c.nh();
  const double* D = b.D.data();
  DriftSum ds;
  double ph[kBlock], cs[kBlock], sn[kBlock];
  for (size_t j0 = 0; j0 < n; j0 += kBlock) {
    const int m = n - j0 < (size_t)kBlock ? (int)(n - j0) : kBlock;
    // a e^{-i omega t}, a = A e^{i (k D.x + phi)}: the component's complex
    // amplitude at the COM (the sea's phase, docs/physics.md section 11)
    for (int i = 0; i < m; i++) {
      const Wave& w = sea.waves[j0 + i];
      ph[i] = w.k * (w.dx * x[0] + w.dy * x[1]) + w.ph - w.omega * t;
    }
    for (int i = m; i < ((m + 3) & ~3); i++) ph[i] = 0;
    phaseSinCos(ph, m, sn, cs);  // within 3 ulp (sea.h)
    for (int i = 0; i < m; i++) {
      const size_t j = j0 + i;
      if (b.iw[j] == -2) continue;
      const Wave& w = sea.waves[j];
      TableWeights tw;
      weightsAt(nh, b.iw[j], b.tw[j], w.dir * (M_PI / 180) - psi, &tw);
      double acc[12];
      blendD(D, tw, acc);
      const double A = r * w.amp, c = A * cs[i], s = A * sn[i];
      for (int k = 0; k < 6; k++) F[k] += acc[2 * k] * c - acc[2 * k + 1] * s;
      driftAdd(b, tw, w.amp * cs[i], w.amp * sn[i], &ds);  // empty table: none
    }
  }
  driftFinish(b, ds, r, F);  // mean and slow drift
}

void diffractionStep(const Diffraction& df, const Sea& sea, const mjModel* m, const mjData* d,
                     double* out, char* told, std::string* notices) {
  for (size_t ib = 0; ib < df.db.size(); ib++) {
    const DiffBody& b = df.db[ib];
    double* w = out + 6 * ib;
    const mjtNum* R = d->xmat + 9 * b.body;
    // Q = R R0^T: world from the table's axes, the body's turn since qpos0
    double Q[9];
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        Q[3 * i + j] = R[3 * i] * b.R0[3 * j] + R[3 * i + 1] * b.R0[3 * j + 1] +
                       R[3 * i + 2] * b.R0[3 * j + 2];
      }
    }
    // the waves' heading in the table's axes: turned by Q's yaw
    const double psi = std::atan2(Q[3], Q[0]);
    double F[6];
    diffractionWrench(b, sea, d->xipos + 3 * b.body, psi, d->time, F);
    // the wrench turns with the body, roll and pitch too, as the radiation
    // force does (body axes, radstep.cc): the two nearly cancel in long
    // waves, and turning one alone leaves a mean surge force of second
    // order against the waves (docs/physics.md section 15, "Frame")
    mju_mulMatVec(w, Q, F, 3, 3);
    mju_mulMatVec(w + 3, Q, F + 3, 3, 3);
    bool fin = true;
    for (int k = 0; k < 6; k++) fin = fin && std::isfinite(w[k]);
    if (!fin) {
      for (int k = 0; k < 6; k++) w[k] = 0;
      if (!told[ib]) {
        told[ib] = 1;
        char line[256], who[128];
        std::snprintf(line, sizeof(line),
                      "body %s: diffraction force not finite at t = %g s; mjbuoy leaves it "
                      "out\n", bodyLabel(m, b.body, who, sizeof who), d->time);
        // within the capacity reserved in makeState: no allocation while stepping
        if (notices->size() + std::strlen(line) < notices->capacity()) *notices += line;
      }
    }
  }
}

}  // namespace mjb
