// VulkanDevice: the contract on Vulkan 1.3. The CPU validates, snaps and sets up each triangle
// (exact_proxy.cpp, shared with the GL device); the GPU draws a proxy rectangle per triangle and
// the shaders (the contract's GLSL as SPIR-V) decide coverage and depth; fixed-function stencil,
// depth compare and scissor, all dynamic state, do the rest.
//
// Coordinates: the interface speaks GL window coordinates (row 0 at the bottom); Vulkan's
// framebuffer has row 0 at the top. GL row j is framebuffer row height - 1 - j throughout: the
// viewport has a negative height, scissors and read-back regions are mirrored, read-backs are
// returned bottom row first, and the fragment shader turns gl_FragCoord back into GL's j.
//
// Nothing runs when it is given: every command is recorded (vulkan_recorder.hpp) and run by
// finish(), or by a read-back that must return its values at once.

#include "recode/backends/vulkan_device.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "recode/backends/exact_depth.hpp"
#include "recode/backends/exact_proxy.hpp"
#include "recode/backends/proxy_cache.hpp"
#include "recode/raster/device_checks.hpp"
#include "recode/raster/fixed_point.hpp"
#include "vulkan_context.hpp"
#include "vulkan_depth_stencil_image.hpp"
#include "vulkan_draw_state.hpp"
#include "vulkan_image_cache.hpp"
#include "vulkan_pipeline.hpp"
#include "vulkan_recorder.hpp"
#include "vulkan_summary.hpp"

namespace recode::backends {

namespace {

using detail::vkCheck;
using raster::PixelRect;

// The depth attachment holds q 2^-24 for the contract's 24-bit q: exact in a 32-bit float, and
// ordered as q is, so the float depth compare is the contract's integer compare.
constexpr float kDepthUnit = 1.0f / 16777216.0f;

// The pipelines every device of that arithmetic shares, made with its context on first use
// (never destroyed, like the context).
const detail::ExactPipelines& makePipelines(ShaderArithmetic arithmetic) {
  return *new detail::ExactPipelines(detail::createExactPipelines(
      detail::VulkanContext::instance(arithmetic).device(), arithmetic));
}

const detail::ExactPipelines& sharedPipelines(ShaderArithmetic arithmetic) {
  if (arithmetic == ShaderArithmetic::Native64) {
    static const detail::ExactPipelines& native = makePipelines(ShaderArithmetic::Native64);
    return native;
  }
  static const detail::ExactPipelines& emulated = makePipelines(ShaderArithmetic::Emulated32);
  return emulated;
}

}  // namespace

struct VulkanDevice::Impl {
  int width = 0;
  int height = 0;
  ShaderArithmetic arithmetic = ShaderArithmetic::Native64;
  const raster::RenderState* state = nullptr;  // the device's (RenderStateDevice::state_)
  detail::VulkanContext* context = nullptr;
  const detail::ExactPipelines* pipelines = nullptr;
  detail::CommandRecorder* recorder = nullptr;  // sharedRecorder(arithmetic)
  raster::TransferCounters transfers;           // what this device's calls made the recorder do

  // Runs `call` on the recorder, counting what it made the recorder do as this device's.
  template <typename Call>
  decltype(auto) counted(Call&& call) {
    return detail::countedOn(*recorder, transfers, std::forward<Call>(call));
  }
  // The proxies of the blocks drawn last, and where the last lists went in staging memory (by
  // ProxyCache id, with the recording they are valid in): a pass that draws a block again in
  // the same recording binds the bytes already there.
  ProxyCache proxyCache;
  struct Upload {
    std::uint64_t id = 0;
    std::uint64_t recording = 0;
    detail::CommandRecorder::Staged staged;
  };
  std::array<Upload, 2 * ProxyCache::kKeptBlocks> uploads{};
  std::size_t nextUpload = 0;

