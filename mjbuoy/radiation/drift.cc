// mean wave drift from the panel solution (docs/physics.md section 18)
#include "radiation/drift.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <tuple>

#include <Eigen/Dense>

namespace mjb {

namespace {

const double kPi = 3.14159265358979323846;
const int kTheta = 720;  // most Kochin-function angles (periodic trapezoid: spectral)

// column c of a column-major n-row matrix
const dcplx* col(const dcplx* a, int n, int c) { return a + (size_t)n * c; }

// headings of the field's solve
int nhead(const PanelField& f) { return f.out->nh(); }

// the total disturbance's source strength or potential on row i: the
// diffraction column of heading h plus the radiation columns times the
// body velocity -i omega xi
dcplx total(const dcplx* a, int n, int i, int h, const PanelField& f, const dcplx* xi) {
  dcplx s = col(a, n, 6 + h)[i];
  for (int j = 0; j < 6; j++) s += dcplx(0, -f.omega) * xi[j] * col(a, n, j)[i];
  return s;
}

// incident potential per unit amplitude at x (panel frame), heading beta:
// phi0 = -i g/omega e^{K z} e^{i K (x - ref) . (cos b, sin b)}
dcplx incident(const PanelField& f, const double* x, double beta, dcplx grad[3]) {
  const double* r = f.out->ref;
  double cb = std::cos(beta), sb = std::sin(beta);
  double ph = f.K * ((x[0] - r[0]) * cb + (x[1] - r[1]) * sb);
  dcplx p = dcplx(0, -f.out->g / f.omega) * std::exp(f.K * x[2]) * std::polar(1.0, ph);
  if (grad) {
    grad[0] = dcplx(0, f.K * cb) * p;
    grad[1] = dcplx(0, f.K * sb) * p;
    grad[2] = f.K * p;
  }
  return p;
}

// displacement xi_t + alpha x (x - ref) of the body point x [m/m]
void pointMotion(const dcplx* xi, const double* x, const double* ref, dcplx d[3]) {
  double r[3] = {x[0] - ref[0], x[1] - ref[1], x[2] - ref[2]};
  d[0] = xi[0] + xi[4] * r[2] - xi[5] * r[1];
  d[1] = xi[1] + xi[5] * r[0] - xi[3] * r[2];
  d[2] = xi[2] + xi[3] * r[1] - xi[4] * r[0];
}

// body panels sharing a vertex with each body panel (vertices matched by
// position, 1e-9 of the mesh size, so split meshes connect)
std::vector<std::vector<int>> neighbours(const PanelField& f) {
  const std::vector<Panel>& pn = *f.pn;
  double lo = 1e300, hi = -1e300;
  for (int i = 0; i < f.nb; i++)
    for (int v = 0; v < pn[i].nv; v++)
      for (int k = 0; k < 3; k++)
        lo = std::fmin(lo, pn[i].v[v][k]), hi = std::fmax(hi, pn[i].v[v][k]);
  double q = 1e-9 * (hi - lo) + 1e-300;
  std::map<std::tuple<long long, long long, long long>, std::vector<int>> at;
  for (int i = 0; i < f.nb; i++)
    for (int v = 0; v < pn[i].nv; v++) {
      const double* p = pn[i].v[v];
      at[std::make_tuple(std::llround(p[0] / q), std::llround(p[1] / q), std::llround(p[2] / q))]
          .push_back(i);
    }
  std::vector<std::vector<int>> nb(f.nb);
  for (auto& e : at)
    for (int i : e.second)
      for (int j : e.second)
        if (i != j) nb[i].push_back(j);
  for (auto& v : nb) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }
  return nb;
}

// total potential on the body panels and its gradient at their centroids
// for heading h: the normal part from the body condition (dphi/dn = the
// body's normal velocity), the tangential part a weighted least-squares
// fit to the neighbours' potentials (docs/physics.md section 18)
void surfaceField(const PanelField& f, const std::vector<std::vector<int>>& nbr, int h,
                  const dcplx* xi, std::vector<dcplx>* phi, std::vector<dcplx>* grad) {
  const std::vector<Panel>& pn = *f.pn;
  const double beta = f.out->heading[h];
  int nb = f.nb;
  phi->resize(nb);
  grad->resize(3 * nb);
  std::vector<dcplx> vn(nb);
  for (int i = 0; i < nb; i++) {
    (*phi)[i] = total(f.phi, nb, i, h, f, xi) + incident(f, pn[i].c, beta, nullptr);
    dcplx d[3];
    pointMotion(xi, pn[i].c, f.out->ref, d);
    vn[i] = dcplx(0, -f.omega) * (d[0] * pn[i].n[0] + d[1] * pn[i].n[1] + d[2] * pn[i].n[2]);
  }
  for (int i = 0; i < nb; i++) {
    const Panel& p = pn[i];
    // tangent basis
    double a[3] = {1, 0, 0};
    if (std::fabs(p.n[0]) > 0.8) a[0] = 0, a[1] = 1;
    double d0 = a[0] * p.n[0] + a[1] * p.n[1] + a[2] * p.n[2];
    double t1[3], t2[3];
    for (int k = 0; k < 3; k++) t1[k] = a[k] - d0 * p.n[k];
    double l1 = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
    for (int k = 0; k < 3; k++) t1[k] /= l1;
    t2[0] = p.n[1] * t1[2] - p.n[2] * t1[1];
    t2[1] = p.n[2] * t1[0] - p.n[0] * t1[2];
    t2[2] = p.n[0] * t1[1] - p.n[1] * t1[0];
    double m00 = 0, m01 = 0, m11 = 0;
    dcplx r0 = 0, r1 = 0;
    for (int j : nbr[i]) {
      double d[3] = {pn[j].c[0] - p.c[0], pn[j].c[1] - p.c[1], pn[j].c[2] - p.c[2]};
      double u = d[0] * t1[0] + d[1] * t1[1] + d[2] * t1[2];
      double v = d[0] * t2[0] + d[1] * t2[1] + d[2] * t2[2];
      double dn = d[0] * p.n[0] + d[1] * p.n[1] + d[2] * p.n[2];
      double w = 1 / (u * u + v * v + dn * dn);
      // the neighbour's potential less its normal offset's part
      dcplx df = (*phi)[j] - (*phi)[i] - vn[i] * dn;
      m00 += w * u * u, m01 += w * u * v, m11 += w * v * v;
      r0 += w * u * df, r1 += w * v * df;
    }
    double det = m00 * m11 - m01 * m01;
    dcplx g1 = 0, g2 = 0;
    if (det > 1e-12 * (m00 * m11 + 1e-300)) {
      g1 = (m11 * r0 - m01 * r1) / det;
      g2 = (m00 * r1 - m01 * r0) / det;
    }
    for (int k = 0; k < 3; k++) (*grad)[3 * i + k] = g1 * t1[k] + g2 * t2[k] + vn[i] * p.n[k];
  }
}

// the waterline edges of body panel p (both ends on z = 0): their
// 2-point Gauss points at[2][3], the edge length L and its outward
// horizontal normal (nx, ny); false if e is not one
bool waterEdge(const Panel& p, int e, double at[2][3], double* L, double* nx, double* ny) {
  double tol = 1e-6 * (1 + p.diam);
  const double* v0 = p.v[e];
  const double* v1 = p.v[(e + 1) % p.nv];
  if (std::fabs(v0[2]) > tol || std::fabs(v1[2]) > tol) return false;
  double ex = v1[0] - v0[0], ey = v1[1] - v0[1];
  *L = std::hypot(ex, ey);
  if (!(*L > 0)) return false;
  *nx = ey / *L, *ny = -ex / *L;
  if (*nx * p.n[0] + *ny * p.n[1] < 0) *nx = -*nx, *ny = -*ny;
  for (int gp = 0; gp < 2; gp++) {
    double u = 0.5 + (gp ? 0.5 : -0.5) / std::sqrt(3.0);
    for (int k = 0; k < 3; k++) at[gp][k] = v0[k] + u * (v1[k] - v0[k]);
  }
  return true;
}

// the mean of alpha x F1 (Fx, Fy) and of alpha x M1 + xi x F1 (Mz), added
// to F: Pinkster's rotation term for the first-order force F1 [6]
void rotationTerm(const dcplx* x, const dcplx* F1, double F[3]) {
  auto crossm = [](const dcplx* a, const dcplx* c, int k) {
    int i = (k + 1) % 3, j = (k + 2) % 3;
    return 0.5 * (a[i] * std::conj(c[j]) - a[j] * std::conj(c[i])).real();
  };
  F[0] += crossm(x + 3, F1, 0);
  F[1] += crossm(x + 3, F1, 1);
  F[2] += crossm(x + 3, F1 + 3, 2) + crossm(x, F1, 2);
}

}  // namespace

