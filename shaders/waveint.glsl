// waveint.glsl: exact integrals of e^L over a triangle on which L is linear
// (complex), by divided differences of exp at the corner values
// (Hermite-Genocchi, docs/physics.md "Linear wave kinematics and
// pressure"): integral(e^L dA) = 2 A exp[L0, L1, L2] and the barycentric
// moments integral(lambda_i e^L dA) = 2 A exp[Li, Li, Lj, Lk]. Complex
// numbers are vec2 (re, im).

// k h beyond which the finite-depth profile's second exponential,
// e^(-k (zs + 2 h)) <= e^(-k h) of the surface value, is below float's
// resolution and dropped (gl.cc gwave sets e2kh = 0)
const float WI_KHMAX = 17.0;

vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 cexp(vec2 z) { return exp(z.x) * seaCosSin(z.y); }  // (sea.glsl)

// nodes 0, x, y within r of each other (|x|, |y|, |y - x| <= r): s0 =
// exp[0,x,y], sa = exp[0,0,x,y], sb = exp[0,x,x,y], as the Taylor series
// exp[z_1..z_n] = sum_{m>=n-1} h_{m-n+1}(z) / m! (h: complete homogeneous
// symmetric polynomials; h_n(x,y) = x h_{n-1}(x,y) + y^n, h_n(x,x,y) =
// x h_{n-1}(x,x,y) + h_n(x,y)) to nt >= 4 terms, nt the same for every
// invocation (llvmpipe runs a loop with per-lane exits, or a nested loop,
// in the hot path several times slower than the terms it would save).
// Counts: a fast component's (gl.cc gwave: the first term left out,
// (nt + 1) r^nt / (nt + 2)!, below 2.5e-7 at the step's largest node gap
// r), or WI_TERMS for a split part (triPart) with r <= WI_TAYLOR: (WI_TERMS
// + 1) / (WI_TERMS + 2)! = 2.5e-7 of 1 at r = 1, 2e-6 of the sums (1/2,
// 1/6), far below the parity tolerance (1e-4)
const float WI_TAYLOR = 1.0;
const int WI_TERMS = 9;
// WI_NOMOM (the programs for Kerner's pressure, gl.cc kVNomom: the
// pressure's moments unused) sums s0 only, sa = sb = 0: the u chain is a
// third of each term

// term n >= 2 of the series from term n - 1's h_{n-1}(x,y) in g and
// h_{n-1}(x,x,y) in u, yn = y^(n-1): f2 = 1/(n+2)!, f3 = 1/(n+3)!
void ddTerm(vec2 x, vec2 y, float f2, float f3, inout vec2 yn, inout vec2 g, inout vec2 u,
            inout vec2 s0, inout vec2 sa, inout vec2 sb) {
  yn = cmul(yn, y);
  g = cmul(x, g) + yn;
  s0 += f2 * g;
#ifndef WI_NOMOM
  u = cmul(x, u) + g;
  sa += f3 * g;
  sb += f3 * u;
#endif
}

void ddSeries(vec2 x, vec2 y, int nt, out vec2 s0, out vec2 sa, out vec2 sb) {
  // term 0 and term 1, which needs no complex product (h_1(x,y) = x + y,
  // h_1(x,x,y) = 2x + y)
  vec2 yn = y, g = x + y, u = x + g;
  s0 = vec2(0.5, 0.0) + (1.0 / 6.0) * g;
  sa = sb = vec2(0.0);
#ifndef WI_NOMOM
  sa = vec2(1.0 / 6.0, 0.0) + (1.0 / 24.0) * g;
  sb = vec2(1.0 / 6.0, 0.0) + (1.0 / 24.0) * u;
#endif
  // term 2, always summed (nt >= 4), then terms 3, 4, ... two a pass
  // (half the loop's passes: llvmpipe updates and tests its lane mask
  // each pass); nt odd (gl.cc gwave; WI_TERMS), so the pairs end at nt -
  // 1 (an even nt: one term more)
  ddTerm(x, y, 1.0 / 24.0, 1.0 / 120.0, yn, g, u, s0, sa, sb);
  float f3 = 1.0 / 120.0;  // 1/(n+2)! at the pass's first term n
  int n = 3;
  do {  // nt >= 4; the test at the end: llvmpipe runs a loop's body once more, masked, after a break at the top
    float q = f3 / float((n + 3) * (n + 4));  // 1/(n+4)!: one division a pass
    ddTerm(x, y, f3, q * float(n + 4), yn, g, u, s0, sa, sb);
    ddTerm(x, y, q * float(n + 4), q, yn, g, u, s0, sa, sb);
    f3 = q;
  } while ((n += 2) < nt);
}

