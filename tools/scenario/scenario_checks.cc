// mjbuoy-scenario: quantities and the checks that bound them
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "scenario.h"

namespace scn {

static const char* kPartNames[mjbNPART] = {"pressure", "viscous", "drag", "slamming", "damping", "wind"};

const char* quantityUnit(Quantity q) {
  switch (q) {
    case Quantity::ROLL: case Quantity::PITCH: case Quantity::YAW: case Quantity::TILT:
      return "deg";
    case Quantity::VX: case Quantity::VY: case Quantity::VZ: return "m/s";
    case Quantity::FX: case Quantity::FY: case Quantity::FZ: case Quantity::FORCE: return "N";
    case Quantity::TX: case Quantity::TY: case Quantity::TZ: case Quantity::TORQUE: return "N m";
    case Quantity::SENSOR: return "";  // the sensor's own units
    default: return "m";
  }
}

static std::string bodyName(const mjModel* m, int b) { return m->names + m->name_bodyadr[b]; }

double quantityValue(const Sample& s, int b, Quantity q, int part) {
  const mjtNum* R = s.d->xmat + 9 * b;
  const mjtNum* p = s.d->xpos + 3 * b;
  const double deg = 180 / M_PI;
  switch (q) {
    case Quantity::X: return p[0];
    case Quantity::Y: return p[1];
    case Quantity::Z: return p[2];
    // R = Rz(yaw) Ry(pitch) Rx(roll), as in mjbuoy-sim
    case Quantity::ROLL: return std::atan2(R[7], R[8]) * deg;
    case Quantity::PITCH: return -std::asin(std::fmax(-1.0, std::fmin(1.0, R[6]))) * deg;
    case Quantity::YAW: return std::atan2(R[3], R[0]) * deg;
    // angle between the body's z axis and the world's: 0 upright, 180 capsized
    case Quantity::TILT: return std::acos(std::fmax(-1.0, std::fmin(1.0, R[8]))) * deg;
    case Quantity::HEAVE: return p[2] - mjb_seaHeight(s.b, p[0], p[1], s.t);
    case Quantity::ETA: return mjb_seaHeight(s.b, p[0], p[1], s.t);
    // as computed by the mj_forward of the sampled state (scenario_run.cc)
    case Quantity::SENSOR: return s.d->sensordata[b];
    case Quantity::VX: case Quantity::VY: case Quantity::VZ: {
      mjtNum v[6];  // [angular; linear] at the body frame origin, world frame
      mj_objectVelocity(s.m, s.d, mjOBJ_BODY, b, v, 0);
      return v[3 + (int)q - (int)Quantity::VX];
    }
    default: break;
  }
  const mjtNum* w = part < 0 ? mjb_wrench(s.b, s.d) : mjb_wrenchPart(s.b, s.d, part);
  if (!w) return 0;
  w += 6 * b;
  switch (q) {
    case Quantity::FORCE: return mju_norm3(w);
    case Quantity::TORQUE: return mju_norm3(w + 3);
    default: return w[(int)q - (int)Quantity::FX];
  }
}

int sensorAddress(const mjModel* m, const std::string& name, int index, std::string* why) {
  int id = mj_name2id(m, mjOBJ_SENSOR, name.c_str());
  if (id < 0) {
    std::string names;
    for (int i = 0; i < m->nsensor && i < 12; i++) {
      const char* n = mj_id2name(m, mjOBJ_SENSOR, i);
      names += (i ? ", " : "") + std::string(n ? n : "(unnamed)");
    }
    if (m->nsensor > 12) names += ", ...";
    *why = "no sensor \"" + name + "\" in the model (" +
           (m->nsensor ? "sensors: " + names : std::string("it has no <sensor>")) + ")";
    return -1;
  }
  if (index < 0 || index >= m->sensor_dim[id]) {
    *why = "index = " + std::to_string(index) + " is out of range for sensor \"" + name +
           "\" of dim " + std::to_string(m->sensor_dim[id]) + "; index is in [0, " +
           std::to_string(m->sensor_dim[id] - 1) + "]";
    return -1;
  }
  return m->sensor_adr[id] + index;
}

static std::string boundText(double lo, double hi, const std::string& unit) {
  std::string u = unit.empty() ? "" : " " + unit;
  if (std::isinf(lo)) return "<= " + num(hi) + u;
  if (std::isinf(hi)) return ">= " + num(lo) + u;
  return "within [" + num(lo) + ", " + num(hi) + "]" + u;
}

// "> bound 0.01 m" or "< bound -0.01 m", with the target if one was given
static std::string violated(const Check& c, double v, const std::string& unit) {
  std::string u = unit.empty() ? "" : " " + unit;
  std::string s = v > c.hi ? "> bound " + num(c.hi) + u : "< bound " + num(c.lo) + u;
  if (c.has_target) s += " (target " + num(c.target) + " +- " + num(c.tol) + ")";
  return s;
}

static std::string window(const Check& c) {
  return "over [" + num(c.from) + ", " + num(c.to) + "] s";
}

std::string checkLabel(const Check& c) {
  std::string l = c.kind_name;
  if (!c.sensor.empty()) {
    l += " sensor " + c.sensor + (c.index ? "[" + std::to_string(c.index) + "]" : "");
  } else if (!c.body_spec.empty()) {
    // a list of names reads "(barge buoy).z"
    std::istringstream in(c.body_spec);
    std::string spec, w;
    int n = 0;
    while (in >> w) spec += (n++ ? " " : "") + w;
    if (n > 1) spec = "(" + spec + ")";
    l += " " + spec + "." + c.quantity_name;
    if (c.part >= 0) l += std::string(" (") + kPartNames[c.part] + ")";
    if (c.kind == Kind::WRENCH && c.stat == Stat::MEAN) l += " mean";
    if (c.kind == Kind::WRENCH && c.stat == Stat::STD) l += " std";
  }
  l += c.kind != Kind::FINITE && c.kind != Kind::ENERGY && c.stat == Stat::VALUE
           ? " at t = " + num(c.at) + " s"
           : " " + window(c);
  if (!c.name.empty()) l += " [" + c.name + "]";
  return l;
}

static std::string divergedText(double t, const std::string& why) {
  return "the simulation diverged at t = " + num(t) + " s: " + why;
}

// value, range, mean, std, settled and wrench: one statistic per body
class QuantityEval : public Evaluator {
 public:
  QuantityEval(const Check& c, const mjModel* m, double dt)
      : c_(c), m_(m), dt_(dt), acc_(c.bodies.size()) {}

