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

#define BUOY_LOCAL 64        // workgroup size of every stage
#define BUOY_NPART 4         // per-triangle force families: pressure, viscous, drag, slam

// bindings
#define B_VERT 0     // GVert[]      static: hull vertices, body frame
#define B_TRI 1      // GTri[]       static: triangles
#define B_HULL 2     // GHull[]      static: per-hull constants
#define B_BODY 3     // GBody[]      per step: body poses and velocities
#define B_PHASE 4    // float[]      per step: phase of wave i at body b, b * nwave + i
#define B_VOUT 5     // vec4[]       vertex: position rel. COM (xyz), height above water (w)
#define B_LAB 6      // vec2[]       vertex: surface particle label rel. COM
#define B_WET 7      // GWet[]       triangle: wet data
#define B_TF 8       // vec4[]       triangle: force, torque per family (2 BUOY_NPART each)
#define B_HOUT 9     // GHullOut[]   hull: flow and wet totals
#define B_OUT 10     // vec4[]       body: force, torque per family (2 x 5 each)
#define B_SLAMPREV 11  // vec4[]     triangle: previous step's velocity (xyz), wet area (w)
#define B_SLAMCUR 12   // vec4[]     triangle: this step's, written on its first call
#define B_WAVE 13    // GWave[]      static: wave components

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
  int t0;          // first triangle
  int nt;          // triangles
  int pad;
  vec4 shape;      // area S [m^2], mass share [kg], form factor 1+k, vref [m/s]
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
};

struct GWave {
  float amp;
  float k;
  float omega;
  float steep;
  float dx;
  float dy;
  float pad0;
  float pad1;
};

struct GWet {
  vec4 c;          // wet centroid rel. COM (xyz), wet area (w)
  vec4 n;          // outward unit normal (xyz), whole triangle's area (w)
  vec4 e;          // wet polygon extent along the flow: min, max; centroid's (z)
};

struct GHullOut {
  float wet;       // wet area [m^2]
  float lo;        // wet extent along the flow [m]
  float hi;
  float sbar;      // area-weighted mean position, 0 rear .. 1 front
  float cf;        // ITTC 1957 C_F
  float pad0;
  float pad1;
  float pad2;
};

#ifdef __cplusplus
static_assert(sizeof(GVert) == 16, "std430 stride of GVert");
static_assert(sizeof(GTri) == 16, "std430 stride of GTri");
static_assert(sizeof(GHull) == 96, "std430 stride of GHull");
static_assert(sizeof(GBody) == 128, "std430 stride of GBody");
static_assert(sizeof(GWave) == 32, "std430 stride of GWave");
static_assert(sizeof(GWet) == 48, "std430 stride of GWet");
static_assert(sizeof(GHullOut) == 32, "std430 stride of GHullOut");
}  // namespace glsl
}  // namespace mjb
#endif

#endif  // MJBUOY_SHADERS_PIPELINE_H_
