// Cutting a framebuffer's commands into epochs (tile_frame_epochs.hpp).

#include "tile_frame_epochs.hpp"

#include <algorithm>

namespace recode::backends::detail {

namespace {

using raster::PixelRect;

bool contains(const PixelRect& outer, const PixelRect& inner) {
  return inner.x0 >= outer.x0 && inner.y0 >= outer.y0 && inner.x1 <= outer.x1 &&
         inner.y1 <= outer.y1;
}

bool meets(const PixelRect& a, const PixelRect& b) {
  return !a.intersect(b).empty();
}

// Whether commands i and i + 1 reset depth and every stencil bit over one rectangle.
bool resetsAt(const std::vector<EpochCommand>& c, std::size_t i) {
  if (i + 1 >= c.size() || c[i].rect != c[i + 1].rect)
    return false;
  const auto depth = [](const EpochCommand& e) { return e.kind == TileCommandKind::ClearDepth; };
  const auto stencil = [](const EpochCommand& e) {
    return e.kind == TileCommandKind::ClearStencil && e.fullStencilClear;
  };
  return (depth(c[i]) && stencil(c[i + 1])) || (stencil(c[i]) && depth(c[i + 1]));
}

}  // namespace

EpochCommand epochCommandOf(const TileCommand& command, const PixelRect& rect) {
  EpochCommand e;
  e.kind = command.kind;
  e.rect = rect;
  e.fullStencilClear = command.kind == TileCommandKind::ClearStencil && command.clearMask == 0xFFu;
  return e;
}

PixelRect unite(const PixelRect& a, const PixelRect& b) {
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

std::vector<EpochSpan> cutIntoEpochs(const std::vector<EpochCommand>& commands) {
  // The runs between resets, each with the rectangle of its reset (if it starts with one) and
  // the bounding box of its commands.
  std::vector<EpochSpan> epochs;
  std::size_t begin = 0;
  while (begin < commands.size()) {
    const bool reset = resetsAt(commands, begin);
    std::size_t end = begin + (reset ? 2 : 1);
    while (end < commands.size() && !resetsAt(commands, end))
      ++end;
    PixelRect bounds = commands[begin].rect;
    for (std::size_t c = begin + 1; c < end; ++c)
      bounds = unite(bounds, commands[c].rect);
    if (reset && contains(commands[begin].rect, bounds)) {
      epochs.push_back({begin, end, commands[begin].rect, false, false});
    } else {
      // Joined to the epochs before it until one holds everything joined, or none is left.
      EpochSpan joined{begin, end, bounds, true, false};
      while (!epochs.empty()) {
        EpochSpan& last = epochs.back();
        if (last.loads || contains(last.footprint, joined.footprint)) {
          last.end = end;
          if (last.loads)
            last.footprint = unite(last.footprint, joined.footprint);
          break;
        }
        joined.begin = last.begin;
        joined.footprint = unite(joined.footprint, last.footprint);
        epochs.pop_back();
      }
      if (epochs.empty() || epochs.back().end != end)
        epochs.push_back(joined);
    }
    begin = end;
  }
  if (epochs.size() <= kMostEpochsCompared) {
    for (std::size_t i = 0; i < epochs.size(); ++i) {
      bool alone = true;
      for (std::size_t j = 0; j < epochs.size() && alone; ++j)
        alone = i == j || !meets(epochs[i].footprint, epochs[j].footprint);
      epochs[i].alone = alone;
    }
  }
  return epochs;
}

}  // namespace recode::backends::detail
