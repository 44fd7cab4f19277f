#pragma once
// Where a device's buffers differ from a golden vector's expected ones, pixel by pixel: what
// `recode replay --diff` lists and what `recode conform` reports first.

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "recode/raster/golden.hpp"

namespace recode::kit {

enum class Buffer { Depth, Stencil };
[[nodiscard]] std::string_view toString(Buffer b);  // "depth", "stencil"

struct PixelDifference {
  int x = 0, y = 0;  // GL window coordinates: y = 0 is the bottom row
  Buffer buffer = Buffer::Depth;
  std::uint32_t expected = 0, got = 0;
};

struct BufferComparison {
  long long depthPixels = 0;    // pixels whose depth differs
  long long stencilPixels = 0;  // pixels whose stencil differs
  // In scan order (row 0 first, x increasing; at one pixel depth before stencil), at most
  // `limit` of them.
  std::vector<PixelDifference> differences;

  [[nodiscard]] bool matches() const { return depthPixels == 0 && stencilPixels == 0; }
  [[nodiscard]] std::optional<PixelDifference> first() const;
};

// Compares whole buffers (row-major, bottom row first) with the vector's expected ones.
[[nodiscard]] BufferComparison compareBuffers(const raster::GoldenVector& golden,
                                              std::span<const std::uint32_t> depth,
                                              std::span<const std::uint8_t> stencil,
                                              std::size_t limit = SIZE_MAX);

}  // namespace recode::kit
