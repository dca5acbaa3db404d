#version 430
// stage 2, one workgroup per chunk of one hull's triangles (GChunk), each
// invocation BUOY_PER of them: cut each triangle at the waterline and
// integrate the pressure exactly (mjbuoy/hull/pressure.cc; the linear dynamic
// pressure and the water velocity per wave component in closed form,
// waveint.glsl), then Kerner's viscous resistance, pressure/suction drag
// and slamming at the wet centroid with the water velocity's mean over the
// wet part (mjbuoy/hull/hydro.cc, docs/physics.md); each invocation sums its triangles in a fixed order,
// so no per-triangle buffer. The viscous force needs the hull's wetted length and sbar, known
// only after all its triangles: its per-triangle factor (1 + sbar - s_k),
// s_k = (e_k - lo) / len, is linear in e_k, so the chunk keeps sum g and
// sum e g (g = A |v|^2 t / |t|) and bodies.comp applies the factor.
#include "shared.h"
#include "pipeline.h"
#include "sea.glsl"
#include "waveint.glsl"

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
uniform samplerBuffer tExp;    // B_EXP

// e^L of component wv at a piece's corner 0 of Wheeler height zs [m]:
// e^(k zs + i theta), e^(-k (zs + 2 h) + i theta), from vertex v's e^(i
// theta) (verts.comp, sea.glsl expTexel) turned by r = e^(i dtheta) to the
// corner (1 at a vertex)
vec4 expAt(int v, int w, GWave wv, float zs, vec2 r) {
  vec4 t = texelFetch(tExp, expTexel(v, w));
  vec2 e = cmul((w & 1) == 0 ? t.xy : t.zw, r);
  // e^(k zs) >= e^(-k h) > e^-17 where e2kh > 0 (zs >= -h): no overflow
  float ep = exp(wv.k * zs);
#ifdef WI_DEEP
  return vec4(ep * e, 0.0, 0.0);  // (every e2kh is 0, gl.cc: no division)
#else
  float em = wv.e2kh > 0.0 ? wv.e2kh / ep : 0.0;
  return vec4(ep * e, em * e);
#endif
}

uniform int nchunk;
uniform float rhog;    // rho g [N/m^3]
uniform float rho;     // [kg/m^3]
uniform int hasprev;   // slamming history exists
uniform int first;     // first call of this step: record the history
uniform float slamdt;  // time since the previous step's first call [s]
uniform int linear;    // linear wave pressure (mjbuoy/hull/wavepress.cc), else Kerner's
uniform int nfast;     // components integrated by one series per piece (gl.cc)

// a NaN to add to a sum whose intermediate was not finite: the CPU side
// reports a non-finite family (mjb_notices), never a silent zero
const float kNaN = uintBitsToFloat(0x7fc00000u);

// per-invocation sums over its triangles (BUOY_NSUM vec4, see pipeline.h)
vec3 pF, pT, vG, vEG, vCG, vECG, dF, dT, sF, sT;
vec4 wt;
float rhomax;  // the node gaps' reach over k (pieceRho) [m]

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
// u: 1 / (1/m + (r x u) . I^-1 (r x u)) (mjbuoy/hull/rigid.cc effMass)
float effMass(int b, vec3 cc, vec3 u) {
  vec4 r0 = body[b].rig0, r1 = body[b].rig1, r2 = body[b].rig2;
  vec3 w = cross(cc - r0.xyz, u);
  vec3 Jw = vec3(r1.x * w.x + r1.w * w.y + r2.x * w.z,
                 r1.w * w.x + r1.y * w.y + r2.y * w.z,
                 r2.x * w.x + r2.y * w.y + r1.z * w.z);
  return 1.0 / (r0.w + dot(w, Jw));
}

// one fan piece of the wet polygon, corners rotated so corner 0 is the
// highest (largest Wheeler height zs: Re of every L - L0 <= 0 then)
struct Piece {
  vec3 q0, q1, q2;   // corners rel. COM
  vec3 zs;           // Wheeler heights [m]
  vec4 dp;           // horizontal position differences q1 - q0, q2 - q0
  vec4 dl;           // the same of the Gerstner labels
  float a2;          // twice the area (0: skip)
  int rot;           // corner 0 is the polygon corner c0 + rot of (c0, c1, c2)
};