bool driftRao(const PanelField& f, const DriftBody& b, std::vector<dcplx>* xi) {
  int nh = nhead(f);
  xi->assign(6 * nh, 0);
  if (!b.free) return true;
  int id[6], n = 0;
  for (int k = 0; k < 6; k++)
    if (b.dof[k]) id[n++] = k;
  if (!n) return true;
  double w = f.omega;
  Eigen::MatrixXcd Z(n, n);
  const double* A = &f.out->A[36 * f.w];
  const double* B = &f.out->B[36 * f.w];
  for (int r = 0; r < n; r++)
    for (int c = 0; c < n; c++) {
      int o = 6 * id[r] + id[c];
      Z(r, c) = dcplx(-w * w * (b.M[o] + A[o]) + b.C[o], -w * (B[o] + b.D[o]));
    }
  Eigen::FullPivLU<Eigen::MatrixXcd> lu(Z);
  if (!lu.isInvertible()) return false;
  for (int h = 0; h < nh; h++) {
    Eigen::VectorXcd X(n);
    for (int r = 0; r < n; r++) {
      int o = (f.w * nh + h) * 6 + id[r];
      X(r) = dcplx(f.out->Xre[o], f.out->Xim[o]);
    }
    Eigen::VectorXcd s = lu.solve(X);
    for (int r = 0; r < n; r++) {
      if (!std::isfinite(s(r).real()) || !std::isfinite(s(r).imag())) return false;
      (*xi)[6 * h + id[r]] = s(r);
    }
  }
  return true;
}

