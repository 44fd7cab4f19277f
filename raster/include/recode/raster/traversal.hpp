#pragma once
// Coverage traversal: walks a triangle's pixels in 64x64 tiles and 8x8 blocks, rejecting
// and accepting whole tiles and blocks from their corner samples (the edge functions are
// linear, so their extremes over a block are at its corner samples). Fragments come out per
// 8x8 block as a 64-bit coverage mask; the order is fixed (tiles, then blocks, row by row
// from the bottom; bits row-major from the block's bottom-left pixel), so results are the
// same bytes on every run.

#include <cstdint>

#include "recode/raster/state.hpp"
#include "recode/raster/triangle_setup.hpp"

namespace recode::raster {

inline constexpr int kTileSize = 64;
inline constexpr int kBlockSize = 8;

// Receives the covered pixels of one 8x8 block whose bottom-left pixel is (blockX, blockY):
// bit (row * 8 + col) is pixel (blockX + col, blockY + row). Never called with mask 0.
class BlockSink {
 public:
  virtual ~BlockSink() = default;
  virtual void coveredBlock(int blockX, int blockY, std::uint64_t mask) = 0;
};

// What the traversal did, for tests and profiling. A triangle whose pixels in the clip lie in
// one block counts one partial block and no tile.
struct TraversalStats {
  std::uint64_t tilesRejected = 0;
  std::uint64_t tilesAccepted = 0;
  std::uint64_t blocksRejected = 0;
  std::uint64_t blocksAccepted = 0;
  std::uint64_t blocksPartial = 0;
};

// Bits of the 8x8 block whose bottom-left pixel is (x, y) that lie inside `rect`.
[[nodiscard]] std::uint64_t blockMaskInside(int x, int y, const PixelRect& rect);

// Visits every pixel of `clip` whose centre the triangle covers under the fill rule, once.
void traverseTriangle(const TriangleCoverage& tri, const PixelRect& clip, BlockSink& sink,
                      TraversalStats* stats = nullptr);

}  // namespace recode::raster
