// DepthStencilImage: a graphics device's depth/stencil attachment and its read-backs.
#include "vulkan_depth_stencil_image.hpp"

#include <cstring>
#include <optional>
#include <utility>

namespace recode::backends::detail {

namespace {

constexpr VkImageAspectFlags kBothAspects = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;

}  // namespace

DepthStencilImage::DepthStencilImage(VulkanContext& context, CommandRecorder& recorder,
                                     ImageCache& cache, VkFormat format, int width, int height,
                                     VkClearDepthStencilValue start)
    : context_(context), recorder_(recorder), cache_(cache), width_(width), height_(height) {
  const std::optional<ImageSlot> kept = cache_.take(width, height);
  slot_ = kept ? *kept : makeImage(format, capacityFor(width), capacityFor(height));
  initialise(kept.has_value(), start);
}

DepthStencilImage::~DepthStencilImage() {
  // Commands recorded for this image must run before it goes: they are in the shared recording,
  // beside other devices' commands.
  try {
    recorder_.finish();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw
  }
  if (std::optional<ImageSlot> unkept = cache_.give(slot_)) {
    vkDestroyImageView(context_.device(), unkept->view, nullptr);
    vkDestroyImage(context_.device(), unkept->image, nullptr);
    vkFreeMemory(context_.device(), unkept->memory, nullptr);
  }
}

ImageSlot DepthStencilImage::makeImage(VkFormat format, int capacityWidth,
                                       int capacityHeight) const {
  const VkDevice device = context_.device();
  ImageSlot made;
  made.capacityWidth = capacityWidth;
  made.capacityHeight = capacityHeight;
  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {static_cast<std::uint32_t>(capacityWidth),
                 static_cast<std::uint32_t>(capacityHeight), 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
               VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  vkCheck(vkCreateImage(device, &info, nullptr, &made.image), "vkCreateImage");
  VkMemoryRequirements requirements{};
  vkGetImageMemoryRequirements(device, made.image, &requirements);
  made.memory = context_.allocate(requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  vkCheck(vkBindImageMemory(device, made.image, made.memory, 0), "vkBindImageMemory");
  VkImageViewCreateInfo viewInfo{};
  viewInfo.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
  viewInfo.image = made.image;
  viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = format;
  viewInfo.subresourceRange = {kBothAspects, 0, 1, 0, 1};
  vkCheck(vkCreateImageView(device, &viewInfo, nullptr, &made.view), "vkCreateImageView");
  return made;
}

// GENERAL layout (a kept image is in it already), then `start` everywhere.
void DepthStencilImage::initialise(bool reused, VkClearDepthStencilValue start) {
  const VkImage image = slot_.image;
  recorder_.record(image, [&](VkCommandBuffer cmd) {
    const VkImageSubresourceRange range{kBothAspects, 0, 1, 0, 1};
    if (!reused) {
      VkImageMemoryBarrier barrier{};
      barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
      barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
      barrier.newLayout = VK_IMAGE_LAYOUT_GENERAL;
      barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      barrier.image = image;
      barrier.subresourceRange = range;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                           0, 0, nullptr, 0, nullptr, 1, &barrier);
    }
    vkCmdClearDepthStencilImage(cmd, image, VK_IMAGE_LAYOUT_GENERAL, &start, 1, &range);
  });
}

VkRect2D DepthStencilImage::framebufferRect(const raster::PixelRect& r) const {
  return {{r.x0, height_ - r.y1},
          {static_cast<std::uint32_t>(r.width()), static_cast<std::uint32_t>(r.height())}};
}

void DepthStencilImage::beginRendering(VkCommandBuffer cmd) const {
  VkRenderingAttachmentInfo attachment{};
  attachment.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
  attachment.imageView = slot_.view;
  attachment.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
  attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  VkRenderingInfo rendering{};
  rendering.sType = VK_STRUCTURE_TYPE_RENDERING_INFO;
  rendering.renderArea = {
      {0, 0}, {static_cast<std::uint32_t>(width_), static_cast<std::uint32_t>(height_)}};
  rendering.layerCount = 1;
  rendering.pDepthAttachment = &attachment;
  rendering.pStencilAttachment = &attachment;
  vkCmdBeginRendering(cmd, &rendering);
}

VkBufferImageCopy DepthStencilImage::aspectCopy(const raster::PixelRect& r,
                                                VkImageAspectFlags aspect,
                                                VkDeviceSize offset) const {
  const VkRect2D source = framebufferRect(r);
  VkBufferImageCopy region{};
  region.bufferOffset = offset;
  region.imageSubresource = {aspect, 0, 0, 1};
  region.imageOffset = {source.offset.x, source.offset.y, 0};
  region.imageExtent = {source.extent.width, source.extent.height, 1};
  return region;
}

void DepthStencilImage::readAspect(const raster::PixelRect& r, VkImageAspectFlags aspect,
                                   std::size_t texel,
                                   std::function<void(std::vector<std::uint8_t>)> deliver) const {
  const std::size_t rowBytes = static_cast<std::size_t>(r.width()) * texel;
  const std::size_t bytes = rowBytes * static_cast<std::size_t>(r.height());
  const int h = r.height();
  recorder_.readBack(slot_.image, aspect, aspectCopy(r, aspect, 0), bytes,
                     [rowBytes, bytes, h, deliver = std::move(deliver)](const std::uint8_t* rows) {
                       std::vector<std::uint8_t> out(bytes);
                       for (int k = 0; k < h; ++k) {
                         std::memcpy(out.data() + static_cast<std::size_t>(k) * rowBytes,
                                     rows + static_cast<std::size_t>(h - 1 - k) * rowBytes,
                                     rowBytes);
                       }
                       deliver(std::move(out));
                     });
}

}  // namespace recode::backends::detail
