// sea.glsl: Gerstner and Airy surface in each body's frame (same maths as
// mjbuoy/sea.cc, in positions relative to the body's COM; the per-body
// phases come from the CPU in double). Needs shared.h and buoy.h first.

// B_WAVE and B_PHASE through buffer textures: llvmpipe gathers a texel in
// straight SIMD code, but loads a storage buffer at a loop-varying index
// lane by lane
uniform samplerBuffer tWave;   // B_WAVE as RGBA32F, three texels per component
uniform samplerBuffer tPhase;  // B_PHASE as R32F

// component i, but its steepness (0: only the label solve reads it, a
// texel more to gather)
GWave waveAt(int i) {
  vec4 u = texelFetch(tWave, 3 * i), v = texelFetch(tWave, 3 * i + 1);
  return GWave(u.x, u.y, u.z, u.w, v.x, v.y, v.z, v.w, 0.0, 0.0, 0.0, 0.0);
}
float waveSteep(int i) { return texelFetch(tWave, 3 * i + 2).x; }

uniform int nwave;
uniform int ngerst;      // Gerstner components among them (steep > 0 ones matter)
uniform float depth;     // water depth [m], 0 = deep
uniform vec2 current;    // [m/s]

float phaseAt(int b, int i) { return texelFetch(tPhase, b * nwave + i).x; }

// B_EXP (pipeline.h): vertex v's texel holding component w's e^(i theta),
// two components a texel, w even in xy, odd in zw (half the stores:
// llvmpipe stores lane by lane)
int expTexel(int v, int w) { return v * ((nwave + 1) >> 1) + (w >> 1); }

float theta(GWave w, float ph, vec2 a) { return ph + w.k * (w.dx * a.x + w.dy * a.y); }

// the phase of component w (phase ph at the COM) at the point x whose
// Gerstner label is a: Gerstner components at the label, Airy ones (kind
// 1) at x
float thetaAt(GWave w, float ph, vec2 a, vec2 x) { return theta(w, ph, w.kind != 0.0 ? x : a); }

// residual f = a - Q A D sin(theta(a)) - x and the upper triangle of its
// Jacobian J = I - sum Q A k cos(theta) D D^T (j00, j01, j11); Airy
// components have steep 0 here (gl.cc) and drop out
vec2 seaResidual(int b, vec2 x, vec2 a, out vec3 J) {
  vec2 f = a - x;
  J = vec3(1.0, 0.0, 1.0);
  for (int i = 0; i < nwave; i++) {
    GWave w = waveAt(i);
    float qa = waveSteep(i) * w.amp;
    if (qa == 0.0) continue;
    float th = theta(w, phaseAt(b, i), a), s = sin(th), c = cos(th), jc = qa * w.k * c;
    f -= qa * s * vec2(w.dx, w.dy);
    J -= jc * vec3(w.dx * w.dx, w.dx * w.dy, w.dy * w.dy);
  }
  return f;
}

// particle label (rel. COM) whose displaced position is x, Newton from a,
// safeguarded as mjbuoy/sea.cc label(): J stays positive definite below
// folding, so the Newton step is a descent direction of |f|^2 and is
// halved until |f| drops (near folding, sum Q k A -> 1, J is nearly
// singular and full steps overshoot); stops when the step is below 0.1 mm
// or |f| no longer drops in float
vec2 seaLabel(int b, vec2 x, vec2 a) {
  if (ngerst == 0) return x;
  vec3 J;
  vec2 f = seaResidual(b, x, a, J);
  for (int it = 0; it < 40; it++) {
    float r2 = dot(f, f);
    if (r2 == 0.0) break;
    float det = J.x * J.z - J.y * J.y;
    vec2 st = vec2(J.z * f.x - J.y * f.y, J.x * f.y - J.y * f.x) / det;
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

// Wheeler stretch (as mjbuoy/sea.cc): the profile height zs in [-h, 0] of a
// point z above the level under the surface eta
float seaStretch(float z, float eta) {
  if (depth <= 0.0) return min(z - eta, 0.0);
  if (depth + eta <= 0.0) return -depth;
  return clamp((z - eta) * depth / (depth + eta), -depth, 0.0);
}

// the linear profiles, velocity and dynamic pressure below the surface:
// per component integrated over the wet pieces in closed form (waveint.glsl,
// tris.comp), from e^L at the wet vertices (verts.comp)
