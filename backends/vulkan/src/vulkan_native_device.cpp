// VulkanNativeDevice: the device interface mapped one to one onto Vulkan's graphics pipeline, as
// GlDevice maps it onto GL's fixed-function state. The host validates and snaps the vertices;
// native_vk.vert only undoes the viewport transform; the driver clips, rasterizes, interpolates
// depth and converts it, and its fixed-function depth and stencil units, scissor and culling (all
// dynamic state) apply the rest. The attachment, the recording and the read-backs are the exact
// Vulkan device's (vulkan_depth_stencil_image.hpp, vulkan_recorder.hpp), and so is the y flip: GL
// row j is framebuffer row height - 1 - j, through a viewport of negative height.

#include "recode/backends/vulkan_native_device.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "recode/raster/device_checks.hpp"
#include "recode/raster/fixed_point.hpp"
#include "vulkan_context.hpp"
#include "vulkan_depth_stencil_image.hpp"
#include "vulkan_draw_state.hpp"
#include "vulkan_image_cache.hpp"
#include "vulkan_native_pipeline.hpp"
#include "vulkan_recorder.hpp"

namespace recode::backends {

namespace {

using raster::PixelRect;

// The logical device, recording and image cache of the native devices: the ones that ask for
// no 64-bit shader arithmetic (native_vk.vert uses none), shared with the vulkan-32 device.
constexpr ShaderArithmetic kArithmetic = ShaderArithmetic::Emulated32;

// What a depth/stencil attachment needs of its format: the attachment itself, the read-backs
// (transfer source) and the first clear of a new image (transfer destination).
constexpr VkFormatFeatureFlags kAttachmentFeatures =
    VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT |
    VK_FORMAT_FEATURE_TRANSFER_DST_BIT;

// D24_UNORM_S8_UINT, the format of GL's DEPTH24_STENCIL8 and of the contract's buffers, where the
// driver can render to it and copy it out; else D32_SFLOAT_S8_UINT, which the context requires
// (the exact devices' format), its float depth rounded to 24 bits on read-back.
VkFormat chooseFormat(const detail::VulkanContext& context) {
  const VkFormatFeatureFlags d24 = context.optimalFeatures(VK_FORMAT_D24_UNORM_S8_UINT);
  return (d24 & kAttachmentFeatures) == kAttachmentFeatures ? VK_FORMAT_D24_UNORM_S8_UINT
                                                            : VK_FORMAT_D32_SFLOAT_S8_UINT;
}

// What every native device of the process shares: the format, its pipelines and the images of
// devices that are gone (of that format, so not the exact devices' cache). Made on first use and
// never destroyed, as the context.
struct NativeShared {
  detail::VulkanContext* context = nullptr;
  detail::CommandRecorder* recorder = nullptr;
  VkFormat format = VK_FORMAT_UNDEFINED;
  detail::NativePipelines pipelines;
  detail::ImageCache* cache = nullptr;
};

const NativeShared& shared() {
  static const NativeShared* made = [] {
    auto* s = new NativeShared;
    s->context = &detail::VulkanContext::instance(kArithmetic);
    s->recorder = &detail::sharedRecorder(kArithmetic);
    s->format = chooseFormat(*s->context);
    s->pipelines = detail::createNativePipelines(s->context->device(), s->format);
    s->cache = new detail::ImageCache;
    return s;
  }();
  return *made;
}

// One axis of the viewport, in GL window coordinates: the largest power of two the driver allows,
// centred on the framebuffer, as the GL device places its own. A vertex within size / 2 of the
// centre is inside the view volume, so the driver draws it as given and never clips it (a
// clipped triangle gets new, off-grid vertices); a viewport the size of the framebuffer would
// clip at the framebuffer's edge wherever the driver has no guard band.
struct ViewportAxis {
  int origin = 0;
  int size = 1;
  [[nodiscard]] float centre() const { return static_cast<float>(origin + size / 2); }
};

ViewportAxis viewportAxis(int framebuffer, std::uint32_t maxSize) {
  ViewportAxis axis;
  while (static_cast<std::uint32_t>(axis.size) * 2 <= maxSize)
    axis.size *= 2;
  if (axis.size < framebuffer)
    throw std::runtime_error("Vulkan native device: maxViewportDimensions " +
                             std::to_string(maxSize) + " is smaller than the framebuffer's " +
                             std::to_string(framebuffer) + " pixels");
  axis.origin = -(axis.size - framebuffer) / 2;
  return axis;
}

const char* formatName(VkFormat format) {
  return format == VK_FORMAT_D24_UNORM_S8_UINT ? "D24_UNORM_S8_UINT" : "D32_SFLOAT_S8_UINT";
}

VkCullModeFlags vkCullMode(raster::CullMode mode) {
  switch (mode) {
    case raster::CullMode::Front:
      return VK_CULL_MODE_FRONT_BIT;
    case raster::CullMode::Back:
      return VK_CULL_MODE_BACK_BIT;
    case raster::CullMode::None:
      break;
  }
  return VK_CULL_MODE_NONE;
}

// The 24-bit depths of a depth aspect's copy: D24_UNORM_S8_UINT copies out as 32-bit words with
// the depth in the low 24 bits (the high 8 undefined); D32_SFLOAT_S8_UINT as floats, which are
// rounded to the nearest 24-bit step as a UNORM conversion would (half away from zero).
std::vector<std::uint32_t> depthFromCopy(const std::vector<std::uint8_t>& bytes, VkFormat format) {
  std::vector<std::uint32_t> out(bytes.size() / 4);
  if (format == VK_FORMAT_D24_UNORM_S8_UINT) {
    std::memcpy(out.data(), bytes.data(), 4 * out.size());
    for (std::uint32_t& word : out)
      word &= raster::kDepthMax;
    return out;
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    float stored = 0.0f;
    std::memcpy(&stored, bytes.data() + 4 * k, 4);
    const double scaled = std::clamp(static_cast<double>(stored), 0.0, 1.0) * raster::kDepthMax;
    out[k] = static_cast<std::uint32_t>(std::lround(scaled));
  }
  return out;
}

// Indices drawn at a time (whole triangles): a draw's staging stays well inside the recorder's
// flush size, and its index count inside vkCmdDrawIndexed's, however large the draw.
constexpr std::size_t kIndicesPerDraw = 3 * (std::size_t{1} << 20);

}  // namespace

struct VulkanNativeDevice::Impl {
  int width = 0;
  int height = 0;
  const raster::RenderState* state = nullptr;  // the device's (RenderStateDevice::state_)
  const NativeShared* shared = nullptr;
  detail::CommandRecorder* recorder = nullptr;
  raster::TransferCounters transfers;  // what this device's calls made the recorder do
  std::optional<detail::DepthStencilImage> target;
  VkViewport viewport{};
  detail::WindowPushConstants window{};
  // A draw's vertices (x, y, z as floats) then its indices, staged as one block; reused.
  std::vector<std::uint8_t> drawScratch;

