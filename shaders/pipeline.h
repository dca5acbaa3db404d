// pipeline.h: buffer layouts and bindings of the buoyancy pipeline (gl.cc and
// shaders/{verts,wet,hulls,hydro,bodies}.comp), under the rules of
// shared.h, which must be included first. All floats: positions are kept
// relative to each body's centre of mass and wave phases per body are
// reduced mod 2 pi in double on the CPU, so single precision loses nothing
// that matters even kilometres from the origin.
#ifndef MJBUOY_SHADERS_PIPELINE_H_
#define MJBUOY_SHADERS_PIPELINE_H_

#ifdef __cplusplus
namespace mjb {
namespace glsl {
#endif

// workgroup sizes, tuned for Mesa llvmpipe, which runs a workgroup on one
// thread, 8 invocations per SIMD vector (256-bit AVX2). One vector per
// workgroup and long per-invocation loops win: at 200 Wigley 7744 boats,
// CPU ms/step (tris local x per): 8x16 175, 8x64 163, 8x256 157, 16x64 174,
// 64x16 201, 64x64 195; verts local 8 vs 64 at 8x64: 151 vs 163; 8x256 vs
// 8x64 again: 148 vs 155 (and 64 vs 66 at 800 x 576). Chunks of 2048
// triangles leave a lone small hull on one core, which costs < 0.1 ms.
// MJBUOY_GL_GROUPS overrides them (gl.cc) by defining them first.
#ifndef BUOY_VERT_LOCAL
#define BUOY_VERT_LOCAL 8    // verts.comp: invocations per vertex chunk workgroup
#endif
#ifndef BUOY_LOCAL
#define BUOY_LOCAL 8         // tris.comp: invocations per triangle chunk workgroup
#endif
#ifndef BUOY_PER
#define BUOY_PER 256         // triangles (vertices) per invocation: chunk = local x per
#endif
#ifndef BUOY_BODY_LOCAL
#define BUOY_BODY_LOCAL 8    // bodies.comp: bodies per workgroup
#endif
#define BUOY_NSUM 11         // vec4 sums per chunk: pressure F, T; viscous g, e g, c x g,
                             // e c x g; drag F, T; slam F, T; wet area, lo, hi, sum A e
#define BUOY_NPART 4         // per-body force families: pressure, viscous, drag, slam

// bindings
#define B_VERT 0     // GVert[]      static: hull vertices, body frame
#define B_TRI 1      // GTri[]       static: triangles
#define B_HULL 2     // GHull[]      static: per-hull constants
#define B_BODY 3     // GBody[]      per step: body poses and velocities
#define B_PHASE 4    // float[]      per step: phase of wave i at body b, b * nwave + i (texture)
#define B_VOUT 5     // vec4[]       vertex: position rel. COM (xyz), height above water (w)
#define B_LAB 6      // vec2[]       vertex: surface particle label rel. COM
#define B_CHUNK 7    // GChunk[]     static: triangle chunks, one hull each
#define B_CPART 8    // vec4[]       chunk invocation: BUOY_NSUM sums (tris.comp)
#define B_VCHUNK 9   // GChunk[]     static: vertex chunks, one hull each
#define B_OUT 10     // vec4[]       body: force, torque per family (2 x 5 each)
#define B_SLAMPREV 11  // vec4[]     triangle: previous step's velocity (xyz), wet area (w)
#define B_SLAMCUR 12   // vec4[]     triangle: this step's, written on its first call
#define B_WAVE 13    // GWave[]      static: wave components (read as a buffer texture)
#define B_EXP 14     // vec4[]       (image unit 0, not an SSBO binding) vertex x component
                     //              pair: every vertex's e^(i theta) of two components a
                     //              texel (sea.glsl expTexel)
#define B_OFF 15     // vec2[]       per mjData: vertex label minus position (rel. COM) at
                     //              three steps, a ring of three slots of nvert each: this
                     //              step's (written on its first call), the last, the one
                     //              before (verts.comp; gl.cc labelGuess)

struct GVert {
  float x;
  float y;
  float z;
  int hull;
};

struct GTri {
  int v0;
  int v1;
  int v2;
  int hull;
};

struct GHull {
  int body;        // slot in GBody[]
  int c0;          // first chunk
  int nc;          // chunks
  int nt;          // triangles
  vec4 shape;      // area S [m^2], share of the rigid group's hulls, form factor 1+k, vref [m/s]
  vec4 drag;       // C_PD1, C_PD2, f_P
  vec4 suction;    // C_SD1, C_SD2, f_S
  vec4 slam;       // gain, Gamma_max, p
  vec4 damp;       // linear, angular
};

struct GBody {
  vec4 r0;         // rows of the rotation matrix (body frame to world)
  vec4 r1;
  vec4 r2;
  vec4 orig;       // body frame origin minus COM (xyz) [m]; w: COM z minus sea level [m]
  vec4 vlin;       // COM linear velocity (xyz) [m/s]
  vec4 vang;       // angular velocity (xyz) [rad/s]
  vec4 flow;       // unit flow direction (xyz), w: COM speed relative to the water [m/s]
  int t0;          // first triangle of the body
  int nt;          // triangles of the body
  int h0;          // first hull of the body
  int nh;          // hulls of the body
  vec4 rig0;       // rigid group (mjbuoy/hull/rigid.h): COM minus body COM (xyz) [m], w: 1 / mass [1/kg]
  vec4 rig1;       // inverse inertia about the group COM, world: xx yy zz xy [1/(kg m^2)]
  vec4 rig2;       // xz yz (xy), 0 0
};

struct GWave {     // read as three texels (sea.glsl): the first is all the surface needs,
                   // the first two all the pressure, the third only the label solve
  float kx;        // wave vector k (dx, dy) [1/m]
  float ky;
  float amp;       // [m]
  float kind;      // 0 Gerstner, 1 Airy (whose steep is 0 here)
  float k;         // wave number [1/m]
  float c;         // phase speed omega / k [m/s]
  float terms;     // series terms of a piece's integrals (waveint.glsl ddSeries, gl.cc gwave)
  float e2kh;      // e^(-2 k h) at finite depth h if k h < 17, else 0 (deep: 0)
  float steep;
  float dx;        // unit direction
  float dy;
  float pad;
};

struct GChunk {
  int hull;
  int t0;          // first triangle (vertex)
  int nt;          // triangles (vertices), at most BUOY_LOCAL (BUOY_VERT_LOCAL) x BUOY_PER
  int pad;
};

#ifdef __cplusplus
static_assert(sizeof(GVert) == 16, "std430 stride of GVert");
static_assert(sizeof(GTri) == 16, "std430 stride of GTri");
static_assert(sizeof(GHull) == 96, "std430 stride of GHull");
static_assert(sizeof(GBody) == 176, "std430 stride of GBody");
static_assert(sizeof(GWave) == 48, "std430 stride of GWave");
static_assert(sizeof(GChunk) == 16, "std430 stride of GChunk");
}  // namespace glsl
}  // namespace mjb
#endif

#endif  // MJBUOY_SHADERS_PIPELINE_H_