// (rot >= 0: corner 0 is that corner instead)
Piece makePiece(vec3 p0, vec3 p1, vec3 p2, float z0, float z1, float z2, vec2 m0, vec2 m1,
                vec2 m2, vec3 n, int rot) {
  Piece P;
  float A = 0.5 * dot(cross(p1 - p0, p2 - p0), n);
  P.a2 = A > 0.0 ? 2.0 * A : 0.0;
  P.rot = rot >= 0 ? rot : z0 >= z1 && z0 >= z2 ? 0 : z1 >= z2 ? 1 : 2;
  bool r0 = P.rot == 0, r1 = P.rot == 1;
  P.q0 = r0 ? p0 : r1 ? p1 : p2;
  P.q1 = r0 ? p1 : r1 ? p2 : p0;
  P.q2 = r0 ? p2 : r1 ? p0 : p1;
  P.zs = r0 ? vec3(z0, z1, z2) : r1 ? vec3(z1, z2, z0) : vec3(z2, z0, z1);
  vec2 l0 = r0 ? m0 : r1 ? m1 : m2, l1 = r0 ? m1 : r1 ? m2 : m0, l2 = r0 ? m2 : r1 ? m0 : m1;
  P.dp = vec4(P.q1.xy - P.q0.xy, P.q2.xy - P.q0.xy);
  P.dl = vec4(l1 - l0, l2 - l0);
  return P;
}

// component wv's phase is at the position (Airy), not at the label
#define AIRY(wv) ((wv).kind != 0.0)

// the exponent's changes from corner 0 to corners 1, 2 of piece P for
// component wv: L = k zs + i theta (Airy phase at x, Gerstner at the label)
void pieceSpan(Piece P, GWave wv, out vec2 x, out vec2 y) {
  vec2 kd = vec2(wv.kx, wv.ky);
  vec4 d = AIRY(wv) ? P.dp : P.dl;
  x = vec2(wv.k * (P.zs.y - P.zs.x), dot(kd, d.xy));
  y = vec2(wv.k * (P.zs.z - P.zs.x), dot(kd, d.zw));
}

// adds component wv's integrals over piece P, whose corner 0 has e^L = E0
// (B_EXP layout), nt series terms (GWave.terms: enough for the piece's
// node gap, gl.cc): ps += (Re S, Re M1, Re M2) times amp / (1 +
// e^(-2kh)), the dynamic pressure over rho g and its barycentric moments
// (corner 0's is the first minus the others), vs += the water velocity
// times area. split: the piece in n^2 parts (triPart, n per invocation),
// for components whose node gap may exceed what one series covers
void wavePiece(Piece P, GWave wv, vec4 E0, bool split, inout vec3 ps, inout vec3 vs) {
  vec2 x, y;
  pieceSpan(P, wv, x, y);
  int n = split ? triParts(x, y) : 1;
  // e^(k zs) and, at finite depth, e^(-k (zs + 2h)) (real parts flip);
  // loops test at their end: llvmpipe runs every if's body and, after a
  // break at the top, a loop's body once more, each for all lanes, masked
#ifdef WI_DEEP
  const float e2 = 0.0;  // (gl.cc): the divisions below fold away
#else
  float e2 = wv.e2kh;
#endif
  float sv = 0.0;
  vec2 S = vec2(0.0), M1 = S, M2 = S;
  int f = 0;
  do {
    float sg = f == 0 ? 1.0 : -1.0;
    vec2 xf = vec2(sg * x.x, x.y), yf = vec2(sg * y.x, y.y), e = f == 0 ? E0.xy : E0.zw;
    vec2 s = vec2(0.0), m1 = s, m2 = s;
    if (split) {
      for (int k = 0; k < n * n; k++) triPart(xf, yf, e, 1.0, n, k, s, m1, m2);
    } else {
      vec2 s0, sa, sb;
      ddSeries(xf, yf, int(wv.terms), s0, sa, sb);
      // exp[0,x,y,y] = s0 - sa - sb (the three moments add up to S)
      s = cmul(e, s0);
      m1 = cmul(e, sb);
      m2 = cmul(e, s0 - sa - sb);
    }
    S += s;
    M1 += m1;
    M2 += m2;
    sv += sg * s.y;
#ifdef WI_DEEP
  } while (false);  // every e2 is 0 (gl.cc): no loop left to manage
#else
  } while (++f < (e2 > 0.0 ? 2 : 1));
