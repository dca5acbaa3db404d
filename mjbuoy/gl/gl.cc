// gl backend: the buoyancy pipeline as three compute dispatches for all
// hulls of all bodies (shaders/*.comp), one readback of one wrench per body
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "gl/egl.h"
#include "gl/gl.h"
#include "gl/glprog.h"
#include "gl/gltimer.h"
#include "shared.h"
#include "pipeline.h"
#include "hull/rigid.h"
#include "mjbuoy.h"

namespace mjb {

using namespace glsl;  // NOLINT: the shared layouts

static const char* kStage[] = {"verts.comp", "tris.comp", "bodies.comp"};
enum { kVerts, kTris, kBodies, kNStage };
// program variants, by #define at build (glMake), picked per step (progs):
// llvmpipe runs every if's body and every loop's at least once, masked, so
// a uniform cannot skip work, a define can. Bits: WI_SPLIT (tris.comp:
// components whose pieces need splitting, nfast < nwave), WI_NOMOM (Kerner's
// pressure: no pressure moments), WI_DEEP (every e^(-2kh) is 0: no
// finite-depth second pass), all three read by tris.comp only; WI_AIRY
// (no Gerstner component: no label solve) and WI_ONE (one component: its
// loops unrolled), read by verts.comp only. llvmpipe compiles a program's
// machine code at its first dispatch, so the unused cost only their GLSL
// compile at attach (12 programs and bodies.comp)
enum { kVSplit = 1, kVNomom = 2, kVDeep = 4, kVAiry = 8, kVOne = 16, kNVar = 32 };
static const char* kVarDef[] = {"WI_SPLIT", "WI_NOMOM", "WI_DEEP", "WI_AIRY", "WI_ONE"};
const int kVertVar = kVAiry | kVOne;             // the bits verts.comp reads
const int kTrisVar = kVSplit | kVNomom | kVDeep;  // the bits tris.comp reads
const int kMaxGroups = 65535;  // GL 4.3's minimum GL_MAX_COMPUTE_WORK_GROUP_COUNT
const int kNTex = 7;           // buffer textures (units 0 .. kNTex - 1)

struct GlBackend {
  GlContext ctx;
  GLuint vprog[kNVar] = {0};    // verts.comp by variant (only kVertVar bits: the rest 0)
  GLuint tprog[kNVar] = {0};    // tris.comp by variant (only kTrisVar bits: the rest 0)
  GLuint bprog = 0;             // bodies.comp
  GLuint buf[15] = {0};         // by binding point
  GLuint tex[kNTex] = {0};      // buffer textures of B_VOUT, B_LAB, B_TRI, B_VERT, B_EXP, B_WAVE,
                                // B_PHASE (units 0..6)
  GlTimer timer;
  int tstage[kNStage] = {0};
  std::mutex mu;                // one context: one thread at a time
  int nvert = 0, ntri = 0, nhull = 0, nslot = 0, nwave = 0, nchunk = 0, nvchunk = 0;
  // the components in the buffers' order, wave number ascending (perm:
  // buffer slot -> sea index), the first nfast fast (fastWave) at reach:
  // a bound on every piece's node gap over k [m], raised when a step
  // reports more (glWrench)
  std::vector<int> perm;
  double reach = 0;
  // the reach each mjData's steps have raised it to (from reach0, the first
  // guess): the buffers are redone for the data stepped when its reach is
  // not the one they hold, so no mjData's results depend on another's
  double reach0 = 0;
  std::map<const GlState*, double> reachOf;
  // the start-up ramp's gain on the amplitudes in the wave buffer (sea.h
  // gain): redone in a step whose time has another
  double gain = 1;
  int nfast = 0;
  int var = 0;                  // the sea's variant bits but kVSplit (seaUniforms)
  int vlocal = BUOY_VERT_LOCAL, local = BUOY_LOCAL, per = BUOY_PER, blocal = BUOY_BODY_LOCAL;
  GLint uHasprev[kNVar], uFirst[kNVar], uSlamdt[kNVar];  // per-step uniforms of the
                                // tprog, looked up in glMake
  GLint uvFirst[kNVar], uvGw[kNVar], uvOff[kNVar][3];  // and of the vprog (labelGuess)
  std::vector<GBody> body;      // per step, one per hull body (staging without persist)
  std::vector<float> phase;     // per step, nslot x nwave
  std::vector<float> out;       // readback, nslot x 10 x 4
  // persistent coherent mappings of B_BODY, B_PHASE (GL 4.4), else the
  // vectors above with glBufferSubData
  bool persist = false;
  GBody* bodyp = nullptr;
  float* phasep = nullptr;
};

static GLint loc(GlBackend* g, GLuint p, const char* name) {
  return g->ctx.gl.GetUniformLocation(p, name);
}

// the uniform called name of all triangle programs
static void trisUniform(GlBackend* g, const char* name, int v) {
  for (GLuint p : g->tprog) if (p) g->ctx.gl.ProgramUniform1i(p, loc(g, p, name), v);
}
static void trisUniform(GlBackend* g, const char* name, float v) {
  for (GLuint p : g->tprog) if (p) g->ctx.gl.ProgramUniform1f(p, loc(g, p, name), v);
}

// the programs of this step's stages (kVerts, kTris, kBodies)
static void progs(const GlBackend* g, GLuint* p) {
  int v = g->var | (g->nfast < g->nwave ? kVSplit : 0);
  p[kVerts] = g->vprog[v & kVertVar];
  p[kTris] = g->tprog[v & kTrisVar];
  p[kBodies] = g->bprog;
}

// buffer at binding point i with n bytes (data may be null)
static void makeBuffer(GlBackend* g, int i, size_t n, const void* data, GLenum usage) {
  const GladGLContext& gl = g->ctx.gl;
  gl.GenBuffers(1, &g->buf[i]);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, g->buf[i]);
  gl.BufferData(GL_SHADER_STORAGE_BUFFER, n ? n : 16, data, usage);
}

