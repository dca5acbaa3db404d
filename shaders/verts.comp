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

// e^(k zs + i theta) of component w at body b's point x of label a, Wheeler
// height zs
vec2 expDeep(int b, int w, vec2 a, vec2 x, float zs) {
  GWave wv = waveAt(w);
  float th = thetaAt(wv, phaseAt(b, w), a, x);
  return exp(wv.k * zs) * vec2(cos(th), sin(th));
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
      vec2 a = seaLabel(b, r.xy, r.xy);
      float eta = seaEta(b, a, r.xy);
      vec4 q = vec4(r, r.z + o.w - eta);
      lab[i] = a;
      vout[i] = q;
      // each component's e^(k zs + i theta) and e^(-k (zs + 2 h) + i theta),
      // zs the Wheeler height: the two exponentials of the linear profiles
      // cosh(k (zs + h)) / cosh(k h) and its kin (docs/physics.md), each
      // bounded by 1 (the second 0 where e^(-k h) is below float's
      // resolution, gl.cc gwave); at dry vertices too (zs = 0: e^(i theta),
      // from which tris.comp turns the cut points')
      float zs = seaStretch(r.z + o.w, eta);
      int w = 0;
      if (paired != 0) {
        // two components a texel (sea.glsl expTexel), 0 past the last
        if (nwave > 0) do {
          vec2 e0 = expDeep(b, w, a, r.xy, zs);
          vec2 e1 = w + 1 < nwave ? expDeep(b, w + 1, a, r.xy, zs) : vec2(0.0);
          imageStore(iExp, expTexel(i, w), vec4(e0, e1));
        } while ((w += 2) < nwave);
      } else if (nwave > 0) do {
        GWave wv = waveAt(w);
        float th = thetaAt(wv, phaseAt(b, w), a, r.xy), k = wv.k;
        vec2 cs = vec2(cos(th), sin(th));
        // e^(-k (zs + 2h)) = e^(-2kh) / e^(k zs), no second exp: e^(k zs) >=
        // e^(-k h) > e^-17 where e2kh > 0 (zs >= -h)
        float ep = exp(k * zs), em = wv.e2kh > 0.0 ? wv.e2kh / ep : 0.0;
        imageStore(iExp, expTexel(i, w), vec4(ep * cs, em * cs));
      } while (++w < nwave);
    }
  }
}