#endif
  float amp = wv.amp * P.a2, cv = amp * wv.c / (1.0 - e2);
  // velocity: horizontal (e+ + e-) cos, vertical (e+ - e-) sin, over 1 - e^(-2kh),
  // amp omega = amp c k
  vs += cv * vec3(S.x * vec2(wv.kx, wv.ky), wv.k * sv);
  // pressure: (e+ + e-) cos over 1 + e^(-2kh), its moments
  ps += amp / (1.0 + e2) * vec3(S.x, M1.x, M2.x);
}

// the largest node gap over k of piece P's integrals, for any component:
// max over corner pairs of sqrt(dzs^2 + max(|dp|^2, |dl|^2)) [m]
float pieceRho(Piece P) {
  vec4 d = vec4(P.dp.zw - P.dp.xy, P.dl.zw - P.dl.xy);
  vec3 dz = vec3(P.zs.y - P.zs.x, P.zs.z - P.zs.x, P.zs.z - P.zs.y);
  vec3 h = vec3(max(dot(P.dp.xy, P.dp.xy), dot(P.dl.xy, P.dl.xy)),
                max(dot(P.dp.zw, P.dp.zw), dot(P.dl.zw, P.dl.zw)), max(dot(d.xy, d.xy), dot(d.zw, d.zw)));
  vec3 r2 = dz * dz + h;
  return sqrt(max(r2.x, max(r2.y, r2.z)));
}

// a wet triangle between its cut (setup), its wave pieces (wave) and its
// forces (finish)
struct Tri {
  int k;             // triangle
  int nv;            // wave pieces (0: no waves; -1: nothing wet, all done)
  int nw;            // wet vertices
  int i0;            // the vertex whose e^L corner 0 takes, turned by dx0, dm0
  vec3 n;            // unit normal
  float tlen;        // twice the area of the whole triangle
  vec3 q0, q1, q2;   // wet polygon (the fan's first piece), its fourth corner pca
  vec3 pca;
  float area, dA;    // wet area, pressure head times area (hydrostatic and wave)
  vec3 drA, rA, vs;  // its moment, the area's, the water velocity times area
  vec2 dx0, dm0;
  Piece A1, A2;
};