// workgroup sizes: the tuned defaults of pipeline.h, or for tuning
// MJBUOY_GL_GROUPS="verts tris per bodies" (powers of two, 1 .. 1024 each)
static bool groupSizes(GlBackend* g, std::string* err) {
  const char* env = std::getenv("MJBUOY_GL_GROUPS");
  if (!env || !*env) return true;
  int v[4];
  char end;
  bool ok = std::sscanf(env, "%d %d %d %d %c", v, v + 1, v + 2, v + 3, &end) == 4;
  for (int x : v) ok = ok && x >= 1 && x <= 1024 && !(x & (x - 1));
  if (!ok) {
    *err = std::string("MJBUOY_GL_GROUPS=\"") + env +
           "\": want four powers of two in 1..1024: verts tris per bodies (e.g. \"8 8 256 8\")";
    return false;
  }
  g->vlocal = v[0], g->local = v[1], g->per = v[2], g->blocal = v[3];
  return true;
}

// one wave component as the shaders read it, its amplitude times the
// start-up ramp's gain (sea.h; the shaders read every amplitude from here,
// so the surface, labels and pressure all see the ramp); Airy components
// (kind 1) take no part in the label search: steep 0; e^(-2 k h) for the finite-depth
// profiles (0 deep, or where k h >= 17: shaders/waveint.glsl WI_KHMAX)
static GWave gwave(const Wave& w, double depth, double reach, double gain) {
  double kh = w.k * depth;
  float e2 = depth > 0 && kh < 17 ? float(std::exp(-2 * kh)) : 0.0f;
  GWave o{float(w.k * w.dx), float(w.k * w.dy), float(gain * w.amp), float(w.kind), float(w.k),
          float(w.omega / w.k), 0, e2, float(w.kind == 0 ? w.steep : 0), float(w.dx), float(w.dy), 0};
  // the series length of its piece integrals (shaders/waveint.glsl
  // ddSeries): the fewest terms n >= 4 whose first left out, (n + 1) r^n /
  // (n + 2)!, is below 2.5e-7 at the node gap r = k reach; the largest,
  // 13, covers r = 2.17 (fast components have r <= WI_ROT = 2)
  double r = w.k * reach, f = 120;  // f = (n + 2)!
  int n = 4;
  for (; n < 13; n++) {
    f *= n + 2;
    if (std::pow(2.5e-7 * f / (n + 1), 1.0 / n) >= r) break;
  }
  o.terms = float(n | 1);  // odd: ddSeries sums its terms from the third two at a time
  return o;
}

// a component is fast (one series per piece, its turn along an edge by a
// Taylor series: shaders/tris.comp) while k reach <= WI_ROT
static bool fastWave(const Wave& w, double reach) { return w.k * reach <= 2.0; }

