// summarizePixels, the definition every device's summary matches, and its 16 words.
#include "recode/raster/pixel_summary.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace recode::raster {

namespace {

void requireSize(std::size_t size, const PixelRect& rect, const char* what) {
  if (size != static_cast<std::size_t>(rect.area()))
    throw std::invalid_argument(std::string("summarizePixels: ") + what + " holds " +
                                std::to_string(size) + " values for a rectangle of " +
                                std::to_string(rect.area()) + " pixels");
}

}  // namespace

PixelSummary summarizePixels(const PixelRect& rect, std::span<const std::uint8_t> stencil,
                             std::span<const std::uint32_t> nearDepth,
                             std::span<const std::uint32_t> farDepth,
                             const StencilClasses& classes) {
  requireSize(stencil.size(), rect, "the stencil");
  const bool withDepth = !nearDepth.empty() || !farDepth.empty();
  if (withDepth) {
    requireSize(nearDepth.size(), rect, "the near depth");
    requireSize(farDepth.size(), rect, "the far depth");
  }
  requireStencilClasses(classes, "summarizePixels");
  PixelSummary s;
  PixelRect bounds{rect.x1, rect.y1, rect.x0, rect.y0};  // grows from inside out
  DepthIntervals depth{0xFFFFFFFFu, 0, 0, 0};
  bool anyMarked = false;
  std::size_t i = 0;
  for (int y = rect.y0; y < rect.y1; ++y) {
    for (int x = rect.x0; x < rect.x1; ++x, ++i) {
      const std::uint8_t c = classes.classOf[stencil[i]];
      ++s.classCounts[c];
      if (((classes.marked >> c) & 1u) == 0)
        continue;
      anyMarked = true;
      bounds = {std::min(bounds.x0, x), std::min(bounds.y0, y), std::max(bounds.x1, x + 1),
                std::max(bounds.y1, y + 1)};
      if (!withDepth)
        continue;
      std::uint32_t lo = nearDepth[i], hi = farDepth[i];
      if (lo > hi) {
        ++depth.inverted;
        lo = hi = intervalMidpoint(lo, hi);
      }
      depth.nearest = std::min(depth.nearest, lo);
      depth.farthest = std::max(depth.farthest, hi);
      depth.longest = std::max(depth.longest, hi - lo);
    }
  }
  if (anyMarked) {
    s.markedBounds = bounds;
    if (withDepth)
      s.depth = depth;
  }
  return s;
}

void requireStencilClasses(const StencilClasses& classes, const char* caller) {
  for (std::size_t v = 0; v < classes.classOf.size(); ++v)
    if (classes.classOf[v] >= kMaxStencilClasses)
      throw std::invalid_argument(std::string(caller) + ": stencil value " + std::to_string(v) +
                                  " has class " + std::to_string(classes.classOf[v]) +
                                  ", not below " + std::to_string(kMaxStencilClasses));
}

std::array<std::uint32_t, kPixelSummaryWords> packPixelSummary(const PixelSummary& summary) {
  std::array<std::uint32_t, kPixelSummaryWords> words{};
  std::copy(summary.classCounts.begin(), summary.classCounts.end(), words.begin());
  const PixelRect& b = summary.markedBounds;
  if (!b.empty()) {
    words[kMaxStencilClasses] =
        static_cast<std::uint32_t>(b.x0) | (static_cast<std::uint32_t>(b.x1) << 16);
    words[kMaxStencilClasses + 1] =
        static_cast<std::uint32_t>(b.y0) | (static_cast<std::uint32_t>(b.y1) << 16);
  }
  if (summary.depth) {
    words[12] = summary.depth->nearest;
    words[13] = summary.depth->farthest;
    words[14] = summary.depth->longest;
    words[15] = summary.depth->inverted;
  }
  return words;
}

PixelSummary unpackPixelSummary(std::span<const std::uint32_t> words, const PixelRect& rect,
                                bool withDepth, const char* device) {
  const auto refuse = [&](const std::string& what) {
    throw std::runtime_error(std::string(device) + ": a pixel summary over " +
                             std::to_string(rect.width()) + " x " + std::to_string(rect.height()) +
                             " pixels came back with " + what);
  };
  if (words.size() != kPixelSummaryWords)
    refuse(std::to_string(words.size()) + " words, not " + std::to_string(kPixelSummaryWords));
  PixelSummary s;
  long long total = 0;
  for (int c = 0; c < kMaxStencilClasses; ++c) {
    s.classCounts[static_cast<std::size_t>(c)] = words[static_cast<std::size_t>(c)];
    total += words[static_cast<std::size_t>(c)];
  }
  if (total != rect.area())
    refuse("class counts adding up to " + std::to_string(total));
  const std::uint32_t xs = words[kMaxStencilClasses], ys = words[kMaxStencilClasses + 1];
  const PixelRect bounds{static_cast<int>(xs & 0xFFFFu), static_cast<int>(ys & 0xFFFFu),
                         static_cast<int>(xs >> 16), static_cast<int>(ys >> 16)};
  if (!bounds.empty()) {
    if (bounds.intersect(rect) != bounds)
      refuse("marked bounds outside it");
    s.markedBounds = bounds;
  }
  if (withDepth && !bounds.empty()) {
    DepthIntervals d{words[12], words[13], words[14], words[15]};
    if (d.nearest == kSummaryBadDepth)
      refuse("a depth buffer value that is not a multiple of 2^-24 below 1");
    s.depth = d;
  }
  return s;
}

}  // namespace recode::raster
