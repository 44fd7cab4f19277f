// The images of destroyed Vulkan devices, kept for the next devices.
#include "vulkan_image_cache.hpp"

#include <algorithm>

#include "recode/raster/device_checks.hpp"

namespace recode::backends::detail {

namespace {

long long area(const ImageSlot& s) {
  return static_cast<long long>(s.capacityWidth) * s.capacityHeight;
}

}  // namespace

std::optional<ImageSlot> ImageCache::take(int width, int height) {
  const std::lock_guard<std::mutex> hold(lock_);
  auto best = slots_.end();
  for (auto it = slots_.begin(); it != slots_.end(); ++it) {
    if (it->capacityWidth < width || it->capacityHeight < height)
      continue;
    if (best == slots_.end() || area(*it) < area(*best))
      best = it;
  }
  if (best == slots_.end())
    return std::nullopt;
  const ImageSlot slot = *best;
  slots_.erase(best);
  return slot;
}

std::optional<ImageSlot> ImageCache::give(const ImageSlot& slot) {
  const std::lock_guard<std::mutex> hold(lock_);
  if (slots_.size() >= kMaxKept || area(slot) > kMaxKeptPixels)
    return slot;
  slots_.push_back(slot);
  return std::nullopt;
}

ImageCache& imageCache(ShaderArithmetic arithmetic) {
  static ImageCache* caches = new ImageCache[kShaderArithmeticCount];  // leaked, as the context
  return caches[indexOf(arithmetic)];
}

int capacityFor(int size) {
  constexpr int kStep = 64;
  return std::min((size + kStep - 1) / kStep * kStep, raster::kMaxFramebufferSize);
}

}  // namespace recode::backends::detail
