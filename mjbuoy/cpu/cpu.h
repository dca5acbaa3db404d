// cpu: the cpu backend as the glue sees it: its plan of threads, its
// per-mjData scratch and the wrench of one evaluation (docs/physics.md,
// "Cost"); its stages are internal (cpuhull.h)
#ifndef MJBUOY_CPU_H_
#define MJBUOY_CPU_H_

#include <cstddef>
#include <vector>

#include <mujoco/mujoco.h>

#include "hull/hullset.h"
#include "hull/hullstate.h"
#include "sea/sea.h"

namespace mjb {

struct Pool;

// the threads of an attached model (api/glue.cc threads): chunk c is
// hulls [split[c], split[c + 1]); the pool has nthreads - 1 workers (none
// when the scene is small); splitHulls: too few hulls to balance, so each
// hull's chunks (hullChunks) are shared among the threads instead
struct CpuPlan {
  int nthreads = 1;
  std::vector<int> split;
  bool splitHulls = false;
  Pool* pool = nullptr;
};

// one chunk of a hull's sums (cpu.cc hullChunks): pass 1's pressure
// wrench [N, N m], wet area [m^2], its first moment along the flow [m^3]
// and the wet extent along it [m]; pass 2's unit viscous wrench and its
// first moment along the flow (cpuhull.h passChunk), drag and slamming
// wrenches
struct ChunkSum {
  double wp[6], wet, wdir, lo, hi;
  double wv1[6], wvd[6], wd[6], ws[6];
};

// wet triangle data of one call, per thread for the largest hull, reused
// hull after hull so it stays in cache (cpuhull.h TriScr)
struct TriState {
  std::vector<double> area;    // wet area [m^2], 1 each
  std::vector<double> c;       // wet centroid relative to the body COM, 3 each [m]
  std::vector<double> n;       // outward unit normal, 3 each
  std::vector<double> u;       // water velocity, mean over the wet part, 3 each [m/s]
  size_t per = 0;              // triangles per thread
};

// the cpu backend's per-mjData scratch and counters, beside the
// HullState; sized at creation, never resized while stepping
struct CpuState {
  // per thread: Newton and structure-of-arrays scratch (cpustate.cc
  // scratchSize), per doubles each
  std::vector<double> scr;
  size_t per = 0, mi = 0;
  // per thread: triangle indices for the lane kernels (cpupass.cc, trivec.h),
  // 4 per triangle of the largest hull
  std::vector<int> iscr;
  size_t iper = 0;
  // per thread: the chunk sums of the hull it owns, cper each
  std::vector<ChunkSum> csum;
  size_t cper = 0;
  // per thread: surface solves done and Newton steps they took
  // (mjbuoy-bench reports steps per solve)
  std::vector<long> nsolve, niter;
  // per thread: wall seconds in the vertex stage (transform, surface
  // search, e^L at wet vertices; mjbuoy-bench reports it)
  std::vector<double> vsec;
  // the vertices' neighbours along the hulls' edges (global indices):
  // vertex i's at adj[adjOff[i], adjOff[i + 1]); vertex integration sums
  // at a dry vertex only when one of them is wet (cpusum.h)
  std::vector<int> adjOff, adj;
  TriState tri;                // this call
};

// the chunks the cpu backend cuts a hull of nt triangles into (cpu.cc):
// fixed by nt alone, so results keep their bits for any thread count
int hullChunks(int nt);

// allocate cs for the hulls hs on sea with room for wcap components and
// the threads of plan (cpustate.cc)
void makeCpuState(const HullSet& hs, const Sea& sea, size_t wcap, const CpuPlan& plan,
                  CpuState* cs);
// about the bytes makeCpuState allocates with nthreads threads
size_t cpuStateBytes(const HullSet& hs, const Sea& sea, size_t wcap, int nthreads);

// fill s->wrench and s->part for the hulls hs on sea from d's current
// state, with the threads of plan and the scratch cs
void cpuWrench(const HullSet& hs, const Sea& sea, const CpuPlan& plan, const mjModel* m,
               const mjData* d, HullState* s, CpuState* cs);

}  // namespace mjb

#endif  // MJBUOY_CPU_H_