  // Draws `proxies` in the state set (an `id` of 0: a list not kept, staged anew).
  void drawProxies(const std::vector<ProxyTriangle>& proxies, std::uint64_t id) {
    if (proxies.empty())
      return;
    // No other thread's finish() may come between the staging and the draw that reads it.
    const auto hold = recorder->hold();
    std::optional<detail::CommandRecorder::Staged> staged;
    if (id != 0) {
      const std::uint64_t recording = recorder->recordingsRun();
      for (const Upload& upload : uploads)
        if (upload.id == id && upload.recording == recording)
          staged = upload.staged;
    }
    if (!staged) {
      staged = counted(
          [&] { return recorder->stage(proxies.data(), proxies.size() * sizeof(ProxyTriangle)); });
      if (id != 0) {
        uploads[nextUpload] = {id, recorder->recordingsRun(), *staged};
        nextUpload = (nextUpload + 1) % uploads.size();
      }
    }
    // Instances are drawn in order and Vulkan keeps primitive order for depth and stencil
    // (rasterization order), so triangles reach each pixel in index order as the contract
    // requires. The two halves of a proxy rectangle share an edge, which Vulkan's
    // rasterization rules hand to exactly one of them.
    render(pipelines->exact, 0.0f, [&](VkCommandBuffer cmd) {
      detail::setDepthStencilState(cmd, *state);
      vkCmdBindVertexBuffers(cmd, 0, 1, &staged->buffer, &staged->offset);
      vkCmdDraw(cmd, 4, static_cast<std::uint32_t>(proxies.size()), 0, 0);
    });
  }

  std::optional<detail::DepthStencilImage> target;  // made in the constructor

  // Records `body` as draws of the open rendering over the whole image (vulkan_recorder.hpp),
  // with `pipeline` bound, the viewport (negative height: GL's y up), the scissor and the
  // frame's push constants set.
  template <typename Body>
  void render(VkPipeline pipeline, float clearDepth, const Body& body) {
    const auto beginRendering = [&](VkCommandBuffer cmd) { target->beginRendering(cmd); };
    recorder->render(target->image(), target->view(), beginRendering, [&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
      const VkViewport viewport{0.0f,
                                static_cast<float>(height),
                                static_cast<float>(width),
                                -static_cast<float>(height),
                                0.0f,
                                1.0f};
      vkCmdSetViewport(cmd, 0, 1, &viewport);
      const VkRect2D scissor = target->framebufferRect(state->scissor);
      vkCmdSetScissor(cmd, 0, 1, &scissor);
      vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);  // the CPU culls, from the exact facing
      const detail::FramePushConstants frame{
          {static_cast<float>(width), static_cast<float>(height)}, clearDepth};
      vkCmdPushConstants(cmd, pipelines->layout,
                         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof frame,
                         &frame);
      body(cmd);
    });
  }

  // Clears `aspect` over the scissor's rectangle inside the open rendering.
  void clearAttachment(VkCommandBuffer cmd, VkImageAspectFlags aspect,
                       VkClearDepthStencilValue value) const {
    detail::clearAttachmentRect(cmd, aspect, value, target->framebufferRect(state->scissor));
  }

  // Records a read-back of one aspect of a GL-window rectangle, counted as this device's.
  void readAspect(const PixelRect& r, VkImageAspectFlags aspect, std::size_t texel,
                  std::function<void(std::vector<std::uint8_t>)> deliver) {
    counted([&] { target->readAspect(r, aspect, texel, std::move(deliver)); });
  }
};

VulkanDevice::VulkanDevice(int width, int height, ShaderArithmetic arithmetic)
    : RenderStateDevice(width, height), impl_(std::make_unique<Impl>()) {
  raster::checkFramebufferSize(width, height);
  Impl& d = *impl_;
  d.width = width;
  d.height = height;
  d.arithmetic = arithmetic;
  d.state = &state_;
  d.pipelines = &sharedPipelines(arithmetic);  // makes the context too
  d.context = &detail::VulkanContext::instance(arithmetic);
  d.recorder = &detail::sharedRecorder(arithmetic);
  // The start state of CpuDevice: depth 2^24 - 1 (stored as (2^24 - 1) 2^-24), stencil 0.
  d.target.emplace(*d.context, *d.recorder, detail::imageCache(arithmetic),
                   detail::kExactDepthStencilFormat, width, height,
                   VkClearDepthStencilValue{static_cast<float>(raster::kDepthMax) * kDepthUnit, 0});
}

VulkanDevice::~VulkanDevice() = default;

int VulkanDevice::width() const {
  return impl_->width;
}

int VulkanDevice::height() const {
  return impl_->height;
}

std::string VulkanDevice::renderer() const {
  return impl_->context->deviceName();
}

ShaderArithmetic VulkanDevice::arithmetic() const {
  return impl_->arithmetic;
}