// the cut of triangle k and its hydrostatic part
Tri setup(int k, float zc) {
  Tri T;
  T.k = k;
  T.nv = -1;
  ivec4 t = texelFetch(tTri, k);
  vec4 P0 = texelFetch(tVout, t.x), P1 = texelFetch(tVout, t.y), P2 = texelFetch(tVout, t.z);
  vec3 cr = cross(P1.xyz - P0.xyz, P2.xyz - P0.xyz);
  float tlen = length(cr);
  bool w0 = P0.w <= 0.0, w1 = P1.w <= 0.0, w2 = P2.w <= 0.0;
  bool dry = P0.w >= 0.0 && P1.w >= 0.0 && P2.w >= 0.0;
  if (tlen <= 0.0 || dry) {
    if (first != 0) scur[k] = vec4(0.0);
    return T;
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
  // pressure (wave)
  bool lin = linear != 0;
  float d0 = lin ? -(P0.z + zc) : -P0.w, d1 = lin ? -(P1.z + zc) : -P1.w;
  float d2 = lin ? -(P2.z + zc) : -P2.w, da = lin ? -(a.z + zc) : -a.w;
  float db = lin ? -(bq.z + zc) : -bq.w, dc = lin ? -(c.z + zc) : -c.w;
  float dab = lin ? -(pab.z + zc) : 0.0, dca = lin ? -(pca.z + zc) : 0.0;
  if (nw == 3) {
    q0 = P0.xyz; q1 = P1.xyz; q2 = P2.xyz;
    piece(q0, q1, q2, d0, d1, d2, n, area, dA, drA, rA);
  } else if (nw == 1) {
    q0 = a.xyz; q1 = pab; q2 = pca;
    piece(q0, q1, q2, da, dab, dca, n, area, dA, drA, rA);
  } else {
    q0 = pab; q1 = bq.xyz; q2 = c.xyz;
    piece(q0, q1, q2, dab, db, dc, n, area, dA, drA, rA);
    piece(pab, c.xyz, pca, dab, dc, dca, n, area, dA, drA, rA);
  }
  if (!(area > 0.0)) {
    if (!(area <= 0.0)) pF += vec3(kNaN);  // NaN area: heights not finite
    if (first != 0) scur[k] = vec4(0.0);
    return T;
  }
  T.nv = 0;
  T.nw = nw;
  T.n = n;
  T.tlen = tlen;
  T.q0 = q0;
  T.q1 = q1;
  T.q2 = q2;
  T.pca = pca;
  T.area = area;
  T.dA = dA;
  T.drA = drA;
  T.rA = rA;
  T.vs = vec3(0.0);

  // the waves over the wet polygon c0 c1 c2 (c3), fanned from c0: its
  // pieces, each integrated exactly about its highest corner (wave,
  // waveint.glsl); the water velocity is its mean over the wet part
  // (docs/physics.md)
  if (nwave > 0) {
    vec2 L0 = texelFetch(tLab, t.x).xy, L1 = texelFetch(tLab, t.y).xy, L2 = texelFetch(tLab, t.z).xy;
    // labels: at the cut points cut with the same fractions as the positions
    vec2 ma = o0 ? L0 : o1 ? L1 : L2, mb = o0 ? L1 : o1 ? L2 : L0, mc = o0 ? L2 : o1 ? L0 : L1;
    vec2 mab = ma + a.w / (a.w - bq.w) * (mb - ma), mca = ma + a.w / (a.w - c.w) * (mc - ma);
    // Wheeler heights at the wet vertices, 0 at the cut points
    float s0 = seaStretch(P0.z + zc, P0.z + zc - P0.w), s1 = seaStretch(P1.z + zc, P1.z + zc - P1.w);
    float s2 = seaStretch(P2.z + zc, P2.z + zc - P2.w);
    float sa = o0 ? s0 : o1 ? s1 : s2, sb = o0 ? s1 : o1 ? s2 : s0, sc = o0 ? s2 : o1 ? s0 : s1;
    // polygon corners: vertex index (-1 at a cut), position, label, zs
    vec3 c0 = nw == 3 ? P0.xyz : nw == 1 ? a.xyz : pab, c1 = nw == 3 ? P1.xyz : nw == 1 ? pab : bq.xyz;
    vec3 c2 = nw == 3 ? P2.xyz : nw == 1 ? pca : c.xyz;
    vec2 n0 = nw == 3 ? L0 : nw == 1 ? ma : mab, n1 = nw == 3 ? L1 : nw == 1 ? mab : mb;
    vec2 n2 = nw == 3 ? L2 : nw == 1 ? mca : mc;
    float z0 = nw == 3 ? s0 : nw == 1 ? sa : 0.0, z1 = nw == 3 ? s1 : nw == 1 ? 0.0 : sb;
    float z2 = nw == 3 ? s2 : nw == 1 ? 0.0 : sc;
#ifdef WI_SPLIT
    Piece A1 = makePiece(c0, c1, c2, z0, z1, z2, n0, n1, n2, n, -1);
    Piece A2 = makePiece(c0, c2, pca, z0, z2, 0.0, n0, n2, mca, n, -1);
    // corner 0 of the pieces (the highest; a quad's two share it): a
    // vertex, or the cut point pab, whose e^L is that of its edge's dry
    // end (zs = 0 at both; verts.comp stores every vertex) turned by the
    // phase change along the edge (theta is linear in x, or in the label)
    int ia = o0 ? t.x : o1 ? t.y : t.z, ib = o0 ? t.y : o1 ? t.z : t.x;
    bool cut0 = nw == 2 || (nw == 1 && A1.rot == 1);
    int iv = nw == 3 ? (A1.rot == 0 ? t.x : A1.rot == 1 ? t.y : t.z) : ia;
    int i0 = cut0 && nw == 1 ? ib : iv;
    vec2 dx0 = cut0 ? pab.xy - (nw == 1 ? bq.xy : a.xy) : vec2(0.0);
    vec2 dm0 = cut0 ? mab - (nw == 1 ? mb : ma) : vec2(0.0);
#else
    // every component fast (k reach <= WI_ROT, gl.cc): corner 0 a wet
    // vertex, whose e^L verts.comp stored, no turn: the highest of a
    // whole triangle, a lone wet vertex (a), a quad's c for both pieces;
    // Re(L - L0) <= k reach <= 2 leaves the series' bound as it is
    // (docs/physics.md "Cost (gl backend, float)")
    int r1 = nw == 3 ? -1 : nw == 1 ? 0 : 2;
    Piece A1 = makePiece(c0, c1, c2, z0, z1, z2, n0, n1, n2, n, r1);
    Piece A2 = makePiece(c0, c2, pca, z0, z2, 0.0, n0, n2, mca, n, 1);
    int ia = o0 ? t.x : o1 ? t.y : t.z, ic = o0 ? t.z : o1 ? t.x : t.y;
    int i0 = nw == 3 ? (A1.rot == 0 ? t.x : A1.rot == 1 ? t.y : t.z) : nw == 1 ? ia : ic;
    vec2 dx0 = vec2(0.0), dm0 = vec2(0.0);
#endif
    int nv = nw == 2 ? 2 : 1;
    T.nv = nv;
    T.i0 = i0;
    T.dx0 = dx0;
    T.dm0 = dm0;
    T.A1 = A1;
    T.A2 = A2;
    // the node gaps' and the turns' reach over k, reported to gl.cc, which
    // sizes the series (GWave.terms) and nfast to it and repeats the step
    // where it fell short
    rhomax = max(rhomax, max(max(pieceRho(A1), nv == 2 ? pieceRho(A2) : 0.0),
                             sqrt(max(dot(dx0, dx0), dot(dm0, dm0)))));
  }
  return T;
}

// piece pc of T's wet polygon: every component's dynamic pressure and
// water velocity
void wave(inout Tri T, int pc) {
      bool lin = linear != 0;
      int i0 = T.i0;
      vec2 dx0 = T.dx0, dm0 = T.dm0;
      vec3 vs = T.vs;
      Piece P = pc == 0 ? T.A1 : T.A2;
      vec3 ps = vec3(0.0);
      // components [0, nfast) (k ascending): one series each, the turn
      // by its Taylor series (k times the reach <= WI_ROT, gl.cc)
      if (nfast > 0) {
        int w = 0;
        do {
          GWave wv = waveAt(w);
#ifdef WI_SPLIT
          vec2 r = rotation(dot(vec2(wv.kx, wv.ky), AIRY(wv) ? dx0 : dm0));
#else
          const vec2 r = vec2(1.0, 0.0);  // corner 0 is a vertex (setup)
#endif
          wavePiece(P, wv, expAt(i0, w, wv, P.zs.x, r), false, ps, vs);
        } while (++w < nfast);
      }
#ifdef WI_SPLIT
      // the rest: split into parts, turned by cos and sin (a second
      // program, gl.cc kSplit: this loop's body would run at least once)
      for (int w = nfast; w < nwave; w++) {
        GWave wv = waveAt(w);
        float ph = dot(vec2(wv.kx, wv.ky), AIRY(wv) ? dx0 : dm0);
        wavePiece(P, wv, expAt(i0, w, wv, P.zs.x, seaCosSin(ph)), true, ps, vs);
      }
#endif
      if (lin) {
        T.dA += ps.x;
        T.drA += (ps.x - ps.y - ps.z) * P.q0 + ps.y * P.q1 + ps.z * P.q2;
      }
      T.vs = vs;
}

// T's forces: pressure, viscous, drag, slamming
void finish(Tri T, int b, GHull hl, vec3 dir, vec3 vlin, vec3 vang) {
  int k = T.k, nw = T.nw;
  vec3 q0 = T.q0, q1 = T.q1, q2 = T.q2, pca = T.pca, n = T.n, rA = T.rA, drA = T.drA, vs = T.vs;
  float area = T.area, dA = T.dA, tlen = T.tlen;
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

  // flow-relative velocity: point velocity minus the water's, its mean
  // over the wet part
  vec3 v = vlin + cross(vang, cc) - (vec3(current, 0.0) + vs / A);
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
    rhomax = 0.0;
    // each invocation's triangles j = l, l + BUOY_LOCAL, ..., as a stream
    // of wet pieces, one per pass: an invocation moves on to its next wet
    // triangle while others still work on a quad's second piece, and
    // passes its dry ones at the cost of a cut (llvmpipe runs all lanes
    // of a vector through each pass, so a pass per triangle would cost
    // every vector its wettest lane's pieces)
    int j = l, pc = 0;
    bool live = false;
    Tri T;
    do {
      while (!live && j < ch.nt) {
        T = setup(ch.t0 + j, zc);
        live = T.nv >= 0;
        pc = 0;
        if (!live) j += BUOY_LOCAL;
      }
      if (live) {
        if (pc < T.nv) wave(T, pc);
        if (++pc >= T.nv) {
          finish(T, b, hl, dir, vlin, vang);
          live = false;
          j += BUOY_LOCAL;
        }
      }
    } while (live || j < ch.nt);
    // no shared memory and no barrier (llvmpipe runs barrier shaders as
    // coroutines): each invocation stores its sums, bodies.comp adds them
    int o = BUOY_NSUM * (BUOY_LOCAL * ci + l);
    cpart[o] = vec4(pF, rhomax);
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