  void sample(const Sample& s) override {
    const double eps = 1e-3 * dt_;
    if (c_.stat == Stat::VALUE) {
      if (done_ || s.t < c_.at - 0.5 * dt_) return;
      done_ = true;
    } else if (s.t < c_.from - eps || s.t > c_.to + eps) {
      return;
    }
    last_ = s.t;
    for (size_t i = 0; i < c_.bodies.size(); i++) {
      double v = quantityValue(s, c_.bodies[i], c_.quantity, c_.part);
      Acc& a = acc_[i];
      if (!std::isfinite(v)) {
        if (!a.bad) { a.bad = true; a.badv = v; a.badt = s.t; }
        continue;
      }
      a.n++;
      double d = v - a.mean;
      a.mean += d / a.n;
      a.m2 += d * (v - a.mean);
      if (v < a.min) { a.min = v; a.tmin = s.t; }
      if (v > a.max) { a.max = v; a.tmax = s.t; }
      a.value = v;
      a.tvalue = s.t;
    }
  }

  Result finish(double diverged, const std::string& why) override {
    Result r;
    r.label = checkLabel(c_);
    r.kind = c_.kind_name;
    bool complete = c_.stat == Stat::VALUE ? done_ : last_ >= c_.to - 0.5 * dt_;
    if (!complete) {
      r.pass = false;
      r.detail = "not evaluated to the end: " +
                 (std::isinf(diverged) ? std::string("no sample in the window")
                                       : divergedText(diverged, why));
      return r;
    }
    const std::string unit = quantityUnit(c_.quantity);
    const std::string u = unit.empty() ? "" : " " + unit;
    const bool many = c_.bodies.size() > 1;
    int worst = -1, nbad = 0;
    double worstv = 0;
    std::vector<std::string> details(c_.bodies.size());
    std::vector<double> stat(c_.bodies.size());
    for (size_t i = 0; i < c_.bodies.size(); i++) {
      const Acc& a = acc_[i];
      double viol = 0;
      std::string& d = details[i];
      if (a.bad) {
        viol = kInf;
        d = "value " + num(a.badv) + u + " (at t = " + num(a.badt) + " s)";
      } else if (c_.stat == Stat::RANGE) {
        double vhi = a.max - c_.hi, vlo = c_.lo - a.min;
        viol = std::max({vhi, vlo, 0.0});
        if (viol > 0 && vhi >= vlo) {
          d = "max " + num(a.max) + u + " " + violated(c_, a.max, unit) + " (at t = " +
              num(a.tmax) + " s)";
        } else if (viol > 0) {
          d = "min " + num(a.min) + u + " " + violated(c_, a.min, unit) + " (at t = " +
              num(a.tmin) + " s)";
        } else {
          d = "min " + num(a.min) + u + ", max " + num(a.max) + u;
        }
      } else {
        const char* what = c_.stat == Stat::MEAN ? "mean" : c_.stat == Stat::STD ? "std" : "value";
        double v = c_.stat == Stat::MEAN  ? a.mean
                   : c_.stat == Stat::STD ? std::sqrt(a.n ? a.m2 / a.n : 0.0)
                                          : a.value;
        stat[i] = v;
        viol = std::max({v - c_.hi, c_.lo - v, 0.0});
        d = std::string(what) + " " + num(v) + u;
        if (viol > 0) d += " " + violated(c_, v, unit);
        if (c_.stat == Stat::VALUE) d += " (at t = " + num(a.tvalue) + " s)";
      }
      if (viol > 0) {
        nbad++;
        if (worst < 0 || viol > worstv) { worst = (int)i; worstv = viol; }
      }
    }
    if (worst >= 0) {
      r.pass = false;
      r.detail = (many ? bodyName(m_, c_.bodies[worst]) + ": " : "") + details[worst];
      if (many) {
        r.detail += "; " + std::to_string(nbad) + " of " + std::to_string(c_.bodies.size()) +
                    " bodies out of bounds";
      }
      return r;
    }
    std::string b = boundText(c_.lo, c_.hi, unit);
    if (!many) {
      r.detail = details[0] + " " + b;
    } else if (c_.stat == Stat::RANGE) {
      size_t lo = 0, hi = 0;
      for (size_t i = 1; i < acc_.size(); i++) {
        if (acc_[i].min < acc_[lo].min) lo = i;
        if (acc_[i].max > acc_[hi].max) hi = i;
      }
      r.detail = std::to_string(acc_.size()) + " bodies: min " + num(acc_[lo].min) + u + " (" +
                 bodyName(m_, c_.bodies[lo]) + "), max " + num(acc_[hi].max) + u + " (" +
                 bodyName(m_, c_.bodies[hi]) + ") " + b;
    } else {
      size_t lo = 0, hi = 0;
      for (size_t i = 1; i < stat.size(); i++) {
        if (stat[i] < stat[lo]) lo = i;
        if (stat[i] > stat[hi]) hi = i;
      }
      const char* what = c_.stat == Stat::MEAN ? "mean" : c_.stat == Stat::STD ? "std" : "value";
      r.detail = std::to_string(acc_.size()) + " bodies: " + what + " from " + num(stat[lo]) + u +
                 " (" + bodyName(m_, c_.bodies[lo]) + ") to " + num(stat[hi]) + u + " (" +
                 bodyName(m_, c_.bodies[hi]) + ") " + b;
    }
    return r;
  }

