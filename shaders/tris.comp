#version 430
// stage 2, one workgroup per chunk of one hull's triangles (GChunk), each
// invocation BUOY_PER of them: cut each triangle at the waterline and
// integrate the pressure exactly (mjbuoy/pressure.cc), then Kerner's
// viscous resistance, pressure/suction drag and slamming at the wet centroid
// (mjbuoy/hydro.cc); each invocation sums its triangles in a fixed order,
// so no per-triangle buffer. The viscous force needs the hull's wetted length and sbar, known
// only after all its triangles: its per-triangle factor (1 + sbar - s_k),
// s_k = (e_k - lo) / len, is linear in e_k, so the chunk keeps sum g and
// sum e g (g = A |v|^2 t / |t|) and bodies.comp applies the factor.
#include "shared.h"
#include "pipeline.h"
#include "sea.glsl"

layout(local_size_x = BUOY_LOCAL) in;
layout(std430, binding = B_HULL) readonly buffer Hulls { GHull hull[]; };
layout(std430, binding = B_BODY) readonly buffer Bodies { GBody body[]; };
layout(std430, binding = B_CHUNK) readonly buffer Chunks { GChunk chunk[]; };
layout(std430, binding = B_CPART) writeonly buffer Cpart { vec4 cpart[]; };  // per invocation
layout(std430, binding = B_SLAMPREV) readonly buffer Sprev { vec4 sprev[]; };
layout(std430, binding = B_SLAMCUR) writeonly buffer Scur { vec4 scur[]; };

uniform samplerBuffer tVout;   // B_VOUT, B_LAB and B_TRI as buffer textures
uniform samplerBuffer tLab;
uniform isamplerBuffer tTri;

uniform int nchunk;
uniform float rhog;    // rho g [N/m^3]
uniform float rho;     // [kg/m^3]
uniform int hasprev;   // slamming history exists
uniform int first;     // first call of this step: record the history
uniform float slamdt;  // time since the previous step's first call [s]
uniform int linear;    // linear wave pressure (mjbuoy/wavepress.cc), else Kerner's

// a NaN to add to a sum whose intermediate was not finite: the CPU side
// reports a non-finite family (mjb_notices), never a silent zero
const float kNaN = uintBitsToFloat(0x7fc00000u);

// per-invocation sums over its triangles (BUOY_NSUM vec4, see pipeline.h)
vec3 pF, pT, vG, vEG, vCG, vECG, dF, dT, sF, sT;
vec4 wt;

// exact moments of pressure depth d over triangle q (fan piece of the wet polygon)
void piece(vec3 q0, vec3 q1, vec3 q2, float d0, float d1, float d2, vec3 n, inout float area,
           inout float dA, inout vec3 drA, inout vec3 rA) {
  float A = 0.5 * dot(cross(q1 - q0, q2 - q0), n);
  float sd = d0 + d1 + d2;
  vec3 sr = q0 + q1 + q2;
  area += A;
  dA += A * sd / 3.0;
  drA += A / 12.0 * (d0 * q0 + d1 * q1 + d2 * q2 + sd * sr);
  rA += A * sr / 3.0;
}

// effective mass of body b's rigid group at cc (rel. body COM) along unit
// u: 1 / (1/m + (r x u) . I^-1 (r x u)) (mjbuoy/rigid.cc effMass)
float effMass(int b, vec3 cc, vec3 u) {
  vec4 r0 = body[b].rig0, r1 = body[b].rig1, r2 = body[b].rig2;
  vec3 w = cross(cc - r0.xyz, u);
  vec3 Jw = vec3(r1.x * w.x + r1.w * w.y + r2.x * w.z,
                 r1.w * w.x + r1.y * w.y + r2.y * w.z,
                 r2.x * w.x + r2.y * w.y + r1.z * w.z);
  return 1.0 / (r0.w + dot(w, Jw));
}

