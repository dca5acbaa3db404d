// mjbuoy-sweep: statistics of a quantity over a window, and the amplitude
// and phase at one frequency from a least-squares fitted sinusoid
// y(t) = c + a cos(w t) + b sin(w t) (docs/sweeps.md)
#include <cmath>
#include <cstring>

#include "sweep.h"

namespace swp {

using scn::Invalid;
using scn::num;

static const double kNan = std::nan("");

// least-squares c, a, b of y = c + a cos(w t) + b sin(w t): the 3 x 3
// normal equations, solved by Gaussian elimination with partial pivoting
static bool fitSine(const std::vector<double>& t, const std::vector<double>& y, double w,
                    double* a, double* b) {
  double A[3][4] = {};
  for (size_t i = 0; i < t.size(); i++) {
    double f[3] = {1, std::cos(w * t[i]), std::sin(w * t[i])};
    for (int r = 0; r < 3; r++) {
      for (int c = 0; c < 3; c++) A[r][c] += f[r] * f[c];
      A[r][3] += f[r] * y[i];
    }
  }
  for (int k = 0; k < 3; k++) {
    int p = k;
    for (int r = k + 1; r < 3; r++) if (std::fabs(A[r][k]) > std::fabs(A[p][k])) p = r;
    if (!(std::fabs(A[p][k]) > 1e-12 * t.size())) return false;  // window shorter than a period
    if (p != k) for (int c = 0; c < 4; c++) std::swap(A[k][c], A[p][c]);
    for (int r = k + 1; r < 3; r++) {
      double m = A[r][k] / A[k][k];
      for (int c = k; c < 4; c++) A[r][c] -= m * A[k][c];
    }
  }
  double x[3];
  for (int k = 2; k >= 0; k--) {
    double s = A[k][3];
    for (int c = k + 1; c < 3; c++) s -= A[k][c] * x[c];
    x[k] = s / A[k][k];
  }
  *a = x[1];
  *b = x[2];
  return true;
}

// the phase [deg] of R cos(w t + phi) = a cos(w t) + b sin(w t)
static double phaseOf(double a, double b) { return std::atan2(-b, a) * 180 / M_PI; }

double statValue(StatKind k, const std::vector<double>& t, const std::vector<double>& v,
                 const std::vector<double>& eta, double omega) {
  const size_t n = v.size();
  if (k == StatKind::PERIOD) return 2 * M_PI / omega;
  if (n < 2) return kNan;
  double mean = 0, m2 = 0, sq = 0, lo = v[0], hi = v[0];
  for (size_t i = 0; i < n; i++) {
    double d = v[i] - mean;
    mean += d / (i + 1);
    m2 += d * (v[i] - mean);
    sq += v[i] * v[i];
    lo = std::fmin(lo, v[i]);
    hi = std::fmax(hi, v[i]);
  }
  double sd = std::sqrt(m2 / n);
  switch (k) {
    case StatKind::MEAN: return mean;
    case StatKind::STD: return sd;
    case StatKind::SIG: return 4 * sd;  // significant value, 4 std (Hs = 4 sqrt(m0))
    case StatKind::MAX: return hi;
    case StatKind::MIN: return lo;
    case StatKind::RMS: return std::sqrt(sq / n);
    case StatKind::TZ: {
      // mean time between up-crossings of the mean, crossings interpolated linearly
      double first = kNan, last = kNan;
      long up = 0;
      for (size_t i = 1; i < n; i++) {
        double y0 = v[i - 1] - mean, y1 = v[i] - mean;
        if (y0 < 0 && y1 >= 0) {
          double tc = t[i - 1] + (t[i] - t[i - 1]) * (-y0) / (y1 - y0);
          if (!up) first = tc;
          last = tc;
          up++;
        }
      }
      return up >= 2 ? (last - first) / (up - 1) : kNan;
    }
    default: break;
  }
  double a, b, ae, be;
  if (!fitSine(t, v, omega, &a, &b)) return kNan;
  double amp = std::hypot(a, b);
  if (k == StatKind::AMP) return amp;
  if (!fitSine(t, eta, omega, &ae, &be)) return kNan;
  double ampe = std::hypot(ae, be);
  if (k == StatKind::RAO) return ampe > 0 ? amp / ampe : kNan;
  // phase of the response relative to the wave at the body, in (-180, 180]
  double p = phaseOf(a, b) - phaseOf(ae, be);
  while (p > 180) p -= 360;
  while (p <= -180) p += 360;
  return p;
}

// the frequency of mjbuoy.wave.<name> in the compiled model:
// omega^2 = g k tanh(k h) (docs/mjcf.md section 3), deep water without depth
static double waveOmega(const mjModel* m, const std::string& name, double* lambda) {
  int id = mj_name2id(m, mjOBJ_NUMERIC, ("mjbuoy.wave." + name).c_str());
  if (id < 0 || m->numeric_size[id] < 2) return kNan;
  *lambda = m->numeric_data[m->numeric_adr[id] + 1];
  double k = 2 * M_PI / *lambda, g = -m->opt.gravity[2];
  int d = mj_name2id(m, mjOBJ_NUMERIC, "mjbuoy.sea.depth");
  double th = d >= 0 ? std::tanh(k * m->numeric_data[m->numeric_adr[d]]) : 1.0;
  return std::sqrt(g * k * th);
}

Stats::Stats(const Sweep& s, const scn::Scenario& sc, const mjModel* m)
    : s_(s), dt_(m->opt.timestep) {
  for (const Stat& st : s.stats) {
    Series x;
    x.from = st.from;
    x.to = st.has_to ? st.to : sc.duration;
    if (x.to > sc.duration + 1e-9 || x.from >= x.to) {
      throw Invalid(s.given, st.line, "<stat name=\"" + st.name + "\">: the window [" + num(x.from) +
                                         ", " + num(x.to) + "] s is not within the run [0, " +
                                         num(sc.duration) + "] s");
    }
    if (!st.sensor.empty()) {
      std::string why;
      x.body = scn::sensorAddress(m, st.sensor, st.index, &why);  // scn::quantityValue's "body"
      if (x.body < 0) throw Invalid(s.given, st.line, "<stat name=\"" + st.name + "\">: " + why);
    } else if (st.kind != StatKind::PERIOD) {
      x.body = mj_name2id(m, mjOBJ_BODY, st.body.c_str());
      if (x.body <= 0) {
        throw Invalid(s.given, st.line, "<stat name=\"" + st.name + "\">: no body \"" + st.body +
                                           "\" in model " + sc.model_attr);
      }
    }
    if (!st.wave.empty()) {
      double lambda = 0;
      x.omega = waveOmega(m, st.wave, &lambda);
      if (!(x.omega > 0)) {
        throw Invalid(s.given, st.line, "<stat name=\"" + st.name + "\">: the model has no wave "
                                           "mjbuoy.wave." + st.wave);
      }
    } else if (st.period > 0) {
      x.omega = 2 * M_PI / st.period;
    }
    series_.push_back(x);
  }
}

void Stats::sample(const scn::Sample& smp) {
  const double eps = 1e-3 * dt_;
  for (size_t i = 0; i < series_.size(); i++) {
    Series& x = series_[i];
    const Stat& st = s_.stats[i];
    if (st.kind == StatKind::PERIOD || smp.t < x.from - eps || smp.t > x.to + eps) continue;
    x.t.push_back(smp.t);
    x.v.push_back(scn::quantityValue(smp, x.body, st.quantity, st.part));
    if (st.kind == StatKind::PHASE || st.kind == StatKind::RAO) {
      x.eta.push_back(scn::quantityValue(smp, x.body, scn::Quantity::ETA, -1));
    }
  }
}

std::vector<double> Stats::finish(double diverged) const {
  std::vector<double> out;
  for (size_t i = 0; i < series_.size(); i++) {
    const Series& x = series_[i];
    const Stat& st = s_.stats[i];
    bool complete = st.kind == StatKind::PERIOD ||
                    (diverged > x.to && !x.t.empty() && x.t.back() >= x.to - 0.5 * dt_);
    bool finite = true;
    for (double v : x.v) finite = finite && std::isfinite(v);
    out.push_back(complete && finite ? statValue(st.kind, x.t, x.v, x.eta, x.omega) : kNan);
  }
  return out;
}

}  // namespace swp
