// The compute device's loop budgets (tile_frame_budgets.hpp).

#include "tile_frame_budgets.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace recode::backends::detail {

namespace {

std::uint64_t ceilDiv(std::uint64_t a, std::uint64_t b) {
  return (a + b - 1) / b;
}

// A sort step's charge for a list of `entries` (tile_sort.comp): the longest sift, findMSB + 1
// levels, and the step's own loop test.
std::uint64_t sortStepCost(std::uint64_t entries) {
  return static_cast<std::uint64_t>(std::bit_width(entries) - 1) + 2;
}

}  // namespace

TileLoopBudgets tileLoopBudgets(std::uint32_t loopLimit) {
  TileLoopBudgets b;
  if (loopLimit == 0)
    return b;
  const std::uint32_t spare = loopLimit - kTileLoopMargin;
  b.rasterWork = spare / kTileJobsPerBundle;
  b.sortWork = spare / kTileLanesPerBundle;
  b.scatterBlocks = spare / kTileLanesPerBundle;
  b.resolveLater = spare / kTileLanesPerBundle;
  // tile_box.comp: a lane takes every 64th vertex, four iterations each (the vertex and its
  // three coordinates); tile_scan.comp: a lane takes a 256th of the jobs, two loops over them.
  b.boxVertices = std::uint64_t{spare} / 4 * 64;
  b.scanJobs = std::uint64_t{spare} / 2 * 256;
  return b;
}

std::uint32_t tileRasterRounds(std::uint64_t commands, std::uint64_t triangles,
                               std::uint32_t budget) {
  if (budget == kTileUnbounded)
    return 1;
  // A round runs budget / kTileWorkUnit units in full before it stops (tile_raster.comp).
  const std::uint64_t perRound = budget / kTileWorkUnit;
  return static_cast<std::uint32_t>(
      std::max<std::uint64_t>(1, ceilDiv(commands + triangles, perRound)));
}

std::uint32_t tileSortRounds(std::uint64_t entries, std::uint32_t budget) {
  if (budget == kTileUnbounded || entries < 2)
    return 1;
  const std::uint64_t steps = entries / 2 + entries - 1;
  const std::uint64_t perRound = budget / sortStepCost(entries);
  return static_cast<std::uint32_t>(std::max<std::uint64_t>(1, ceilDiv(steps, perRound)));
}

std::uint32_t tileScatterChunks(std::uint64_t gridBlocks, std::uint32_t perChunk) {
  if (perChunk == kTileUnbounded)
    return 1;
  return static_cast<std::uint32_t>(std::max<std::uint64_t>(1, ceilDiv(gridBlocks, perChunk)));
}

void checkTileCounters(const std::array<std::uint32_t, kTileCounters>& counted,
                       std::uint64_t columns, std::uint64_t sorted, std::uint32_t loopLimit) {
  const auto fail = [loopLimit](const std::string& what) {
    std::string cause = loopLimit != 0 ? "; this driver ends a shader invocation's loops after " +
                                             std::to_string(loopLimit) + " iterations"
                                       : "";
    throw std::runtime_error("vulkan-compute: " + what + cause +
                             ", so the frame's buffers are not the contract's and are not used");
  };
  const auto asked = [](std::uint64_t n) { return static_cast<std::uint32_t>(n); };
  if (counted[kTileCounterScatterShort] != 0)
    fail("the binning stage's scatter ended " + std::to_string(counted[kTileCounterScatterShort]) +
         " invocations' loops before their end");
  if (counted[kTileCounterSortedJobs] != asked(sorted))
    fail("the binning stage's sort put " + std::to_string(counted[kTileCounterSortedJobs]) +
         " of " + std::to_string(sorted) + " jobs' lists in order");
  if (counted[kTileCounterRasterColumns] != asked(columns))
    fail("the raster stage ran " + std::to_string(counted[kTileCounterRasterColumns]) + " of " +
         std::to_string(columns) + " job columns to their end");
  if (counted[kTileCounterResolveShort] != 0)
    fail("the resolve stage ended " + std::to_string(counted[kTileCounterResolveShort]) +
         " invocations' loops before their end");
}

}  // namespace recode::backends::detail
