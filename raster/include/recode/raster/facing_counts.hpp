#pragma once
// Per-pixel counts of front-facing and back-facing fragments of one draw: the watertightness
// check that RECODE's face counting relies on (a closed mesh gives equal counts everywhere,
// a convex one at most one of each).

#include <cstdint>
#include <span>
#include <vector>

#include "recode/raster/device.hpp"

namespace recode::raster {

struct FacingCounts {
  // Whole framebuffer, row-major, bottom row first; counts saturate at 255.
  std::vector<std::uint8_t> front;
  std::vector<std::uint8_t> back;

  // Pixels where the two counts differ.
  [[nodiscard]] long long unequalPixels() const;
};

// Draws the triangles twice on `device` (back faces culled, then front faces culled) with the
// depth test off, counting fragments in the stencil over the whole framebuffer. Overwrites the
// stencil buffer and leaves the device's scissor, depth, stencil and cull state changed.
[[nodiscard]] FacingCounts countFacingFragments(DepthStencilDevice& device,
                                                std::span<const WindowVertex> vertices,
                                                std::span<const std::uint32_t> indices);

}  // namespace recode::raster
