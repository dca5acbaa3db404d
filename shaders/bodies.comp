#version 430
// stage 5, one workgroup per body: sum its triangles' forces and torques
// per family in a fixed order (strided partial sums, then a tree), add the
// simple damping of its hulls; any number of triangles, no power of two
#include "shared.h"
#include "pipeline.h"

layout(local_size_x = BUOY_LOCAL) in;
layout(std430, binding = B_HULL) readonly buffer Hulls { GHull hull[]; };
layout(std430, binding = B_BODY) readonly buffer Bodies { GBody body[]; };
layout(std430, binding = B_TF) readonly buffer Tf { vec4 tf[]; };
layout(std430, binding = B_HOUT) readonly buffer Hout { GHullOut hout[]; };
layout(std430, binding = B_OUT) writeonly buffer Out { vec4 outw[]; };

shared vec4 part[BUOY_LOCAL];

void main() {
  int b = int(gl_WorkGroupID.x), l = int(gl_LocalInvocationID.x);
  GBody bd = body[b];
  for (int j = 0; j < 2 * BUOY_NPART; j++) {
    vec4 s = vec4(0.0);
    for (int k = bd.t0 + l; k < bd.t0 + bd.nt; k += BUOY_LOCAL) s += tf[8 * k + j];
    part[l] = s;
    barrier();
    for (int st = BUOY_LOCAL / 2; st > 0; st /= 2) {
      if (l < st) part[l] += part[l + st];
      barrier();
    }
    if (l == 0) outw[10 * b + j] = part[0];
    barrier();
  }
  if (l != 0) return;
  // simple damping, scaled by each hull's wet fraction
  vec3 f = vec3(0.0), t = vec3(0.0);
  for (int h = bd.h0; h < bd.h0 + bd.nh; h++) {
    float rs = hout[h].wet / hull[h].shape.x;
    f -= hull[h].damp.x * rs * bd.vlin.xyz;
    t -= hull[h].damp.y * rs * bd.vang.xyz;
  }
  outw[10 * b + 8] = vec4(f, 0.0);
  outw[10 * b + 9] = vec4(t, 0.0);
}