  // Runs `call` on the recorder, counting what it made the recorder do as this device's.
  template <typename Call>
  decltype(auto) counted(Call&& call) {
    return detail::countedOn(*recorder, transfers, std::forward<Call>(call));
  }

  // The viewport (vulkan_native_pipeline.hpp): GL's P x Q viewport at (ox, oy), mirrored onto
  // the framebuffer as (ox, height - oy) with height -Q, and depth 0..1, so that window z is clip
  // z. native_vk.vert maps x to (x - cx) 2/P, which the driver's transform maps back to x, and
  // y to framebuffer row height - y.
  void placeViewport() {
    const VkPhysicalDeviceLimits& limits = shared->context->limits();
    const ViewportAxis x = viewportAxis(width, limits.maxViewportDimensions[0]);
    const ViewportAxis y = viewportAxis(height, limits.maxViewportDimensions[1]);
    viewport = {static_cast<float>(x.origin),
                static_cast<float>(height - y.origin),
                static_cast<float>(x.size),
                -static_cast<float>(y.size),
                0.0f,
                1.0f};
    window = {{x.centre(), y.centre()},
              {2.0f / static_cast<float>(x.size), 2.0f / static_cast<float>(y.size)}};
  }

  // Records `body` as draws of the open rendering on this device's attachment, with `pipeline`
  // bound, the viewport, the scissor, no culling (a draw sets its own) and the push constants.
  template <typename Body>
  void render(VkPipeline pipeline, const Body& body) {
    const auto beginRendering = [&](VkCommandBuffer cmd) { target->beginRendering(cmd); };
    recorder->render(target->image(), target->view(), beginRendering, [&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
      vkCmdSetViewport(cmd, 0, 1, &viewport);
      const VkRect2D scissor = target->framebufferRect(state->scissor);
      vkCmdSetScissor(cmd, 0, 1, &scissor);
      vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
      vkCmdPushConstants(cmd, shared->pipelines.layout, VK_SHADER_STAGE_VERTEX_BIT, 0,
                         sizeof window, &window);
      body(cmd);
    });
  }