// e^(i p) for |p| <= WI_ROT by its Taylor series to p^15 (alternating: the
// error is below the first term left out, 2^16 / 16! = 3.1e-9)
const float WI_ROT = 2.0;
vec2 rotation(float p) {
  float q = p * p;
  float c = 1.0 + q * (-1.0 / 2.0 + q * (1.0 / 24.0 + q * (-1.0 / 720.0 + q * (1.0 / 40320.0 +
            q * (-1.0 / 3628800.0 + q * (1.0 / 479001600.0 + q * (-1.0 / 87178291200.0)))))));
  float s = p * (1.0 + q * (-1.0 / 6.0 + q * (1.0 / 120.0 + q * (-1.0 / 5040.0 + q * (1.0 /
            362880.0 + q * (-1.0 / 39916800.0 + q * (1.0 / 6227020800.0 + q * (-1.0 /
            1307674368000.0))))))));
  return vec2(c, s);
}

// parts of a piece: one whose node gap r (max of |x|, |y|, |y - x|)
// exceeds WI_TAYLOR is split into n^2 similar triangles of gap r / n
// (n <= 64), each summed by its series about its own corner 0; the
// series' terms then stay below e^WI_TAYLOR, so float round-off stays
// below 3e-7 of the largest |e^L| (pieces up to 64 units of r: some 10
// wavelengths). NaN: one part, and the NaN reaches the sums
int triParts(vec2 x, vec2 y) {
  float r = max(length(x), max(length(y), length(y - x)));
  float nr = ceil(r / WI_TAYLOR);
  return nr > 1.0 ? int(min(nr, 64.0)) : 1;
}

// adds the integrals of e^L over part k of n^2 of a triangle on which L is
// linear with corner values L0 + (0, x, y), e0 = e^L0, a2 twice its area:
// S += integral e^L dA, M1, M2 += integral lambda_1,2 e^L dA (the
// corner-0 moment is S - M1 - M2). Part k: cell (i, j) = (k / n, k % n) of
// the n x n grid of barycentrics (alpha, beta), its lower triangle if
// inside, else the upper triangle of the mirrored cell; part 0's corner 0
// is the piece's (cexp(0) = 1 exactly)
void triPart(vec2 x, vec2 y, vec2 e0, float a2, int n, int k, inout vec2 S, inout vec2 M1,
             inout vec2 M2) {
  int i = k / n, j = k - i * n;
  bool up = i + j <= n - 1;
  vec2 c = up ? vec2(i, j) : vec2(n - i, n - j);   // corner 0 in units 1/n
  float sg = up ? 1.0 : -1.0, fn = float(n);        // corners 1, 2 at c + sg (1,0), (0,1)
  vec2 xs = x / fn, ys = y / fn, s0, sa, sb;
  ddSeries(sg * xs, sg * ys, WI_TERMS, s0, sa, sb);
  vec2 e = cmul(e0, cexp(c.x * xs + c.y * ys));
  vec2 m0 = cmul(e, sa), m1 = cmul(e, sb), m2 = cmul(e, s0 - sa - sb);
  float w = a2 / (fn * fn);
  S += w * cmul(e, s0);
  // parent barycentrics alpha, beta of the part's three corners
  M1 += w / fn * (c.x * m0 + (c.x + sg) * m1 + c.x * m2);
  M2 += w / fn * (c.y * m0 + c.y * m1 + (c.y + sg) * m2);
}