// the longest edge of any hull [m] (body frame)
static double longestEdge(const HullSet& b) {
  double e2 = 0;
  for (size_t t = 0; t + 2 < b.face.size(); t += 3) {
    for (int j = 0; j < 3; j++) {
      const double* p = &b.vert[3 * b.face[t + j]];
      const double* q = &b.vert[3 * b.face[t + (j + 1) % 3]];
      double d[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
      e2 = std::max(e2, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
  }
  return std::sqrt(e2);
}

// the uniforms that change with the sea
static void seaUniforms(GlBackend* g, const Sea& sea);

// the wave buffer from the sea at g->reach and the ramp's gain g->gain,
// sorted; nfast
static void uploadWaves(GlBackend* g, const Sea& sea) {
  const GladGLContext& gl = g->ctx.gl;
  int* p = g->perm.data();
  for (int i = 0; i < g->nwave; i++) p[i] = i;
  std::sort(p, p + g->nwave, [&](int a, int c) {
    return sea.waves[a].k < sea.waves[c].k || (sea.waves[a].k == sea.waves[c].k && a < c);
  });
  g->nfast = 0;
  while (g->nfast < g->nwave && fastWave(sea.waves[p[g->nfast]], g->reach)) g->nfast++;
  // uploaded in pieces from the stack: no allocation per step
  GWave buf[64];
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, g->buf[B_WAVE]);
  for (int i0 = 0; i0 < g->nwave; i0 += 64) {
    int n = std::min(64, g->nwave - i0);
    for (int i = 0; i < n; i++) {
      buf[i] = gwave(sea.waves[p[i0 + i]], sea.depth, g->reach, g->gain);
    }
    gl.BufferSubData(GL_SHADER_STORAGE_BUFFER, i0 * sizeof(GWave), n * sizeof(GWave), buf);
  }
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  trisUniform(g, "nfast", g->nfast);
}

// compile every program variant (kVarDef) with the group sizes as defines
static bool makePrograms(GlBackend* g, std::string* err) {
  const GladGLContext& gl = g->ctx.gl;
  std::string defs = "#define BUOY_VERT_LOCAL " + std::to_string(g->vlocal) +
                     "\n#define BUOY_LOCAL " + std::to_string(g->local) +
                     "\n#define BUOY_PER " + std::to_string(g->per) +
                     "\n#define BUOY_BODY_LOCAL " + std::to_string(g->blocal) + "\n";
  // every tris.comp variant, the verts.comp ones of its bits, bodies.comp
  for (int i = 0; i <= 2 * kNVar; i++) {
    int v = i % kNVar;
    bool vert = i >= kNVar && i < 2 * kNVar;
    if (v & ~(vert ? kVertVar : kTrisVar)) continue;
    std::string d = defs;
    for (int j = 0; j < 5; j++) {
      if (v & (1 << j)) d += std::string("#define ") + kVarDef[j] + " 1\n";
    }
    GLuint& p = i == 2 * kNVar ? g->bprog : vert ? g->vprog[v] : g->tprog[v];
    p = glProgram(gl, kStage[i == 2 * kNVar ? kBodies : vert ? kVerts : kTris], err, d);
    if (!p) return false;
  }
  return true;
}

// the static data the buffers start from: vertices, triangles, hulls and
// their chunks, bodies, waves (room for wcap components)
struct GlStatic {
  std::vector<GVert> vert;
  std::vector<GTri> tri;
  std::vector<GHull> hull;
  std::vector<GChunk> chunk, vchunk;
  std::vector<GWave> wave;
};

static void staticData(GlBackend* g, const HullSet& hs, const Sea& sea, size_t wcap,
                       GlStatic* st) {
  const mjModel* m = hs.m;
  g->nvert = hs.vert.size() / 3;
  g->ntri = hs.face.size() / 3;
  g->nhull = hs.hull.size();
  g->nslot = hs.body.size();
  std::vector<int> slot(m->nbody, -1);
  for (int i = 0; i < g->nslot; i++) slot[hs.body[i]] = i;
  std::vector<GVert>& vert = st->vert;
  std::vector<GTri>& tri = st->tri;
  std::vector<GHull>& hull = st->hull;
  std::vector<GChunk>& chunk = st->chunk;
  std::vector<GChunk>& vchunk = st->vchunk;
  vert.assign(g->nvert, GVert{});
  tri.assign(g->ntri, GTri{});
  hull.assign(g->nhull, GHull{});
  const int csize = g->local * g->per;
  g->body.assign(g->nslot, GBody{});
  for (int h = 0; h < g->nhull; h++) {
    const Hull& hl = hs.hull[h];
    const HullParams& p = hl.par;
    for (int i = hl.v0; i < hl.v0 + hl.nv; i++) {
      vert[i] = GVert{float(hs.vert[3 * i]), float(hs.vert[3 * i + 1]), float(hs.vert[3 * i + 2]), h};
    }
    for (int k = hl.t0; k < hl.t0 + hl.nt; k++) {
      tri[k] = GTri{hs.face[3 * k], hs.face[3 * k + 1], hs.face[3 * k + 2], h};
    }
    int s = slot[hl.body];
    hull[h].body = s;
    hull[h].c0 = chunk.size();
    hull[h].nt = hl.nt;
    for (int t = 0; t < hl.nt; t += csize) {
      chunk.push_back(GChunk{h, hl.t0 + t, std::min(csize, hl.nt - t), 0});
    }
    hull[h].nc = int(chunk.size()) - hull[h].c0;
    for (int v = 0; v < hl.nv; v += g->vlocal * g->per) {
      vchunk.push_back(GChunk{h, hl.v0 + v, std::min(g->vlocal * g->per, hl.nv - v), 0});
    }
    hull[h].shape = vec4{float(hl.area), float(hl.share), float(p.viscous), float(p.vref)};
    hull[h].drag = vec4{float(p.drag[0]), float(p.drag[1]), float(p.drag[2]), 0};
    hull[h].suction = vec4{float(p.suction[0]), float(p.suction[1]), float(p.suction[2]), 0};
    hull[h].slam = vec4{float(p.slam[0]), float(p.slam[1]), float(p.slam[2]), 0};
    hull[h].damp = vec4{float(p.damp[0]), float(p.damp[1]), 0, 0};
    // hulls are grouped by body (mjb_attach), so each body's ranges are contiguous
    GBody& bd = g->body[s];
    if (!bd.nh) {
      bd.h0 = h;
      bd.t0 = hl.t0;
    }
    bd.nh++;
    bd.nt += hl.nt;
  }
  g->nwave = sea.waves.size();
  // room for wcap components, so mjb_setSea only rewrites (glSetSea)
  const int cap = std::max<int>(wcap, g->nwave);
  st->wave.assign(cap, GWave{});
  g->perm.assign(cap, 0);
  g->reach = g->reach0 = 1.25 * longestEdge(hs);  // a first guess; the steps raise it
  g->phase.assign(g->nslot * std::max(cap, 1), 0);
  g->out.assign(g->nslot * 40, 0);
  g->nchunk = chunk.size();
  g->nvchunk = vchunk.size();
}

// the buffers, within the driver's buffer texture size (false and err if
// not): static data from st, per-step inputs (mapped for good where GL 4.4
// can), outputs
static bool makeBuffers(GlBackend* g, const GlStatic& st, std::string* err) {
  const GladGLContext& gl = g->ctx.gl;
  // each vertex's e^(i theta) per component, two a texel (shaders/sea.glsl
  // expTexel), room for the capacity so mjb_setSea creates nothing; within
  // the driver's limits (checked before anything is allocated)
  const int cap = st.wave.size();
  const size_t nexp = size_t(g->nvert) * ((cap + 1) / 2);
  GLint tmax = 0;  // texels; GL guarantees only 65536, llvmpipe has 2^27
  gl.GetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &tmax);
  if (nexp > size_t(tmax)) {
    *err = "gl backend: " + std::to_string(g->nvert) + " vertices x " + std::to_string(cap) +
           " wave components (mjbuoy.sea.capacity, else the sea's count) = " +
           std::to_string(nexp) + " texels (two components each) exceed the driver's buffer texture size (" +
           std::to_string(tmax) + " texels); use fewer components or boats, or backend cpu";
    return false;
  }
  makeBuffer(g, B_EXP, std::max<size_t>(nexp, 1) * 16, nullptr, GL_DYNAMIC_COPY);
  makeBuffer(g, B_VERT, st.vert.size() * sizeof(GVert), st.vert.data(), GL_STATIC_DRAW);
  makeBuffer(g, B_TRI, st.tri.size() * sizeof(GTri), st.tri.data(), GL_STATIC_DRAW);
  makeBuffer(g, B_HULL, st.hull.size() * sizeof(GHull), st.hull.data(), GL_STATIC_DRAW);
  makeBuffer(g, B_WAVE, st.wave.size() * sizeof(GWave), st.wave.data(), GL_STATIC_DRAW);
  // the per-step inputs: written in place where GL 4.4 can map them for
  // good (on llvmpipe a mapping is the buffer's own memory: no copy)
  g->persist = gl.VERSION_4_4 && gl.BufferStorage && gl.MapBufferRange;
  if (g->persist) {
    const GLbitfield wr = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    auto mapped = [&](int i, size_t n, GLbitfield fl) {
      gl.GenBuffers(1, &g->buf[i]);
      gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, g->buf[i]);
      gl.BufferStorage(GL_SHADER_STORAGE_BUFFER, n, nullptr, fl);
      return gl.MapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, n, fl);
    };
    g->bodyp = static_cast<GBody*>(mapped(B_BODY, g->nslot * sizeof(GBody), wr));
    g->phasep = static_cast<float*>(mapped(B_PHASE, g->phase.size() * sizeof(float), wr));
    if (!g->bodyp || !g->phasep) {
      *err = "gl backend: could not map its per-step buffers (glMapBufferRange)";
      return false;
    }
    std::memcpy(g->bodyp, g->body.data(), g->nslot * sizeof(GBody));
  } else {
    makeBuffer(g, B_BODY, g->nslot * sizeof(GBody), nullptr, GL_DYNAMIC_DRAW);
    makeBuffer(g, B_PHASE, g->phase.size() * sizeof(float), nullptr, GL_DYNAMIC_DRAW);
    g->bodyp = g->body.data();
    g->phasep = g->phase.data();
  }
  makeBuffer(g, B_VOUT, g->nvert * 16, nullptr, GL_DYNAMIC_COPY);
  makeBuffer(g, B_LAB, g->nvert * 8, nullptr, GL_DYNAMIC_COPY);
  makeBuffer(g, B_CHUNK, st.chunk.size() * sizeof(GChunk), st.chunk.data(), GL_STATIC_DRAW);
  makeBuffer(g, B_VCHUNK, st.vchunk.size() * sizeof(GChunk), st.vchunk.data(), GL_STATIC_DRAW);
  makeBuffer(g, B_CPART, st.chunk.size() * g->local * BUOY_NSUM * 16, nullptr, GL_DYNAMIC_COPY);
  makeBuffer(g, B_OUT, g->out.size() * sizeof(float), nullptr, GL_DYNAMIC_READ);
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  // the per-triangle gathers read through texel fetches: llvmpipe gathers a
  // texel per lane in straight-line SIMD code, an SSBO load with a
  // per-lane index in a scalar loop per component
  if (std::max(g->ntri, g->nvert) > tmax) {
    *err = "gl backend: " + std::to_string(g->ntri) + " triangles and " +
           std::to_string(g->nvert) + " vertices exceed the driver's buffer texture size (" +
           std::to_string(tmax) + " texels); use backend cpu";
    return false;
  }
  return true;
}

