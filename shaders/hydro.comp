#version 430
// stage 4, one invocation per wet triangle: Kerner's viscous resistance,
// pressure/suction drag and slamming at the wet centroid (mjbuoy/hydro.cc)
#include "shared.h"
#include "pipeline.h"
#include "sea.glsl"

layout(local_size_x = BUOY_LOCAL) in;
layout(std430, binding = B_TRI) readonly buffer Tris { GTri tri[]; };
layout(std430, binding = B_HULL) readonly buffer Hulls { GHull hull[]; };
layout(std430, binding = B_BODY) readonly buffer Bodies { GBody body[]; };
layout(std430, binding = B_LAB) readonly buffer Labs { vec2 lab[]; };
layout(std430, binding = B_WET) readonly buffer Wets { GWet wet[]; };
layout(std430, binding = B_HOUT) readonly buffer Hout { GHullOut hout[]; };
layout(std430, binding = B_TF) buffer Tf { vec4 tf[]; };
layout(std430, binding = B_SLAMPREV) readonly buffer Sprev { vec4 sprev[]; };
layout(std430, binding = B_SLAMCUR) writeonly buffer Scur { vec4 scur[]; };

uniform int ntri;
uniform float rho;
uniform int hasprev;   // slamming history exists
uniform int first;     // first call of this step: record the history
uniform float slamdt;  // time since the previous step's first call [s]

void put(int k, int p, vec3 f, vec3 c) {
  tf[8 * k + 2 * p] = vec4(f, 0.0);
  tf[8 * k + 2 * p + 1] = vec4(cross(c, f), 0.0);
}

void triangle(int k) {
  GTri t = tri[k];
  GWet w = wet[k];
  float A = w.c.w;
  for (int p = 1; p < BUOY_NPART; p++) put(k, p, vec3(0.0), vec3(0.0));
  if (!(A > 0.0)) {
    if (first != 0) scur[k] = vec4(0.0);
    return;
  }
  GHull hl = hull[t.hull];
  int b = hl.body;
  GHullOut ho = hout[t.hull];
  vec3 c = w.c.xyz, n = w.n.xyz;

  // flow-relative velocity: point velocity minus the water's there; the
  // label search starts from the mean of the vertex labels
  vec2 a = seaLabel(b, c.xy, (lab[t.v0] + lab[t.v1] + lab[t.v2]) / 3.0);
  float zb = min(c.z + body[b].orig.w - seaEta(b, a), 0.0);
  vec3 v = body[b].vlin.xyz + cross(body[b].vang.xyz, c) - seaVelocity(b, a, zb);
  float v2 = dot(v, v), sp = sqrt(v2);

  // viscous: 0.5 rho C_F (1+k_i) A |v|^2 against the tangential flow
  float ff = hl.shape.z;
  if (ff > 0.0) {
    float len = ho.hi > ho.lo ? ho.hi - ho.lo : 0.0;
    float sk = len > 0.0 ? (w.e.z - ho.lo) / len : ho.sbar;
    vec3 tg = v - dot(v, n) * n;
    float tl = length(tg);
    vec3 f = vec3(0.0);
    if (tl > 1e-6 * sp) f = -0.5 * rho * ho.cf * ff * (1.0 + ho.sbar - sk) * A * v2 / tl * tg;
    put(k, 1, f, c);
  }

  // pressure (cos > 0) and suction (cos < 0) drag
  if (sp > 0.0) {
    float cs = dot(v, n) / sp, u = sp / hl.shape.w, s = 0.0;
    if (cs > 0.0) s = -(hl.drag.x * u + hl.drag.y * u * u) * A * pow(cs, hl.drag.z);
    if (cs < 0.0) s = (hl.suction.x * u + hl.suction.y * u * u) * A * pow(-cs, hl.suction.z);
    put(k, 2, s * n, c);
  }

  // slamming: Gamma = |A v - A' v'| / (S dt), stopping force m v (2A/S_hull) / dt
  if (hasprev != 0 && hl.slam.x > 0.0 && slamdt > 0.0 && sp > 0.0) {
    float cs = dot(v, n) / sp;
    if (cs > 0.0) {
      vec4 pv = sprev[k];
      float gamma = length(A * v - pv.w * pv.xyz) / (w.n.w * slamdt);
      float r = min(gamma / hl.slam.y, 1.0);
      float s = -hl.slam.x * pow(r, hl.slam.z) * cs * hl.shape.y * 2.0 * A / hl.shape.x / slamdt;
      put(k, 3, s * v, c);
    }
  }
  if (first != 0) scur[k] = vec4(v, A);
}

// grid-stride: the dispatch is capped at GL's minimum of 65535 workgroups
void main() {
  int n = int(gl_NumWorkGroups.x * gl_WorkGroupSize.x);
  for (int k = int(gl_GlobalInvocationID.x); k < ntri; k += n) triangle(k);
}
