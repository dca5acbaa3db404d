#version 430
// stage 3, one workgroup per hull: wet area, wetted length along the flow,
// Kerner's mean position sbar and the ITTC 1957 C_F at the hull's Rn
#include "shared.h"
#include "pipeline.h"

layout(local_size_x = BUOY_LOCAL) in;
layout(std430, binding = B_HULL) readonly buffer Hulls { GHull hull[]; };
layout(std430, binding = B_BODY) readonly buffer Bodies { GBody body[]; };
layout(std430, binding = B_WET) readonly buffer Wets { GWet wet[]; };
layout(std430, binding = B_HOUT) writeonly buffer Hout { GHullOut hout[]; };

uniform float nu;     // kinematic viscosity [m^2/s]

shared vec4 part[BUOY_LOCAL];   // wet area, min, max, sum of area * position

void main() {
  int h = int(gl_WorkGroupID.x), l = int(gl_LocalInvocationID.x);
  GHull hl = hull[h];
  vec4 s = vec4(0.0, 1e30, -1e30, 0.0);
  for (int k = hl.t0 + l; k < hl.t0 + hl.nt; k += BUOY_LOCAL) {
    GWet w = wet[k];
    if (w.c.w > 0.0) s = vec4(s.x + w.c.w, min(s.y, w.e.x), max(s.z, w.e.y), s.w + w.c.w * w.e.z);
  }
  part[l] = s;
  barrier();
  for (int st = BUOY_LOCAL / 2; st > 0; st /= 2) {
    if (l < st) {
      vec4 a = part[l], b = part[l + st];
      part[l] = vec4(a.x + b.x, min(a.y, b.y), max(a.z, b.z), a.w + b.w);
    }
    barrier();
  }
  if (l != 0) return;
  s = part[0];
  float len = s.z > s.y ? s.z - s.y : 0.0;
  float sbar = s.x > 0.0 && len > 0.0 ? (s.w - s.y * s.x) / len / s.x : 0.0;
  float rn = max(body[hl.body].flow.w * len / nu, 1e3);  // hydro.h kRnMin
  float lg = log(rn) / log(10.0) - 2.0;
  hout[h].wet = s.x;
  hout[h].lo = s.y;
  hout[h].hi = s.z;
  hout[h].sbar = sbar;
  hout[h].cf = 0.075 / (lg * lg);
}