// the buffer textures the per-triangle gathers read, and their units
static void makeTextures(GlBackend* g) {
  const GladGLContext& gl = g->ctx.gl;
  const GLenum tfmt[kNTex] = {GL_RGBA32F, GL_RG32F,   GL_RGBA32I, GL_RGBA32F,
                              GL_RGBA32F, GL_RGBA32F, GL_R32F};
  const int tbuf[kNTex] = {B_VOUT, B_LAB, B_TRI, B_VERT, B_EXP, B_WAVE, B_PHASE};
  gl.GenTextures(kNTex, g->tex);
  for (int i = 0; i < kNTex; i++) {
    gl.BindTexture(GL_TEXTURE_BUFFER, g->tex[i]);
    gl.TexBuffer(GL_TEXTURE_BUFFER, tfmt[i], g->buf[tbuf[i]]);
  }
  gl.BindTexture(GL_TEXTURE_BUFFER, 0);
  trisUniform(g, "tVout", 0);
  trisUniform(g, "tLab", 1);
  trisUniform(g, "tTri", 2);
  trisUniform(g, "tExp", 4);
  for (GLuint p : g->vprog) {
    if (!p) continue;
    gl.ProgramUniform1i(p, loc(g, p, "tVert"), 3);
    gl.ProgramUniform1i(p, loc(g, p, "nvchunk"), g->nvchunk);
  }
  for (int i = 0; i < 2 * kNVar; i++) {
    GLuint p = i < kNVar ? g->tprog[i] : g->vprog[i - kNVar];
    if (!p) continue;
    gl.ProgramUniform1i(p, loc(g, p, "tWave"), 5);
    gl.ProgramUniform1i(p, loc(g, p, "tPhase"), 6);
  }
}

