// Planes sloped along both axes that land exactly on a quantisation tie at every sample. With
// L = 2^24 - 1 and a point P whose coordinates are multiples of 128 (as every sample's are), the
// plane
//   z(Q) = 0.5 + (A du + B dv) / (128 L),   (du, dv) = Q - P along the (u, v) axes,
// has z L = 8388607.5 + (A du + B dv) / 128 at a sample: a half-integer, so the exact depth is a
// tie k + 0.5 everywhere, with k even or odd. A vertex on the line A du + B dv = c L has the
// float depth 0.5 + c / 128, so three such vertices (c of both signs, each on its own line) give
// a triangle through that plane: with |A| up to 128 and B = +-1 both slopes are non-zero, tx
// reaches about 0.5 and ty up to 2^-9 (different binades, so the order of the sum matters), and
// no depth difference is zero. The contract's separately rounded double arithmetic lands on the
// tie or an ulp off it; another order of the evaluation, division of the slopes, anchor or
// precision lands elsewhere at some samples, and every other rounding of a tie shows directly.
// (The depths have few bits, so the slopes' products are exact here: a fused numerator is left
// to the steep slivers.)
#include <cstdlib>

#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

constexpr long long kL = (1LL << 24) - 1;

struct Offset {
  long long du, dv;
  int c;  // A du + B dv = c L
};

// A point of the line A du + B dv = c L (B = +-1) whose dv is at most `near` and within |A| of it.
Offset onLine(long long A, long long B, int c, long long near) {
  // B dv = c L (mod |A|) fixes dv's residue; B is its own inverse.
  const long long m = std::llabs(A);
  const long long residue = ((B * c * kL) % m + m) % m;
  const long long dv = near - ((near - residue) % m + m) % m;
  return {(c * kL - B * dv) / A, dv, c};
}

}  // namespace

cmd::Draw slopedTiePlane(Rng& rng, int width, int height) {
  const long long A = rng.uniform(6, 128) * (rng.chance(50) ? 1 : -1);
  const long long B = rng.chance(50) ? 1 : -1;
  const bool uIsY = rng.chance(50);
  const long long px = 128 * rng.uniform(0, 2 * width), py = 128 * rng.uniform(0, 2 * height);
  // |c| L / |A| stays below 2^23 minus the frame: every vertex inside the fixed-point box.
  const int cMax = static_cast<int>(std::llabs(A) / 2 - 1);
  const int c0 = -static_cast<int>(rng.uniform(1, cMax));
  int c1 = static_cast<int>(rng.uniform(1, cMax)), c2 = c1;
  while (c2 == c1)
    c2 = static_cast<int>(rng.uniform(1, cMax));
  // One vertex on a line at negative c near the frame's height, two on lines at positive c far
  // above and below it: the frame lies inside the triangle.
  const Offset v[3] = {onLine(A, B, c0, rng.uniform(-4096, 4096)),
                       onLine(A, B, c1, rng.uniform(1LL << 21, 1LL << 22)),
                       onLine(A, B, c2, -rng.uniform(1LL << 21, 1LL << 22))};
  cmd::Draw d;
  for (const Offset& o : v) {
    const long long X = px + (uIsY ? o.dv : o.du), Y = py + (uIsY ? o.du : o.dv);
    d.vertices.push_back(fixedVertex(X, Y, 0.5f + static_cast<float>(o.c) / 128.0f));
  }
  // Submitted from any vertex, in either winding: the plane and its ties stay the same.
  const auto first = static_cast<std::uint32_t>(rng.uniform(0, 2));
  const bool flip = rng.chance(50);
  for (std::uint32_t k = 0; k < 3; ++k)
    d.indices.push_back((first + (flip ? 3 - k : k)) % 3);
  return d;
}

}  // namespace recode::kit::detail