void driftFar(const PanelField& f, const std::vector<dcplx>& xi, double* out) {
  const std::vector<Panel>& pn = *f.pn;
  const double* ref = f.out->ref;
  int n = f.nb + f.nl, nh = nhead(f);
  double K = f.K, g = f.out->g, rho = f.out->rho;
  // far field of the sources: phi ~ 2 pi i K e^{Kz} H0(K r) H(theta) with
  // H = sum sigma dS e^{K z} e^{-i K (x cos th + y sin th)}; elevation
  // eta_s = a(theta) e^{iKr} / sqrt(r), a = (i omega / g) 2 pi i K
  // sqrt(2 / (pi K)) e^{-i pi/4} H (docs/physics.md section 18)
  const dcplx ca = dcplx(0, f.omega / g) * dcplx(0, 2 * kPi * K) * std::sqrt(2 / (kPi * K)) *
                   std::polar(1.0, -kPi / 4);
  // the Kochin function is a trigonometric polynomial of degree about
  // K r_max in theta (r_max the panels' largest horizontal distance from
  // ref): the periodic trapezoid rule with 4 K r_max + 64 points integrates
  // |a|^2 exactly to rounding
  double rmax = 0;
  for (int i = 0; i < n; i++)
    rmax = std::fmax(rmax, std::hypot(pn[i].c[0] - ref[0], pn[i].c[1] - ref[1]) + pn[i].diam);
  const int nth = std::min(kTheta, 4 * (int)std::ceil(K * rmax) + 64);
  // angles: the nth of the grid, then each heading; E(t, i) the phase
  // factor of panel i at angle t, Ed the same times d/dtheta's factor, so
  // that every heading's H and H' are one product each (E S)
  const int na = nth + nh;
  Eigen::MatrixXcd E(na, n), Ed(na, n), S(n, nh);
  for (int t = 0; t < na; t++) {
    double th = t < nth ? 2 * kPi * t / nth : f.out->heading[t - nth];
    double c = std::cos(th), sn = std::sin(th);
    for (int i = 0; i < n; i++) {
      double x = pn[i].c[0] - ref[0], y = pn[i].c[1] - ref[1];
      E(t, i) = ca * std::polar(1.0, -K * (x * c + y * sn));
      Ed(t, i) = dcplx(0, -K * (-x * sn + y * c)) * E(t, i);
    }
  }
  for (int h = 0; h < nh; h++)
    for (int i = 0; i < n; i++)
      S(i, h) = total(f.sig, n, i, h, f, &xi[6 * h]) * pn[i].area * std::exp(K * pn[i].c[2]);
  Eigen::MatrixXcd a = E * S, ad = Ed * S;
  const dcplx e4 = std::polar(1.0, -kPi / 4);
  const double sk = 2 * std::sqrt(2 * kPi / K), dth = 2 * kPi / nth;
  for (int h = 0; h < nh; h++) {
    double ix = 0, iy = 0, im = 0;
    for (int t = 0; t < nth; t++) {
      double th = t * dth, q = std::norm(a(t, h));
      ix += q * std::cos(th) * dth;
      iy += q * std::sin(th) * dth;
      im += (ad(t, h) * std::conj(a(t, h))).imag() * dth;
    }
    const double beta = f.out->heading[h];
    const dcplx ab = a(nth + h, h), adb = ad(nth + h, h);
    double cross = sk * (std::conj(ab) * e4).real();
    // Maruo: F = -(rho g / 4) [int |a|^2 (cos, sin) dth
    //   + 2 sqrt(2 pi/K) (cos b, sin b) Re(a*(b) e^{-i pi/4})]
    out[3 * h + 0] = -(rho * g / 4) * (ix + std::cos(beta) * cross);
    out[3 * h + 1] = -(rho * g / 4) * (iy + std::sin(beta) * cross);
    // Newman: Mz = -(rho g / 4K) [int Im(a' a*) dth - 2 sqrt(2 pi/K) Im(e^{-i pi/4} a'*(b))]
    out[3 * h + 2] = -(rho * g / (4 * K)) * (im - sk * (e4 * std::conj(adb)).imag());
  }
}