  // Stages drawScratch (`vertexBytes` of vertices, then `count` indices) and draws the indices
  // as a triangle list in the state set. One block, so that no flush of the recording can come
  // between the vertices and the indices.
  void drawIndexed(std::size_t vertexBytes, std::size_t count) {
    // No other thread's finish() may come between the staging and the draw that reads it.
    const auto hold = recorder->hold();
    const detail::CommandRecorder::Staged staged =
        counted([&] { return recorder->stage(drawScratch.data(), drawScratch.size()); });
    // Vulkan keeps primitive order for depth and stencil (rasterization order), within a draw and
    // from one draw to the next in a rendering: triangles reach each pixel in index order.
    render(shared->pipelines.draw, [&](VkCommandBuffer cmd) {
      detail::setDepthStencilState(cmd, *state);
      vkCmdSetCullMode(cmd, vkCullMode(state->cull));
      vkCmdBindVertexBuffers(cmd, 0, 1, &staged.buffer, &staged.offset);
      vkCmdBindIndexBuffer(cmd, staged.buffer, staged.offset + vertexBytes, VK_INDEX_TYPE_UINT32);
      vkCmdDrawIndexed(cmd, static_cast<std::uint32_t>(count), 1, 0, 0, 0);
    });
  }

  // Records a read-back of one aspect of a GL-window rectangle, counted as this device's.
  void readAspect(const PixelRect& r, VkImageAspectFlags aspect, std::size_t texel,
                  std::function<void(std::vector<std::uint8_t>)> deliver) {
    counted([&] { target->readAspect(r, aspect, texel, std::move(deliver)); });
  }
};

VulkanNativeDevice::VulkanNativeDevice(int width, int height)
    : RenderStateDevice(width, height), impl_(std::make_unique<Impl>()) {
  raster::checkFramebufferSize(width, height);
  Impl& d = *impl_;
  d.width = width;
  d.height = height;
  d.state = &state_;
  d.shared = &shared();  // makes the context too
  d.recorder = d.shared->recorder;
  d.placeViewport();
  // Depth 1.0 (2^24 - 1 in either format) and stencil 0, as CpuDevice starts.
  d.target.emplace(*d.shared->context, *d.recorder, *d.shared->cache, d.shared->format, width,
                   height, VkClearDepthStencilValue{1.0f, 0});
}

VulkanNativeDevice::~VulkanNativeDevice() = default;

int VulkanNativeDevice::width() const {
  return impl_->width;
}

int VulkanNativeDevice::height() const {
  return impl_->height;
}

std::string VulkanNativeDevice::renderer() const {
  return impl_->shared->context->deviceName();
}

std::string VulkanNativeDevice::depthStencilFormat() const {
  return formatName(impl_->shared->format);
}

void VulkanNativeDevice::clearDepth(double depth) {
  if (!std::isfinite(depth))
    throw std::invalid_argument("clearDepth: value is not finite");
  Impl& d = *impl_;
  // The depth write mask applies to clears: with it off, a depth clear changes nothing.
  if (!state_.depthWrite || state_.scissor.empty())
    return;
  // GL clamps the clear depth to [0, 1]; Vulkan requires it there. The driver converts it.
  const float value = static_cast<float>(std::clamp(depth, 0.0, 1.0));
  d.render(d.shared->pipelines.clear, [&](VkCommandBuffer cmd) {
    detail::clearAttachmentRect(cmd, VK_IMAGE_ASPECT_DEPTH_BIT, {value, 0},
                                d.target->framebufferRect(state_.scissor));
  });
}

void VulkanNativeDevice::clearStencil(std::uint8_t value) {
  Impl& d = *impl_;
  if (state_.stencilWriteMask == 0 || state_.scissor.empty())
    return;
  d.render(d.shared->pipelines.clear, [&](VkCommandBuffer cmd) {
    if (state_.stencilWriteMask == 0xFF) {  // every bit written: a clear of the open rendering
      detail::clearAttachmentRect(cmd, VK_IMAGE_ASPECT_STENCIL_BIT, {0.0f, value},
                                  d.target->framebufferRect(state_.scissor));
    } else {  // vkCmdClearAttachments ignores write masks: the clear rectangle under them
      detail::drawMaskedStencilClear(cmd, value, state_.stencilWriteMask);
    }
  });
}

void VulkanNativeDevice::drawTriangles(std::span<const raster::WindowVertex> vertices,
                                       std::span<const std::uint32_t> indices) {
  raster::checkDraw(vertices, indices);
  if (state_.scissor.empty())  // the scissor test discards every fragment
    return;
  Impl& d = *impl_;
  // The vertices as x, y snapped to the 1/256 grid and z, as the GL device hands them to GL; the
  // indices as given (an indexed draw, as GL's glDrawElements).
  std::vector<float> xyz(3 * vertices.size());
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    xyz[3 * k] = raster::snapToSubpixel(vertices[k].x);
    xyz[3 * k + 1] = raster::snapToSubpixel(vertices[k].y);
    xyz[3 * k + 2] = vertices[k].z;
  }
  const std::size_t vertexBytes = xyz.size() * sizeof(float);
  for (std::size_t first = 0; first < indices.size(); first += kIndicesPerDraw) {
    const std::size_t count = std::min(kIndicesPerDraw, indices.size() - first);
    d.drawScratch.resize(vertexBytes + count * sizeof(std::uint32_t));
    std::memcpy(d.drawScratch.data(), xyz.data(), vertexBytes);
    std::memcpy(d.drawScratch.data() + vertexBytes, indices.data() + first,
                count * sizeof(std::uint32_t));
    d.drawIndexed(vertexBytes, count);
  }
}

