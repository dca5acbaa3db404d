// catenary: static elastic catenary with seabed contact (catenary.h;
// docs/mooring.md "Initial state")
#include "mooring/catenary.h"

#include <algorithm>
#include <cmath>

namespace mjb {

// Jonkman 2007 eqs. 4-1, 4-2 (suspended) and 4-3, 4-4 with C_B = 0 (on the
// bed): the fairlead's span x and height z for fairlead tension hf, vf
void catenaryEnd(Catenary* c, double* x, double* z) {
  const double W = c->w, L = c->len, EA = c->ea, hf = c->hf, vf = c->vf;
  const double r = vf / hf;
  if (c->bed && vf < W * L) {
    c->lb = L - std::max(vf, 0.0) / W;
    *x = c->lb + hf / W * std::asinh(r) + hf * L / EA;
    *z = hf / W * (std::sqrt(1 + r * r) - 1) + vf * vf / (2 * EA * W);
    return;
  }
  c->lb = 0;
  const double ra = (vf - W * L) / hf;
  *x = hf / W * (std::asinh(r) - std::asinh(ra)) + hf * L / EA;
  *z = hf / W * (std::sqrt(1 + r * r) - std::sqrt(1 + ra * ra)) + (vf * L - W * L * L / 2) / EA;
}

namespace {

// the fairlead height for hf, vf (catenaryEnd's z)
double heightAt(Catenary c, double hf, double vf) {
  double x, z;
  c.hf = hf;
  c.vf = vf;
  catenaryEnd(&c, &x, &z);
  return z;
}

// the vf that puts the fairlead at height z for horizontal tension hf: the
// height rises with vf in both regimes, so bisection on a bracket grown
// until it holds z
double vfFor(const Catenary& c, double hf, double z) {
  const double WL = c.w * c.len;
  double lo = c.bed ? 0 : -WL, hi = WL;
  for (int i = 0; i < 200 && heightAt(c, hf, hi) < z; i++) hi = 2 * hi + WL;
  for (int i = 0; i < 200 && !c.bed && heightAt(c, hf, lo) > z; i++) lo = 2 * lo - WL;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * (std::fabs(hi) + WL); i++) {
    double mid = 0.5 * (lo + hi);
    (heightAt(c, hf, mid) < z ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// the span for hf with vf from the height (vfFor); sets c's hf, vf, lb
double spanAt(Catenary* c, double hf, double z) {
  c->hf = hf;
  c->vf = vfFor(*c, hf, z);
  double x, zz;
  catenaryEnd(c, &x, &zz);
  return x;
}

}  // namespace

// the span grows with hf once vf meets the height, so the solution is a
// bisection on hf (in its logarithm: hf spans many decades between a slack
// chain and a taut rope), which converges from any start where Newton on
// (hf, vf) can run off to hf = 0 when much of the line is grounded
bool catenarySolve(double x, double z, double len, double ea, double w, bool bed,
                   Catenary* c) {
  c->len = len;
  c->ea = ea;
  c->w = w;
  c->bed = bed;
  if (!(x > 1e-9 * len) || !(w > 0) || !(ea > 0) || !(len > 0)) return false;
  if (bed && z < 0) return false;
  Catenary t = *c;
  double lo = 1e-9 * w * len, hi = w * len;
  if (!(spanAt(&t, lo, z) < x)) return false;  // even slack the line reaches past x
  for (int i = 0; i < 200 && spanAt(&t, hi, z) < x; i++) hi *= 2;
  for (int i = 0; i < 200 && hi / lo - 1 > 1e-15; i++) {
    double mid = std::sqrt(lo * hi);
    (spanAt(&t, mid, z) < x ? lo : hi) = mid;
  }
  double fx = spanAt(&t, std::sqrt(lo * hi), z), fz;
  catenaryEnd(&t, &fx, &fz);
  const double tol = 1e-7 * std::max({x, std::fabs(z), len});
  if (!(std::fabs(fx - x) < tol && std::fabs(fz - z) < tol)) return false;
  *c = t;
  return true;
}

void catenaryPoint(const Catenary& c, double s, double* x, double* z, double* t) {
  const double W = c.w, EA = c.ea, hf = c.hf;
  if (c.lb > 0) {
    if (s <= c.lb) {
      *x = s * (1 + hf / EA);
      *z = 0;
      *t = hf;
      return;
    }
    const double vs = W * (s - c.lb), r = vs / hf;
    *x = c.lb + hf / W * std::asinh(r) + hf * s / EA;
    *z = hf / W * (std::sqrt(1 + r * r) - 1) + vs * vs / (2 * EA * W);
    *t = std::hypot(hf, vs);
    return;
  }
  const double va = c.vf - W * c.len, vs = va + W * s, ra = va / hf, r = vs / hf;
  *x = hf / W * (std::asinh(r) - std::asinh(ra)) + hf * s / EA;
  *z = hf / W * (std::sqrt(1 + r * r) - std::sqrt(1 + ra * ra)) + (va * s + W * s * s / 2) / EA;
  *t = std::hypot(hf, vs);
}

}  // namespace mjb