void driftNear(const PanelField& f, const DriftBody& b, const std::vector<dcplx>& xi,
               double* out) {
  const std::vector<Panel>& pn = *f.pn;
  const double* ref = f.out->ref;
  int nb = f.nb, nh = nhead(f);
  double rho = f.out->rho, g = f.out->g, w = f.omega;
  std::vector<std::vector<int>> nbr = neighbours(f);
  std::vector<dcplx> phi, grad;
  for (int h = 0; h < nh; h++) {
    const dcplx* x = &xi[6 * h];
    surfaceField(f, nbr, h, x, &phi, &grad);
    double F[3] = {0, 0, 0};
    auto add = [&](const double* at, const double* fo) {
      F[0] += fo[0], F[1] += fo[1];
      F[2] += (at[0] - ref[0]) * fo[1] - (at[1] - ref[1]) * fo[0];
    };
    for (int i = 0; i < nb; i++) {
      const Panel& p = pn[i];
      const dcplx* gi = &grad[3 * i];
      // velocity squared: -rho/2 |grad Phi|^2 pressure, mean (rho/4) |grad phi|^2 n dS
      double q = std::norm(gi[0]) + std::norm(gi[1]) + std::norm(gi[2]);
      // pressure gradient: -rho X . grad Phi_t, mean (rho/2) Re(X . conj(-i w grad phi)) n dS
      dcplx d[3];
      pointMotion(x, p.c, ref, d);
      double pg = 0;
      for (int k = 0; k < 3; k++) pg += (d[k] * std::conj(dcplx(0, -w) * gi[k])).real();
      double s = (rho / 4) * q + (rho / 2) * pg;
      double fo[2] = {s * p.n[0] * p.area, s * p.n[1] * p.area};
      add(p.c, fo);
      // waterline: edges of the panel on z = 0, -(rho g/4) |zeta_r|^2 n dl,
      // zeta = (i w / g) phi at z = 0 (2-point Gauss along the edge)
      for (int e = 0; e < p.nv; e++) {
        double at[2][3], L, nx, ny;
        if (!waterEdge(p, e, at, &L, &nx, &ny)) continue;
        for (int gp = 0; gp < 2; gp++) {
          dcplx ph = phi[i];
          for (int k = 0; k < 3; k++) ph += gi[k] * (at[gp][k] - p.c[k]);
          dcplx dz[3];
          pointMotion(x, at[gp], ref, dz);
          dcplx zr = dcplx(0, w / g) * ph - dz[2];
          double c = -(rho * g / 4) * std::norm(zr) * 0.5 * L;
          double fw[2] = {c * nx, c * ny};
          add(at[gp], fw);
        }
      }
    }
    if (b.free) {
      // rotation: mean of alpha x F1, F1 = M xdd = -w^2 M xi (the first-order
      // force on the body), and of the moment's alpha x M1 + xi x F1 (z part)
      dcplx F1[6];
      for (int r = 0; r < 6; r++) {
        F1[r] = 0;
        for (int c = 0; c < 6; c++) F1[r] += -w * w * b.M[6 * r + c] * x[c];
      }
      rotationTerm(x, F1, F);
    }
    for (int k = 0; k < 3; k++) out[3 * h + k] = F[k];
  }
}

