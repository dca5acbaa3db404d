// sea.glsl: Gerstner and Airy surface in each body's frame (same maths as
// mjbuoy/sea/sea.cc, in positions relative to the body's COM; the per-body
// phases come from the CPU in double). Needs shared.h and buoy.h first.

// B_WAVE and B_PHASE through buffer textures: llvmpipe gathers a texel in
// straight SIMD code, but loads a storage buffer at a loop-varying index
// lane by lane
uniform samplerBuffer tWave;   // B_WAVE as RGBA32F, three texels per component
uniform samplerBuffer tPhase;  // B_PHASE as R32F

// component i's first texel, all the surface needs (k dx, k dy, amp, kind)
vec4 waveHead(int i) { return texelFetch(tWave, 3 * i); }
// component i but its label-solve texel (steep, dx, dy: 0 here)
GWave waveAt(int i) {
  vec4 u = texelFetch(tWave, 3 * i), v = texelFetch(tWave, 3 * i + 1);
  return GWave(u.x, u.y, u.z, u.w, v.x, v.y, v.z, v.w, 0.0, 0.0, 0.0, 0.0);
}

// (cos t, sin t) from one range reduction (llvmpipe's cos and sin reduce
// each their own): t = q pi/2 + r, |r| <= pi/4 (pi/2 in two floats,
// Cody-Waite), Taylor polynomials to r^9 and r^8, whose first terms left
// out, r^11/11! and r^10/10!, are below 2.4e-8 at r = pi/4 (a fifth of
// float's resolution of 1), then turned by q quarter turns
vec2 seaCosSin(float t) {
  float q = floor(t * 0.63661977 + 0.5);
  float r = fma(q, -1.5707964, t);
  r = fma(q, 4.3711388e-8, r);
  float r2 = r * r;
  float s = r * (1.0 + r2 * (-1.0 / 6.0 + r2 * (1.0 / 120.0 + r2 * (-1.0 / 5040.0 +
            r2 * (1.0 / 362880.0)))));
  float c = 1.0 + r2 * (-0.5 + r2 * (1.0 / 24.0 + r2 * (-1.0 / 720.0 + r2 * (1.0 / 40320.0))));
  int iq = int(q) & 3;  // two's complement: q mod 4 for negative q too
  vec2 cs = (iq & 1) != 0 ? vec2(-s, c) : vec2(c, s);
  return iq >= 2 ? -cs : cs;
}

#ifdef WI_ONE
const int nwave = 1;     // (gl.cc: a one-component sea's programs, their loops unrolled)
#else
uniform int nwave;
#endif
uniform int ngerst;      // Gerstner components among them (steep > 0 ones matter)
uniform float depth;     // water depth [m], 0 = deep
uniform vec2 current;    // [m/s]

float phaseAt(int b, int i) { return texelFetch(tPhase, b * nwave + i).x; }

// B_EXP (pipeline.h): vertex v's texel holding component w's e^(i theta),
// two components a texel, w even in xy, odd in zw (half the stores:
// llvmpipe stores lane by lane)
int expTexel(int v, int w) { return v * ((nwave + 1) >> 1) + (w >> 1); }

// the phase of component w (head: waveHead) at a, ph at the COM
float theta(vec4 w, float ph, vec2 a) { return ph + dot(w.xy, a); }

// the phase of component w (phase ph at the COM) at the point x whose
// Gerstner label is a: Gerstner components at the label, Airy ones (kind
// 1) at x
#ifdef WI_AIRY
float thetaAt(vec4 w, float ph, vec2 a, vec2 x) { return theta(w, ph, x); }  // (all Airy, gl.cc)
#else
float thetaAt(vec4 w, float ph, vec2 a, vec2 x) { return theta(w, ph, w.w != 0.0 ? x : a); }
#endif

// residual f = a - Q A D sin(theta(a)) - x and the upper triangle of its
// Jacobian J = I - sum Q A k cos(theta) D D^T (j00, j01, j11); Airy
// components have steep 0 here (gl.cc) and drop out
vec2 seaResidual(int b, vec2 x, vec2 a, out vec3 J) {
  vec2 f = a - x;
  J = vec3(1.0, 0.0, 1.0);
  for (int i = 0; i < nwave; i++) {
    vec4 w = waveHead(i), u = texelFetch(tWave, 3 * i + 2);  // u: steep, dx, dy
    float qa = u.x * w.z;
    if (qa == 0.0) continue;
    vec2 cs = seaCosSin(theta(w, phaseAt(b, i), a));
    // J's k D D^T as (k D) D^T
    f -= qa * cs.y * u.yz;
    J -= qa * cs.x * vec3(w.x * u.y, w.x * u.z, w.y * u.z);
  }
  return f;
}

// particle label (rel. COM) whose displaced position is x, Newton from a,
// safeguarded as mjbuoy/sea/sea.cc label(): J stays positive definite below
// folding, so the Newton step is a descent direction of |f|^2 and is
// halved until |f| drops (near folding, sum Q k A -> 1, J is nearly
// singular and full steps overshoot); stops when the step is below 0.1 mm
// or |f| no longer drops in float. Departs from sea.cc: a full step below
// 0.1 mm is taken without a residual after it (Newton's error after it,
// ~ k |st|^2, is below float's resolution of the label), so a guess from
// the last steps (verts.comp, a micrometre off) costs one residual, and
// no line search on float noise
vec2 seaLabel(int b, vec2 x, vec2 a) {
  if (ngerst == 0) return x;
  vec3 J;
  vec2 f = seaResidual(b, x, a, J);
  for (int it = 0; it < 40; it++) {
    float r2 = dot(f, f);
    if (r2 == 0.0) break;
    float det = J.x * J.z - J.y * J.y;
    vec2 st = vec2(J.z * f.x - J.y * f.y, J.x * f.y - J.y * f.x) / det;
    if (dot(st, st) < 1e-8) {
      a -= st;
      break;
    }
    vec2 an = a, fn = f;
    vec3 Jn = J;
    bool down = false;
    for (int h = 0; h < 24 && !down; h++) {
      an = a - st;
      fn = seaResidual(b, x, an, Jn);
      down = dot(fn, fn) < r2;
      st *= 0.5;
    }
    if (!down) break;  // no further progress in float
    a = an;
    f = fn;
    J = Jn;
    // a 0.1 mm step: Newton's next error is ~k (k Q A) |st|^2 / det, below
    // float's resolution of the label away from folding
    if (dot(st, st) < 0.25e-8) break;  // st was halved once past the step taken
  }
  return a;
}

// Wheeler stretch (as mjbuoy/sea/sea.cc): the profile height zs in [-h, 0] of a
// point z above the level under the surface eta
float seaStretch(float z, float eta) {
  if (depth <= 0.0) return min(z - eta, 0.0);
  if (depth + eta <= 0.0) return -depth;
  return clamp((z - eta) * depth / (depth + eta), -depth, 0.0);
}

// the linear profiles, velocity and dynamic pressure below the surface:
// per component integrated over the wet pieces in closed form (waveint.glsl,
// tris.comp), from e^L at the wet vertices (verts.comp)
