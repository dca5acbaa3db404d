#version 430
// stage 3, one invocation per body: add up its hulls' per-invocation sums
// (tris.comp) in a fixed order; per hull the wetted length, Kerner's mean
// position sbar and the ITTC 1957 C_F at the hull's Rn, which scale its
// viscous sums; add the simple damping of its hulls
#include "shared.h"
#include "pipeline.h"

layout(local_size_x = BUOY_BODY_LOCAL) in;
layout(std430, binding = B_HULL) readonly buffer Hulls { GHull hull[]; };
layout(std430, binding = B_BODY) readonly buffer Bodies { GBody body[]; };
layout(std430, binding = B_CPART) readonly buffer Cpart { vec4 cpart[]; };
layout(std430, binding = B_OUT) writeonly buffer Out { vec4 outw[]; };

uniform int nslot;
uniform float nu;     // kinematic viscosity [m^2/s]
uniform float rho;    // [kg/m^3]

void main() {
  int b = int(gl_GlobalInvocationID.x);
  if (b >= nslot) return;
  GBody bd = body[b];
  vec3 pF = vec3(0.0), pT = vec3(0.0), vF = vec3(0.0), vT = vec3(0.0);
  vec3 dF = vec3(0.0), dT = vec3(0.0), sF = vec3(0.0), sT = vec3(0.0);
  vec3 f = vec3(0.0), t = vec3(0.0);
  float reach = 0.0;  // the largest piece reach over k (tris.comp pieceRho) [m]
  for (int h = bd.h0; h < bd.h0 + bd.nh; h++) {
    GHull hl = hull[h];
    vec3 G = vec3(0.0), EG = vec3(0.0), CG = vec3(0.0), ECG = vec3(0.0);
    vec4 wt = vec4(0.0, 1e30, -1e30, 0.0);
    for (int c = BUOY_LOCAL * hl.c0; c < BUOY_LOCAL * (hl.c0 + hl.nc); c++) {
      int o = BUOY_NSUM * c;
      pF += cpart[o].xyz;
      reach = max(reach, cpart[o].w);
      pT += cpart[o + 1].xyz;
      G += cpart[o + 2].xyz;
      EG += cpart[o + 3].xyz;
      CG += cpart[o + 4].xyz;
      ECG += cpart[o + 5].xyz;
      dF += cpart[o + 6].xyz;
      dT += cpart[o + 7].xyz;
      sF += cpart[o + 8].xyz;
      sT += cpart[o + 9].xyz;
      vec4 x = cpart[o + 10];
      wt = vec4(wt.x + x.x, min(wt.y, x.y), max(wt.z, x.z), wt.w + x.w);
    }
    // wetted length along the flow, sbar (0 rear .. 1 front), C_F
    float len = wt.z > wt.y ? wt.z - wt.y : 0.0;
    float sbar = wt.x > 0.0 && len > 0.0 ? (wt.w - wt.y * wt.x) / len / wt.x : 0.0;
    float rn = max(bd.flow.w * len / nu, 1e3);  // hydro.h kRnMin
    float lg = log(rn) / log(10.0) - 2.0;
    float cf = 0.075 / (lg * lg);
    if (hl.shape.z > 0.0) {
      // sum (1 + sbar - (e_k - lo) / len) g_k; s_k = sbar when len = 0
      float al = len > 0.0 ? 1.0 + sbar + wt.y / len : 1.0, be = len > 0.0 ? 1.0 / len : 0.0;
      float K = -0.5 * rho * cf * hl.shape.z;
      vF += K * (al * G - be * EG);
      vT += K * (al * CG - be * ECG);
    }
    // simple damping, scaled by the hull's wet fraction
    float rs = wt.x / hl.shape.x;
    f -= hl.damp.x * rs * bd.vlin.xyz;
    t -= hl.damp.y * rs * bd.vang.xyz;
  }
  outw[10 * b] = vec4(pF, reach);
  outw[10 * b + 1] = vec4(pT, 0.0);
  outw[10 * b + 2] = vec4(vF, 0.0);
  outw[10 * b + 3] = vec4(vT, 0.0);
  outw[10 * b + 4] = vec4(dF, 0.0);
  outw[10 * b + 5] = vec4(dT, 0.0);
  outw[10 * b + 6] = vec4(sF, 0.0);
  outw[10 * b + 7] = vec4(sT, 0.0);
  outw[10 * b + 8] = vec4(f, 0.0);
  outw[10 * b + 9] = vec4(t, 0.0);
}