void driftFK(const PanelField& f, const DriftBody& b, const std::vector<dcplx>& xi, double* out) {
  const std::vector<Panel>& pn = *f.pn;
  const double* ref = f.out->ref;
  const int nh = nhead(f);
  const double rho = f.out->rho, g = f.out->g, w = f.omega;
  for (int h = 0; h < nh; h++) {
    const dcplx* x = &xi[6 * h];
    const double beta = f.out->heading[h];
    double F[3] = {0, 0, 0};
    dcplx F1[6] = {0, 0, 0, 0, 0, 0};  // first-order Froude-Krylov force, then + hydrostatic
    auto add = [&](const double* at, double fx, double fy) {
      F[0] += fx, F[1] += fy;
      F[2] += (at[0] - ref[0]) * fy - (at[1] - ref[1]) * fx;
    };
    for (int i = 0; i < f.nb; i++) {
      const Panel& p = pn[i];
      dcplx gi[3], d[3];
      const dcplx ph = incident(f, p.c, beta, gi);
      pointMotion(x, p.c, ref, d);
      // velocity squared (rho/4) |grad phi_I|^2 and pressure gradient
      // (rho/2) Re(X . conj(-i w grad phi_I)), as driftNear's with phi_I
      double q = std::norm(gi[0]) + std::norm(gi[1]) + std::norm(gi[2]), pg = 0;
      for (int k = 0; k < 3; k++) pg += (d[k] * std::conj(dcplx(0, -w) * gi[k])).real();
      const double s = ((rho / 4) * q + (rho / 2) * pg) * p.area;
      add(p.c, s * p.n[0], s * p.n[1]);
      // F1 = -int p1 n dS, p1 = i w rho phi_I (moment about ref)
      const dcplx p1 = dcplx(0, w * rho) * ph * p.area;
      const double r[3] = {p.c[0] - ref[0], p.c[1] - ref[1], p.c[2] - ref[2]};
      const double rn[3] = {r[1] * p.n[2] - r[2] * p.n[1], r[2] * p.n[0] - r[0] * p.n[2],
                            r[0] * p.n[1] - r[1] * p.n[0]};
      for (int k = 0; k < 3; k++) F1[k] -= p1 * p.n[k], F1[3 + k] -= p1 * rn[k];
      // waterline -(rho g/4) |eta_I - X_3|^2 n dl, eta_I = (i w / g) phi_I(z = 0)
      for (int e = 0; e < p.nv; e++) {
        double at[2][3], L, nx, ny;
        if (!waterEdge(p, e, at, &L, &nx, &ny)) continue;
        for (int gp = 0; gp < 2; gp++) {
          dcplx dz[3];
          pointMotion(x, at[gp], ref, dz);
          const dcplx zr = dcplx(0, w / g) * incident(f, at[gp], beta, nullptr) - dz[2];
          const double c = -(rho * g / 4) * std::norm(zr) * 0.5 * L;
          add(at[gp], c * nx, c * ny);
        }
      }
    }
    if (b.free) {
      // rotation: F1 the first-order Froude-Krylov plus hydrostatic force
      for (int r = 0; r < 6; r++)
        for (int c = 0; c < 6; c++) F1[r] -= b.Cb[6 * r + c] * x[c];
      rotationTerm(x, F1, F);
    }
    for (int k = 0; k < 3; k++) out[3 * h + k] = F[k];
  }
}

