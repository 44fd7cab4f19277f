#pragma once
// A summary of the buffers over a rectangle, small enough to read back for every pair test of
// a frame (kPixelSummaryBytes): the stencil's pixels counted by class (the caller's table maps
// each stencil value to a class), the bounding rectangle of the pixels of the classes the caller
// marks, and, over those marked pixels, the interval from a depth kept earlier (the near end,
// DepthStencilDevice::keepDepthLater) to the depth now (the far end). A GPU device may work it
// out in its own memory (the Vulkan device does, in a compute shader), so that neither the
// stencil nor the depths come back. summarizePixels is the definition every device matches bit
// for bit; the reductions are integer counts, minima and maxima, so their order does not matter.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "recode/raster/state.hpp"

namespace recode::raster {

inline constexpr int kMaxStencilClasses = 10;
inline constexpr std::size_t kPixelSummaryWords = 16;
inline constexpr std::size_t kPixelSummaryBytes = 4 * kPixelSummaryWords;

// How the stencil's values are counted.
struct StencilClasses {
  std::array<std::uint8_t, 256> classOf{};  // the class of each stencil value, < kMaxStencilClasses
  std::uint16_t marked = 0;                 // bit c set: the pixels of class c are marked
};

// The depth interval over the marked pixels. A pixel whose near end lies beyond its far end
// (the two ends met within rounding) is counted as inverted and taken as the single depth
// intervalMidpoint(near, far) at both ends.
struct DepthIntervals {
  std::uint32_t nearest = 0;   // the least near end
  std::uint32_t farthest = 0;  // the greatest far end
  std::uint32_t longest = 0;   // the greatest far end - near end
  std::uint32_t inverted = 0;  // pixels whose ends were inverted
  friend bool operator==(const DepthIntervals&, const DepthIntervals&) = default;
};

struct PixelSummary {
  std::array<std::uint32_t, kMaxStencilClasses> classCounts{};  // pixels of each class
  PixelRect markedBounds;  // the marked pixels' bounding rectangle; empty when there are none
  // With a near end and at least one marked pixel.
  std::optional<DepthIntervals> depth;
  friend bool operator==(const PixelSummary&, const PixelSummary&) = default;
};

// The depth between two ends that met within rounding: their midpoint, rounded down, without
// overflow.
[[nodiscard]] constexpr std::uint32_t intervalMidpoint(std::uint32_t nearEnd,
                                                       std::uint32_t farEnd) {
  return nearEnd / 2 + farEnd / 2 + (nearEnd & farEnd & 1u);
}

// The summary of buffers over `rect` (readStencil's layout): `stencil` and `farDepth` as they
// are now, `nearDepth` as kept earlier. Without near depths (both spans empty) there is no depth
// interval. Throws std::invalid_argument when a span's size is not rect's area (the depth spans
// may both be empty), or a class in the table is not below kMaxStencilClasses.
[[nodiscard]] PixelSummary summarizePixels(const PixelRect& rect,
                                           std::span<const std::uint8_t> stencil,
                                           std::span<const std::uint32_t> nearDepth,
                                           std::span<const std::uint32_t> farDepth,
                                           const StencilClasses& classes);

// Throws std::invalid_argument, naming `caller`, when a class in the table is not below
// kMaxStencilClasses.
void requireStencilClasses(const StencilClasses& classes, const char* caller);

// The words a device delivers: the class counts, the bounds as two words (x0 | x1 << 16,
// y0 | y1 << 16; framebuffers are at most kMaxFramebufferSize wide), then nearest, farthest,
// longest and inverted (zero without a depth interval).
[[nodiscard]] std::array<std::uint32_t, kPixelSummaryWords> packPixelSummary(
    const PixelSummary& summary);
// packPixelSummary undone; `withDepth`: the summary was asked with a near end. Throws
// std::runtime_error naming `device` when the words cannot be a summary (a class count past
// the rectangle's area, bounds outside it, nearest 0xFFFFFFFF: the depth buffer held a value
// that is not a 24-bit depth).
[[nodiscard]] PixelSummary unpackPixelSummary(std::span<const std::uint32_t> words,
                                              const PixelRect& rect, bool withDepth,
                                              const char* device);

// What a device's shader writes in `nearest` when a stored depth is not a multiple of 2^-24
// in [0, 1): not a depth at all.
inline constexpr std::uint32_t kSummaryBadDepth = 0xFFFFFFFFu;

}  // namespace recode::raster
