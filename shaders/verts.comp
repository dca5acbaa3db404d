#version 430
// stage 1, one workgroup per chunk of one hull's vertices (GChunk), so the
// body's pose and wave phases are uniform loads: body frame -> relative to
// the body's COM, and the height above the wave surface there
#include "shared.h"
#include "pipeline.h"
#include "sea.glsl"

layout(local_size_x = BUOY_VERT_LOCAL) in;
layout(std430, binding = B_HULL) readonly buffer Hulls { GHull hull[]; };
layout(std430, binding = B_BODY) readonly buffer Bodies { GBody body[]; };
layout(std430, binding = B_VCHUNK) readonly buffer Vchunks { GChunk vchunk[]; };
uniform samplerBuffer tVert;                       // B_VERT as a buffer texture
layout(std430, binding = B_VOUT) writeonly buffer Vout { vec4 vout[]; };
layout(std430, binding = B_LAB) writeonly buffer Labs { vec2 lab[]; };

uniform int nvchunk;

void main() {
  int l = int(gl_LocalInvocationID.x);
  // loops past 65535 chunks, GL's guaranteed workgroup count (uniform per group)
  for (int ci = int(gl_WorkGroupID.x); ci < nvchunk; ci += int(gl_NumWorkGroups.x)) {
    GChunk ch = vchunk[ci];
    int b = hull[ch.hull].body;
    vec3 r0 = body[b].r0.xyz, r1 = body[b].r1.xyz, r2 = body[b].r2.xyz;
    vec4 o = body[b].orig;
    for (int j = l; j < ch.nt; j += BUOY_VERT_LOCAL) {
      int i = ch.t0 + j;
      vec3 p = texelFetch(tVert, i).xyz;
      vec3 r = vec3(dot(r0, p), dot(r1, p), dot(r2, p)) + o.xyz;
      vec2 a = seaLabel(b, r.xy, r.xy);
      vec4 q = vec4(r, r.z + o.w - seaEta(b, a, r.xy));
      lab[i] = a;
      vout[i] = q;
    }
  }
}