 private:
  struct Acc {
    long n = 0;
    double mean = 0, m2 = 0, min = kInf, max = -kInf, tmin = 0, tmax = 0;
    double value = 0, tvalue = 0;
    bool bad = false;
    double badv = 0, badt = 0;
  };
  Check c_;
  const mjModel* m_;
  double dt_;
  std::vector<Acc> acc_;
  bool done_ = false;
  double last_ = -kInf;
};

// finite: every state finite, |qvel| bounded, no MuJoCo reset
class FiniteEval : public Evaluator {
 public:
  FiniteEval(const Check& c, const mjModel* m, double dt) : c_(c), m_(m), dt_(dt) {}

  void sample(const Sample& s) override {
    const double eps = 1e-3 * dt_;
    if (s.t < c_.from - eps || s.t > c_.to + eps) return;
    last_ = s.t;
    if (!fail_.empty()) return;
    const mjData* d = s.d;
    auto dof = [&](int i) {
      int j = m_->dof_jntid[i];
      const char* jn = m_->names + m_->name_jntadr[j];
      return " (body " + bodyName(m_, m_->dof_bodyid[i]) +
             (*jn ? std::string(", joint ") + jn : std::string()) + ")";
    };
    for (int i = 0; i < m_->nq && fail_.empty(); i++) {
      if (!std::isfinite(d->qpos[i])) {
        fail_ = "qpos[" + std::to_string(i) + "] = " + num(d->qpos[i]);
      }
    }
    for (int i = 0; i < m_->nv && fail_.empty(); i++) {
      double v = d->qvel[i];
      if (!std::isfinite(v) || std::fabs(v) > c_.maxqvel) {
        fail_ = "|qvel[" + std::to_string(i) + "]| = " + num(std::fabs(v)) + dof(i) +
                (std::isfinite(v) ? " > bound " + num(c_.maxqvel) : "");
      } else if (!std::isfinite(d->qacc[i])) {
        fail_ = "qacc[" + std::to_string(i) + "] = " + num(d->qacc[i]) + dof(i);
      }
      maxv_ = std::max(maxv_, std::fabs(v));
    }
    const mjtNum* w = mjb_wrench(s.b, d);
    for (int b = 0; w && b < m_->nbody && fail_.empty(); b++) {
      for (int k = 0; k < 6; k++) {
        if (!std::isfinite(w[6 * b + k])) {
          fail_ = "mjbuoy wrench of body " + bodyName(m_, b) + " = " + num(w[6 * b + k]);
          break;
        }
      }
    }
    if (!fail_.empty()) fail_ += " (at t = " + num(s.t) + " s)";
  }

