// Planes that land exactly on the quantisation's ties. With v0 = (U0, V0, z0) at the fixed-point
// limit U0 = -+2^23, v1 = (U0 +- L, V0, z1) with L = 2^24 - 1, and v2 = (U0, V0 +- 2^23, z0), the
// plane varies along the U axis only (dz/dV = 0 exactly) and at the sample U = 256 i + 128 the
// exact value of z * 16777215 is z0 * L + (z1 - z0) * dU with dU = |U - U0| = 2^7 * odd:
//   z0 = 0,   z1 = m / 256, m odd:               m * odd / 2, a half-integer;
//   z0 = 0.5, z1 = m / 256, m - 128 = 2 mod 4:   8388607.5 + odd, a half-integer with k even.
// The contract's double arithmetic reaches the exact half-integer at many samples (its
// roundings cancel), and there rounds half to even. Another anchor, fused evaluation or
// precision misses the tie by an ulp up or down and rounds the other way at about half of them,
// which is what makes these planes catch anchor and arithmetic variants. Not every reading:
// with ty exactly 0 the order of the sum does not matter, and the depths' few bits make the
// slopes' products exact (slopedTiePlane and the steep slivers of depth_arithmetic cover those).
#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

cmd::Draw tiePlane(Rng& rng, int width, int height, bool alongY, bool halfAnchor) {
  const long long su = rng.chance(50) ? 1 : -1, sv = rng.chance(50) ? 1 : -1;
  const long long sizeV = alongY ? width : height;
  const long long u0 = -su * kLimit, u1 = u0 + su * ((1LL << 24) - 1);
  // V0 outside the frame on the side away from v2, so that the triangle covers the frame.
  const long long v0 = sv > 0 ? -256 * rng.uniform(1, 64) - rng.uniform(0, 255)
                              : 256 * (sizeV + rng.uniform(1, 64)) + rng.uniform(0, 255);
  const long long v2 = v0 + sv * kLimit;
  float z0 = 0.0f, z1 = 0.0f;
  if (halfAnchor) {
    z0 = 0.5f;
    z1 = static_cast<float>(4 * rng.uniform(0, 63) + 2) / 256.0f;  // m = 2 mod 4
  } else {
    z1 = static_cast<float>(2 * rng.uniform(0, 127) + 1) / 256.0f;  // m odd
  }
  const auto vertex = [alongY](long long u, long long v, float z) {
    return alongY ? fixedVertex(v, u, z) : fixedVertex(u, v, z);
  };
  cmd::Draw d;
  d.vertices = {vertex(u0, v0, z0), vertex(u1, v0, z1), vertex(u0, v2, z0)};
  d.indices = {0, 1, 2};
  if (rng.chance(50))
    d.indices = {0, 2, 1};  // the other winding: the same plane, anchored at v0 still
  return d;
}

}  // namespace recode::kit::detail
