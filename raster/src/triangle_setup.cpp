#include "recode/raster/triangle_setup.hpp"

#include <algorithm>

#include "recode/raster/fixed_point.hpp"
#include "recode/raster/invariants.hpp"

namespace recode::raster {

namespace {

// Edge a->b of a counter-clockwise triangle: E = (xb - xa)(Y - ya) - (yb - ya)(X - xa),
// positive on the interior side. Exclusive edges get c - 1 so that "E >= 0" rejects ties.
EdgeFunction makeEdge(const FixedVertex& a, const FixedVertex& b) {
  const std::int64_t dx = b.x - a.x;
  const std::int64_t dy = b.y - a.y;
  EdgeFunction e;
  e.a = -dy;
  e.b = dx;
  e.c = a.x * b.y - b.x * a.y;
  if (!isInclusiveEdge(dx, dy))
    e.c -= 1;
  return e;
}

// Twice the signed area of the snapped triangle, exact: positive when counter-clockwise.
std::int64_t twiceArea(const FixedVertex& v0, const FixedVertex& v1, const FixedVertex& v2) {
  return (v1.x - v0.x) * (v2.y - v0.y) - (v2.x - v0.x) * (v1.y - v0.y);
}

// setupCoverage written into `t`, false for a zero-area triangle. setupTriangle fills its own
// result with it in place: copying a returned TriangleCoverage into it read the callee's
// stores back in wider loads, which stalled the store forwarding.
[[gnu::always_inline]] inline bool coverageInto(const FixedVertex& v0, const FixedVertex& v1,
                                                const FixedVertex& v2, TriangleCoverage& t) {
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
    return false;

  t.frontFacing = area2 > 0;
  // Coverage uses the counter-clockwise order; the depth plane uses the submitted order.
  const FixedVertex& p1 = t.frontFacing ? v1 : v2;
  const FixedVertex& p2 = t.frontFacing ? v2 : v1;
  t.edges = {makeEdge(v0, p1), makeEdge(p1, p2), makeEdge(p2, v0)};

  const std::int64_t minX = std::min({v0.x, v1.x, v2.x}), maxX = std::max({v0.x, v1.x, v2.x});
  const std::int64_t minY = std::min({v0.y, v1.y, v2.y}), maxY = std::max({v0.y, v1.y, v2.y});
  const std::int64_t half = kSubpixelOne / 2;
  // Pixel i is a candidate when its centre 256 i + 128 lies in [min, max].
  t.bounds.x0 = static_cast<int>(-floorDiv(-(minX - half), kSubpixelOne));
  t.bounds.x1 = static_cast<int>(floorDiv(maxX - half, kSubpixelOne) + 1);
  t.bounds.y0 = static_cast<int>(-floorDiv(-(minY - half), kSubpixelOne));
  t.bounds.y1 = static_cast<int>(floorDiv(maxY - half, kSubpixelOne) + 1);
  return true;
}

}  // namespace

std::optional<TriangleCoverage> setupCoverage(const FixedVertex& v0, const FixedVertex& v1,
                                              const FixedVertex& v2) {
  // One named result on every path, so that it is built in the caller's storage.
  std::optional<TriangleCoverage> t(std::in_place);
  if (!coverageInto(v0, v1, v2, *t))
    t.reset();
  return t;
}

std::optional<TriangleSetup> setupTriangle(const FixedVertex& v0, const FixedVertex& v1,
                                           const FixedVertex& v2) {
  // One named result on every path, so that it is built in the caller's storage.
  std::optional<TriangleSetup> setup(std::in_place);
  if (!setupTriangleInto(v0, v1, v2, *setup))
    setup.reset();
  return setup;
}

bool setupTriangleInto(const FixedVertex& v0, const FixedVertex& v1, const FixedVertex& v2,
                       TriangleSetup& t) {
  if (!coverageInto(v0, v1, v2, t))
    return false;

  // Depth plane through the three snapped vertices, in the submitted order:
  // dz/dX = (dz1 e2y - dz2 e1y) / area2, dz/dY = (dz2 e1x - dz1 e2x) / area2.
  const std::int64_t e1x = v1.x - v0.x, e1y = v1.y - v0.y;
  const std::int64_t e2x = v2.x - v0.x, e2y = v2.y - v0.y;
  const double z0 = static_cast<double>(v0.z);
  const double dz1 = static_cast<double>(v1.z) - z0;
  const double dz2 = static_cast<double>(v2.z) - z0;
  const double a2 = static_cast<double>(twiceArea(v0, v1, v2));
  t.depth.x0 = v0.x;
  t.depth.y0 = v0.y;
  t.depth.z0 = z0;
  t.depth.dzdx = (dz1 * static_cast<double>(e2y) - dz2 * static_cast<double>(e1y)) / a2;
  t.depth.dzdy = (dz2 * static_cast<double>(e1x) - dz1 * static_cast<double>(e2x)) / a2;
  return true;
}

}  // namespace recode::raster
