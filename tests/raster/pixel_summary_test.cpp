// summarizePixels, the definition every device's summary matches: counted against a direct
// per-pixel count on random buffers, the inverted-interval rule, the 16 words there and back,
// and the errors for inputs no device should hand over.

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "recode/raster/cpu_device.hpp"
#include "recode/raster/device.hpp"
#include "recode/raster/pixel_summary.hpp"

using namespace recode::raster;

namespace {

// Stencil values 0-15 in classes value % 7, classes 2 and 5 marked.
StencilClasses someClasses() {
  StencilClasses c;
  for (std::size_t v = 0; v < c.classOf.size(); ++v)
    c.classOf[v] = static_cast<std::uint8_t>(v % 7);
  c.marked = (1u << 2) | (1u << 5);
  return c;
}

}  // namespace

TEST_CASE("a pixel summary counts, bounds and measures what a pixel-by-pixel loop does",
          "[raster][summary]") {
  std::mt19937 random(7);
  const StencilClasses classes = someClasses();
  for (int trial = 0; trial < 50; ++trial) {
    const PixelRect rect{static_cast<int>(random() % 9), static_cast<int>(random() % 9), 0, 0};
    const PixelRect r{rect.x0, rect.y0, rect.x0 + 1 + static_cast<int>(random() % 12),
                      rect.y0 + 1 + static_cast<int>(random() % 12)};
    const auto n = static_cast<std::size_t>(r.area());
    std::vector<std::uint8_t> stencil(n);
    std::vector<std::uint32_t> nearDepth(n), farDepth(n);
    for (std::size_t i = 0; i < n; ++i) {
      stencil[i] = static_cast<std::uint8_t>(random() % 16);
      nearDepth[i] = static_cast<std::uint32_t>(random() % 1000);
      farDepth[i] = static_cast<std::uint32_t>(random() % 1000);
    }
    const PixelSummary s = summarizePixels(r, stencil, nearDepth, farDepth, classes);
    // The same, written out differently: marked pixels gathered first, then reduced.
    std::vector<long long> counts(kMaxStencilClasses, 0);
    int x0 = 1 << 20, y0 = 1 << 20, x1 = -1, y1 = -1;
    std::uint32_t nearest = ~0u, farthest = 0, longest = 0, inverted = 0;
    for (int y = r.y0; y < r.y1; ++y) {
      for (int x = r.x0; x < r.x1; ++x) {
        const auto i = static_cast<std::size_t>((y - r.y0) * r.width() + (x - r.x0));
        const int c = classes.classOf[stencil[i]];
        ++counts[static_cast<std::size_t>(c)];
        if (c != 2 && c != 5)
          continue;
        x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
        std::uint32_t lo = nearDepth[i], hi = farDepth[i];
        if (lo > hi) {
          ++inverted;
          lo = hi = (lo + hi) / 2;  // both below 2^31 here: the sum cannot wrap
        }
        nearest = std::min(nearest, lo);
        farthest = std::max(farthest, hi);
        longest = std::max(longest, hi - lo);
      }
    }
    for (int c = 0; c < kMaxStencilClasses; ++c)
      CHECK(s.classCounts[static_cast<std::size_t>(c)] == counts[static_cast<std::size_t>(c)]);
    if (x1 < 0) {
      CHECK(s.markedBounds.empty());
      CHECK(!s.depth);
      continue;
    }
    CHECK(s.markedBounds == PixelRect{x0, y0, x1 + 1, y1 + 1});
    REQUIRE(s.depth);
    CHECK(*s.depth == DepthIntervals{nearest, farthest, longest, inverted});
    // The words there and back.
    const auto words = packPixelSummary(s);
    CHECK(unpackPixelSummary(words, r, true, "test") == s);
  }
}

TEST_CASE("the inverted-interval midpoint rounds down and cannot overflow", "[raster][summary]") {
  CHECK(intervalMidpoint(5, 2) == 3);
  CHECK(intervalMidpoint(7, 3) == 5);
  CHECK(intervalMidpoint(0xFFFFFFFFu, 0xFFFFFFFDu) == 0xFFFFFFFEu);
}

TEST_CASE("summaries refuse what cannot be a summary", "[raster][summary]") {
  const PixelRect r{0, 0, 2, 2};
  const std::vector<std::uint8_t> stencil(4, 0);
  StencilClasses bad = someClasses();
  bad.classOf[200] = kMaxStencilClasses;
  CHECK_THROWS_WITH(summarizePixels(r, stencil, {}, {}, bad),
                    "summarizePixels: stencil value 200 has class 10, not below 10");
  CHECK_THROWS_AS(summarizePixels(r, std::vector<std::uint8_t>(3, 0), {}, {}, someClasses()),
                  std::invalid_argument);
  // Counts that do not add up to the rectangle, bounds outside it, a depth that is no depth.
  std::array<std::uint32_t, kPixelSummaryWords> words{};
  words[0] = 3;
  CHECK_THROWS_WITH(unpackPixelSummary(words, r, false, "GPU"),
                    "GPU: a pixel summary over 2 x 2 pixels came back with class counts adding up "
                    "to 3");
  words[0] = 4;
  words[10] = 0u | (5u << 16);
  words[11] = 0u | (1u << 16);
  CHECK_THROWS_WITH(unpackPixelSummary(words, r, false, "GPU"),
                    "GPU: a pixel summary over 2 x 2 pixels came back with marked bounds "
                    "outside it");
  words[10] = 0u | (1u << 16);
  words[12] = kSummaryBadDepth;
  CHECK_THROWS_WITH(unpackPixelSummary(words, r, true, "GPU"),
                    "GPU: a pixel summary over 2 x 2 pixels came back with a depth buffer value "
                    "that is not a multiple of 2^-24 below 1");
}

TEST_CASE("the interface's summaries come from its read-backs on any device", "[raster][summary]") {
  CpuDevice device(6, 5);
  device.setScissor({1, 1, 5, 4});
  device.clearStencil(9);  // class 2: marked
  device.clearDepth(0.25);
  const std::shared_ptr<const KeptDepth> nearEnd = device.keepDepthLater({0, 0, 6, 5});
  device.clearDepth(0.75);
  const PixelSummary s =
      device.summarizeLater({0, 0, 6, 5}, someClasses(), nearEnd.get()).take().front();
  CHECK(s.classCounts[2] == 12);
  CHECK(s.classCounts[0] == 18);
  CHECK(s.markedBounds == PixelRect{1, 1, 5, 4});
  REQUIRE(s.depth);
  CHECK(s.depth->nearest == 4194304u);    // 0.25 in 2^-24 steps
  CHECK(s.depth->farthest == 12582911u);  // 0.75 (2^24 - 1), rounded
  CHECK(s.depth->inverted == 0);
  // A near end kept over another rectangle is refused.
  const std::shared_ptr<const KeptDepth> other = device.keepDepthLater({0, 0, 3, 3});
  CHECK_THROWS_AS(device.summarizeLater({0, 0, 6, 5}, someClasses(), other.get()),
                  std::invalid_argument);
}
