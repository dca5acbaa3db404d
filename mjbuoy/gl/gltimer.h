// gltimer: GPU time of named stages, for benchmarks. Each stage is framed by
// two GL_TIMESTAMP queries (glQueryCounter), so stages may nest or overlap.
// Results are read `lag` frames later, when the GPU has long finished them,
// so timing never makes the CPU wait; timerFlush waits for the rest. Call
// everything with the timer's context current.
#ifndef MJBUOY_GLTIMER_H_
#define MJBUOY_GLTIMER_H_

#include <string>
#include <vector>

#include <glad/gl.h>

namespace mjb {

struct GlStage {
  std::string name;
  double last = 0;             // latest result [ms]
  double sum = 0;              // all results [ms]
  long n = 0;                  // number of results
  std::vector<GLuint> query;   // per ring slot: begin, end
  std::vector<char> pending;   // per ring slot: issued, not read yet
  double mean() const { return n ? sum / n : 0; }
};

struct GlTimer {
  const GladGLContext* gl = nullptr;
  int lag = 2;                 // frames between a query and its read-back
  long frame = 0;
  std::vector<GlStage> stage;
};

// start t on gl's context; lag >= 1 frames of queries in flight
void timerInit(GlTimer* t, const GladGLContext* gl, int lag = 2);

// delete t's queries
void timerFree(GlTimer* t);

// id of the stage called name, added on first use
int timerStage(GlTimer* t, const char* name);

// mark the start and the end of stage id in the GL command stream
void timerBegin(GlTimer* t, int id);
void timerEnd(GlTimer* t, int id);

// end of a frame: collect every result that is ready, without waiting
void timerFrame(GlTimer* t);

// wait for and collect every pending result
void timerFlush(GlTimer* t);

}  // namespace mjb

#endif  // MJBUOY_GLTIMER_H_
