// sea.glsl: Gerstner surface in each body's frame (same maths as
// mjbuoy/sea.cc, in positions relative to the body's COM; the per-body
// phases come from the CPU in double). Needs shared.h and buoy.h first.

layout(std430, binding = B_PHASE) readonly buffer Phases { float phase[]; };
layout(std430, binding = B_WAVE) readonly buffer Waves { GWave wave[]; };

uniform int nwave;
uniform float depth;     // water depth [m], 0 = deep
uniform vec2 current;    // [m/s]

float theta(int b, int i, vec2 a) {
  return phase[b * nwave + i] + wave[i].k * (wave[i].dx * a.x + wave[i].dy * a.y);
}

// particle label (rel. COM) whose displaced position is x, Newton from a
vec2 seaLabel(int b, vec2 x, vec2 a) {
  for (int it = 0; it < 16 && nwave > 0; it++) {
    vec2 f = a - x;
    float j00 = 1.0, j01 = 0.0, j11 = 1.0;
    for (int i = 0; i < nwave; i++) {
      float th = theta(b, i, a), s = sin(th), c = cos(th);
      float qa = wave[i].steep * wave[i].amp, jc = qa * wave[i].k * c;
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

// surface height of particle a relative to the still level [m]
float seaEta(int b, vec2 a) {
  float z = 0.0;
  for (int i = 0; i < nwave; i++) z += wave[i].amp * cos(theta(b, i, a));
  return z;
}

// water velocity at depth zb <= 0 below particle a [m/s]
vec3 seaVelocity(int b, vec2 a, float zb) {
  vec3 v = vec3(current, 0.0);
  if (depth > 0.0) zb = max(zb, -depth);
  for (int i = 0; i < nwave; i++) {
    float th = theta(b, i, a), w = wave[i].omega;
    float uh = wave[i].steep * wave[i].amp * w * cos(th);
    float uz = wave[i].amp * w * sin(th);
    float fh, fz;
    if (depth > 0.0) {
      float kd = wave[i].k * depth, kz = wave[i].k * (zb + depth);
      if (kd < 20.0) {
        fh = cosh(kz) / cosh(kd);
        fz = sinh(kz) / sinh(kd);
      } else {
        // cosh, sinh overflow in float past 89 (inf / inf); as mjbuoy/sea.cc
        float e = exp(kz - kd), z2 = exp(-2.0 * kz);
        fh = e * (1.0 + z2);
        fz = e * (1.0 - z2);
      }
    } else {
      fh = fz = exp(wave[i].k * zb);
    }
    v += vec3(uh * fh * wave[i].dx, uh * fh * wave[i].dy, uz * fz);
  }
  return v;
}