// the uniforms that never change, the locations of the per-step ones, the
// stage timers
static void fixedUniforms(GlBackend* g, const Sea& sea) {
  const GladGLContext& gl = g->ctx.gl;
  trisUniform(g, "nchunk", g->nchunk);
  trisUniform(g, "rhog", float(sea.rho * sea.g));
  trisUniform(g, "rho", float(sea.rho));
  gl.ProgramUniform1i(g->bprog, loc(g, g->bprog, "nslot"), g->nslot);
  gl.ProgramUniform1f(g->bprog, loc(g, g->bprog, "nu"), float(sea.nu));
  gl.ProgramUniform1f(g->bprog, loc(g, g->bprog, "rho"), float(sea.rho));
  seaUniforms(g, sea);
  uploadWaves(g, sea);
  for (int i = 0; i < kNVar; i++) {
    if (!g->tprog[i]) continue;
    g->uHasprev[i] = loc(g, g->tprog[i], "hasprev");
    g->uFirst[i] = loc(g, g->tprog[i], "first");
    g->uSlamdt[i] = loc(g, g->tprog[i], "slamdt");
  }
  for (int i = 0; i < kNVar; i++) {
    GLuint p = g->vprog[i];
    if (!p) continue;
    g->uvFirst[i] = loc(g, p, "first");
    g->uvGw[i] = loc(g, p, "gw");
    g->uvOff[i][0] = loc(g, p, "offNew");
    g->uvOff[i][1] = loc(g, p, "offLast");
    g->uvOff[i][2] = loc(g, p, "offOld");
  }
  timerInit(&g->timer, &gl);
  for (int i = 0; i < kNStage; i++) g->tstage[i] = timerStage(&g->timer, kStage[i]);
}

bool glMake(const HullSet& hs, const Sea& sea, size_t wcap, GlBackend** out,
            std::string* renderer, std::string* err) {
  *out = nullptr;
  auto g = new GlBackend;
  if (!glCreate(&g->ctx, err)) {
    delete g;
    return false;
  }
  GlCurrent cur(&g->ctx);
  if (!cur.ok()) {
    *err = cur.error();
    glDestroy(&g->ctx);
    delete g;
    return false;
  }
  GlStatic st;
  bool ok = groupSizes(g, err) && makePrograms(g, err);
  if (ok) staticData(g, hs, sea, wcap, &st);
  ok = ok && makeBuffers(g, st, err);
  *out = g;
  if (!ok) {
    glFree(out);
    return false;
  }
  makeTextures(g);
  fixedUniforms(g, sea);
  *renderer = g->ctx.renderer;
  return true;
}

static void seaUniforms(GlBackend* g, const Sea& sea) {
  const GladGLContext& gl = g->ctx.gl;
  for (int i = 0; i < 2 * kNVar; i++) {
    GLuint p = i < kNVar ? g->tprog[i] : g->vprog[i - kNVar];
    if (!p) continue;
    gl.ProgramUniform1i(p, loc(g, p, "nwave"), g->nwave);
    gl.ProgramUniform1i(p, loc(g, p, "ngerst"), sea.ng);
    gl.ProgramUniform1f(p, loc(g, p, "depth"), float(sea.depth));
    gl.ProgramUniform2f(p, loc(g, p, "current"), float(sea.current[0]), float(sea.current[1]));
  }
  // flat water needs no dynamic pressure, whatever the model
  bool kerner = sea.kerner || sea.waves.empty();
  trisUniform(g, "linear", int(!kerner));
  bool deep = true, airy = true;  // as gwave's e2kh; Airy: no label search
  for (const Wave& w : sea.waves) {
    deep = deep && !(sea.depth > 0 && w.k * sea.depth < 17);
    airy = airy && w.kind != 0;
  }
  g->var = (kerner ? kVNomom : 0) | (deep ? kVDeep : 0) | (airy ? kVAiry : 0) |
           (g->nwave == 1 ? kVOne : 0);
}

void glSetSea(GlBackend* g, const Sea& sea) {
  if (!g) return;
  std::lock_guard<std::mutex> lk(g->mu);
  GlCurrent cur(&g->ctx);
  // within the capacity reserved in glMake (mjb_setSea checks): a rewrite,
  // no new GL object; uploaded in pieces from the stack
  g->nwave = sea.waves.size();
  uploadWaves(g, sea);
  seaUniforms(g, sea);
}

