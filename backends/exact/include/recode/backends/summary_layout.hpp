#pragma once
// The host half of the exact GPU devices' pixel summaries: what the shared shader body
// (shaders/pixel_summary.glsl) reads and writes, for the Vulkan and exact GL devices alike.
// Each summary reads one input buffer (the stencil copy padded to a word, the far depths, the
// class table), a kept near depth, and its thirteen parameters, and writes 16 words.

#include <cstddef>
#include <cstdint>

#include "recode/raster/pixel_summary.hpp"
#include "recode/raster/state.hpp"

namespace recode::backends {

// Rectangles of more pixels are summarised on the host from plain read-backs (the interface's
// default): their copies would crowd the device memory a frame's pairs share.
inline constexpr long long kMaxDeviceSummaryPixels = 4LL << 20;

// Whether a device summarises `rect` itself (not empty, not beyond the bound above).
[[nodiscard]] inline bool summarisedOnDevice(const raster::PixelRect& rect) {
  return !rect.empty() && rect.area() <= kMaxDeviceSummaryPixels;
}

// Where a summary's inputs lie in its input buffer, in bytes from the buffer's start.
struct SummaryInputs {
  SummaryInputs(const raster::PixelRect& rect, bool withDepth);
  std::size_t stencilBytes = 0;  // a byte a pixel, padded to a word
  std::size_t farBytes = 0;      // a 32-bit float a pixel with depth, else none
  std::size_t tableBytes = 0;    // the 256 stencil values' classes
  [[nodiscard]] std::size_t farOffset() const { return stencilBytes; }
  [[nodiscard]] std::size_t tableOffset() const { return stencilBytes + farBytes; }
  [[nodiscard]] std::size_t bytes() const { return stencilBytes + farBytes + tableBytes; }
};

// One summary's parameters, as pixel_summary.glsl reads them (its `Summary`, thirteen words).
struct SummaryParameters {
  std::uint32_t stencilByte = 0;
  std::uint32_t farWord = 0;
  std::uint32_t tableWord = 0;
  std::uint32_t nearWord = 0;
  std::uint32_t resultWord = 0;
  std::uint32_t x0 = 0;
  std::uint32_t y0 = 0;
  std::uint32_t y1 = 0;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t marked = 0;
  std::uint32_t withDepth = 0;
  std::uint32_t rowsFromBottom = 0;
};
static_assert(sizeof(SummaryParameters) == 13 * 4, "pixel_summary.glsl reads thirteen words");

// The parameters of a summary of `rect` whose inputs start at byte `inputsOffset` of their
// buffer (laid out as SummaryInputs), whose near depth starts at byte `nearOffset` of its own
// and whose words go to byte `resultOffset` of theirs (offsets are word-aligned); the copies'
// rows run from the bottom (GL) or from the top (Vulkan).
[[nodiscard]] SummaryParameters summaryParameters(const raster::PixelRect& rect,
                                                  const raster::StencilClasses& classes,
                                                  bool withDepth, bool rowsFromBottom,
                                                  std::size_t inputsOffset, std::size_t nearOffset,
                                                  std::size_t resultOffset);

// The summary from the 16 words a device's shader wrote (raster::unpackPixelSummary).
[[nodiscard]] raster::PixelSummary summaryFromBytes(const std::uint8_t* bytes,
                                                    const raster::PixelRect& rect, bool withDepth,
                                                    const char* device);

}  // namespace recode::backends
