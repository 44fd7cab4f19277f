#pragma once
// The depth/stencil attachment of a Vulkan graphics device (the exact VulkanDevice and the native
// VulkanNativeDevice): an image of some depth/stencil format from an ImageCache or made anew, in
// GENERAL layout for its whole life (attachments and transfers need no layout transitions; the
// recorder's barriers order the commands), with what both devices do to it through the shared
// recording: open a rendering on it, map GL window rectangles onto it, read an aspect back.
//
// Coordinates: the interface speaks GL window coordinates (row 0 at the bottom); Vulkan's
// framebuffer has row 0 at the top. GL row j is framebuffer row height - 1 - j: rectangles are
// mirrored here, and read-backs are returned bottom row first.

#include <vulkan/vulkan_core.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "recode/raster/state.hpp"
#include "vulkan_context.hpp"
#include "vulkan_image_cache.hpp"
#include "vulkan_recorder.hpp"

namespace recode::backends::detail {

class DepthStencilImage {
 public:
  // A width x height attachment of `format` on `context`, taken from `cache` when it keeps one
  // large enough, else made (of capacityFor's size); every texel set to `start` by a command
  // recorded on `recorder`.
  DepthStencilImage(VulkanContext& context, CommandRecorder& recorder, ImageCache& cache,
                    VkFormat format, int width, int height, VkClearDepthStencilValue start);
  // Runs what is recorded (this image's commands are in the shared recording), then gives the
  // image back to its cache, or destroys it when the cache is full.
  ~DepthStencilImage();
  DepthStencilImage(const DepthStencilImage&) = delete;
  DepthStencilImage& operator=(const DepthStencilImage&) = delete;

  [[nodiscard]] VkImage image() const { return slot_.image; }
  [[nodiscard]] VkImageView view() const { return slot_.view; }

  // A GL-window rectangle (inside the framebuffer) as a framebuffer rectangle.
  [[nodiscard]] VkRect2D framebufferRect(const raster::PixelRect& r) const;

  // Records vkCmdBeginRendering over width x height with this image as depth and stencil
  // attachment, loaded and stored (the recorder's `beginRendering`).
  void beginRendering(VkCommandBuffer cmd) const;

  // A copy of `aspect` over r into a buffer at `offset` (rows from the image's top down).
  [[nodiscard]] VkBufferImageCopy aspectCopy(const raster::PixelRect& r, VkImageAspectFlags aspect,
                                             VkDeviceSize offset) const;

  // Records a read-back of `aspect` over r (inside the framebuffer), `texel` bytes a pixel;
  // `deliver` gets the bytes, rows bottom first (the copy holds them top first), when the
  // recording has run.
  void readAspect(const raster::PixelRect& r, VkImageAspectFlags aspect, std::size_t texel,
                  std::function<void(std::vector<std::uint8_t>)> deliver) const;

 private:
  [[nodiscard]] ImageSlot makeImage(VkFormat format, int capacityWidth, int capacityHeight) const;
  void initialise(bool reused, VkClearDepthStencilValue start);

  VulkanContext& context_;
  CommandRecorder& recorder_;
  ImageCache& cache_;
  int width_;
  int height_;
  ImageSlot slot_;
};

}  // namespace recode::backends::detail
