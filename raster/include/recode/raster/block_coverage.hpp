#pragma once
// The per-pixel coverage test of one 8x8 block, the traversal's innermost loop
// (docs/rasterization.md, section 6): a pixel is covered when all three edge functions are
// non-negative at its centre. Two implementations give the same bits: a scalar loop over the
// pixels asked for, and a SIMD one (Google Highway, chosen at run time for the CPU) that tests
// a row of 8 pixels in one to four vector steps. The traversal uses the scalar loop for a few
// pixels and the SIMD one for more; tests compare them on every target Highway built. In a
// build without Highway (it is optional) the SIMD entry point runs the scalar loop.

#include <cstdint>
#include <functional>

namespace recode::raster {

// The three edge functions over one block: their exact values at the centre of the block's
// pixel (0, 0), and their exact change per pixel along x and along y (a * 256, b * 256).
struct BlockEdges {
  std::int64_t origin[3];
  std::int64_t stepX[3];
  std::int64_t stepY[3];
};

// Bit (row * 8 + col) is set for each covered pixel with col in [c0, c1) and row in [r0, r1)
// (0 <= c0 < c1 <= 8, 0 <= r0 < r1 <= 8); every other bit is 0.
[[nodiscard]] std::uint64_t blockCoverageScalar(const BlockEdges& edges, int c0, int c1, int r0,
                                                int r1);
[[nodiscard]] std::uint64_t blockCoverageSimd(const BlockEdges& edges, int c0, int c1, int r0,
                                              int r1);

// Runs visit(name) once for each Highway target this build has that this CPU runs, with
// blockCoverageSimd dispatched to that target, then restores the normal choice (the best).
// For tests: both versions can then be compared on every target, not only the best.
void forEachSimdTarget(const std::function<void(const char* targetName)>& visit);

}  // namespace recode::raster
