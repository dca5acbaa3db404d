// wind: gusts from the Froya spectrum, drag and friction of the air on dry
// faces (docs/physics.md, "Irregular seas and wind")
#include "sea/wind.h"

#include <algorithm>
#include <cmath>

#include "api/buoy.h"
#include "hull/hull.h"
#include "sea/spectra.h"

namespace mjb {

double froya(double u0, double f) {
  // Froya spectrum at z = 10 m (Andersen and Lovseth 1992; API RP 2A-WSD
  // 2.3.2c; DNV-RP-C205 eq. 2.16): S(f) = 320 (U0/10)^2 / (1 + ft^n)^(5/3n),
  // ft = 172 f (U0/10)^-0.75, n = 0.468, S in m^2/s^2 per Hz
  if (!(f > 0) || !(u0 > 0)) return 0;
  const double n = 0.468;
  double u = u0 / 10, ft = 172 * f * std::pow(u, -0.75);
  return 320 * u * u / std::pow(1 + std::pow(ft, n), 5 / (3 * n));
}

// gusts between kF0 and kF1 [Hz] (periods of 2000 s to 2 s) in bins of
// equal width in log f: the spectrum's energy sits at low frequencies
static const double kF0 = 5e-4, kF1 = 0.5;

void windGusts(Wind* w) {
  const mjbWind& p = w->par.w;
  w->gust.clear();  // keeps capacity
  if (p.gust != mjbGUST_FROYA || !(p.speed > 0)) return;
  Rng r(p.seed);
  const int n = p.ngust, sub = 16;
  const double l0 = std::log(kF0), dl = (std::log(kF1) - l0) / n;
  for (int i = 0; i < n; i++) {
    // draws as in specExpand: frequency in the bin, then phase
    double f = std::exp(l0 + (i + r.uniform()) * dl);
    double ph = 2 * M_PI * r.uniform();
    // the bin's variance, Simpson in log f: integral S(f) f dlog f
    double h = dl / sub, e = 0;
    for (int j = 0; j <= sub; j++) {
      double c = j == 0 || j == sub ? 1 : (j % 2 ? 4 : 2);
      double fj = std::exp(l0 + i * dl + j * h);
      e += c * froya(p.speed, fj) * fj;
    }
    w->gust.push_back(Gust{std::sqrt(2 * e * h / 3), f, ph});
  }
}

double windSpeed(const Wind& w, double t) {
  double u = w.par.w.speed;
  for (const Gust& g : w.gust) u += g.a * std::cos(2 * M_PI * g.f * t + g.ph);
  return u;
}

std::string windMake(Buoy* b) {
  Wind& w = b->wind;
  w.par = b->cfg.wind;
  w.gust.reserve(1024);
  windGusts(&w);
  w.part.clear();
  w.body.clear();
  w.extra.clear();
  for (size_t i = 0; i < b->hull.size(); i++) {
    const Hull& h = b->hull[i];
    w.part.push_back(Wind::Part{h.body, -1 - h.t0, h.nt, int(i)});
  }
  for (int g : w.par.geom) {
    Mesh mesh = hullMesh(b->m, g, &b->cfg.warn);
    int v0 = w.vert.size() / 3, t0 = w.face.size() / 3;
    w.vert.insert(w.vert.end(), mesh.v.begin(), mesh.v.end());
    for (int i : mesh.f) w.face.push_back(i + v0);
    w.part.push_back(Wind::Part{b->m->geom_bodyid[g], t0, mesh.nf(), -1});
  }
  for (const Wind::Part& p : w.part) w.body.push_back(p.body);
  std::sort(w.body.begin(), w.body.end());
  w.body.erase(std::unique(w.body.begin(), w.body.end()), w.body.end());
  for (int bd : w.body) {
    if (!std::binary_search(b->body.begin(), b->body.end(), bd)) w.extra.push_back(bd);
  }
  return "";
}

// the air's force on one dry triangle (corners p, world frame) of a body
// moving with vel ([angular; linear] at com), added to w about com
static void triForce(const Wind& wd, const double U[2], const double* p0, const double* p1,
                     const double* p2, const double* com, const double vel[6], double* w) {
  double c[3], e1[3], e2[3], n[3];
  for (int j = 0; j < 3; j++) {
    c[j] = (p0[j] + p1[j] + p2[j]) / 3 - com[j];
    e1[j] = p1[j] - p0[j];
    e2[j] = p2[j] - p0[j];
  }
  mju_cross(n, e1, e2);
  double a2 = mju_norm3(n);  // twice the area
  if (!(a2 > 0)) return;
  for (int j = 0; j < 3; j++) n[j] /= a2;
  double a = 0.5 * a2, vt[3], vr[3];
  mju_cross(vt, vel, c);  // omega x r
  for (int j = 0; j < 3; j++) vr[j] = (j < 2 ? U[j] : 0) - (vel[3 + j] + vt[j]);
  double V = mju_norm3(vr);
  if (!(V > 0)) return;
  const double q = 0.5 * wd.par.rho;
  double vn = mju_dot3(vr, n), f[3] = {0, 0, 0};
  // pressure drag on windward faces: 0.5 rho C_d V^2 times the face's
  // area projected across the flow (a cos), along the relative flow
  if (vn < 0) {
    double s = q * wd.par.cd * a * (-vn / V) * V;
    for (int j = 0; j < 3; j++) f[j] += s * vr[j];
  }
  // skin friction on every dry face: 0.5 rho C_f a |v_t| v_t
  double tan[3];
  for (int j = 0; j < 3; j++) tan[j] = vr[j] - vn * n[j];
  double st = q * wd.par.cf * a * mju_norm3(tan);
  for (int j = 0; j < 3; j++) f[j] += st * tan[j];
  double t[3];
  mju_cross(t, c, f);
  for (int j = 0; j < 3; j++) {
    w[j] += f[j];
    w[3 + j] += t[j];
  }
}

void windWrench(const Buoy& b, const mjModel* m, const mjData* d, State* s) {
  const Wind& wd = b.wind;
  if (!wd.par.on) return;
  const Sea& sea = b.cfg.sea;
  const double t = d->time, sp = windSpeed(wd, t), dr = wd.par.w.dir * M_PI / 180;
  const double U[2] = {sp * std::cos(dr), sp * std::sin(dr)};
  // a centroid above every crest is dry, below every trough wet; between,
  // the exact surface height decides (centroid rule, docs/physics.md)
  double amp = 0;
  for (const Wave& w : sea.waves) amp += std::fabs(w.amp);
  const int nb6 = 6 * m->nbody;
  for (const Wind::Part& p : wd.part) {
    const int bd = p.body;
    if (s->bad[bd]) continue;
    mjtNum vel[6];
    mj_objectVelocity(m, d, mjOBJ_BODY, bd, vel, 0);
    const mjtNum* x = d->xpos + 3 * bd;
    const mjtNum* R = d->xmat + 9 * bd;
    const mjtNum* com = d->xipos + 3 * bd;
    bool ok = true;
    for (int j = 0; j < 6; j++) ok = ok && std::isfinite(vel[j]);
    if (!ok) continue;
    double* w = s->part.data() + mjbPART_WIND * nb6 + 6 * bd;
    const bool hull = p.t0 < 0;
    const int t0 = hull ? -1 - p.t0 : p.t0;
    // cpu backend: the vertex heights above the surface its water pass
    // left in s->h (unless it skipped the hull as above every crest: all
    // dry); a centroid is dry when their mean is > 0, the linear surface
    // the pressure cut uses. gl: the exact height at the centroid.
    const bool useH = hull && !b.gl;
    bool allDry = false;
    if (useH) {
      const Hull& hl = b.hull[p.hull];
      allDry = x[2] - hl.rad > s->crest + 1e-6 * (1 + std::fabs(x[2]) + hl.rad);
    }
    const int* face = hull ? b.face.data() : wd.face.data();
    const double* vert = hull ? b.vert.data() : wd.vert.data();
    for (int k = t0; k < t0 + p.nt; k++) {
      double q[3][3];
      for (int i = 0; i < 3; i++) {
        const double* v = vert + 3 * face[3 * k + i];
        mju_rotVecMat(q[i], v, R);
        for (int j = 0; j < 3; j++) q[i][j] += x[j];
      }
      if (useH && !allDry) {
        const int* f = face + 3 * k;
        if (s->h[f[0]] + s->h[f[1]] + s->h[f[2]] <= 0) continue;
        triForce(wd, U, q[0], q[1], q[2], com, vel, w);
        continue;
      }
      double cz = (q[0][2] + q[1][2] + q[2][2]) / 3;
      if (cz < sea.level - amp && !allDry) continue;
      if (cz <= sea.level + amp && !allDry) {
        double cx = (q[0][0] + q[1][0] + q[2][0]) / 3, cy = (q[0][1] + q[1][1] + q[2][1]) / 3;
        if (cz <= sea.height(cx, cy, t)) continue;
      }
      triForce(wd, U, q[0], q[1], q[2], com, vel, w);
    }
  }
  for (int bd : wd.body) {
    if (s->bad[bd]) continue;
    const double* w = s->part.data() + mjbPART_WIND * nb6 + 6 * bd;
    for (int j = 0; j < 6; j++) s->wrench[6 * bd + j] += w[j];
  }
}

}  // namespace mjb
