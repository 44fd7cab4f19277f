// Anchor-sensitive planes: slivers along a line through sample points on which the plane is
// constant at z = 0.5 (two vertices on the line, far apart), the third vertex a sub-pixel step
// off it at another depth, so the plane is as steep as the format allows across the line. At
// the samples on the line the exact depth is 0.5, whose 0.5 * 16777215 = 8388607.5 is a tie,
// and z0 + tx + ty cancels terms up to 2^25: the sign of the rounding error decides between
// 8388607 and 8388608. The contract (anchored at the first submitted vertex, separately rounded
// double) and its target variants (another anchor, sorting of the vertices, fused
// multiply-adds, evaluation from the origin or from pixel (0, 0), float arithmetic) err
// differently, and about half of the samples come out other. Each vector is kept only when its
// target variant's bits differ. The first vertex is always one on the line at 0.5, so one depth
// difference is zero and z0 + tx is exact: the order of the sum and a single fused numerator
// do not show here (the depth_arithmetic family aims at those).
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "family.hpp"

namespace recode::kit::detail {

using namespace recode::raster;

namespace {

void addIsoSliver(Rng& rng, int w, int h, cmd::Draw& d) {
  // A line through the sample of pixel (i, j) in direction (p, q) pixels, p and q coprime and
  // not both powers of two: scaling by a power of two would round tx and ty alike and cancel.
  static const std::vector<std::pair<long long, long long>> kDirections = {
      {1, 3}, {3, 1}, {2, 3}, {3, 2}, {1, -3}, {-3, 1}, {2, -3}, {3, -2}, {3, 5}, {5, -3}};
  const auto [p, q] = rng.pick(kDirections);
  const long long sx = centre(rng.uniform(0, w - 1)), sy = centre(rng.uniform(0, h - 1));
  const long long step = 256 * std::max(p < 0 ? -p : p, q < 0 ? -q : q);
  // As far as the fixed-point box allows, so that tx and ty reach about 2^25.
  const long long room = (kLimit - 256LL * std::max(w, h)) / step;
  const long long t0 = room - rng.uniform(0, room / 16), t1 = room - rng.uniform(0, room / 16);
  // z = 0.5 on the line puts every sample on it exactly on a quantisation tie (0.5 * 16777215
  // = 8388607.5): the sign of each evaluation's rounding error decides the bits.
  const float z = 0.5f;
  const auto base = static_cast<std::uint32_t>(d.vertices.size());
  d.vertices.push_back(fixedVertex(sx - t0 * 256 * p, sy - t0 * 256 * q, z));
  d.vertices.push_back(fixedVertex(sx + t1 * 256 * p, sy + t1 * 256 * q, z));
  // The third vertex near the sample, off the line by (ox, oy) with p oy - q ox = +-1 (the
  // least twice-area a step off the line can give) and a depth below 2^-24 with a full
  // mantissa: the steepest plane, and 0.5 - z2 with about 50 significant bits, so that the
  // plane's products do not fit in a double and every evaluation order rounds its own way.
  std::vector<std::pair<long long, long long>> offsets;
  for (long long ox = -5; ox <= 5; ++ox)
    for (long long oy = -5; oy <= 5; ++oy)
      if (p * oy - q * ox == 1 || p * oy - q * ox == -1)
        offsets.emplace_back(ox, oy);
  const auto [ox, oy] = rng.pick(offsets);
  const long long t2 = rng.uniform(-4, 4);
  const float mantissa = static_cast<float>(rng.uniform(1 << 23, (1 << 24) - 1)) / 16777216.0f;
  const float far = std::ldexp(mantissa, -static_cast<int>(rng.uniform(24, 40)));
  d.vertices.push_back(fixedVertex(sx + t2 * 256 * p + ox, sy + t2 * 256 * q + oy, far));
  if (rng.chance(50))
    d.indices.insert(d.indices.end(), {base, base + 1, base + 2});
  else
    d.indices.insert(d.indices.end(), {base, base + 2, base + 1});
}

}  // namespace

Candidate anchorPlanes(Rng& rng, int index) {
  static const Variant kTargets[] = {
      Variant::AnchorRotated,   Variant::AnchorSorted,           Variant::FmaPlane,
      Variant::PlaneFromOrigin, Variant::IncrementalFromPixel00, Variant::FloatPlane};
  const Variant target = kTargets[index % 6];
  Candidate c;
  c.width = 16;
  c.height = 16;
  c.targets = {target};
  c.description =
      "Slivers along lines through sample points on which the plane is 0.5 (a "
      "quantisation tie), their first vertex up to 32768 pixels away, the third a "
      "sub-pixel step off the line at another depth: z0 + tx + ty cancels terms up "
      "to 2^25 and its rounding decides 8388607 or 8388608. Kept because " +
      std::string(variantName(target)) + " rounds them to other depth bits.";
  c.commands = countFacingsKeepDepth();
  cmd::Draw d;
  const long long n = rng.uniform(2, 4);
  for (long long k = 0; k < n; ++k)
    addIsoSliver(rng, c.width, c.height, d);
  c.commands.push_back(std::move(d));
  return c;
}

}  // namespace recode::kit::detail
