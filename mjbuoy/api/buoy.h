// buoy: what mjbuoy keeps per attached model (static) and per mjData (state)
#ifndef MJBUOY_BUOY_H_
#define MJBUOY_BUOY_H_

#include <string>
#include <utility>
#include <vector>

#include <mujoco/mujoco.h>

#include "api/config.h"
#include "cpu/cpu.h"
#include "gl/gl.h"
#include "hull/hullset.h"
#include "hull/hullstate.h"
#include "hull/windload.h"
#include "radiation/diffract.h"
#include "mjbuoy.h"
#include "mooring/mooring.h"
#include "radiation/radcache.h"
#include "radiation/radiation.h"
#include "api/sensor.h"
#include "sea/waveint.h"

namespace mjb {

// static data of one attached model, built once by mjb_attach: its hulls
// (the HullSet base: m, hull, vert, face, tarea, body), the cpu backend's
// threads (the CpuPlan base: nthreads, split, splitHulls, pool) and the rest
struct Buoy : HullSet, CpuPlan {
  Config cfg;
  std::vector<Sensor> sensor;  // user sensors mjbuoy fills (sensor.h)
  std::string warnings;        // newline-separated
  std::string renderer;
  GlBackend* gl = nullptr;     // gl backend, when it runs
  size_t wcap = 0;             // wave components reserved (cpu scratch, gl buffers)
  Wind wind;                   // hull/windload.h
  Radiation rad;               // radiation.h: bodies with added mass and memory
  // the panel solver's coefficients set at attach (radattach.cc): body id
  // and its HydroCoef (about the body COM, body axes), for mjbuoy-hydro
  std::vector<std::pair<int, HydroCoef>> coef;
  Diffraction diff;            // diffract.h: diffraction excitation of those bodies
  RadCacheStats radcache;      // the panel solver's cache at attach (radcache.h)
  Mooring moor;                // mooring lines and the seabed (moorconfig.h)
};

// the static data of an attached model (glue.cc; tools only)
const Buoy* buoyOf(const mjbBuoy* b);

// per-mjData state: the hulls' (the HullState base: wrenches, histories,
// step clock, notices), each backend's own scratch and buffers, the stamp
// of the mjData it serves, radiation and diffraction; sized at creation,
// never resized while stepping
struct State : HullState {
  CpuState cpu;                // cpu/cpu.h: scratch and counters
  GlState gl;                  // gl/gl.h: slamming history and label offsets' buffers
  // stamp of the mjData this state last served (glue.cc, docs/robustness.md):
  // its buffer and its fwdVelocity count (the stage mjcb_passive runs in)
  // at the last callback; with tcur above. A count or time below these, or
  // another buffer, means d is a new mjData at a recycled address or reset
  const void* buf = nullptr;
  long vcount = -1;
  RadState rad;                // radiation.h: memory history, qM stamp
  // diffraction (diffract.h): per body of Buoy::diff its world wrench at
  // the COM, and whether a non-finite one was named
  std::vector<double> dwrench;
  std::vector<char> dtold;
  MoorState moor;              // mooring lines (moorstep.h)
};

// allocate s for b (glue.cc)
void makeState(const Buoy& b, State* s);
// about the bytes makeState allocates with nthreads cpu threads (glue.cc)
size_t stateBytes(const Buoy& b, int nthreads);

// the cpu backend's surface solves for d so far and the Newton steps they
// took (glue.cc; tools only): false if d has no state
bool newtonStats(const mjbBuoy* b, const mjData* d, long* solves, long* steps);
// the cpu backend's seconds in the vertex stage for d so far, all threads
// (glue.cc; tools only): false if d has no state
bool vertexSeconds(const mjbBuoy* b, const mjData* d, double* sec);

}  // namespace mjb

#endif  // MJBUOY_BUOY_H_
