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

// residual f = a - Q A D sin(theta(a)) - x and the upper triangle of its
// Jacobian J = I - sum Q A k cos(theta) D D^T (j00, j01, j11)
vec2 seaResidual(int b, vec2 x, vec2 a, out vec3 J) {
  vec2 f = a - x;
  J = vec3(1.0, 0.0, 1.0);
  for (int i = 0; i < nwave; i++) {
    float th = theta(b, i, a), s = sin(th), c = cos(th);
    float qa = wave[i].steep * wave[i].amp, jc = qa * wave[i].k * c;
    f -= qa * s * vec2(wave[i].dx, wave[i].dy);
    J -= jc * vec3(wave[i].dx * wave[i].dx, wave[i].dx * wave[i].dy, wave[i].dy * wave[i].dy);
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
  if (nwave == 0) return a;
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
