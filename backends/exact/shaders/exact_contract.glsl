// The rasterization contract (docs/rasterization.md, sections 3 to 5) in GLSL, shared by every
// exact GPU device: the GL device prepends "#version 450 core" and its extensions, a Vulkan
// device its own header. Nothing here depends on the graphics API.
//
// Requires double precision (GL_ARB_gpu_shader_fp64, core in GLSL 4.00) and 64-bit integers
// (GL_ARB_gpu_shader_int64). Every floating-point result is declared `precise`, so that no
// compiler fuses a multiply and an add or reorders a sum: the contract rounds each operation
// separately, in the order written.

const double kDepthMax = 16777215.0;  // 2^24 - 1: the largest 24-bit depth

// The exact value of a - q b, for a q within an ulp or two of a / b (then it is representable).
// GLSL does not promise that fma() is fused (Mesa lowers it to a multiply and an add on drivers
// without a fused double operation), so the product's rounding error comes from Dekker's exact
// product instead: each factor split into two halves of at most 26 bits (Veltkamp), whose
// partial products are exact.
void splitHalves(double x, out double high, out double low) {
  precise double scaled = 134217729.0 * x;  // 2^27 + 1
  precise double big = scaled - x;
  precise double h = scaled - big;
  precise double l = x - h;
  high = h;
  low = l;
}

double exactRemainder(double a, double b, double q) {
  precise double product = q * b;
  double qh, ql, bh, bl;
  splitHalves(q, qh, ql);
  splitHalves(b, bh, bl);
  precise double error = ((qh * bh - product) + qh * bl + ql * bh) + ql * bl;  // q b - product
  precise double r = (a - product) - error;
  return r;
}

// a / b rounded to nearest even, whatever the accuracy of the driver's double division (GLSL
// promises none). The hardware quotient is corrected by one Newton step, then the candidate
// and its two neighbours are compared by their exact remainders a - c b. A quotient of two
// doubles is never exactly halfway between two doubles, so the smallest remainder picks the
// correctly rounded one.
double divideRoundedToNearest(double a, double b) {
  if (a == 0.0)
    return 0.0;
  precise double q = a / b;
  precise double c = q + exactRemainder(a, b, q) / b;
  int64_t bits = doubleBitsToInt64(c);
  double larger = int64BitsToDouble(bits + 1l);   // one ulp further from zero
  double smaller = int64BitsToDouble(bits - 1l);  // one ulp nearer to zero
  double rc = abs(exactRemainder(a, b, c));
  double rl = abs(exactRemainder(a, b, larger));
  double rs = abs(exactRemainder(a, b, smaller));
  if (rl < rc)
    return larger;
  if (rs < rc)
    return smaller;
  return c;
}

// Twice the signed area of the snapped triangle (v0, v1, v2): positive when counter-clockwise
// (front-facing), zero when it draws nothing. |result| < 2^49.
int64_t twiceArea(i64vec2 v0, i64vec2 v1, i64vec2 v2) {
  return (v1.x - v0.x) * (v2.y - v0.y) - (v2.x - v0.x) * (v1.y - v0.y);
}

// The depth plane through the snapped vertices in submitted order, anchored at v0: its slopes
// per sub-pixel unit, in the contract's operation order (section 5).
dvec2 depthSlopes(i64vec2 v0, i64vec2 v1, i64vec2 v2, vec3 z) {
  precise double z0 = double(z.x);
  precise double dz1 = double(z.y) - z0;
  precise double dz2 = double(z.z) - z0;
  double e1x = double(v1.x - v0.x);
  double e1y = double(v1.y - v0.y);
  double e2x = double(v2.x - v0.x);
  double e2y = double(v2.y - v0.y);
  double a2 = double(twiceArea(v0, v1, v2));
  precise double left = dz1 * e2y;
  precise double right = dz2 * e1y;
  precise double dzdx = divideRoundedToNearest(left - right, a2);
  precise double left2 = dz2 * e1x;
  precise double right2 = dz1 * e2x;
  precise double dzdy = divideRoundedToNearest(left2 - right2, a2);
  return dvec2(dzdx, dzdy);
}

// The plane at a centre: (z0 + tx) + ty, each product and sum rounded on its own.
double depthAt(double z0, dvec2 slopes, i64vec2 v0, i64vec2 centre) {
  precise double tx = slopes.x * double(centre.x - v0.x);
  precise double ty = slopes.y * double(centre.y - v0.y);
  precise double z = (z0 + tx) + ty;
  return z;
}

// v rounded to the nearest integer, ties to even (nearbyint in the default rounding mode), for
// |v| < 2^62, by a truncating conversion and an exact difference rather than roundEven(): on
// lavapipe (Mesa 22.3) roundEven of a double rounded 8388607.5 down to 8388607 in compute
// shaders, which the conformance kit's depth ties catch.
int64_t roundToNearestEven(double v) {
  int64_t t = int64_t(v);  // towards zero
  precise double rest = v - double(t);  // exact: |rest| < 1
  if (rest > 0.5 || (rest == 0.5 && (t & 1l) != 0l))
    t += 1l;
  else if (rest < -0.5 || (rest == -0.5 && (t & 1l) != 0l))
    t -= 1l;
  return t;
}

// Clamp and quantise to the 24-bit integer q: round half to even of z (2^24 - 1).
uint quantizeDepth(double z) {
  if (!(z > 0.0))
    return 0u;
  if (z >= 1.0)
    return 16777215u;
  precise double scaled = z * kDepthMax;
  return uint(roundToNearestEven(scaled));
}

// Does directed edge a -> b of a counter-clockwise triangle cover the centre? E > 0, or E = 0
// on an inclusive (left or bottom) edge: the fill rule of section 4.
bool edgeCovers(i64vec2 a, i64vec2 b, i64vec2 centre) {
  int64_t dx = b.x - a.x;
  int64_t dy = b.y - a.y;
  int64_t e = dx * (centre.y - a.y) - dy * (centre.x - a.x);
  bool inclusive = dy < 0l || (dy == 0l && dx > 0l);
  return e > 0l || (e == 0l && inclusive);
}

// Coverage of the triangle (v0, v1, v2) in submitted order, of the facing given: the edges run
// counter-clockwise, (v0, v1, v2) when front-facing and (v0, v2, v1) when back-facing.
bool triangleCovers(i64vec2 v0, i64vec2 v1, i64vec2 v2, bool frontFacing, i64vec2 centre) {
  i64vec2 p1 = frontFacing ? v1 : v2;
  i64vec2 p2 = frontFacing ? v2 : v1;
  return edgeCovers(v0, p1, centre) && edgeCovers(p1, p2, centre) && edgeCovers(p2, v0, centre);
}

// The fixed-point position of the centre of the pixel whose window coordinates are fragCoord
// (i + 0.5, j + 0.5): (256 i + 128, 256 j + 128).
i64vec2 pixelCentreFixed(vec2 fragCoord) {
  i64vec2 pixel = i64vec2(ivec2(floor(fragCoord)));
  return pixel * 256l + 128l;
}
