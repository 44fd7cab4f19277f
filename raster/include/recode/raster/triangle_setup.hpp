#pragma once
// Triangle setup: snapped vertices -> three integer edge functions with the fill-rule bias,
// the facing, the pixel bounding box, and the depth plane (docs/rasterization.md, 3 and 5).

#include <array>
#include <cstdint>
#include <optional>

#include "recode/raster/device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/state.hpp"

namespace recode::raster {

// E(X, Y) = a X + b Y + c over 24.8 fixed-point sample positions; a sample is inside the
// edge when E >= 0. The bias that implements the tie rule is already folded into c.
struct EdgeFunction {
  std::int64_t a = 0;
  std::int64_t b = 0;
  std::int64_t c = 0;

  [[nodiscard]] std::int64_t at(std::int64_t x, std::int64_t y) const { return a * x + b * y + c; }
};

// z(X, Y) = (z0 + dzdx (X - x0)) + dzdy (Y - y0), all in double, in exactly that order.
// at() is the contract's formula for one sample; CpuDevice evaluates the same operations per
// 8x8 block (docs/rasterization.md, section 7).
struct DepthPlane {
  std::int64_t x0 = 0;  // fixed-point position of the first submitted vertex
  std::int64_t y0 = 0;
  double z0 = 0.0;
  double dzdx = 0.0;  // per sub-pixel unit
  double dzdy = 0.0;

  [[nodiscard]] double at(std::int64_t x, std::int64_t y) const {
    const double tx = dzdx * static_cast<double>(x - x0);
    const double ty = dzdy * static_cast<double>(y - y0);
    return (z0 + tx) + ty;
  }
};

// What decides which pixel centres a triangle covers.
struct TriangleCoverage {
  std::array<EdgeFunction, 3> edges;
  bool frontFacing = true;  // counter-clockwise in GL window coordinates (y up)
  PixelRect bounds;         // pixels whose centres can be covered (half-open), unclipped
};

struct TriangleSetup : TriangleCoverage {
  DepthPlane depth;
};

// Sub-pixel positions of one vertex after snapping.
struct FixedVertex {
  std::int64_t x = 0;
  std::int64_t y = 0;
  float z = 0.0f;
};

// Inline: it runs three times per triangle, and as a call it returned the vertex through
// memory that the caller read back in wider loads than the callee's stores, which the CPU
// cannot forward (a stall of about as long as the rest of the call).
[[nodiscard]] inline FixedVertex snapVertex(const WindowVertex& v) {
  return {snapToFixed(v.x), snapToFixed(v.y), v.z};
}

// The coverage half of setupTriangle, the same edges, facing and bounds without the depth
// plane's two divisions: for a caller that asks only which centres a triangle covers. Returns
// nullopt for a zero-area triangle.
[[nodiscard]] std::optional<TriangleCoverage> setupCoverage(const FixedVertex& v0,
                                                            const FixedVertex& v1,
                                                            const FixedVertex& v2);

// Returns nullopt for a zero-area triangle (it draws nothing).
[[nodiscard]] std::optional<TriangleSetup> setupTriangle(const FixedVertex& v0,
                                                         const FixedVertex& v1,
                                                         const FixedVertex& v2);

// The same written over every field of `out`, false (and `out` unspecified) for a zero-area
// triangle: for the pipeline's loop, which reuses one setup for every triangle of a draw
// instead of clearing a new one for each.
[[nodiscard]] bool setupTriangleInto(const FixedVertex& v0, const FixedVertex& v1,
                                     const FixedVertex& v2, TriangleSetup& out);

// The fill rule alone: is edge a->b of a counter-clockwise triangle (y up) inclusive, i.e.
// a left edge (going down) or a bottom edge (horizontal, going right)?
[[nodiscard]] constexpr bool isInclusiveEdge(std::int64_t dx, std::int64_t dy) {
  return dy < 0 || (dy == 0 && dx > 0);
}

}  // namespace recode::raster
