// A draw's rasterized triangles and blocks, kept for replays (draw_recording.hpp).
#include "recode/raster/draw_recording.hpp"

namespace recode::raster {

void DrawRecording::start(std::uint64_t key, const PixelRect& scissor) {
  clear();
  key_ = key;
  scissor_ = scissor;
}

void DrawRecording::addTriangle(const TriangleSetup& triangle) {
  if (overflowed_)
    return;
  const Triangle next{triangle.depth, triangle.frontFacing,
                      static_cast<std::uint32_t>(blocks_.size())};
  // The triangle before covered no pixel (a sub-pixel triangle between centres, as many of a
  // fine mesh are): a replay would skip it anyway, so it is not kept.
  if (lastTriangleCoveredNothing())
    triangles_.back() = next;
  else
    triangles_.push_back(next);
}

void DrawRecording::addBlock(int x, int y, std::uint64_t mask) {
  if (overflowed_)
    return;
  if (blocks_.size() >= kMaxBlocks) {
    overflowed_ = true;
    return;
  }
  blocks_.push_back({x, y, mask});
}

void DrawRecording::finish() {
  complete_ = !overflowed_;
  if (lastTriangleCoveredNothing())
    triangles_.pop_back();
}

void DrawRecording::clear() {
  key_ = 0;
  complete_ = false;
  overflowed_ = false;
  triangles_.clear();
  blocks_.clear();
}

bool DrawRecording::serves(std::uint64_t key, const PixelRect& scissor) const {
  if (key == 0 || key != key_ || !complete_)
    return false;
  // An empty scissor draws nothing whatever was recorded.
  return scissor.empty() || scissor_.intersect(scissor) == scissor;
}

}  // namespace recode::raster