// The state setters are RenderStateDevice's: state_ is set as dynamic state in every command
// buffer that draws or clears.

void VulkanDevice::clearDepth(double depth) {
  if (!std::isfinite(depth))
    throw std::invalid_argument("clearDepth: value is not finite");
  Impl& d = *impl_;
  // The depth write mask applies to clears: with it off, a depth clear changes nothing.
  if (!state_.depthWrite || state_.scissor.empty())
    return;
  // The contract's quantisation, stored as the shaders store fragment depth. A clear of the
  // open rendering: it happens in rasterization order with the draws around it, writes the
  // depth aspect alone over the scissor's rectangle, and costs no fragment shading (the depth
  // mask is all or nothing, so no masked clear is needed).
  const float value = static_cast<float>(raster::quantizeDepth(depth)) * kDepthUnit;
  d.render(d.pipelines->clear, value, [&](VkCommandBuffer cmd) {
    d.clearAttachment(cmd, VK_IMAGE_ASPECT_DEPTH_BIT, {value, 0});
  });
}

void VulkanDevice::clearStencil(std::uint8_t value) {
  Impl& d = *impl_;
  if (state_.stencilWriteMask == 0 || state_.scissor.empty())
    return;
  if (state_.stencilWriteMask == 0xFF) {  // every bit written: a clear of the open rendering
    d.render(d.pipelines->clear, 0.0f, [&](VkCommandBuffer cmd) {
      d.clearAttachment(cmd, VK_IMAGE_ASPECT_STENCIL_BIT, {0.0f, value});
    });
    return;
  }
  // vkCmdClearAttachments ignores write masks: the clear pipeline's rectangle under them.
  d.render(d.pipelines->clear, 0.0f, [&](VkCommandBuffer cmd) {
    detail::drawMaskedStencilClear(cmd, value, state_.stencilWriteMask);
  });
}

void VulkanDevice::drawTriangles(std::span<const raster::WindowVertex> vertices,
                                 std::span<const std::uint32_t> indices) {
  impl_->drawProxies(buildProxyTriangles(vertices, indices, state_), 0);
}

void VulkanDevice::drawMesh(const raster::TriangleSource& source) {
  // As CpuDevice: only the triangles that meet the scissor (the others would give no proxy),
  // set up once for every pass that draws the block under that scissor (proxy_cache.hpp).
  Impl& d = *impl_;
  const ProxyCache::Proxies proxies = d.proxyCache.proxies(source, state_);
  d.drawProxies(*proxies.list, proxies.id);
}

raster::PendingRead<std::uint8_t> VulkanDevice::readStencilLater(const PixelRect& rect) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  if (r.empty())
    return raster::PendingRead<std::uint8_t>::ready({});
  raster::PendingRead<std::uint8_t> read = raster::PendingRead<std::uint8_t>::waiting();
  d.readAspect(r, VK_IMAGE_ASPECT_STENCIL_BIT, 1,
               [read](std::vector<std::uint8_t> bytes) mutable { read.deliver(std::move(bytes)); });
  return read;
}

raster::PendingRead<std::uint32_t> VulkanDevice::readDepthLater(const PixelRect& rect) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  if (r.empty())
    return raster::PendingRead<std::uint32_t>::ready({});
  raster::PendingRead<std::uint32_t> read = raster::PendingRead<std::uint32_t>::waiting();
  // The depth aspect of D32_SFLOAT_S8_UINT copies out as tightly packed 32-bit floats.
  d.readAspect(r, VK_IMAGE_ASPECT_DEPTH_BIT, 4, [read](std::vector<std::uint8_t> bytes) mutable {
    read.deliver(depthFromStoredFloats(bytes, "Vulkan device"));
  });
  return read;
}

std::shared_ptr<const raster::KeptDepth> VulkanDevice::keepDepthLater(const PixelRect& rect) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  if (!summarisedOnDevice(r))
    return DepthStencilDevice::keepDepthLater(r);
  const std::size_t bytes = 4 * static_cast<std::size_t>(r.area());
  const auto hold = d.recorder->hold();
  std::shared_ptr<const raster::KeptDepth> kept;
  d.counted([&] {
    d.recorder->makeRoom(bytes);
    const detail::CommandRecorder::Scratch region = d.recorder->scratch(bytes);
    kept = std::make_shared<detail::VulkanKeptDepth>(*d.recorder, impl_.get(), r, region);
    const VkBufferImageCopy copy =
        d.target->aspectCopy(r, VK_IMAGE_ASPECT_DEPTH_BIT, region.offset);
    d.recorder->record(d.target->image(), [&](VkCommandBuffer cmd) {
      vkCmdCopyImageToBuffer(cmd, d.target->image(), VK_IMAGE_LAYOUT_GENERAL, region.buffer, 1,
                             &copy);
    });
  });
  return kept;
}

