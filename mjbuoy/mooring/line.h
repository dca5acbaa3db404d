// line: a lumped-mass mooring line (docs/mooring.md): nodes joined by
// axially elastic segments, with weight, buoyancy, Morison drag and added
// mass, on a flat seabed; its own state, stepped between two model steps
#ifndef MJBUOY_MOORING_LINE_H_
#define MJBUOY_MOORING_LINE_H_

#include <string>
#include <vector>

#include "sea/sea.h"

namespace mjb {

// the properties of a kind of line (mjbuoy.linetype.<type>.*)
struct LineType {
  double mass = 0;     // mass per unstretched length w [kg/m]
  double diam = 0;     // volume-equivalent diameter d [m]
  double ea = 0;       // axial stiffness EA [N]
  double ba = -0.5;    // internal (axial) damping BA: tension per strain rate [N s];
                       // negative: minus the ratio of a segment's critical damping
  double cdn = 1.2;    // normal drag coefficient, on d L
  double cdt = 0.008;  // tangential drag coefficient, on pi d L
  double can = 1.0;    // normal added-mass coefficient
  double cat = 0.0;    // tangential added-mass coefficient
};

// the seabed: a flat plane z = z with a spring-damper per unit contact area
// and regularised Coulomb friction (docs/mooring.md "Seabed")
struct Seabed {
  double z = 0;        // height of the bed [m]
  double k = 3e6;      // vertical stiffness per contact area d L [Pa/m]
  double c = 3e5;      // vertical damping per contact area [Pa s/m]
  double mu[2] = {0.5, 1.0};  // friction coefficients: axial, lateral
  double vs = 0.01;    // slip speed below which friction is viscous [m/s]
};

// one line, its static part
struct Line {
  std::string name;
  LineType t;
  double len = 0;      // unstretched length L [m]
  int nseg = 0;        // segments N (N + 1 nodes; 0 and N are the ends)
  // derived (lineDerive)
  double l0 = 0;       // unstretched segment length L / N [m]
  double mnode = 0;    // mass of an inner node w l0 [kg]
  double vnode = 0;    // displaced volume of an inner node pi d^2 / 4 l0 [m^3]
  double hmax = 0;     // the largest stable sub-step up to kOverStrain (lineStableStep) [s]
};

// the water a line is in
struct LineWater {
  const Sea* sea;      // density, level, waves, current, g
  const Seabed* bed;
  double crest;        // highest possible surface height [m]: above it a node is dry
  // the longest the water's kinematics at the nodes are kept [s]: between
  // evaluations a node sees u + a (t - tw), u and a taken at tw
  double refresh;
};

// one line's state: positions and velocities of all N + 1 nodes (the
// ends' are set by the caller), the water's velocity and acceleration at
// each node taken at the start of a step, and the last tensions
struct LineState {
  std::vector<double> r, v;      // 3 per node [m, m/s]
  std::vector<double> uw, aw;    // water velocity, acceleration, 3 per node
  std::vector<double> f;         // scratch: force per node [N]
  std::vector<double> q;         // scratch: unit tangent per node
  std::vector<double> qs;        // scratch: unit vector of each segment, node i to i + 1
  std::vector<double> im;        // inverse mass across, along each node, wet as at tw [1/kg]
  std::vector<double> ie;        // scratch: im with the drag implicit over the sub-step [1/kg]
  std::vector<double> td;        // scratch: implicit tension increment of each segment [N]
  std::vector<double> tri;       // scratch: the tridiagonal solve, 4 per segment
  std::vector<double> es;        // scratch: strain of each segment at the sub-step's start
  std::vector<double> tseg;      // tension of each segment after the last step [N]
  std::vector<char> wet;         // per node: below the surface at tw
  std::vector<double> st;        // scratch: the static solve (lineStatic), 34 per node
  double tw = -1;                // time the water's kinematics were taken [s]; < 0: none
  double end0[6] = {0}, end1[6] = {0};  // ends at the last step: position, velocity
  double bedlen = 0;             // unstretched length resting on the bed [m]
  int over = 0;                  // segments past kOverStrain in the last step
};

// a strain past which a segment is reported as overloaded
const double kOverStrain = 0.1;

// fill the derived values of l; "" or an error naming the line and field
std::string lineDerive(const LineWater& w, Line* l);

// the largest sub-step [s] at which lineStep is stable while no segment is
// past kOverStrain: 0.8 of 2 / omega_t of the explicit transverse modes at
// tension kOverStrain EA (the axial modes are implicit, stable at any
// step; docs/mooring.md "Integration")
double lineStableStep(const LineWater& w, const Line& l);

// size s for l
void lineMake(const Line& l, LineState* s);

// move l over [t, t + dt]: its ends go linearly from s->end0 to e0 (node 0)
// and from s->end1 to e1 (node N), 6 values each (position, velocity);
// inner nodes take one sub-step, or shorter ones while the tension makes
// the transverse modes too stiff for it: backward Euler in the axial
// stiffness, internal damping and seabed, symplectic Euler in the
// transverse elastic and fluid forces. The
// water's kinematics are taken at t when those held are w.refresh old
void lineStep(const LineWater& w, const Line& l, double t, double dt, const double e0[6],
              const double e1[6], LineState* s);

// the force the line puts on its end node 0 (end = 0) or N (end = 1) at end
// kinematics e (position, velocity) [N]: the end segment's tension along it
// towards the next node, plus the weight less buoyancy of the end node's
// half segment (lumped there) and its drag at time t [s]. tau [s]: the
// time since the line's state (an RK4 stage between steps), by which the
// neighbour node is carried on at its velocity, so the end segment is not
// stretched by the end's motion alone (a spurious stiffness EA / l0
// against a frozen node); returns the segment's tension [N] (0 when slack)
double lineEndForce(const LineWater& w, const Line& l, const LineState& s, int end,
                    const double e[6], double t, double tau, double f[3]);

// put l in place between ends e0 and e1 at rest, on its discrete static
// equilibrium (lineStatic) started from the elastic catenary (catenary.h),
// or from the straight line between the ends when there is no catenary;
// false when the static solve did not converge
bool lineRest(const LineWater& w, const Line& l, const double e0[3], const double e1[3],
              LineState* s);

// move the inner nodes of l (ends fixed) from s->r to the discrete static
// equilibrium of the lumped-mass line in still water: each node's weight,
// buoyancy, segment tensions and seabed contact balance (Newton on the
// total potential energy, convex in the positions; docs/mooring.md "Initial
// state"). Sets s->tseg; returns whether the largest force residual fell
// below 1e-6 of a node's weight (else the nodes stay at the lowest energy reached)
bool lineStatic(const LineWater& w, const Line& l, LineState* s);

// unit tangent at inner node j of the nodes r: along the chord of its two
// neighbours; returns the chord's length [m]
double lineTangent(const double* r, int j, double q[3]);

// submerged weight per unstretched length (w - rho A) g [N/m]
double lineWetWeight(const Sea& sea, const LineType& t);

}  // namespace mjb

#endif  // MJBUOY_MOORING_LINE_H_
