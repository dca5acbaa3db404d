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
vec2 cexp(vec2 z) { return exp(z.x) * vec2(cos(z.y), sin(z.y)); }

// nodes 0, x, y within WI_TAYLOR of each other (|x|, |y| <= WI_TAYLOR):
// s0 = exp[0,x,y], and with mom, sa = exp[0,0,x,y], sb = exp[0,x,x,y], as
// the Taylor series exp[z_1..z_n] = sum_{m>=n-1} h_{m-n+1}(z) / m! (h:
// complete homogeneous symmetric polynomials; h_n(x,y) = x h_{n-1}(x,y) +
// y^n, h_n(x,x,y) = x h_{n-1}(x,x,y) + h_n(x,y)); stops when the bound
// (n+1) r^n / (n+2)! of the next term (and of the moments') is below
// WI_TOL, r = max(|x|, |y|): 2e-6 of the sums (1/2, 1/6), far below the
// gl backend's parity tolerance (1e-4) and 9 terms at most (r = 1)
const float WI_TAYLOR = 1.0;
const float WI_TOL = 3e-7;
void ddTaylor(vec2 x, vec2 y, bool mom, out vec2 s0, out vec2 sa, out vec2 sb) {
  float r = max(length(x), length(y));
  vec2 g = vec2(1.0, 0.0), u = g, yn = g;
  float f2 = 0.5, f3 = 1.0 / 6.0, rn = 1.0;  // 1/(n+2)!, 1/(n+3)!, r^n
  s0 = f2 * g;
  sa = f3 * g;
  sb = f3 * u;
  for (int n = 1; n < 16; n++) {
    rn *= r;
    f2 = f3;
    f3 /= float(n + 3);
    if (rn * f2 * float(n + 1) < WI_TOL) break;
    yn = cmul(yn, y);
    g = cmul(x, g) + yn;
    s0 += f2 * g;
    u = cmul(x, u) + g;
    sa += f3 * g;
    sb += f3 * u;
  }
}

// adds the integrals over a triangle of e^L, L linear, corner values L0 +
// (0, x, y), e0 = e^L0, a2 twice its area: S += integral e^L dA,
// M1, M2 += integral lambda_1,2 e^L dA (with mom; the corner-0 moment is
// S - M1 - M2). Pieces with a node gap r above WI_TAYLOR are split into n^2
// similar triangles of gap r / n (n <= 64), each summed by its series about
// its corner 0; the series' terms then stay below e^WI_TAYLOR, so float
// round-off stays below 3e-7 of the largest |e^L| for any piece up to
// 64 WI_TAYLOR across (past it the parts' series, 16 terms, lose accuracy
// only beyond r = 256: a piece some 40 wavelengths long).
// The first part's corner 0 is the piece's: no transcendental unless split.
void triExp(vec2 x, vec2 y, vec2 e0, float a2, bool mom, inout vec2 S, inout vec2 M1,
            inout vec2 M2) {
  float r = max(length(x), max(length(y), length(y - x)));
  float nr = ceil(r / WI_TAYLOR);
  int n = nr > 1.0 ? int(min(nr, 64.0)) : 1;  // (NaN: 1, and the NaN reaches the sums)
  float fn = float(n), w = a2 / (fn * fn);
  vec2 xs = x / fn, ys = y / fn, s0, sa, sb;
  ddTaylor(xs, ys, mom, s0, sa, sb);
  // corner 0 at (alpha, beta) = (0, 0): moments of its corners 1 (1/n, 0), 2 (0, 1/n)
  S += w * cmul(e0, s0);
  M1 += w / fn * cmul(e0, sb);
  M2 += w / fn * cmul(e0, s0 - sa - sb);
  for (int k = 1; k < n * n; k++) {
    // cell (i, j) of the n x n grid of (alpha, beta): its lower triangle
    // if inside, else the upper triangle of the mirrored cell
    int i = k / n, j = k - i * n;
    bool up = i + j <= n - 1;
    vec2 c = up ? vec2(i, j) : vec2(n - i, n - j);   // corner 0 in units 1/n
    float sg = up ? 1.0 : -1.0;                        // corners 1, 2 at c + sg (1,0), (0,1)
    ddTaylor(sg * xs, sg * ys, mom, s0, sa, sb);
    vec2 e = cmul(e0, cexp(c.x * xs + c.y * ys));
    vec2 m0 = cmul(e, sa), m1 = cmul(e, sb), m2 = cmul(e, s0 - sa - sb);
    S += w * cmul(e, s0);
    // parent barycentrics alpha, beta of the three corners
    M1 += w / fn * (c.x * m0 + (c.x + sg) * m1 + c.x * m2);
    M2 += w / fn * (c.y * m0 + c.y * m1 + (c.y + sg) * m2);
  }
}