raster::PendingRead<raster::PixelSummary> VulkanDevice::summarizeLater(
    const PixelRect& rect, const raster::StencilClasses& classes,
    const raster::KeptDepth* nearEnd) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  const auto* kept = dynamic_cast<const detail::VulkanKeptDepth*>(nearEnd);
  if (kept == nullptr && (nearEnd != nullptr || !summarisedOnDevice(r)))
    return DepthStencilDevice::summarizeLater(r, classes, nearEnd);  // kept on the host, if any
  if (kept != nullptr)
    kept->requireKeptBy(impl_.get(), r);
  raster::requireStencilClasses(classes, "summarizeLater");
  const bool withDepth = kept != nullptr;
  const SummaryInputs inputs(r, withDepth);
  raster::PendingRead<raster::PixelSummary> read =
      raster::PendingRead<raster::PixelSummary>::waiting();
  const auto hold = d.recorder->hold();
  d.counted([&] {
    d.recorder->makeRoom(inputs.bytes() + raster::kPixelSummaryBytes);
    const detail::CommandRecorder::Scratch region = d.recorder->scratch(inputs.bytes());
    const detail::CommandRecorder::Staged out = d.recorder->results(
        raster::kPixelSummaryBytes, [read, r, withDepth](const std::uint8_t* bytes) mutable {
          read.deliver({summaryFromBytes(bytes, r, withDepth, "Vulkan device")});
        });
    // Vulkan's copies run from the image's top row down.
    const SummaryParameters parameters =
        summaryParameters(r, classes, withDepth, false, region.offset,
                          withDepth ? kept->region().offset : 0, out.offset);
    const VkBufferImageCopy stencilCopy =
        d.target->aspectCopy(r, VK_IMAGE_ASPECT_STENCIL_BIT, region.offset);
    const VkBufferImageCopy farCopy =
        d.target->aspectCopy(r, VK_IMAGE_ASPECT_DEPTH_BIT, region.offset + inputs.farOffset());
    const VkBuffer nearBuffer = withDepth ? kept->region().buffer : region.buffer;
    d.recorder->record(d.target->image(), [&](VkCommandBuffer cmd) {
      vkCmdCopyImageToBuffer(cmd, d.target->image(), VK_IMAGE_LAYOUT_GENERAL, region.buffer, 1,
                             &stencilCopy);
      if (withDepth)
        vkCmdCopyImageToBuffer(cmd, d.target->image(), VK_IMAGE_LAYOUT_GENERAL, region.buffer, 1,
                               &farCopy);
      vkCmdUpdateBuffer(cmd, region.buffer, region.offset + inputs.tableOffset(), inputs.tableBytes,
                        classes.classOf.data());
    });
    // The dispatch comes just before the submission, with every other summary's.
    detail::summaryPipeline(d.arithmetic).add(nearBuffer, region.buffer, out.buffer, parameters);
  });
  return read;
}

void VulkanDevice::finish() {
  impl_->counted([&] { impl_->recorder->finish(); });
}

bool VulkanDevice::defers() const {
  return true;
}

raster::TransferCounters VulkanDevice::transfers() const {
  return impl_->transfers;
}

std::vector<std::uint8_t> VulkanDevice::readStencil(const PixelRect& rect) const {
  // The interface's read-backs are const; running the recording changes no state it shows.
  auto& self = const_cast<VulkanDevice&>(*this);
  raster::PendingRead<std::uint8_t> read = self.readStencilLater(rect);
  self.finish();
  return read.take();
}

std::vector<std::uint32_t> VulkanDevice::readDepth(const PixelRect& rect) const {
  auto& self = const_cast<VulkanDevice&>(*this);
  raster::PendingRead<std::uint32_t> read = self.readDepthLater(rect);
  self.finish();
  return read.take();
}

}  // namespace recode::backends
