// gltimer: GL timestamp queries per named stage, read back frames later
#include "gl/gltimer.h"

#include <cstdint>

namespace mjb {
namespace {

// read slot k of s into its statistics; without wait, only if ready
bool collect(const GladGLContext& gl, GlStage* s, int k, bool wait) {
  GLuint q0 = s->query[2 * k], q1 = s->query[2 * k + 1];
  if (!wait) {
    // the end stamp is written after the begin stamp, so it decides
    GLint ready = 0;
    gl.GetQueryObjectiv(q1, GL_QUERY_RESULT_AVAILABLE, &ready);
    if (!ready) return false;
  }
  GLuint64 a = 0, b = 0;  // [ns]
  gl.GetQueryObjectui64v(q0, GL_QUERY_RESULT, &a);
  gl.GetQueryObjectui64v(q1, GL_QUERY_RESULT, &b);
  s->last = 1e-6 * double(int64_t(b - a));
  s->sum += s->last;
  s->n++;
  s->pending[k] = 0;
  return true;
}

int slot(const GlTimer* t) {
  return int(t->frame % (t->lag + 1));
}

}  // namespace

void timerInit(GlTimer* t, const GladGLContext* gl, int lag) {
  *t = GlTimer();
  t->gl = gl;
  t->lag = lag < 1 ? 1 : lag;
}

void timerFree(GlTimer* t) {
  for (GlStage& s : t->stage) t->gl->DeleteQueries(GLsizei(s.query.size()), s.query.data());
  t->stage.clear();
}

int timerStage(GlTimer* t, const char* name) {
  for (size_t i = 0; i < t->stage.size(); i++) {
    if (t->stage[i].name == name) return int(i);
  }
  GlStage s;
  s.name = name;
  s.query.assign(2 * (t->lag + 1), 0);
  s.pending.assign(t->lag + 1, 0);
  t->gl->GenQueries(GLsizei(s.query.size()), s.query.data());
  t->stage.push_back(s);
  return int(t->stage.size()) - 1;
}

void timerBegin(GlTimer* t, int id) {
  GlStage* s = &t->stage[id];
  int k = slot(t);
  // the slot's old result is lag frames old; waiting here is rare
  if (s->pending[k]) collect(*t->gl, s, k, true);
  t->gl->QueryCounter(s->query[2 * k], GL_TIMESTAMP);
}

void timerEnd(GlTimer* t, int id) {
  GlStage* s = &t->stage[id];
  int k = slot(t);
  t->gl->QueryCounter(s->query[2 * k + 1], GL_TIMESTAMP);
  s->pending[k] = 1;
}

void timerFrame(GlTimer* t) {
  for (GlStage& s : t->stage) {
    for (int j = 1; j <= t->lag + 1; j++) {  // oldest slot first
      int k = int((t->frame + j) % (t->lag + 1));
      if (s.pending[k]) collect(*t->gl, &s, k, false);
    }
  }
  t->frame++;
}

void timerFlush(GlTimer* t) {
  for (GlStage& s : t->stage) {
    for (int j = 1; j <= t->lag + 1; j++) {  // oldest slot first
      int k = int((t->frame + j) % (t->lag + 1));
      if (s.pending[k]) collect(*t->gl, &s, k, true);
    }
  }
}

}  // namespace mjb