// Radon's degree-5 7-point rule (as mjbuoy/wavepress.cc): barycentric
// points and weights
const float RA = 0.10128650732345634, RB = 0.47014206410511511;
const float WA = 0.12593918054482715, WB = 0.13239415278850619;

// the dynamic pressure over rho g [m] integrated over piece q (+= into dA
// and drA, as the hydrostatic depth); e, l: the surface height above the
// level and Gerstner label at its corners, linear in between (as the cut
// assumes), so no label search at the quadrature points
void dynPiece(int b, vec3 q0, vec3 q1, vec3 q2, vec3 e, vec2 l0, vec2 l1, vec2 l2, vec3 n,
              float zc, inout float dA, inout vec3 drA) {
  float A = 0.5 * dot(cross(q1 - q0, q2 - q0), n);
  if (!(A > 0.0)) return;
  for (int i = 0; i < 7; i++) {
    vec3 bc = i == 0 ? vec3(1.0 / 3.0) : i < 4 ? vec3(RA) : vec3(RB);
    float o = i == 0 ? 1.0 / 3.0 : i < 4 ? 1.0 - 2.0 * RA : 1.0 - 2.0 * RB;
    int j = (i - 1) % 3;
    if (i > 0) bc[j] = o;
    float w = i == 0 ? 0.225 : i < 4 ? WA : WB;
    vec3 r = bc.x * q0 + bc.y * q1 + bc.z * q2;
    vec2 a = bc.x * l0 + bc.y * l1 + bc.z * l2;
    float p = w * A * seaDynamic(b, a, r.xy, r.z + zc, dot(bc, e));
    dA += p;
    drA += p * r;
  }
}

