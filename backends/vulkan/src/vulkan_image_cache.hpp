#pragma once
// Depth/stencil images kept from Vulkan devices that are gone, for the next devices: a run's
// pair frames change size as blocks move, and a new image costs its allocation and the first
// touch of its pages (page faults and page clearing were among the largest costs of a
// random-shapes frame on lavapipe), where taking a kept one costs a clear.

#include <vulkan/vulkan_core.h>

#include <mutex>
#include <optional>
#include <vector>

#include "recode/backends/vulkan_shader_arithmetic.hpp"

namespace recode::backends::detail {

// A depth/stencil image with its memory and view, of a capacity at least the device's size: the
// device draws in its first width x height texels (framebuffer rows 0 to height - 1 hold GL rows
// height - 1 to 0) and never reads or writes beyond them.
struct ImageSlot {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  int capacityWidth = 0;
  int capacityHeight = 0;
};

class ImageCache {
 public:
  // The smallest kept image that holds width x height, if any.
  std::optional<ImageSlot> take(int width, int height);
  // Keeps the image, unless kMaxKept are kept or it is larger than kMaxKeptPixels: then
  // returns it, for the caller to destroy.
  std::optional<ImageSlot> give(const ImageSlot& slot);

  static constexpr std::size_t kMaxKept = 16;
  static constexpr long long kMaxKeptPixels = 4096LL * 4096LL;

 private:
  std::mutex lock_;
  std::vector<ImageSlot> slots_;
};

// The process's cache of images made on that arithmetic's logical device, never destroyed (as
// the context).
[[nodiscard]] ImageCache& imageCache(ShaderArithmetic arithmetic);

// The side a new image is made for `size` pixels: a multiple of 64 (at most the largest
// framebuffer), so that the next sizes fit it.
[[nodiscard]] int capacityFor(int size);

}  // namespace recode::backends::detail
