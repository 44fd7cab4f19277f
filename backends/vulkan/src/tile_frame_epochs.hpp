#pragma once
// How the compute device's frame cuts one framebuffer's commands into epochs (tile_frame.hpp),
// apart from everything Vulkan so that it can be tested on its own.
//
// An epoch starts at a reset, a depth clear and a stencil clear of all eight bits over one
// rectangle R, one right after the other (in either order), and runs to the next reset. It
// depends on nothing before it when every one of its commands lies inside R: a pixel inside R
// is set by the reset before anything reads it, and no pixel outside is touched. Its footprint
// is R. An epoch that reaches outside its R is joined to the one before it (and, while the
// joined commands reach outside that one's R too, to the one before that), down to the first
// epoch, whose commands come before any reset and which starts from the framebuffer as it is;
// such an epoch's footprint is the bounding box of its commands. An epoch whose footprint meets
// no other epoch's is `alone`: its pixels' final values are its own, and it may store them
// directly.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "recode/raster/state.hpp"
#include "tile_frame_layout.hpp"

namespace recode::backends::detail {

struct EpochCommand {
  TileCommandKind kind = TileCommandKind::Draw;
  raster::PixelRect rect;         // inside the framebuffer, not empty
  bool fullStencilClear = false;  // a stencil clear whose write mask is 0xFF
};

struct EpochSpan {
  std::size_t begin = 0;  // commands [begin, end)
  std::size_t end = 0;
  raster::PixelRect footprint;
  bool loads = false;  // starts from the framebuffer
  bool alone = false;  // no other epoch's footprint meets this one's
};

[[nodiscard]] EpochCommand epochCommandOf(const TileCommand& command,
                                          const raster::PixelRect& rect);

// The smallest rectangle holding both.
[[nodiscard]] raster::PixelRect unite(const raster::PixelRect& a, const raster::PixelRect& b);

// The epochs of `commands` (one framebuffer's, in order): consecutive spans covering them all.
// Epochs are checked for being alone only while there are at most kMostEpochsCompared (the
// check is quadratic); past that none is, and the resolve stage gives every pixel its value.
inline constexpr std::size_t kMostEpochsCompared = 64;
[[nodiscard]] std::vector<EpochSpan> cutIntoEpochs(const std::vector<EpochCommand>& commands);

}  // namespace recode::backends::detail
