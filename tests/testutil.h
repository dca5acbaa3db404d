// test helpers: inline MJCF loading and an attached model bundle
#ifndef MJBUOY_TESTS_TESTUTIL_H_
#define MJBUOY_TESTS_TESTUTIL_H_

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "mjbuoy.h"

namespace mjbt {

static const double kRho = 1000, kG = 9.81;

// compile an MJCF string; NULL with the message in err on failure
inline mjModel* loadXML(const std::string& xml, std::string* err = nullptr) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "model.xml", xml.size());
  int i = mj_findFileVFS(&vfs, "model.xml");
  std::memcpy(vfs.filedata[i], xml.data(), xml.size());
  char e[1024] = "";
  mjModel* m = mj_loadXML("model.xml", &vfs, e, sizeof(e));
  mj_deleteVFS(&vfs);
  if (err) *err = e;
  return m;
}

// a compiled model with mjbuoy attached and one mjData
struct Scene {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  mjbBuoy* b = nullptr;
  std::string err;
  explicit Scene(const std::string& xml) {
    m = loadXML(xml, &err);
    if (!m) return;
    char e[1024];
    b = mjb_attach(m, nullptr, e, sizeof(e));
    if (!b) {
      err = e;
      return;
    }
    d = mj_makeData(m);
  }
  ~Scene() {
    if (d) mj_deleteData(d);
    if (b) mjb_detach(b);
    if (m) mj_deleteModel(m);
  }
  bool ok() const { return m && b && d; }
  const mjtNum* wrench(int body) const { return mjb_wrench(b, d) + 6 * body; }
  int body(const char* name) const { return mj_name2id(m, mjOBJ_BODY, name); }
  // step until sim time T, returning the mean of f() over the last `window`
  // s. Counts steps rather than looping `while (d->time < T)`: MuJoCo
  // resets a diverging simulation to time 0, and such a loop would never
  // end; a reset fails the test and returns NaN
  template <class F>
  double settle(double T, double window, F f) {
    const double dt = m->opt.timestep;
    const long steps = std::lround((T - d->time) / dt), from = steps - std::lround(window / dt);
    const int resets0 = resets();
    double sum = 0;
    long n = 0;
    for (long k = 0; k < steps; k++) {
      mj_step(m, d);
      if (resets() != resets0) {
        ADD_FAILURE() << "MuJoCo reset the diverging simulation in step " << k << " of " << steps;
        return NAN;
      }
      if (k >= from) {
        sum += f();
        n++;
      }
    }
    return n ? sum / n : NAN;
  }
  // MuJoCo's count of unstable states it caught (and reset)
  int resets() const {
    return d->warning[mjWARN_BADQPOS].number + d->warning[mjWARN_BADQVEL].number +
           d->warning[mjWARN_BADQACC].number;
  }
};

// qpos and every body's mjbuoy wrench after each of `steps` steps, in one
// vector (runs compared bit for bit)
inline std::vector<double> stepRecord(const mjModel* m, mjData* d, mjbBuoy* b, int steps) {
  std::vector<double> out;
  for (int i = 0; i < steps; i++) {
    mj_step(m, d);
    out.insert(out.end(), d->qpos, d->qpos + m->nq);
    const mjtNum* w = mjb_wrench(b, d);
    out.insert(out.end(), w, w + 6 * m->nbody);
  }
  return out;
}

// steps from d->time to sim time T [s]. Loops count steps rather than run
// `while (d->time < T)`: MuJoCo resets a diverging simulation to time 0 and
// such a loop would never end
inline long stepsTo(const mjModel* m, const mjData* d, double T) {
  return std::max(0L, std::lround((T - d->time) / m->opt.timestep));
}

// roll about x [rad] of a body (marine convention, R = Rz Ry Rx)
inline double roll(const mjData* d, int b) {
  const mjtNum* R = d->xmat + 9 * b;
  return std::atan2(R[7], R[8]);
}

// solve f(x) = 0 for x in [lo, hi] by bisection, f(lo) and f(hi) of opposite signs
template <class F>
double bisect(F f, double lo, double hi, double tol = 1e-13) {
  double flo = f(lo);
  for (int i = 0; i < 200 && hi - lo > tol; i++) {
    double mid = 0.5 * (lo + hi), fm = f(mid);
    if ((fm < 0) == (flo < 0)) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

#ifdef MJB_MODELS
// a shipped model (models/) with radiation on and extra custom entries,
// its meshes found from anywhere
inline std::string shippedModel(const char* file, const std::string& extra) {
  std::ifstream in(std::string(MJB_MODELS "/") + file);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string x = ss.str();
  size_t md = x.find("meshdir=\"meshes\"");
  if (md != std::string::npos) x.replace(md, 16, "meshdir=\"" MJB_MODELS "/meshes\"");
  size_t at = x.find("<custom>");
  if (at != std::string::npos)
    x.insert(at + 8, "<text name=\"mjbuoy.radiation\" data=\"on\"/>" + extra);
  return x;
}
#endif

}  // namespace mjbt

#endif  // MJBUOY_TESTS_TESTUTIL_H_
