// catenary: the static elastic catenary of a line with seabed contact
// (Irvine 1981 ch. 2; the quasi-static equations of Jonkman 2007, NREL/TP-
// 500-41958 sec. 4.2, as MAP++ and MoorPy solve them), with no seabed friction
#ifndef MJBUOY_MOORING_CATENARY_H_
#define MJBUOY_MOORING_CATENARY_H_

namespace mjb {

// a solved line: horizontal and vertical tension at the fairlead, and the
// length lying on the bed
struct Catenary {
  double hf = 0, vf = 0;  // fairlead tension components [N] (vf upward)
  double lb = 0;          // unstretched length on the seabed [m]
  double len = 0, ea = 0, w = 0;  // the line: L [m], EA [N], weight per length [N/m]
  bool bed = false;       // the anchor is on the bed (contact allowed)
};

// the fairlead position (x along the span, z up, relative to the anchor)
// of a line with fairlead tension hf, vf (c's hf, vf; c.lb is set)
void catenaryEnd(Catenary* c, double* x, double* z);

// solve for hf, vf so that the fairlead is at horizontal span x >= 0 and
// height z above the anchor, for a line of unstretched length len, axial
// stiffness ea and submerged weight w > 0 per length; bed: the anchor is on
// a bed the line may rest on. False (c untouched but for the line) when no
// such shape exists (the line slack on the bed reaches past x, or x = 0)
// or the solution misses the ends by more than 1e-7 of the line's size
bool catenarySolve(double x, double z, double len, double ea, double w, bool bed,
                   Catenary* c);

// the point at unstretched arc length s from the anchor of a solved line:
// horizontal x and vertical z from the anchor [m], and the tension [N]
void catenaryPoint(const Catenary& c, double s, double* x, double* z, double* t);

}  // namespace mjb

#endif  // MJBUOY_MOORING_CATENARY_H_