raster::PendingRead<std::uint8_t> VulkanNativeDevice::readStencilLater(const PixelRect& rect) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  if (r.empty())
    return raster::PendingRead<std::uint8_t>::ready({});
  raster::PendingRead<std::uint8_t> read = raster::PendingRead<std::uint8_t>::waiting();
  d.readAspect(r, VK_IMAGE_ASPECT_STENCIL_BIT, 1,
               [read](std::vector<std::uint8_t> bytes) mutable { read.deliver(std::move(bytes)); });
  return read;
}

raster::PendingRead<std::uint32_t> VulkanNativeDevice::readDepthLater(const PixelRect& rect) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  if (r.empty())
    return raster::PendingRead<std::uint32_t>::ready({});
  raster::PendingRead<std::uint32_t> read = raster::PendingRead<std::uint32_t>::waiting();
  const VkFormat format = d.shared->format;
  d.readAspect(r, VK_IMAGE_ASPECT_DEPTH_BIT, 4,
               [read, format](std::vector<std::uint8_t> bytes) mutable {
                 read.deliver(depthFromCopy(bytes, format));
               });
  return read;
}

void VulkanNativeDevice::finish() {
  impl_->counted([&] { impl_->recorder->finish(); });
}

bool VulkanNativeDevice::defers() const {
  return true;
}

raster::TransferCounters VulkanNativeDevice::transfers() const {
  return impl_->transfers;
}

std::vector<std::uint8_t> VulkanNativeDevice::readStencil(const PixelRect& rect) const {
  // The interface's read-backs are const; running the recording changes no state it shows.
  auto& self = const_cast<VulkanNativeDevice&>(*this);
  raster::PendingRead<std::uint8_t> read = self.readStencilLater(rect);
  self.finish();
  return read.take();
}

std::vector<std::uint32_t> VulkanNativeDevice::readDepth(const PixelRect& rect) const {
  auto& self = const_cast<VulkanNativeDevice&>(*this);
  raster::PendingRead<std::uint32_t> read = self.readDepthLater(rect);
  self.finish();
  return read.take();
}

}  // namespace recode::backends
