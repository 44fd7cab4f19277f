#pragma once
// Triangle setup's steps (triangle_setup.hpp), inline for raster's own sources: the pipeline's
// loop sets each triangle up with them in place, so the snapped vertices stay in registers.
// Called through memory, setupTriangleInto read them back in 16-byte loads right after the
// loop's 8-byte stores, which the CPU cannot forward (about a sixth of its time). Private: the
// depth plane's arithmetic must be compiled with raster's -ffp-contract=off.

#include <algorithm>
#include <cstdint>

#include "recode/raster/fixed_point.hpp"
#include "recode/raster/invariants.hpp"
#include "recode/raster/triangle_setup.hpp"

namespace recode::raster::detail {

// Edge a->b of a counter-clockwise triangle: E = (xb - xa)(Y - ya) - (yb - ya)(X - xa),
// positive on the interior side. Exclusive edges get c - 1 so that "E >= 0" rejects ties.
inline EdgeFunction makeEdge(const FixedVertex& a, const FixedVertex& b) {
  const std::int64_t dx = b.x - a.x;
  const std::int64_t dy = b.y - a.y;
  EdgeFunction e;
  e.a = -dy;
  e.b = dx;
  // Without a branch: an edge's direction is as good as random from one triangle to the next,
  // and a mispredicted branch here cost about a tenth of a small triangle's setup.
  e.c = a.x * b.y - b.x * a.y - static_cast<std::int64_t>(!isInclusiveEdge(dx, dy));
  return e;
}

// Twice the signed area of the snapped triangle, exact: positive when counter-clockwise.
inline std::int64_t twiceArea(const FixedVertex& v0, const FixedVertex& v1, const FixedVertex& v2) {
  return (v1.x - v0.x) * (v2.y - v0.y) - (v2.x - v0.x) * (v1.y - v0.y);
}

// setupCoverage written into `t`; returns twiceArea, 0 for a zero-area triangle (then `t` is
// left unfinished). setupTriangle fills its own result with it in place: copying a returned
// TriangleCoverage into it read the callee's stores back in wider loads, which stalled the
// store forwarding.
[[gnu::always_inline]] inline std::int64_t coverageInto(const FixedVertex& v0,
                                                        const FixedVertex& v1,
                                                        const FixedVertex& v2,
                                                        TriangleCoverage& t) {
  // The device refuses vertices beyond kMaxWindowCoordinate, which keeps every product of the
  // edge functions below 2^49 (docs/rasterization.md, section 3).
  constexpr std::int64_t kMaxFixed = static_cast<std::int64_t>(kMaxWindowCoordinate) * kSubpixelOne;
  for (const FixedVertex* v : {&v0, &v1, &v2}) {
    RECODE_INVARIANT(
        v->x >= -kMaxFixed && v->x <= kMaxFixed && v->y >= -kMaxFixed && v->y <= kMaxFixed,
        "snapped vertices lie within the fixed-point range |X|, |Y| <= 2^23");
  }
  const std::int64_t area2 = twiceArea(v0, v1, v2);
  if (area2 == 0)
    return 0;

  t.frontFacing = area2 > 0;
  // Coverage uses the counter-clockwise order; the depth plane uses the submitted order.
  const FixedVertex& p1 = t.frontFacing ? v1 : v2;
  const FixedVertex& p2 = t.frontFacing ? v2 : v1;
  t.edges = {makeEdge(v0, p1), makeEdge(p1, p2), makeEdge(p2, v0)};

  const std::int64_t minX = std::min({v0.x, v1.x, v2.x}), maxX = std::max({v0.x, v1.x, v2.x});
  const std::int64_t minY = std::min({v0.y, v1.y, v2.y}), maxY = std::max({v0.y, v1.y, v2.y});
  // Pixel i is a candidate when its centre lies in [min, max].
  t.bounds.x0 = static_cast<int>(firstPixelCentreFrom(minX));
  t.bounds.x1 = static_cast<int>(lastPixelCentreTo(maxX) + 1);
  t.bounds.y0 = static_cast<int>(firstPixelCentreFrom(minY));
  t.bounds.y1 = static_cast<int>(lastPixelCentreTo(maxY) + 1);
  return area2;
}

// setupTriangleInto's work (triangle_setup.hpp).
[[gnu::always_inline]] inline bool setupInto(const FixedVertex& v0, const FixedVertex& v1,
                                             const FixedVertex& v2, TriangleSetup& t) {
  const std::int64_t area2 = coverageInto(v0, v1, v2, t);
  if (area2 == 0)
    return false;

  // Depth plane through the three snapped vertices, in the submitted order:
  // dz/dX = (dz1 e2y - dz2 e1y) / area2, dz/dY = (dz2 e1x - dz1 e2x) / area2.
  const std::int64_t e1x = v1.x - v0.x, e1y = v1.y - v0.y;
  const std::int64_t e2x = v2.x - v0.x, e2y = v2.y - v0.y;
  const double z0 = static_cast<double>(v0.z);
  const double dz1 = static_cast<double>(v1.z) - z0;
  const double dz2 = static_cast<double>(v2.z) - z0;
  const double a2 = static_cast<double>(area2);
  t.depth.x0 = v0.x;
  t.depth.y0 = v0.y;
  t.depth.z0 = z0;
  // Both quotients in one packed division: each lane is the IEEE quotient of the same operands,
  // so the bits are those of two scalar divisions, at the latency of one.
  using Pair = double __attribute__((vector_size(16)));
  const Pair left = Pair{dz1, dz2} * Pair{static_cast<double>(e2y), static_cast<double>(e1x)};
  const Pair right = Pair{dz2, dz1} * Pair{static_cast<double>(e1y), static_cast<double>(e2x)};
  const Pair slopes = (left - right) / a2;
  t.depth.dzdx = slopes[0];
  t.depth.dzdy = slopes[1];
  return true;
}

}  // namespace recode::raster::detail
