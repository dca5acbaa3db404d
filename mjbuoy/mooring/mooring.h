// mooring: the lines of a model, their ends and the seabed (static), and
// their per-mjData state (docs/mooring.md)
#ifndef MJBUOY_MOORING_MOORING_H_
#define MJBUOY_MOORING_MOORING_H_

#include <vector>

#include "mooring/line.h"

namespace mjb {

// one end of a line: a site (id >= 0, on body) or a fixed world point p
struct LineEnd {
  int site = -1;
  int body = 0;        // the site's body; 0 (world) for a fixed point
  bool moves = false;  // the body can move (gets the line's force)
  double p[3] = {0, 0, 0};  // fixed point [m]
};

// a line and its ends: end[0] the anchor (node 0), end[1] the fairlead (node N)
struct MoorLine {
  Line line;
  LineEnd end[2];
};

struct Mooring {
  std::vector<MoorLine> line;
  Seabed bed;
  bool defaultBed = false;  // deep sea: the bed lies at the lowest fixed anchor
  std::vector<int> body;    // bodies at moving ends, ascending, once each
};

// per-mjData state of all lines
struct MoorState {
  std::vector<LineState> ls;
  std::vector<double> wrench;   // nbody x 6: the lines' force and torque about xipos
  // per line and end (2 each): last tension [N] and force vector on the end [N]
  std::vector<double> tend, fend;
  std::vector<char> told;       // per line: overload named (1), non-finite named (2)
  std::vector<char> bad;        // per line: its state is not finite (no force)
  std::vector<double> eend;     // per line: its ends' position and velocity now, 12
  std::vector<char> ev;         // per line: what the last evaluation has to report
  long key = -1;                // the step clock (util/stepclock.h)
  double tcur = 0;
};

}  // namespace mjb

#endif  // MJBUOY_MOORING_MOORING_H_
