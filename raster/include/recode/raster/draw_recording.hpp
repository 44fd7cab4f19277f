#pragma once
// What one draw of a TriangleSource rasterized, kept so that a later draw of the same source can
// skip snapping, setup and traversal. RECODE's passes draw each block up to five times in a
// pair test, under different depth and stencil state but the same geometry: the triangles that
// survive setup, their facings and depth planes, and the covered pixels of each 8x8 block do
// not depend on that state (docs/rasterization.md: coverage is the edge functions' alone). A
// replay applies the recorded blocks again, in the recorded order, masked to the current
// scissor and skipping the triangles the current cull mode discards, so it writes exactly the
// fragments a fresh draw would.
//
// A recording is made only from a draw that culls nothing (so every triangle is in it) and
// serves only draws whose scissor lies inside the recorded one (a smaller rectangle's covered
// pixels are the recorded ones inside it). A triangle that covered no pixel is not kept: a
// replay would visit it for nothing, and a fine mesh's sub-pixel triangles often fall between
// centres.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "recode/raster/state.hpp"
#include "recode/raster/triangle_setup.hpp"

namespace recode::raster {

class DrawRecording {
 public:
  struct Triangle {
    DepthPlane plane;
    bool frontFacing = true;
    // Its blocks are [firstBlock, the next triangle's firstBlock), never none once finished.
    std::uint32_t firstBlock = 0;
  };
  struct Block {
    std::int32_t x = 0;  // bottom-left pixel, on the 8x8 grid
    std::int32_t y = 0;
    std::uint64_t mask = 0;  // covered pixels inside the recorded scissor, never 0
  };

  // A draw that records more covered blocks than this (16 bytes each) is not kept: a huge
  // framebuffer filled many times over would otherwise hold hundreds of megabytes.
  static constexpr std::size_t kMaxBlocks = std::size_t{1} << 20;

  // Starts recording a draw of the source named `key` (TriangleSource::contentKey, not 0)
  // under `scissor`, forgetting the previous recording but keeping its memory.
  void start(std::uint64_t key, const PixelRect& scissor);
  void addTriangle(const TriangleSetup& triangle);
  void addBlock(int x, int y, std::uint64_t mask);
  // Ends the recording: it serves draws from now on, unless it outgrew kMaxBlocks.
  void finish();
  // Forgets the recording, keeping its memory.
  void clear();

  // Whether this recording can stand for a draw of source `key` under `scissor`.
  [[nodiscard]] bool serves(std::uint64_t key, const PixelRect& scissor) const;

  [[nodiscard]] const std::vector<Triangle>& triangles() const { return triangles_; }
  [[nodiscard]] const std::vector<Block>& blocks() const { return blocks_; }

 private:
  // Whether the last triangle added has no block after it (yet): it covered no pixel.
  [[nodiscard]] bool lastTriangleCoveredNothing() const {
    return !triangles_.empty() && triangles_.back().firstBlock == blocks_.size();
  }

  std::uint64_t key_ = 0;  // 0: nothing usable recorded
  bool complete_ = false;
  bool overflowed_ = false;
  PixelRect scissor_;
  std::vector<Triangle> triangles_;
  std::vector<Block> blocks_;
};

}  // namespace recode::raster
