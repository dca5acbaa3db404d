// gl: the OpenGL compute backend as the glue sees it: created for a hull
// set and a sea, per-mjData buffers, the wrench of one evaluation
#ifndef MJBUOY_GL_H_
#define MJBUOY_GL_H_

#include <cstddef>
#include <string>

#include <mujoco/mujoco.h>

#include "hull/hullset.h"
#include "hull/hullstate.h"
#include "sea/sea.h"

namespace mjb {

struct GlBackend;  // gl.cc: context, programs, static buffers

// the gl backend's per-mjData buffers, beside the HullState
struct GlState {
  unsigned slambuf[2] = {0, 0};  // slamming history buffers, [slamcur] = this step's
  int slamcur = 0;
  // the label offsets' ring (shaders/pipeline.h B_OFF), the slot this
  // step's first call writes, and how many steps before it the ring holds
  // (0 to 2; their times HullState::tgOff, tgOld)
  unsigned offbuf = 0;
  int offslot = 0, offn = 0;
};

// create the backend for the hulls hs on sea with room for wcap wave
// components into *out, and name its renderer (false and err if GL is
// unusable, *out null)
bool glMake(const HullSet& hs, const Sea& sea, size_t wcap, GlBackend** out,
            std::string* renderer, std::string* err);
// fill s->wrench and s->part for the hulls hs on sea from d's current
// state, as cpuWrench (cpu/cpu.h) does, with d's buffers gs
void glWrench(GlBackend* g, const HullSet& hs, const Sea& sea, const mjModel* m,
              const mjData* d, HullState* s, GlState* gs);
// free *g with its context; *g becomes null
void glFree(GlBackend** g);
void glFreeState(GlBackend* g, GlState* s);
// copy src's slamming history buffers into dst's (created if needed)
bool glCopyState(GlBackend* g, GlState* dst, const GlState* src);
int glStageTimes(GlBackend* g, const char** name, double* ms, int n);
// upload sea's current waves and current (mjb_setSea)
void glSetSea(GlBackend* g, const Sea& sea);

}  // namespace mjb

#endif  // MJBUOY_GL_H_