void triangle(int k, int b, GHull hl, vec3 dir, vec3 vlin, vec3 vang, float zc) {
  ivec4 t = texelFetch(tTri, k);
  vec4 P0 = texelFetch(tVout, t.x), P1 = texelFetch(tVout, t.y), P2 = texelFetch(tVout, t.z);
  vec3 cr = cross(P1.xyz - P0.xyz, P2.xyz - P0.xyz);
  float tlen = length(cr);
  bool w0 = P0.w <= 0.0, w1 = P1.w <= 0.0, w2 = P2.w <= 0.0;
  bool dry = P0.w >= 0.0 && P1.w >= 0.0 && P2.w >= 0.0;
  if (tlen <= 0.0 || dry) {
    if (first != 0) scur[k] = vec4(0.0);
    return;
  }
  vec3 n = cr / tlen;
  // Sutherland-Hodgman against h <= 0 without indexing arrays (which
  // llvmpipe spills): rotate the odd vertex (the only wet one, or the only
  // dry one) to the front, keeping the winding; the wet part is one
  // triangle, or a quad as two
  int nw = int(w0) + int(w1) + int(w2);
  bool o0 = w0 == (nw == 1), o1 = w1 == (nw == 1);
  vec4 a = o0 ? P0 : o1 ? P1 : P2;
  vec4 bq = o0 ? P1 : o1 ? P2 : P0;
  vec4 c = o0 ? P2 : o1 ? P0 : P1;
  vec3 pab = a.xyz + a.w / (a.w - bq.w) * (bq.xyz - a.xyz);
  vec3 pca = a.xyz + a.w / (a.w - c.w) * (c.xyz - a.xyz);
  float area = 0.0, dA = 0.0;
  vec3 drA = vec3(0.0), rA = vec3(0.0);
  vec3 q0, q1, q2;
  // depths: Kerner's below the surface, -h (0 on the cut); linear theory's
  // hydrostatic part below the still level, -(z + zc), plus the dynamic
  // pressure by quadrature
  bool lin = linear != 0;
  float d0 = lin ? -(P0.z + zc) : -P0.w, d1 = lin ? -(P1.z + zc) : -P1.w;
  float d2 = lin ? -(P2.z + zc) : -P2.w, da = lin ? -(a.z + zc) : -a.w;
  float db = lin ? -(bq.z + zc) : -bq.w, dc = lin ? -(c.z + zc) : -c.w;
  float dab = lin ? -(pab.z + zc) : 0.0, dca = lin ? -(pca.z + zc) : 0.0;
  vec2 L0 = texelFetch(tLab, t.x).xy, L1 = texelFetch(tLab, t.y).xy, L2 = texelFetch(tLab, t.z).xy;
  vec2 l3 = L0 + L1 + L2;
  // surface height above the level (z - h) and label at the corners and
  // cut points, the labels cut with the same fractions as the positions
  vec2 ma = o0 ? L0 : o1 ? L1 : L2, mb = o0 ? L1 : o1 ? L2 : L0, mc = o0 ? L2 : o1 ? L0 : L1;
  vec2 mab = ma + a.w / (a.w - bq.w) * (mb - ma), mca = ma + a.w / (a.w - c.w) * (mc - ma);
  float ea = a.z + zc - a.w, eb = bq.z + zc - bq.w, ec = c.z + zc - c.w;
  float eab = pab.z + zc, eca = pca.z + zc;
  if (nw == 3) {
    q0 = P0.xyz; q1 = P1.xyz; q2 = P2.xyz;
    piece(q0, q1, q2, d0, d1, d2, n, area, dA, drA, rA);
    if (lin) {
      vec3 e = vec3(P0.z - P0.w, P1.z - P1.w, P2.z - P2.w) + zc;
      dynPiece(b, q0, q1, q2, e, L0, L1, L2, n, zc, dA, drA);
    }
  } else if (nw == 1) {
    q0 = a.xyz; q1 = pab; q2 = pca;
    piece(q0, q1, q2, da, dab, dca, n, area, dA, drA, rA);
    if (lin) dynPiece(b, q0, q1, q2, vec3(ea, eab, eca), ma, mab, mca, n, zc, dA, drA);
  } else {
    q0 = pab; q1 = bq.xyz; q2 = c.xyz;
    piece(q0, q1, q2, dab, db, dc, n, area, dA, drA, rA);
    piece(pab, c.xyz, pca, dab, dc, dca, n, area, dA, drA, rA);
    if (lin) {
      dynPiece(b, q0, q1, q2, vec3(eab, eb, ec), mab, mb, mc, n, zc, dA, drA);
      dynPiece(b, pab, c.xyz, pca, vec3(eab, ec, eca), mab, mc, mca, n, zc, dA, drA);
    }
  }
  if (!(area > 0.0)) {
    if (!(area <= 0.0)) pF += vec3(kNaN);  // NaN area: heights not finite
    if (first != 0) scur[k] = vec4(0.0);
    return;
  }
  float e0 = dot(q0, dir), e1 = dot(q1, dir), e2 = dot(q2, dir);
  float e3 = nw == 2 ? dot(pca, dir) : e0;
  float A = area;
  vec3 cc = rA / A;
  float ez = dot(cc, dir);
  wt += vec4(A, 0.0, 0.0, A * ez);
  wt.y = min(wt.y, min(min(e0, e1), min(e2, e3)));
  wt.z = max(wt.z, max(max(e0, e1), max(e2, e3)));
  pF -= rhog * dA * n;
  pT -= rhog * cross(drA, n);

  // flow-relative velocity: point velocity minus the water's there; the
  // label search starts from the mean of the vertex labels
  vec2 la = seaLabel(b, cc.xy, l3 / 3.0);
  float eta = seaEta(b, la, cc.xy);
  vec3 v = vlin + cross(vang, cc) - seaVelocity(b, la, cc.xy, cc.z + zc, eta);
  float v2 = dot(v, v), sp = sqrt(v2);
  if (!(sp <= 3.0e38)) {
    // |v| not finite in float (NaN water velocity, or overflow)
    vG += vec3(kNaN);
    dF += vec3(kNaN);
    if (hasprev != 0 && hl.slam.x > 0.0 && slamdt > 0.0) sF += vec3(kNaN);
  }

  // viscous: 0.5 rho C_F (1+k_i) (1 + sbar - s_k) A |v|^2 against the
  // tangential flow; here only g = A |v|^2 t / |t| and e_k g
  vec3 tg = v - dot(v, n) * n;
  float tl = length(tg);
  if (tl > 1e-6 * sp) {
    vec3 g = A * v2 / tl * tg, cg = cross(cc, g);
    vG += g;
    vEG += ez * g;
    vCG += cg;
    vECG += ez * cg;
  }

  // pressure (cos > 0) and suction (cos < 0) drag
  float cs = sp > 0.0 ? dot(v, n) / sp : 0.0;
  // (one pow for both: SIMD lanes of either sign would run both branches)
  if (sp > 0.0 && cs != 0.0) {
    float u = sp / hl.shape.w;
    vec3 k = cs > 0.0 ? -hl.drag.xyz : hl.suction.xyz;
    float s = (k.x * u + k.y * u * u) * A * pow(abs(cs), cs > 0.0 ? hl.drag.z : hl.suction.z);
    dF += s * n;
    dT += cross(cc, s * n);
  }

  // slamming: Gamma = |A v - A' v'| / (S dt), stopping force
  // share m_eff v (2A/S_hull) / dt with the effective mass m_eff at cc along v
  if (hasprev != 0 && hl.slam.x > 0.0 && slamdt > 0.0 && cs > 0.0) {
    vec4 pv = sprev[k];
    float gamma = length(A * v - pv.w * pv.xyz) / (0.5 * tlen * slamdt);
    float r = min(gamma / hl.slam.y, 1.0);
    float me = hl.shape.y * effMass(b, cc, v / sp);
    float s = -hl.slam.x * pow(r, hl.slam.z) * cs * me * 2.0 * A / hl.shape.x / slamdt;
    sF += s * v;
    sT += cross(cc, s * v);
  }
  if (first != 0) scur[k] = vec4(v, A);
}

