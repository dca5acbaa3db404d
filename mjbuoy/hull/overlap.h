// overlap: closed pieces of one hull mesh that intersect (merged without a
// boolean union), whose shared volume the pressure would count twice
#ifndef MJBUOY_OVERLAP_H_
#define MJBUOY_OVERLAP_H_

#include <string>
#include <vector>

#include "hull/hull.h"

namespace mjb {

// pairs of closed pieces (connected by shared vertices, every edge used
// twice) that share volume: a vertex or triangle centroid of one lies inside
// the other (generalized winding number above 3/4: points on the other's
// surface, at most 1/2 on a face and less on a convex edge or corner, do
// not count), or an edge of one passes through a triangle of the other
// (strictly: pieces that only touch do not count); pieces numbered from 1
// in the order of their first triangle. ntri gets each piece's triangle
// count. Load time only
std::vector<std::pair<int, int>> overlappingPieces(const Mesh& mesh, std::vector<int>* ntri);

// a warning for geom gname if its mesh has overlapping closed pieces
void checkOverlap(const Mesh& mesh, const std::string& gname, std::vector<std::string>* warn);

}  // namespace mjb

#endif  // MJBUOY_OVERLAP_H_
