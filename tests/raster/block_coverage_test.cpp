// The block coverage test's two versions (block_coverage.hpp) against a direct evaluation of
// each pixel's edge values, on every Highway target this build runs here: the SIMD version
// must give the scalar loop's bits exactly, for every clip window, including edge values of 0
// (covered: the fill rule's ties are settled in the edge constants, not here) and -1.

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "recode/raster/block_coverage.hpp"

namespace {

using recode::raster::BlockEdges;

// Each pixel's three edge values from the origin, no stepping: an oracle independent of both
// loops.
std::uint64_t directCoverage(const BlockEdges& e, int c0, int c1, int r0, int r1) {
  std::uint64_t mask = 0;
  for (int r = r0; r < r1; ++r)
    for (int c = c0; c < c1; ++c) {
      bool inside = true;
      for (int k = 0; k < 3; ++k)
        inside = inside && e.origin[k] + c * e.stepX[k] + r * e.stepY[k] >= 0;
      if (inside)
        mask |= std::uint64_t{1} << (r * 8 + c);
    }
  return mask;
}

// Edges whose zero crosses the block: steps of up to 2^32 (a * 256 for a window of 2^16
// pixels), origins within 8 steps of 0, and sometimes exactly 0 or -1 at a pixel.
BlockEdges randomEdges(std::mt19937_64& rng) {
  std::uniform_int_distribution<std::int64_t> step(-(std::int64_t{1} << 32), std::int64_t{1} << 32);
  std::uniform_int_distribution<int> pick(0, 7);
  BlockEdges e{};
  for (int k = 0; k < 3; ++k) {
    e.stepX[k] = pick(rng) == 0 ? 0 : step(rng) >> pick(rng) * 4;
    e.stepY[k] = pick(rng) == 0 ? 0 : step(rng) >> pick(rng) * 4;
    const int c = pick(rng), r = pick(rng);
    const std::int64_t atPixel = pick(rng) < 2 ? -pick(rng) % 2 : step(rng) >> pick(rng) * 4;
    e.origin[k] = atPixel - c * e.stepX[k] - r * e.stepY[k];
  }
  return e;
}

}  // namespace

TEST_CASE("block coverage: scalar and SIMD give the direct evaluation's bits on every target",
          "[raster][simd]") {
  std::vector<std::string> targets;
  recode::raster::forEachSimdTarget([&](const char* name) {
    targets.emplace_back(name);
    std::mt19937_64 rng(20261124);
    std::uniform_int_distribution<int> bound(0, 8);
    long long covered = 0, partial = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      const BlockEdges e = randomEdges(rng);
      int c0 = bound(rng), c1 = bound(rng), r0 = bound(rng), r1 = bound(rng);
      if (c0 == c1 || r0 == r1)
        continue;
      if (c0 > c1)
        std::swap(c0, c1);
      if (r0 > r1)
        std::swap(r0, r1);
      const std::uint64_t expected = directCoverage(e, c0, c1, r0, r1);
      INFO("target " << name << ", trial " << trial << ", columns [" << c0 << ", " << c1
                     << "), rows [" << r0 << ", " << r1 << ")");
      REQUIRE(recode::raster::blockCoverageScalar(e, c0, c1, r0, r1) == expected);
      REQUIRE(recode::raster::blockCoverageSimd(e, c0, c1, r0, r1) == expected);
      covered += expected != 0;
      const std::uint64_t window = directCoverage(BlockEdges{}, c0, c1, r0, r1);
      partial += expected != 0 && expected != window;
    }
    // The trials reach the interesting cases: blocks partly covered, not only all or none.
    INFO("covered " << covered << ", partly " << partial);
    CHECK(covered > 2000);
    CHECK(partial > 1000);
  });
  INFO("targets run");
  for (const std::string& t : targets)
    INFO(t);
  CHECK(!targets.empty());
}
