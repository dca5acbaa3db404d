// hydro: Kerner's (2016) hydrodynamic forces on one wet triangle
//
// v is the flow-relative velocity of the wet triangle's centroid: its point
// velocity minus the water's (current + wave orbital) velocity there [m/s].
// n is the outward unit normal, A the wet area [m^2]. Forces in N.
#ifndef MJBUOY_HYDRO_H_
#define MJBUOY_HYDRO_H_

#include <cfloat>
#include <cmath>

namespace mjb {

// Reynolds numbers below this are clamped: the ITTC line has a pole at
// Rn = 100 and is meaningless below about 1e3 (peers clamp there too)
static const double kRnMin = 1e3;

// ITTC 1957 model-ship correlation line C_F = 0.075 / (log10 Rn - 2)^2
double ittc57(double rn);

// viscous resistance (Kerner part 2): F = 0.5 rho C_F (1+k_i) A |v| v_f,
// with v_f = -|v| t / |t| the tangential flow direction scaled by |v|
// (t = v - (v.n) n). Zero when the flow is normal to the triangle.
void viscousForce(double rho, double cf, double ff, double A, const double n[3],
                  const double v[3], double f[3]);

// pressure drag (cos = v.n/|v| > 0, the face advances into the water):
//   F = -(c1 |v|/vr + c2 (|v|/vr)^2) A cos^fp n
// suction drag (cos < 0, the face retreats):
//   F = +(s1 |v|/vr + s2 (|v|/vr)^2) A |cos|^fs n
// drag = {c1, c2, fp}, suction = {s1, s2, fs}, vr the reference speed
void dragForce(const double drag[3], const double suction[3], double vr, double A,
               const double n[3], const double v[3], double f[3]);

// slamming (Kerner part 2) for one original hull triangle of area S:
// Q = A_wet v is its swept-volume rate, Gamma = |Q - Q_prev| / (S dt), and
//   F = -clamp(Gamma / gmax, 0, 1)^p cos F_stop,  F_stop = m v (2 A_wet / S_hull) / dt
// for advancing faces (cos > 0). Kerner's F_stop = m v 2A/S is a momentum;
// we divide by the step dt so the force stops the motion in one step at
// most. mass is the effective mass of the rigid group at the centroid
// along v times the hull's share (rigid.h; docs/physics.md "Slamming with
// the effective mass"): summed over a closed hull (sum of A cos over
// advancing faces is at most S_hull / 2) the impulses are a convex
// combination of point stops, so they never reverse a point's motion nor
// raise the kinetic energy.
// gain scales the result (1: Kerner's model, 0: off). q and qprev are Q
// now and at the previous step [m^3/s] as the history keeps them
// (sweptRate, in float: docs/physics.md 4.4).
void slamForce(double gain, double gmax, double p, double mass, double shull, double S,
               double A, const double v[3], const double q[3], const double qprev[3],
               const double n[3], double dt, double f[3]);

// the swept-volume rate Q = A v [m^3/s] of wet area A [m^2] moving at v
// [m/s], in float as the slamming history keeps it (docs/physics.md 4.4);
// beyond float's range +-inf, as the lanes' conversion gives (a cast
// would be undefined there)
inline void sweptRate(double A, const double v[3], float q[3]) {
  for (int j = 0; j < 3; j++) {
    const double x = A * v[j];
    q[j] = std::fabs(x) <= FLT_MAX ? float(x) : x > 0 ? INFINITY : x < 0 ? -INFINITY : NAN;
  }
}

}  // namespace mjb

#endif  // MJBUOY_HYDRO_H_