void glFreeState(GlBackend* g, GlState* s) {
  if (!g) return;
  // one thread at a time in the context, as every other use of it
  std::lock_guard<std::mutex> lk(g->mu);
  g->reachOf.erase(s);
  if (!s->slambuf[0]) return;
  GlCurrent cur(&g->ctx);
  // without the context current the names would delete another context's
  // buffers: they are left to the context's end (glFree) instead
  if (cur.ok()) {
    g->ctx.gl.DeleteBuffers(2, s->slambuf);
    g->ctx.gl.DeleteBuffers(1, &s->offbuf);
  }
  s->slambuf[0] = s->slambuf[1] = s->offbuf = 0;
}

// s's per-data buffers, zeroed: the slamming history (n bytes each) and
// the label offsets' ring
static void makeStateBuffers(GlBackend* g, GlState* s, GLsizeiptr n, bool zero) {
  const GladGLContext& gl = g->ctx.gl;
  const GLsizeiptr no = GLsizeiptr(3 * 2 * sizeof(float)) * std::max(g->nvert, 1);
  std::vector<char> z(zero ? std::max(n, no) : 0, 0);
  gl.GenBuffers(2, s->slambuf);
  gl.GenBuffers(1, &s->offbuf);
  for (GLuint x : {s->slambuf[0], s->slambuf[1], s->offbuf}) {
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, x);
    gl.BufferData(GL_SHADER_STORAGE_BUFFER, x == s->offbuf ? no : n, zero ? z.data() : nullptr,
                  GL_DYNAMIC_COPY);
  }
}

bool glCopyState(GlBackend* g, GlState* dst, const GlState* src) {
  if (!g || !src->slambuf[0]) return true;
  std::lock_guard<std::mutex> lk(g->mu);
  GlCurrent cur(&g->ctx);
  if (!cur.ok()) return false;
  const GladGLContext& gl = g->ctx.gl;
  GLsizeiptr n = GLsizeiptr(4 * sizeof(float)) * std::max(g->ntri, 1);
  GLsizeiptr no = GLsizeiptr(3 * 2 * sizeof(float)) * std::max(g->nvert, 1);
  if (!dst->slambuf[0]) makeStateBuffers(g, dst, n, false);
  auto r = g->reachOf.find(src);
  if (r != g->reachOf.end()) g->reachOf[dst] = r->second;
  for (int i = 0; i < 3; i++) {
    gl.BindBuffer(GL_COPY_READ_BUFFER, i < 2 ? src->slambuf[i] : src->offbuf);
    gl.BindBuffer(GL_COPY_WRITE_BUFFER, i < 2 ? dst->slambuf[i] : dst->offbuf);
    gl.CopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, i < 2 ? n : no);
  }
  gl.Finish();
  return true;
}

void glFree(GlBackend** out) {
  GlBackend* g = *out;
  if (!g) return;
  {
    GlCurrent cur(&g->ctx);
    const GladGLContext& gl = g->ctx.gl;
    timerFree(&g->timer);
    for (GLuint& p : g->vprog) if (p) gl.DeleteProgram(p);
    for (GLuint& p : g->tprog) if (p) gl.DeleteProgram(p);
    if (g->bprog) gl.DeleteProgram(g->bprog);
    for (GLuint& x : g->buf) if (x) gl.DeleteBuffers(1, &x);
    for (GLuint& x : g->tex) if (x) gl.DeleteTextures(1, &x);
  }
  glDestroy(&g->ctx);
  delete g;
  *out = nullptr;
}

// per-step body data, in double until the last moment: positions relative
// to the COM, wave phases at the COM reduced mod 2 pi
static void bodies(GlBackend* g, const HullSet& hs, const Sea& sea, const mjModel* m,
                   const mjData* d, HullState* s) {
  for (int i = 0; i < g->nslot; i++) {
    int bd = hs.body[i];
    GBody& o = g->bodyp[i];
    const mjtNum* R = d->xmat + 9 * bd;
    const mjtNum* x = d->xpos + 3 * bd;
    const mjtNum* c = d->xipos + 3 * bd;
    mjtNum vel[6], uw[3];
    mj_objectVelocity(m, d, mjOBJ_BODY, bd, vel, 0);
    bool ok = true;
    for (int j = 0; j < 9; j++) ok = ok && std::isfinite(R[j]);
    for (int j = 0; j < 3; j++) ok = ok && std::isfinite(x[j]) && std::isfinite(c[j]);
    for (int j = 0; j < 6; j++) ok = ok && std::isfinite(vel[j]);
    s->bad[bd] = !ok;
    if (!ok) {
      // park it far above the water: no force, nothing non-finite on the GPU
      std::memset(&o.r0, 0, 7 * sizeof(vec4));
      o.r0.x = o.r1.y = o.r2.z = 1;
      o.orig.w = 1e6;
      o.flow.x = 1;
      o.rig0 = vec4{0, 0, 0, 1};
      o.rig1 = o.rig2 = vec4{0, 0, 0, 0};
      continue;
    }
    o.r0 = vec4{float(R[0]), float(R[1]), float(R[2]), 0};
    o.r1 = vec4{float(R[3]), float(R[4]), float(R[5]), 0};
    o.r2 = vec4{float(R[6]), float(R[7]), float(R[8]), 0};
    o.orig = vec4{float(x[0] - c[0]), float(x[1] - c[1]), float(x[2] - c[2]),
                  float(c[2] - sea.level)};
    o.vlin = vec4{float(vel[3]), float(vel[4]), float(vel[5]), 0};
    o.vang = vec4{float(vel[0]), float(vel[1]), float(vel[2]), 0};
    // the rigid group's mass and inertia, for the slamming effective mass
    Rigid rg;
    rigidGroup(m, d, bd, &rg);
    o.rig0 = vec4{float(rg.com[0] - c[0]), float(rg.com[1] - c[1]), float(rg.com[2] - c[2]),
                  float(rg.minv)};
    o.rig1 = vec4{float(rg.iinv[0]), float(rg.iinv[1]), float(rg.iinv[2]), float(rg.iinv[3])};
    o.rig2 = vec4{float(rg.iinv[4]), float(rg.iinv[5]), 0, 0};
    // the hull's flow (as cpu.cc): COM velocity relative to the water there
    sea.velocity(c, d->time, uw);
    double vr[3] = {vel[3] - uw[0], vel[4] - uw[1], vel[5] - uw[2]};
    double sp = std::sqrt(vr[0] * vr[0] + vr[1] * vr[1] + vr[2] * vr[2]);
    for (int j = 0; j < 3; j++) (&o.flow.x)[j] = float(sp > 1e-9 ? vr[j] / sp : R[3 * j]);
    o.flow.w = float(sp);
    for (int w = 0; w < g->nwave; w++) {
      const Wave& wv = sea.waves[g->perm[w]];
      double th = wv.k * (wv.dx * c[0] + wv.dy * c[1]) - wv.omega * d->time + wv.ph;
      g->phasep[i * g->nwave + w] = float(std::remainder(th, 2 * M_PI));
    }
  }
}

