// The compute device's loop budgets (backends/vulkan/src/tile_frame_budgets.hpp): every stage's
// invocation stays within a CPU driver's loop limit, the rounds bound every job, and a stage
// that did less than it was asked is an error that names it. Vulkan-free.

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "tile_frame_budgets.hpp"

using namespace recode::backends::detail;

namespace {

constexpr std::uint32_t kLimit = 65535;  // llvmpipe's

// A raster job's loop iterations in one round at most: its budget, plus what no budget counts
// (the epoch's binary search over at most 2^32 epochs, eight loads, eight stores or carries, the
// workgroup's loop and a resumed command's test).
std::uint64_t rasterRoundIterations(std::uint32_t budget) {
  return budget + 32 + 8 + 8 + 2 + 1;
}

}  // namespace

TEST_CASE("a driver without a loop limit gets one round, one chunk and no budget",
          "[tile-budgets]") {
  const TileLoopBudgets b = tileLoopBudgets(0);
  CHECK(b.rasterWork == kTileUnbounded);
  CHECK(b.sortWork == kTileUnbounded);
  CHECK(b.scatterBlocks == kTileUnbounded);
  CHECK(b.resolveLater == kTileUnbounded);
  CHECK(tileRasterRounds(10, 1'000'000, b.rasterWork) == 1);
  CHECK(tileSortRounds(1'000'000, b.sortWork) == 1);
  CHECK(tileScatterChunks(1'000'000, b.scatterBlocks) == 1);
}

TEST_CASE("under llvmpipe's limit, a SIMD bundle of two jobs or sixteen lanes stays within it",
          "[tile-budgets]") {
  const TileLoopBudgets b = tileLoopBudgets(kLimit);
  // Raster: a bundle holds at most two jobs, each within its budget and the uncounted.
  CHECK(2 * rasterRoundIterations(b.rasterWork) <= kLimit);
  // Sort, scatter and resolve: sixteen lanes, each its budget and two binary searches.
  CHECK(16 * (std::uint64_t{b.sortWork} + 64) <= kLimit);
  CHECK(16 * (std::uint64_t{b.scatterBlocks} + 64) <= kLimit);
  CHECK(16 * (std::uint64_t{b.resolveLater} + 64) <= kLimit);
  // Box: a lane's every 64th vertex, four iterations each; scan: two loops over a 256th of jobs.
  CHECK(b.boxVertices / 64 * 4 + 64 <= kLimit);
  CHECK(b.scanJobs / 256 * 2 + 16 <= kLimit);
  // And none is needlessly small: within a factor of two of the limit's share.
  CHECK(2 * rasterRoundIterations(b.rasterWork) > kLimit / 2);
  CHECK(16 * std::uint64_t{b.scatterBlocks} > kLimit / 2);
}

TEST_CASE("the rounds bound a job's whole work", "[tile-budgets]") {
  const std::uint32_t budget = tileLoopBudgets(kLimit).rasterWork;
  const std::uint64_t perRound = budget / kTileWorkUnit;  // units a round runs in full
  CHECK(tileRasterRounds(3, 0, budget) == 1);
  CHECK(tileRasterRounds(3, perRound - 3, budget) == 1);
  CHECK(tileRasterRounds(3, perRound - 2, budget) == 2);
  // 70,000 list entries and three commands.
  CHECK(tileRasterRounds(3, 70000, budget) == (70003 + perRound - 1) / perRound);
  // The sort: steps n/2 + n - 1, each charged findMSB(n) + 2.
  const std::uint32_t sortBudget = tileLoopBudgets(kLimit).sortWork;
  CHECK(tileSortRounds(1, sortBudget) == 1);
  REQUIRE(sortBudget == 4031);
  CHECK(tileSortRounds(100, sortBudget) == 1);   // 149 steps of 8: 1,192 <= 4,031
  CHECK(tileSortRounds(1000, sortBudget) == 5);  // 1,499 steps of 11, 366 a round
  const std::uint64_t steps = 35000 + 70000 - 1;
  const std::uint64_t perSortRound = sortBudget / (16 + 2);  // findMSB(70,000) = 16
  CHECK(tileSortRounds(70000, sortBudget) == (steps + perSortRound - 1) / perSortRound);
  const std::uint32_t chunk = tileLoopBudgets(kLimit).scatterBlocks;
  CHECK(tileScatterChunks(chunk, chunk) == 1);
  CHECK(tileScatterChunks(chunk + 1, chunk) == 2);
  CHECK(tileScatterChunks(0, chunk) == 1);
}

TEST_CASE("a stage that did less than it was asked is an error naming it", "[tile-budgets]") {
  std::array<std::uint32_t, kTileCounters> counted{};
  counted[kTileCounterRasterColumns] = 80;
  counted[kTileCounterSortedJobs] = 10;
  CHECK_NOTHROW(checkTileCounters(counted, 80, 10, kLimit));
  const auto message = [&](std::uint64_t columns, std::uint64_t sorted) {
    try {
      checkTileCounters(counted, columns, sorted, kLimit);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(message(88, 10), Catch::Contains("the raster stage ran 80 of 88 job columns") &&
                                  Catch::Contains("65535 iterations"));
  CHECK_THAT(message(80, 11), Catch::Contains("sort put 10 of 11 jobs' lists in order"));
  counted[kTileCounterScatterShort] = 3;
  CHECK_THAT(message(80, 10), Catch::Contains("scatter ended 3 invocations' loops"));
  counted[kTileCounterScatterShort] = 0;
  counted[kTileCounterResolveShort] = 1;
  CHECK_THAT(message(80, 10), Catch::Contains("resolve stage ended 1 invocations' loops"));
}
