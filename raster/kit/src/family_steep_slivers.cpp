// Steep slivers for the depth-arithmetic family: two vertices on a line through sample points of
// the frame, on either side of it, and a third a sub-pixel step off the line, so that the plane
// changes by up to a whole depth range within 1/256 pixel. The line's depth is 0.5 (every sample
// on it an exact quantisation tie), a float within 2^-12 of a depth step of a tie (the rounding
// errors of a steep plane are far larger, so their sign decides as at a tie), or two random
// depths. The two vertices on the line lie up to 32768 pixels away (large coordinate
// differences) or a few pixels (a near-degenerate area of a few fixed-point units), and the
// third sits beside the samples or up to 32768 pixels beyond one of them. Depths carry full
// mantissas in any binade, so that the depth differences need more bits than a double holds and
// no product of the slopes is exact; the triangle is submitted from any vertex in either
// winding.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>

#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

// A depth with a full 24-bit mantissa in a binade from 2^-1 down to 2^-60: its low bits lie far
// below the ulp of a large tx, so that z0 + tx rounds. Never subnormal, even in float.
float fineDepth(Rng& rng, int lowestExponent) {
  const float mantissa = static_cast<float>(rng.uniform(1 << 23, (1 << 24) - 1)) / 16777216.0f;
  return std::ldexp(mantissa, -static_cast<int>(rng.uniform(0, lowestExponent)));
}

// The float nearest to a quantisation tie (k + 0.5) / 16777215 with k below 4096: a float that
// small is within 2^-12 of a depth step of the tie.
float nearTieDepth(Rng& rng) {
  const double k = static_cast<double>(rng.uniform(1, 4095));
  return static_cast<float>((k + 0.5) / 16777215.0);
}

}  // namespace

void addSteepSliver(Rng& rng, int w, int h, cmd::Draw& d) {
  long long p = 0, q = 0;
  while (std::gcd(p, q) != 1) {
    p = rng.uniform(-7, 7);
    q = rng.uniform(-7, 7);
  }
  const long long sx = centre(rng.uniform(0, w - 1)), sy = centre(rng.uniform(0, h - 1));
  const long long step = 256 * std::max(std::llabs(p), std::llabs(q));
  // The frame and the third vertex's offset (at most 56 units) stay inside the fixed-point box.
  const long long room = (kLimit - 256LL * std::max(w, h) - 64) / step;
  // A and B far (up to 32768 pixels) or near (a few pixels: an area of a few units); C beside
  // the samples, or far beyond A or B, where its two edges point almost the same way and the
  // products of the slopes' numerators cancel to a few bits.
  const long long reach = rng.chance(50) ? room : std::min(room, rng.uniform(1, 64));
  const long long t0 = rng.uniform(1, reach), t1 = rng.uniform(1, reach);
  long long t2 = rng.uniform(-4, 4);
  if (rng.chance(50)) {
    t2 = room - rng.uniform(0, room / 16);
    t2 = rng.chance(50) ? std::max(t2, t1) : -std::max(t2, t0);
  }
  // (ox, oy) with p oy - q ox = thickness: Bezout's coefficients of p and q, scaled.
  long long ox = 0, oy = 0;
  for (long long a = -7; a <= 7; ++a)
    for (long long b = -7; b <= 7; ++b)
      if (p * b - q * a == 1)
        ox = a, oy = b;
  // The third vertex on the side that makes the line an inclusive edge (section 4: with C to the
  // left of A -> B the edge runs A -> B, else B -> A), so that the samples on it are drawn.
  const bool leftOfLine = q < 0 || (q == 0 && p > 0);
  const long long thickness = rng.uniform(1, 8) * (leftOfLine ? 1 : -1);
  ox *= thickness;
  oy *= thickness;
  float za = 0.5f, zb = 0.5f;
  switch (rng.uniform(0, 2)) {
    case 0:
      break;  // an exact tie at every sample on the line
    case 1:
      za = zb = nearTieDepth(rng);
      break;
    default:
      za = fineDepth(rng, 40);
      zb = fineDepth(rng, 40);
      break;
  }
  const float zc = rng.chance(50) ? fineDepth(rng, 60) : fineDepth(rng, 24);
  const WindowVertex v[3] = {fixedVertex(sx - t0 * 256 * p, sy - t0 * 256 * q, za),
                             fixedVertex(sx + t1 * 256 * p, sy + t1 * 256 * q, zb),
                             fixedVertex(sx + t2 * 256 * p + ox, sy + t2 * 256 * q + oy, zc)};
  const auto base = static_cast<std::uint32_t>(d.vertices.size());
  d.vertices.insert(d.vertices.end(), v, v + 3);
  // From the third vertex half the time: z0 then has low bits far below the ulp of tx, both
  // depth differences are non-zero, and beyond a far vertex both edges point the same way.
  const auto first = static_cast<std::uint32_t>(rng.chance(50) ? 2 : rng.uniform(0, 1));
  const bool flip = rng.chance(50);
  for (std::uint32_t k = 0; k < 3; ++k)
    d.indices.push_back(base + (first + (flip ? 3 - k : k)) % 3);
}

}  // namespace recode::kit::detail