// the label search's guesses (as cpu.cc's, docs/physics.md "Cost"): each
// vertex's label offset from the last two steps, extrapolated in time to
// t [s] (guessWeights); a new step moves the ring on (this step's slot
// takes the oldest's), a restart starts cold so a rerun repeats its bits.
// Only the step's first call writes its slot, so an RK4 stage guesses from
// the same steps as the step's first call
static void labelGuess(GlBackend* g, HullState* s, GlState* gs, int clock, double t) {
  if (clock == kNewStep) {
    gs->offslot = (gs->offslot + 2) % 3;
    gs->offn = std::min(gs->offn + 1, 2);
    s->tgOld = s->tgOff;
    s->tgOff = s->tprev;
  }
  if (clock == kRestart) gs->offn = 0;
  const double tk[3] = {s->tgOff, s->tgOld, 0};
  double L[3];
  guessWeights(t, tk, gs->offn, L);
  const GladGLContext& gl = g->ctx.gl;
  for (int i = 0; i < kNVar; i++) {
    GLuint p = g->vprog[i];
    if (!p) continue;
    gl.ProgramUniform1i(p, g->uvFirst[i], clock != kMidStep);
    gl.ProgramUniform2f(p, g->uvGw[i], float(L[0]), float(L[1]));
    for (int j = 0; j < 3; j++) {
      gl.ProgramUniform1i(p, g->uvOff[i][j], g->nvert * ((gs->offslot + j) % 3));
    }
  }
}

// gs's reach (a restart starts from the first guess again, so a rerun
// repeats its bits), the wave buffers redone if they hold another data's
// or the ramp's gain at time t [s] differs
static double* dataReach(GlBackend* g, const Sea& sea, const GlState* gs, int clock, double t) {
  auto ri = g->reachOf.find(gs);
  if (ri == g->reachOf.end()) ri = g->reachOf.emplace(gs, g->reach0).first;  // with the buffers
  if (clock == kRestart) ri->second = g->reach0;
  const double gain = sea.gain(t);
  if (ri->second != g->reach || gain != g->gain) {
    g->reach = ri->second;
    g->gain = gain;
    uploadWaves(g, sea);
  }
  return &ri->second;
}

// the step's per-data inputs: body data (unless mapped), buffers,
// textures as images, the mjData's history buffers gs, and the slamming
// uniforms at time t [s] of clock (stepClock)
static void bindStep(GlBackend* g, const HullState& s, const GlState& gs, int clock, double t) {
  const GladGLContext& gl = g->ctx.gl;
  if (!g->persist) {
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, g->buf[B_BODY]);
    gl.BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, g->nslot * sizeof(GBody), g->body.data());
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, g->buf[B_PHASE]);
    gl.BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, g->phase.size() * sizeof(float),
                     g->phase.data());
  }
  for (int i = 0; i < 15; i++) {
    if (g->buf[i] && i != B_EXP) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, i, g->buf[i]);
  }
  gl.BindImageTexture(0, g->tex[4], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, B_SLAMPREV, gs.slambuf[gs.slamcur ^ 1]);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, B_SLAMCUR, gs.slambuf[gs.slamcur]);
  gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, B_OFF, gs.offbuf);
  for (int i = 0; i < kNVar; i++) {
    GLuint p = g->tprog[i];
    if (!p) continue;
    gl.ProgramUniform1i(p, g->uHasprev[i], s.hasPrev);
    gl.ProgramUniform1i(p, g->uFirst[i], clock != kMidStep);
    gl.ProgramUniform1f(p, g->uSlamdt[i], float(s.hasPrev ? t - s.tprev : 0));
  }
}

