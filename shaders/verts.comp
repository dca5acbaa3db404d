#version 430
// stage 1, one invocation per hull vertex: body frame -> relative to the
// body's COM, and the height above the wave surface there
#include "shared.h"
#include "pipeline.h"
#include "sea.glsl"

layout(local_size_x = BUOY_VERT_LOCAL) in;
layout(std430, binding = B_VERT) readonly buffer Verts { GVert vert[]; };
layout(std430, binding = B_HULL) readonly buffer Hulls { GHull hull[]; };
layout(std430, binding = B_BODY) readonly buffer Bodies { GBody body[]; };
layout(std430, binding = B_VOUT) writeonly buffer Vout { vec4 vout[]; };
layout(std430, binding = B_LAB) writeonly buffer Labs { vec2 lab[]; };

uniform int nvert;

void vertex(int i) {
  GVert v = vert[i];
  int b = hull[v.hull].body;
  vec3 p = vec3(v.x, v.y, v.z);
  vec3 r = vec3(dot(body[b].r0.xyz, p), dot(body[b].r1.xyz, p), dot(body[b].r2.xyz, p)) +
           body[b].orig.xyz;
  vec2 a = seaLabel(b, r.xy, r.xy);
  lab[i] = a;
  vout[i] = vec4(r, r.z + body[b].orig.w - seaEta(b, a));
}

// grid-stride: the dispatch is capped at GL's minimum of 65535 workgroups
void main() {
  int n = int(gl_NumWorkGroups.x * gl_WorkGroupSize.x);
  for (int i = int(gl_GlobalInvocationID.x); i < nvert; i += n) vertex(i);
}
