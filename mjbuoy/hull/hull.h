// hull: closed triangle mesh of a hull geom, in its body's frame
#ifndef MJBUOY_HULL_H_
#define MJBUOY_HULL_H_

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

namespace mjb {

struct Mesh {
  std::vector<double> v;  // vertices, 3 per vertex [m]
  std::vector<int> f;     // faces, 3 vertex indices each, counter-clockwise seen from outside
  int nv() const { return v.size() / 3; }
  int nf() const { return f.size() / 3; }
};

// tessellation resolution of primitive geoms (docs/mjcf.md)
enum {
  kBoxDiv = 4,      // each box face: kBoxDiv x kBoxDiv squares
  kRound = 32,      // segments around spheres, ellipsoids, cylinders, capsules
  kSphereRings = 16,  // latitude bands of a sphere (capsule caps: half each)
  kCylDiv = 4,      // bands along a cylinder's or capsule's side
};

// closed outward mesh of primitive geom type with MuJoCo size, in the geom
// frame; round shapes are scaled radially so the enclosed volume is exact
Mesh tessellate(int type, const double size[3]);

// edge topology and enclosed volume of a mesh
struct Topology {
  int boundary;     // edges used by one face only (holes)
  int nonmanifold;  // edges used by more than two faces, or twice the same way
  double volume;    // signed enclosed volume [m^3]; < 0 when normals point inward
};
Topology topology(const Mesh& mesh);

// what repair() found in a welded mesh and did about it
struct Repair {
  int duplicate = 0;    // triangles on the same three vertices as an earlier one: dropped
  int degenerate = 0;   // zero-area triangles: dropped
  int rewound = 0;      // triangles wound against their neighbours: re-wound to match
  int inverted = 0;     // closed pieces enclosing negative volume: all their faces re-wound
  double invvol = 0;    // the enclosed volume of those pieces before [m^3]
  int boundary = 0;     // edges of one triangle only (holes), after repair
  int nonmanifold = 0;  // edges of more than two triangles, or not orientable, after repair
};
Repair repair(Mesh* mesh);

// smallest primitive hull size (half-size, radius, half-length) [m]: below
// 0.1 mm surface tension, not buoyancy, carries a body, and far below the
// triangle areas underflow (docs/mjcf.md)
static const double kMinSize = 1e-4;

// "" if primitive hull geom g is large enough (meshes: always), else the error
std::string sizeError(const mjModel* m, int g);

// mesh of hull geom g in its body frame; appends load warnings
Mesh hullMesh(const mjModel* m, int g, std::vector<std::string>* warn);

}  // namespace mjb

#endif  // MJBUOY_HULL_H_
