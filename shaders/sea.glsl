// sea.glsl: Gerstner and Airy surface and linear kinematics in each body's frame (same maths as
// mjbuoy/sea.cc, in positions relative to the body's COM; the per-body
// phases come from the CPU in double). Needs shared.h and buoy.h first.

layout(std430, binding = B_PHASE) readonly buffer Phases { float phase[]; };
layout(std430, binding = B_WAVE) readonly buffer Waves { GWave wave[]; };

uniform int nwave;
uniform int ngerst;      // Gerstner components among them (steep > 0 ones matter)
uniform float depth;     // water depth [m], 0 = deep
uniform vec2 current;    // [m/s]

float theta(int b, int i, vec2 a) {
  return phase[b * nwave + i] + wave[i].k * (wave[i].dx * a.x + wave[i].dy * a.y);
}

// the phase of component i at the point x whose Gerstner label is a:
// Gerstner components at the label, Airy ones (kind 1) at x
float thetaAt(int b, int i, vec2 a, vec2 x) {
  return theta(b, i, wave[i].kind != 0.0 ? x : a);
}

// particle label (rel. COM) whose displaced position is x, Newton from a;
// Airy components have steep 0 here (gl.cc) and drop out
vec2 seaLabel(int b, vec2 x, vec2 a) {
  if (ngerst == 0) return x;
  for (int it = 0; it < 16; it++) {
    vec2 f = a - x;
    float j00 = 1.0, j01 = 0.0, j11 = 1.0;
    for (int i = 0; i < nwave; i++) {
      float qa = wave[i].steep * wave[i].amp;
      if (qa == 0.0) continue;
      float th = theta(b, i, a), s = sin(th), c = cos(th);
      float jc = qa * wave[i].k * c;
      f -= qa * s * vec2(wave[i].dx, wave[i].dy);
      j00 -= jc * wave[i].dx * wave[i].dx;
      j01 -= jc * wave[i].dx * wave[i].dy;
      j11 -= jc * wave[i].dy * wave[i].dy;
    }
    float det = j00 * j11 - j01 * j01;
    vec2 st = vec2(j11 * f.x - j01 * f.y, j00 * f.y - j01 * f.x) / det;
    a -= st;
    // a 0.1 mm step: Newton's next error is ~k (k Q A) |st|^2 < 1e-8 m, below
    // float's resolution of the label; 1e-7 m would never be reached in float
    if (dot(st, st) < 1e-8) break;
  }
  return a;
}

// surface height relative to the still level [m] above x, whose label is a
float seaEta(int b, vec2 a, vec2 x) {
  float z = 0.0;
  for (int i = 0; i < nwave; i++) z += wave[i].amp * cos(thetaAt(b, i, a, x));
  return z;
}

// Wheeler stretch (as mjbuoy/sea.cc): the profile height zs in [-h, 0] of a
// point z above the level under the surface eta
float seaStretch(float z, float eta) {
  if (depth <= 0.0) return min(z - eta, 0.0);
  if (depth + eta <= 0.0) return -depth;
  return clamp((z - eta) * depth / (depth + eta), -depth, 0.0);
}

// 1 - e^(-2 x) for x >= 0 without cancellation (GLSL has no expm1)
float seaOm2(float x) {
  return x < 0.01 ? 2.0 * x * (1.0 - x * (1.0 - x * 2.0 / 3.0)) : 1.0 - exp(-2.0 * x);
}

// linear depth profiles (ch, sh, cc) = (cosh s / sinh D, sinh s / sinh D,
// cosh s / cosh D), s = k (zs + h), D = k h, as e^(k zs) times bounded
// factors so nothing overflows (float cosh overflows past 89); deep: e^(k zs)
vec3 seaProfile(int i, float zs) {
  float k = wave[i].k, e = exp(k * zs);
  if (depth <= 0.0) return vec3(e);
  float s = k * (zs + depth), D = k * depth, e2s = exp(-2.0 * s), sd = seaOm2(D);
  return vec3(e * (1.0 + e2s) / sd, e * seaOm2(s) / sd, e * (1.0 + e2s) / (1.0 + exp(-2.0 * D)));
}

// water velocity [m/s] at the point (x, z above the level), label a,
// under the surface eta: linear theory of every component
vec3 seaVelocity(int b, vec2 a, vec2 x, float z, float eta) {
  vec3 v = vec3(current, 0.0);
  float zs = seaStretch(z, eta);
  for (int i = 0; i < nwave; i++) {
    float th = thetaAt(b, i, a, x), ao = wave[i].amp * wave[i].omega;
    vec3 f = seaProfile(i, zs);
    float uh = ao * f.x * cos(th);
    v += vec3(uh * wave[i].dx, uh * wave[i].dy, ao * f.y * sin(th));
  }
  return v;
}

// dynamic pressure over rho g [m] at the same point
float seaDynamic(int b, vec2 a, vec2 x, float z, float eta) {
  float zs = seaStretch(z, eta), p = 0.0;
  for (int i = 0; i < nwave; i++) p += wave[i].amp * seaProfile(i, zs).z * cos(thetaAt(b, i, a, x));
  return p;
}