// the three stages for all hulls, timed, and the readback of g->out;
// mine: this data's reach, raised with g->reach
static void dispatch(GlBackend* g, const HullSet& hs, const Sea& sea, const HullState& s,
                     double* mine) {
  const GladGLContext& gl = g->ctx.gl;
  // per-item stages loop (grid-stride) past 65535 groups, GL's guaranteed
  // GL_MAX_COMPUTE_WORK_GROUP_COUNT: beyond it glDispatchCompute does nothing
  const int groups[kNStage] = {std::min(g->nvchunk, kMaxGroups),
                               std::min(g->nchunk, kMaxGroups),
                               (g->nslot + g->blocal - 1) / g->blocal};
  for (int i = 0; i < kNTex; i++) {
    gl.ActiveTexture(GL_TEXTURE0 + i);
    gl.BindTexture(GL_TEXTURE_BUFFER, g->tex[i]);
  }
  // twice where the step's pieces reached further than the series were
  // sized for (tris.comp pieceRho, reported per body in out[40 i + 3]):
  // the wave buffer is redone for the new reach, and the step repeated
  for (int pass = 0; pass < 2; pass++) {
    GLuint prog[kNStage];
    progs(g, prog);
    for (int st = 0; st < kNStage; st++) {
      timerBegin(&g->timer, g->tstage[st]);
      gl.UseProgram(prog[st]);
      if (groups[st] > 0) gl.DispatchCompute(groups[st], 1, 1);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                       GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
      timerEnd(&g->timer, g->tstage[st]);
    }
    gl.UseProgram(0);
    // the readback copies: a persistent read mapping of a buffer the shaders
    // wrote stays zero on Mesa 22.3 llvmpipe (checked), and 160 bytes a body
    // cost nothing next to the dispatches
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, g->buf[B_OUT]);
    gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, g->out.size() * sizeof(float),
                        g->out.data());
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    // (a non-finite reach: the heights were not finite, which the sums report)
    double reach = 0;
    for (int i = 0; i < g->nslot; i++) {
      float r = g->out[40 * i + 3];
      if (!s.bad[hs.body[i]] && std::isfinite(r)) reach = std::max(reach, double(r));
    }
    if (reach <= g->reach || g->nwave == 0) break;
    g->reach = *mine = 1.25 * reach;
    uploadWaves(g, sea);
  }
  for (int i = 0; i <= B_OFF; i++) gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, i, 0);
  gl.BindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  for (int i = kNTex - 1; i >= 0; i--) {
    gl.ActiveTexture(GL_TEXTURE0 + i);
    gl.BindTexture(GL_TEXTURE_BUFFER, 0);
  }
  timerFrame(&g->timer);
}

// s->part of each body that has a finite state from g->out
static void unpack(const GlBackend* g, const HullSet& hs, const mjModel* m, HullState* s) {
  // unpack: part p of slot i at out[40 i + 8 p], force xyz then torque xyz
  const int nb6 = 6 * m->nbody;
  std::memset(s->part.data(), 0, s->part.size() * sizeof(double));
  for (int i = 0; i < g->nslot; i++) {
    int bd = hs.body[i];
    if (s->bad[bd]) continue;
    for (int p = 0; p < mjbPART_WIND; p++) {  // the water families; wind: hull/windload.cc
      double* w = s->part.data() + p * nb6 + 6 * bd;
      const float* o = g->out.data() + 40 * i + 8 * p;
      for (int j = 0; j < 3; j++) {
        w[j] = o[j];
        w[3 + j] = o[4 + j];
      }
    }
  }
}

void glWrench(GlBackend* g, const HullSet& hs, const Sea& sea, const mjModel* m,
              const mjData* d, HullState* s, GlState* gs) {
  std::lock_guard<std::mutex> lk(g->mu);
  GlCurrent cur(&g->ctx);
  if (!cur.ok()) {
    // no force from the water this call, said once; not the last call's
    // wrench again (compute adds the wind to what is here)
    std::fill(s->wrench.begin(), s->wrench.end(), 0.0);
    std::fill(s->part.begin(), s->part.end(), 0.0);
    static const char kLost[] = "mjbuoy: gl backend: the GL context could not be made current "
                                "on this thread; no water force in this call\n";
    if (s->notices.find(kLost) == std::string::npos) s->notices += kLost;
    return;
  }

  // per-data slamming history and label offsets, created on the first call for d
  if (!gs->slambuf[0]) {
    makeStateBuffers(g, gs, GLsizeiptr(4 * sizeof(float)) * std::max(g->ntri, 1), true);
  }
  int clock = stepClock(m, d, s);
  double* mine = dataReach(g, sea, gs, clock, d->time);
  if (clock == kNewStep) gs->slamcur ^= 1;
  labelGuess(g, s, gs, clock, d->time);
  std::memset(s->bad.data(), 0, s->bad.size());
  bodies(g, hs, sea, m, d, s);
  bindStep(g, *s, *gs, clock, d->time);
  dispatch(g, hs, sea, *s, mine);
  unpack(g, hs, m, s);
  finishWrench(hs, m, d, s);
}

}  // namespace mjb

namespace mjb {

int glStageTimes(GlBackend* g, const char** name, double* ms, int n) {
  if (!g) return 0;
  std::lock_guard<std::mutex> lk(g->mu);
  {
    GlCurrent cur(&g->ctx);
    timerFlush(&g->timer);
  }
  for (int i = 0; i < kNStage && i < n; i++) {
    name[i] = kStage[i];
    ms[i] = g->timer.stage[g->tstage[i]].mean();
  }
  return kNStage;
}

}  // namespace mjb