void main() {
  int l = int(gl_LocalInvocationID.x);
  // loops past 65535 chunks, GL's guaranteed workgroup count (uniform per group)
  for (int ci = int(gl_WorkGroupID.x); ci < nchunk; ci += int(gl_NumWorkGroups.x)) {
    GChunk ch = chunk[ci];
    GHull hl = hull[ch.hull];
    int b = hl.body;
    vec3 dir = body[b].flow.xyz, vlin = body[b].vlin.xyz, vang = body[b].vang.xyz;
    float zc = body[b].orig.w;
    pF = pT = vG = vEG = vCG = vECG = dF = dT = sF = sT = vec3(0.0);
    wt = vec4(0.0, 1e30, -1e30, 0.0);
    for (int j = l; j < ch.nt; j += BUOY_LOCAL) triangle(ch.t0 + j, b, hl, dir, vlin, vang, zc);
    // no shared memory and no barrier (llvmpipe runs barrier shaders as
    // coroutines): each invocation stores its sums, bodies.comp adds them
    int o = BUOY_NSUM * (BUOY_LOCAL * ci + l);
    cpart[o] = vec4(pF, 0.0);
    cpart[o + 1] = vec4(pT, 0.0);
    cpart[o + 2] = vec4(vG, 0.0);
    cpart[o + 3] = vec4(vEG, 0.0);
    cpart[o + 4] = vec4(vCG, 0.0);
    cpart[o + 5] = vec4(vECG, 0.0);
    cpart[o + 6] = vec4(dF, 0.0);
    cpart[o + 7] = vec4(dT, 0.0);
    cpart[o + 8] = vec4(sF, 0.0);
    cpart[o + 9] = vec4(sT, 0.0);
    cpart[o + 10] = wt;
  }
}
