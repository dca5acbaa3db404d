// radimport: coefficients from a file at attach (radimport.h)
#include "radiation/radimport.h"

#include <algorithm>
#include <cmath>

#include "radiation/coefxform.h"
#include "radiation/diffract.h"
#include "util/fmt.h"

namespace mjb {

bool resampleHeadings(HydroCoef* c, int n, double* gap) {
  const int nh = c->nh(), nw = c->nw();
  // the file's headings in [0, 2 pi), sorted, with their columns
  std::vector<std::pair<double, int>> h;
  for (int k = 0; k < nh; k++) {
    double b = std::fmod(c->heading[k], 2 * M_PI);
    if (b < 0) b += 2 * M_PI;
    if (b >= 2 * M_PI) b = 0;
    h.push_back({b, k});
  }
  std::sort(h.begin(), h.end());
  *gap = 0;
  for (int k = 0; k < nh; k++) {
    double next = k + 1 < nh ? h[k + 1].first : h[0].first + 2 * M_PI;
    *gap = std::max(*gap, next - h[k].first);
  }
  if (!nh || *gap > kImportGap + 1e-9) return false;
  std::vector<double> out[4];
  std::vector<double>* in[4] = {&c->Xre, &c->Xim, &c->FKre, &c->FKim};
  for (int s = 0; s < 4; s++) out[s].assign(6 * (size_t)nw * n, 0);
  for (int t = 0; t < n; t++) {
    double b = 2 * M_PI * t / n;
    // the file heading at or below b (periodic) and the next
    int lo = nh - 1;
    for (int k = 0; k < nh; k++)
      if (h[k].first <= b + 1e-12) lo = k;
    int hi = (lo + 1) % nh;
    double b0 = h[lo].first > b + 1e-12 ? h[lo].first - 2 * M_PI : h[lo].first;
    double b1 = h[hi].first + (hi <= lo ? 2 * M_PI : 0);
    // a file heading within 1e-9 rad of b is taken as it is
    double u = std::fabs(b - b0) < 1e-9 ? 0 : (b - b0) / (b1 - b0);
    for (int w = 0; w < nw; w++)
      for (int i = 0; i < 6; i++) {
        size_t o = 6 * ((size_t)w * n + t) + i;
        size_t a = 6 * ((size_t)w * nh + h[lo].second) + i;
        size_t e = 6 * ((size_t)w * nh + h[hi].second) + i;
        for (int s = 0; s < 4; s++)
          out[s][o] = u == 0 ? (*in[s])[a] : (1 - u) * (*in[s])[a] + u * (*in[s])[e];
      }
  }
  for (int s = 0; s < 4; s++) in[s]->swap(out[s]);
  c->heading.resize(n);
  for (int t = 0; t < n; t++) c->heading[t] = 2 * M_PI * t / n;
  return true;
}

// area centroid (a fan of triangles from the first vertex, as the panel
// solver's, rankine.cc), area and unit normal (Newell's) of panel f
static void panelGeom(const PanelMesh& p, int f, double c[3], double* area, double n[3]) {
  const int* q = &p.face[4 * f];
  const int nv = q[3] < 0 ? 3 : 4;
  double a[3] = {0, 0, 0}, at = 0;
  c[0] = c[1] = c[2] = 0;
  for (int k = 0; k < nv; k++) {
    const double* u = &p.vert[3 * q[k]];
    const double* v = &p.vert[3 * q[(k + 1) % nv]];
    a[0] += 0.5 * (u[1] * v[2] - u[2] * v[1]);
    a[1] += 0.5 * (u[2] * v[0] - u[0] * v[2]);
    a[2] += 0.5 * (u[0] * v[1] - u[1] * v[0]);
  }
  *area = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  for (int i = 0; i < 3; i++) n[i] = *area > 0 ? a[i] / *area : 0;
  const double* o = &p.vert[3 * q[0]];
  for (int k = 1; k + 1 < nv; k++) {
    const double* u = &p.vert[3 * q[k]];
    const double* v = &p.vert[3 * q[k + 1]];
    double e[3] = {u[0] - o[0], u[1] - o[1], u[2] - o[2]}, g[3] = {v[0] - o[0], v[1] - o[1], v[2] - o[2]};
    double x[3] = {e[1] * g[2] - e[2] * g[1], e[2] * g[0] - e[0] * g[2], e[0] * g[1] - e[1] * g[0]};
    double t = 0.5 * (x[0] * n[0] + x[1] * n[1] + x[2] * n[2]);
    for (int i = 0; i < 3; i++) c[i] += t * (o[i] + u[i] + v[i]) / 3;
    at += t;
  }
  for (int i = 0; i < 3 && at != 0; i++) c[i] /= at;
}

void froudeKrylov(const PanelMesh& body, HydroCoef* c) {
  const int nw = c->nw(), nh = c->nh();
  c->FKre.assign(6 * (size_t)nw * nh, 0);
  c->FKim.assign(c->FKre.size(), 0);
  for (int f = 0; f < body.nface(); f++) {
    double x[3], dS, n[3];
    panelGeom(body, f, x, &dS, n);
    // generalized normal (n, r x n) dS
    const double N[6] = {n[0] * dS, n[1] * dS, n[2] * dS, (x[1] * n[2] - x[2] * n[1]) * dS,
                         (x[2] * n[0] - x[0] * n[2]) * dS, (x[0] * n[1] - x[1] * n[0]) * dS};
    for (int w = 0; w < nw; w++) {
      const double k = c->omega[w] * c->omega[w] / c->g, amp = -c->rho * c->g * std::exp(k * x[2]);
      for (int h = 0; h < nh; h++) {
        const double ph = k * (x[0] * std::cos(c->heading[h]) + x[1] * std::sin(c->heading[h]));
        const double re = amp * std::cos(ph), im = amp * std::sin(ph);
        size_t o = 6 * ((size_t)w * nh + h);
        for (int a = 0; a < 6; a++) c->FKre[o + a] += re * N[a], c->FKim[o + a] += im * N[a];
      }
    }
  }
}

// the file's density to the model's: every coefficient is proportional to it
static void scaleRho(CoefFile* f, double rho) {
  double s = rho / f->c.rho;
  for (auto* v : {&f->c.A, &f->c.B, &f->c.Xre, &f->c.Xim, &f->c.FKre, &f->c.FKim})
    for (double& x : *v) x *= s;
  for (int k = 0; k < 36; k++) f->c.Ainf[k] *= s, f->C[k] *= s;
  f->c.rho = rho;
}

// the exciting force about the COM in world axes on the table's headings
static std::string excitation(const RadImport& in, const CoefFile& f, HydroCoef* cx) {
  const std::string who = "coefficient file " + in.path;
  if (!f.hasX)
    return who + " holds no exciting force, which the diffraction force needs; give it one "
           "(WAMIT: the .3 and .3fk files beside the .1) or turn diffraction off with <text "
           "name=\"mjbuoy.radiation.diffraction\" data=\"off\"/>";
  if (!f.hasFK && !in.body)
    return who + " holds no Froude-Krylov force, whose difference from the exciting force is "
           "the diffraction force mjbuoy adds to its pressure integration; give it (WAMIT: the "
           ".3fk file; BEMIO: excitation/froude-krylov) or turn diffraction off with <text "
           "name=\"mjbuoy.radiation.diffraction\" data=\"off\"/>";
  *cx = f.c;
  cx->A.assign(36 * cx->omega.size(), 0);
  cx->B = cx->A;
  // the world's axes in the body frame: R^T's columns (coefxform.h)
  const double* R = in.R;
  const double Rt[9] = {R[0], R[3], R[6], R[1], R[4], R[7], R[2], R[5], R[8]};
  std::string e = coefTransform(cx, in.com, Rt, in.com);
  if (!e.empty()) return who + ": " + e + " (the body must float upright at qpos0)";
  double gap;
  if (!resampleHeadings(cx, kDiffHeadings, &gap))
    return who + ": its wave headings are up to " + fmt(gap * 180 / M_PI) + " deg apart; the "
           "diffraction force needs headings all round the body no more than " +
           fmt(kImportGap * 180 / M_PI) + " deg apart (e.g. 0 to 345 every 15 deg), or turn "
           "diffraction off with <text name=\"mjbuoy.radiation.diffraction\" data=\"off\"/>";
  if (!f.hasFK) {
    // the hull's own Froude-Krylov force, about the COM in world axes
    HydroCoef fk = *cx;
    froudeKrylov(*in.body, &fk);
    fk.Xre = fk.FKre;
    fk.Xim = fk.FKim;
    for (int k = 0; k < 3; k++) fk.ref[k] = 0;
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    e = coefTransform(&fk, in.comPanel, I, in.com);
    if (!e.empty()) return who + ": " + e;
    cx->FKre.swap(fk.FKre);
    cx->FKim.swap(fk.FKim);
  }
  cx->A.clear();
  cx->B.clear();
  return "";
}

// "water D m deep" or "deep water" (depth 0)
static std::string depthText(double depth) {
  return depth > 0 ? "water " + fmt(depth) + " m deep" : "deep water";
}

std::string importCoef(const RadImport& in, HydroCoef* c, HydroCoef* cx,
                       std::vector<std::string>* warn) {
  CoefOpt o;
  o.rho = in.rho;
  o.g = in.g;
  o.ulen = in.ulen;
  CoefFile f;
  std::string e = readCoefFile(in.path, o, &f);
  if (!e.empty()) return e;
  const std::string who = "coefficient file " + in.path;
  if (in.diffraction && f.hasX && !f.hasFK && in.body)
    warn->push_back(who + " holds no Froude-Krylov force: the diffraction force is its exciting "
                    "force less the Froude-Krylov force on the hull's wet panels");
  if (std::fabs(f.c.rho / in.rho - 1) > 1e-9) {
    warn->push_back(who + " is for rho = " + fmt(f.c.rho) + " kg/m^3; scaled to the model's " +
                    fmt(in.rho) + " kg/m^3");
    scaleRho(&f, in.rho);
  }
  if (std::fabs(f.c.g / in.g - 1) > 1e-6)
    warn->push_back(who + " is for g = " + fmt(f.c.g) + " m/s^2, the model's is " + fmt(in.g) +
                    " m/s^2; its coefficients are used as they are");
  if (std::fabs(f.c.depth - in.depth) > 1e-6 * std::max(f.c.depth, in.depth))
    warn->push_back(who + " is for " + depthText(f.c.depth) + ", the model's sea for " +
                    depthText(in.depth) + " (mjbuoy.sea.depth); its coefficients are used as "
                    "they are: give the file of the model's depth");
  f.c.depth = in.depth;
  f.c.g = in.g;
  if (!f.hasAinf) {
    // the highest frequency's added mass stands in: A(omega) tends to A_inf
    std::copy(f.c.A.end() - 36, f.c.A.end(), f.c.Ainf);
    warn->push_back(who + " has no infinite-frequency added mass; A at its highest frequency, " +
                    fmt(f.c.omega.back()) + " rad/s, stands in for it");
  }
  for (int k = 0; k < 3; k++) f.c.ref[k] = in.origin[k];
  if (in.diffraction) {
    e = excitation(in, f, cx);
    if (!e.empty()) return e;
  }
  *c = f.c;
  for (auto* v : {&c->heading, &c->Xre, &c->Xim, &c->FKre, &c->FKim}) v->clear();
  const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  e = coefTransform(c, in.com, I, in.com);
  return e.empty() ? "" : who + ": " + e;
}

}  // namespace mjb