  Result finish(double diverged, const std::string& why) override {
    Result r;
    r.label = checkLabel(c_);
    r.kind = c_.kind_name;
    if (!fail_.empty()) {
      r.pass = false;
      r.detail = fail_;
    } else if (diverged <= c_.to) {
      r.pass = false;
      r.detail = divergedText(diverged, why);
    } else if (last_ < c_.to - 0.5 * dt_) {
      r.pass = false;
      r.detail = "not evaluated to the end";
    } else {
      r.detail = "all states finite, max |qvel| " + num(maxv_) + " <= bound " + num(c_.maxqvel);
    }
    return r;
  }

 private:
  Check c_;
  const mjModel* m_;
  double dt_;
  std::string fail_;
  double maxv_ = 0, last_ = -kInf;
};

// energy: mean of d->energy (potential + kinetic) over the second half of
// the window minus that over the first half, within the bounds
class EnergyEval : public Evaluator {
 public:
  EnergyEval(const Check& c, double dt) : c_(c), dt_(dt), mid_(0.5 * (c.from + c.to)) {}

  void sample(const Sample& s) override {
    const double eps = 1e-3 * dt_;
    if (s.t < c_.from - eps || s.t > c_.to + eps) return;
    last_ = s.t;
    double e = s.d->energy[0] + s.d->energy[1];
    if (!std::isfinite(e)) {
      if (bad_.empty()) bad_ = "energy " + num(e) + " J (at t = " + num(s.t) + " s)";
      return;
    }
    if (s.t < mid_ - eps) { early_ += e; ne_++; } else { late_ += e; nl_++; }
  }

  Result finish(double diverged, const std::string& why) override {
    Result r;
    r.label = checkLabel(c_);
    r.kind = c_.kind_name;
    if (!bad_.empty()) {
      r.pass = false;
      r.detail = bad_;
      return r;
    }
    if (last_ < c_.to - 0.5 * dt_ || !ne_ || !nl_) {
      r.pass = false;
      r.detail = "not evaluated to the end" +
                 (std::isinf(diverged) ? std::string() : ": " + divergedText(diverged, why));
      return r;
    }
    double e = early_ / ne_, l = late_ / nl_, g = l - e;
    std::string means = "(mean " + num(e) + " J over [" + num(c_.from) + ", " + num(mid_) +
                        "] s, " + num(l) + " J over [" + num(mid_) + ", " + num(c_.to) + "] s)";
    r.pass = g >= c_.lo && g <= c_.hi;
    r.detail = "growth " + num(g) + " J " +
               (r.pass ? boundText(c_.lo, c_.hi, "J") : violated(c_, g, "J")) + " " + means;
    return r;
  }

 private:
  Check c_;
  double dt_, mid_;
  double early_ = 0, late_ = 0, last_ = -kInf;
  long ne_ = 0, nl_ = 0;
  std::string bad_;
};

std::unique_ptr<Evaluator> makeEvaluator(const Check& c, const mjModel* m, double dt) {
  if (c.kind == Kind::FINITE) return std::make_unique<FiniteEval>(c, m, dt);
  if (c.kind == Kind::ENERGY) return std::make_unique<EnergyEval>(c, dt);
  return std::make_unique<QuantityEval>(c, m, dt);
}

}  // namespace scn
