#version 430
// stage 1, one workgroup per chunk of one hull's vertices (GChunk), so the
// body's pose and wave phases are uniform loads: body frame -> relative to
// the body's COM, and the height above the wave surface there
#include "shared.h"
#include "pipeline.h"
#include "sea.glsl"
#include "waveint.glsl"

layout(local_size_x = BUOY_VERT_LOCAL) in;
layout(std430, binding = B_HULL) readonly buffer Hulls { GHull hull[]; };
layout(std430, binding = B_BODY) readonly buffer Bodies { GBody body[]; };
layout(std430, binding = B_VCHUNK) readonly buffer Vchunks { GChunk vchunk[]; };
uniform samplerBuffer tVert;                       // B_VERT as a buffer texture
layout(std430, binding = B_VOUT) writeonly buffer Vout { vec4 vout[]; };
layout(std430, binding = B_LAB) writeonly buffer Labs { vec2 lab[]; };
// B_EXP through an image: a buffer texture holds 2^27 texels on llvmpipe,
// a storage block only 2^27 bytes
layout(binding = 0, rgba32f) uniform writeonly imageBuffer iExp;

uniform int nvchunk;
// the label search's guess (gl.cc labelGuess): the position plus the
// weights gw of the last two steps' offsets in B_OFF at element offsets
// offLast, offOld; this step's first call stores its own at offNew
layout(std430, binding = B_OFF) buffer Offs { vec2 off[]; };
uniform vec2 gw;
uniform int offNew, offLast, offOld;
uniform int first;

// e^(i theta) of component w at body b's point x of label a (xy), and its
// height amp cos(theta) (z)
vec3 turnAt(int b, int w, vec2 a, vec2 x) {
  vec4 wv = waveHead(w);
  vec2 cs = seaCosSin(thetaAt(wv, phaseAt(b, w), a, x));
  return vec3(cs, wv.z * cs.x);
}

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
#ifdef WI_AIRY
      vec2 a = r.xy;  // no Gerstner component: the label is the position (gl.cc)
#else
      vec2 a = seaLabel(b, r.xy, r.xy + gw.x * off[offLast + i] + gw.y * off[offOld + i]);
      // (a label not finite, which the heights report, guesses nothing)
      vec2 da = a - r.xy;
      if (first != 0) off[offNew + i] = all(lessThan(abs(da), vec2(3e38))) ? da : vec2(0.0);
#endif
      // the surface height above the still level, sum amp cos(theta) in
      // component order, and each component's e^(i theta), at dry
      // vertices too (tris.comp turns the cut points' from them, and
      // scales by the profiles' e^(k zs) at each piece's corner 0), in one
      // pass: one cos and sin per vertex and component; two components a
      // texel (sea.glsl expTexel), 0 past the last
      float eta = 0.0;
      int w = 0;
      if (nwave > 0) do {
        bool two = w + 1 < nwave;
        vec3 e0 = turnAt(b, w, a, r.xy), e1 = turnAt(b, two ? w + 1 : w, a, r.xy);
        eta += e0.z;
        eta += two ? e1.z : 0.0;
        imageStore(iExp, expTexel(i, w), vec4(e0.xy, two ? e1.xy : vec2(0.0)));
      } while ((w += 2) < nwave);
      lab[i] = a;
      vout[i] = vec4(r, r.z + o.w - eta);
    }
  }
}