void driftPhase(const PanelField& f, const DriftBody& b, const std::vector<dcplx>& xi,
                double* out) {
  const int nh = nhead(f);
  for (int h = 0; h < nh; h++) {
    const double beta = f.out->heading[h];
    dcplx u[3];
    pointMotion(&xi[6 * h], b.com, f.out->ref, u);
    // U: the COM's displacement along the wave; mean of Re(X_D e^{iK U}) is
    // (1/2) Re(i K X_D conj(U)) (X_D = X - FK, the diffraction force)
    const dcplx U = std::cos(beta) * u[0] + std::sin(beta) * u[1];
    const int to[3] = {0, 1, 5};
    for (int k = 0; k < 3; k++) {
      const int o = (f.w * nh + h) * 6 + to[k];
      const dcplx XD(f.out->Xre[o] - f.out->FKre[o], f.out->Xim[o] - f.out->FKim[o]);
      out[3 * h + k] += 0.5 * (dcplx(0, f.K) * XD * std::conj(U)).real();
    }
  }
}

std::string panelSolveDrift(const PanelMesh& body, const PanelMesh& lid,
                            const std::vector<double>& omega, const std::vector<double>& heading,
                            const DriftBody& b, HydroCoef* out, DriftTable* dt, bool near) {
  int nh = (int)heading.size(), nw = (int)omega.size();
  dt->far.assign(3 * nh * nw, 0);
  dt->near.assign(3 * nh * nw, 0);
  dt->fk.assign(3 * nh * nw, 0);
  std::mutex mu;
  std::string bad;
  PanelFieldFn fn = [&](const PanelField& f) {
    std::vector<dcplx> xi;
    if (!driftRao(f, b, &xi)) {
      std::lock_guard<std::mutex> l(mu);
      char s[160];
      std::snprintf(s, sizeof s, "drift: singular motion equations at omega = %g rad/s", f.omega);
      bad = s;
      return;
    }
    driftFar(f, xi, &dt->far[3 * nh * f.w]);
    driftFK(f, b, xi, &dt->fk[3 * nh * f.w]);
    driftPhase(f, b, xi, &dt->fk[3 * nh * f.w]);
    if (near) driftNear(f, b, xi, &dt->near[3 * nh * f.w]);
  };
  std::string err;
  if (!panelSolve(body, lid, omega, heading, out, &err, &fn)) return err;
  if (!bad.empty()) return bad;
  for (size_t i = 0; i < dt->far.size(); i++)
    if (!std::isfinite(dt->far[i]) || !std::isfinite(dt->near[i]) ||
        !std::isfinite(dt->fk[i])) {
      char s[160];
      std::snprintf(s, sizeof s, "drift: non-finite mean drift at omega = %g rad/s",
                    omega[i / (3 * nh)]);
      return s;
    }
  return "";
}

}  // namespace mjb
