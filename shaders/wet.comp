#version 430
// stage 2, one invocation per triangle: cut at the waterline and integrate
// the pressure exactly (mjbuoy/pressure.cc): F = -rho g dA n, T = -rho g drA x n
#include "shared.h"
#include "pipeline.h"

layout(local_size_x = BUOY_LOCAL) in;
layout(std430, binding = B_TRI) readonly buffer Tris { GTri tri[]; };
layout(std430, binding = B_HULL) readonly buffer Hulls { GHull hull[]; };
layout(std430, binding = B_BODY) readonly buffer Bodies { GBody body[]; };
layout(std430, binding = B_VOUT) readonly buffer Vout { vec4 vout[]; };
layout(std430, binding = B_WET) writeonly buffer Wets { GWet wet[]; };
layout(std430, binding = B_TF) writeonly buffer Tf { vec4 tf[]; };

uniform int ntri;
uniform float rhog;   // rho g [N/m^3]

void triangle(int k) {
  GTri t = tri[k];
  vec3 dir = body[hull[t.hull].body].flow.xyz;
  vec4 P[3] = vec4[3](vout[t.v0], vout[t.v1], vout[t.v2]);
  vec3 cr = cross(P[1].xyz - P[0].xyz, P[2].xyz - P[0].xyz);
  float len = length(cr);
  vec3 n = len > 0.0 ? cr / len : vec3(0.0);
  float area = 0.0, dA = 0.0;
  vec3 drA = vec3(0.0), rA = vec3(0.0);
  float lo = 1e30, hi = -1e30;
  bool dry = P[0].w >= 0.0 && P[1].w >= 0.0 && P[2].w >= 0.0;
  if (len > 0.0 && !dry) {
    // Sutherland-Hodgman against h <= 0 in the parent's winding
    vec3 q[4];
    float d[4];
    int nq = 0;
    for (int i = 0; i < 3; i++) {
      int j = (i + 1) % 3;
      if (P[i].w <= 0.0) { q[nq] = P[i].xyz; d[nq] = -P[i].w; nq++; }
      if ((P[i].w < 0.0 && P[j].w > 0.0) || (P[i].w > 0.0 && P[j].w < 0.0)) {
        int a = P[i].w < 0.0 ? i : j, c = P[i].w < 0.0 ? j : i;
        float s = P[a].w / (P[a].w - P[c].w);
        q[nq] = P[a].xyz + s * (P[c].xyz - P[a].xyz);
        d[nq] = 0.0;
        nq++;
      }
    }
    for (int i = 0; i < nq; i++) {
      float e = dot(q[i], dir);
      lo = min(lo, e);
      hi = max(hi, e);
    }
    // fan: integral(d dA) = A (sum d) / 3, integral(d r dA) = A/12 (sum d r + sum d sum r)
    for (int i = 1; i + 1 < nq; i++) {
      float A = 0.5 * dot(cross(q[i] - q[0], q[i + 1] - q[0]), n);
      float sd = d[0] + d[i] + d[i + 1];
      vec3 sr = q[0] + q[i] + q[i + 1];
      area += A;
      dA += A * sd / 3.0;
      drA += A / 12.0 * (d[0] * q[0] + d[i] * q[i] + d[i + 1] * q[i + 1] + sd * sr);
      rA += A * sr / 3.0;
    }
  }
  if (!(area > 0.0)) area = 0.0;
  vec3 c = area > 0.0 ? rA / area : vec3(0.0);
  wet[k].c = vec4(c, area);
  wet[k].n = vec4(n, 0.5 * len);
  wet[k].e = vec4(lo, hi, dot(c, dir), 0.0);
  bool w = area > 0.0;
  tf[8 * k] = vec4(w ? -rhog * dA * n : vec3(0.0), 0.0);
  tf[8 * k + 1] = vec4(w ? -rhog * cross(drA, n) : vec3(0.0), 0.0);
}

// grid-stride: the dispatch is capped at GL's minimum of 65535 workgroups
void main() {
  int n = int(gl_NumWorkGroups.x * gl_WorkGroupSize.x);
  for (int k = int(gl_GlobalInvocationID.x); k < ntri; k += n) triangle(k);
}
