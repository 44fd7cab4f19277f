#pragma once
// How the compute device keeps every shader invocation's loops within a driver's loop limit
// (VulkanContext::loopLimit: llvmpipe ends an invocation's loops without a word once 65,535
// iterations have run, counted over every loop of the shader). Vulkan-free, so that the rules
// are tested on the CPU (tests/backends/vulkan/tile_frame_budgets_test.cpp).
//
// What each stage's invocations loop over, and how it is kept within the limit:
//   raster   a job's commands and list entries (or, past the lists' capacity, every triangle of
//            its draws), at most eight rows each: the job is charged kTileWorkUnit for each and
//            stops at its budget; further rounds go on from where it stopped
//   sort     a job's heapsort, one invocation a job, at most log2(n) + 2 iterations a step:
//            the same, in rounds
//   scatter  a triangle's candidate blocks: cut into chunks, one invocation a chunk
//   resolve  a pixel's later epochs: a target whose epochs would pass it has them merged
//   box      a block's vertices, 64 an iteration: a larger block is refused with the limit named
//   scan     the jobs, a 256th an invocation: a larger frame is refused likewise
// A CPU driver runs a workgroup's invocations as SIMD bundles of up to 16 lanes (llvmpipe: 8
// with AVX2, 16 with 512-bit vectors) whose loops run as long as any lane's, so a bundle's count
// is at most the sum of its lanes' own: a raster job (8 lanes) shares a bundle with at most one
// other job, and a sort, scatter or resolve lane with at most 15 others. kTileLoopMargin is
// left for what no budget counts (binary searches, a job's loads and stores).

#include <array>
#include <cstdint>

#include "tile_frame_layout.hpp"

namespace recode::backends::detail {

// A budget that never runs out (tile_common.glsl's kUnbounded): a driver without a loop limit.
inline constexpr std::uint32_t kTileUnbounded = 0xFFFFFFFFu;
// tile_common.glsl's kWorkUnit: a raster job's charge for one command or one triangle drawn.
inline constexpr std::uint32_t kTileWorkUnit = 9;
inline constexpr std::uint32_t kTileLoopMargin = 1024;
inline constexpr std::uint32_t kTileJobsPerBundle = 2;
inline constexpr std::uint32_t kTileLanesPerBundle = 16;
// Invocations a raster job has: its eight columns.
inline constexpr std::uint32_t kTileJobLanes = 8;

struct TileLoopBudgets {
  std::uint32_t rasterWork = kTileUnbounded;      // work units a raster job runs a round
  std::uint32_t sortWork = kTileUnbounded;        // loop iterations a sort job runs a round
  std::uint32_t scatterBlocks = kTileUnbounded;   // candidate blocks one scatter invocation visits
  std::uint32_t resolveLater = kTileUnbounded;    // later epochs one resolve invocation compares
  std::uint64_t boxVertices = ~std::uint64_t{0};  // vertices of one block the box stage takes
  std::uint64_t scanJobs = ~std::uint64_t{0};     // jobs the scan takes
};

// The budgets for a driver whose loop limit is `loopLimit` (0: none).
[[nodiscard]] TileLoopBudgets tileLoopBudgets(std::uint32_t loopLimit);

// Rounds the raster stage may need for a job of `commands` commands drawing `triangles`
// triangles in all (its list holds at most those), within `budget` work units a round.
[[nodiscard]] std::uint32_t tileRasterRounds(std::uint64_t commands, std::uint64_t triangles,
                                             std::uint32_t budget);
// Rounds the sort stage may need for a list of at most `entries` entries.
[[nodiscard]] std::uint32_t tileSortRounds(std::uint64_t entries, std::uint32_t budget);
// Invocations a triangle's candidate blocks take when a grid has at most `gridBlocks` blocks.
[[nodiscard]] std::uint32_t tileScatterChunks(std::uint64_t gridBlocks, std::uint32_t perChunk);

// Throws std::runtime_error naming the first stage whose counters (tile_frame_layout.hpp's
// TileCounter) differ from what the frame asked of it: `columns` raster job columns run to their
// end, `sorted` jobs sorted, no scatter or resolve loop ended early. `loopLimit` (0: none) is
// named in the message as the likely cause.
void checkTileCounters(const std::array<std::uint32_t, kTileCounters>& counted,
                       std::uint64_t columns, std::uint64_t sorted, std::uint32_t loopLimit);

}  // namespace recode::backends::detail
