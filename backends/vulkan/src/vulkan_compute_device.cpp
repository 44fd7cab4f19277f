// VulkanComputeDevice: the contract as a tile rasterizer in compute shaders
// (shaders/compute/). The host validates a draw and copies its window vertices and indices to
// the device as they are (a posed block's mesh once, for as long as the block lives); its
// clears, draws and reads then go into the frame (tile_frame.hpp), the job list that every
// compute device of the process shares and that runs as a fixed set of dispatches just before
// the shared recording (vulkan_recorder.hpp) is submitted by finish(). The framebuffer is a
// storage buffer the frame reaches by its address.

#include "recode/backends/vulkan_compute_device.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "recode/backends/summary_layout.hpp"
#include "recode/raster/device_checks.hpp"
#include "recode/raster/fixed_point.hpp"
#include "tile_frame.hpp"
#include "tile_meshes.hpp"
#include "vulkan_compute_pipelines.hpp"
#include "vulkan_context.hpp"
#include "vulkan_recorder.hpp"
#include "vulkan_summary.hpp"

namespace recode::backends {

namespace {

using detail::TileReadForm;
using raster::PixelRect;

// A pose as tile_vertex.comp and tile_box.comp read it: 12 doubles, the linear part row by row,
// then the translation.
void packPose(const raster::Pose& pose, double* out) {
  std::copy(pose.linear.begin(), pose.linear.end(), out);
  std::copy(pose.translation.begin(), pose.translation.end(), out + 9);
}

}  // namespace

struct VulkanComputeDevice::Impl {
  int width = 0;
  int height = 0;
  const raster::RenderState* state = nullptr;  // the device's (RenderStateDevice::state_)
  detail::VulkanContext* context = nullptr;
  detail::CommandRecorder* recorder = nullptr;
  detail::TileFrame* frame = nullptr;
  std::uint32_t target = 0;  // the framebuffer's id in the frame
  raster::TransferCounters transfers;
  detail::DeviceBuffer framebuffer;            // a word a pixel, rows from the bottom
  std::unique_ptr<detail::TileMeshes> meshes;  // the lists and posed meshes kept on the device
  long long posedDraws = 0;
  bool keepStages = false;
  std::shared_ptr<std::optional<DrawStages>> lastStages =
      std::make_shared<std::optional<DrawStages>>();

  // Runs `call` on the recorder, counting what it made the recorder do as this device's.
  template <typename Call>
  decltype(auto) counted(Call&& call) {
    return detail::countedOn(*recorder, transfers, std::forward<Call>(call));
  }

  // The frame's vertex job for `posed` at its pose and view (tile_vertex.comp's 23 doubles).
  static detail::TileVertices posedVertices(const detail::TileMeshes::Posed& r,
                                            const raster::PosedMesh& posed,
                                            std::uint64_t contentKey) {
    detail::TileVertices v;
    v.local = r.local;
    v.vertexCount = r.vertices;
    v.contentKey = contentKey;
    const raster::VertexTransform& t = posed.transform;
    packPose(t.pose, v.transform.data());
    const raster::WindowMapping& m = t.window;
    const std::array<double, 8> mapping{m.umin,   m.urange, m.width,    m.vmin,
                                        m.vrange, m.height, m.depthMax, m.depthRange};
    std::copy(mapping.begin(), mapping.end(), v.transform.begin() + 12);
    for (int k = 0; k < 3; ++k) {
      const int axis = m.axes[static_cast<std::size_t>(k)];
      if (axis < 0 || axis > 2)
        throw std::invalid_argument("drawMesh: a posed draw's window mapping names axis " +
                                    std::to_string(axis) + " (must be 0, 1 or 2)");
      v.transform[static_cast<std::size_t>(20 + k)] = axis;
    }
    return v;
  }

  // A posed draw: the vertex stage on the device, then every triangle of the block (set-up
  // leaves out those whose pixels miss the scissor).
  void drawPosed(const raster::PosedMesh& posed, std::uint64_t contentKey) {
    meshes->releaseExpired();
    const detail::TileMeshes::Posed r = meshes->posed(posed);
    ++posedDraws;
    if (r.triangles == 0 || state->scissor.empty())
      return;
    frame->draw(target, *state, posedVertices(r, posed, contentKey), r.indices, r.triangles);
    captureIfKept();
  }

  // A draw of a kept list's triangles in the current state.
  void drawList(const detail::TileMeshes::List& list) {
    if (list.triangles == 0 || state->scissor.empty())
      return;
    detail::TileVertices vertices;
    vertices.window = list.vertices;
    frame->draw(target, *state, vertices, list.indices, list.triangles);
    captureIfKept();
  }

  // With keepDrawStages: the draw just recorded is copied back after its frame.
  void captureIfKept() {
    if (!keepStages)
      return;
    frame->captureLastDraw(
        target, [last = lastStages, scissor = state->scissor](detail::TileDrawCapture c) {
          *last = stagesOf(c, scissor);
        });
  }

  static DrawStages stagesOf(const detail::TileDrawCapture& c, const PixelRect& scissor) {
    DrawStages s;
    s.scissor = scissor;
    s.gridX0 = c.gridOrigin[0];
    s.gridY0 = c.gridOrigin[1];
    s.gridWidth = static_cast<int>(c.gridWidth);
    s.gridHeight = static_cast<int>(c.gridHeight);
    for (const detail::TileSetUpTriangle& w : c.triangles) {
      SetUpTriangle tri;
      const std::int32_t fixed[6] = {w.x0, w.y0, w.x1, w.y1, w.x2, w.y2};
      std::memcpy(tri.fixed, fixed, sizeof fixed);
      tri.frontFacing = w.front != 0;
      tri.candidates = {w.candidates[0], w.candidates[1], w.candidates[2], w.candidates[3]};
      std::memcpy(&tri.z0, &w.z0, 4);
      std::memcpy(&tri.dzdx, w.dzdx, 8);
      std::memcpy(&tri.dzdy, w.dzdy, 8);
      s.triangles.push_back(tri);
    }
    // The job lists hold every draw of the epoch: this draw's entries, in its own numbering.
    const std::uint32_t end = c.firstTriangle + static_cast<std::uint32_t>(c.triangles.size());
    for (std::size_t b = 0; b < c.jobLists.size(); ++b) {
      std::vector<std::uint32_t> list;
      for (const std::uint32_t t : c.jobLists[b])
        if (t >= c.firstTriangle && t < end)
          list.push_back(t - c.firstTriangle);
      s.blockLists.push_back(std::move(list));
    }
    s.overflowed = c.overflowed;
    for (std::size_t v = 0; v + 2 < c.windowVertices.size(); v += 3)
      s.windowVertices.push_back(
          {c.windowVertices[v], c.windowVertices[v + 1], c.windowVertices[v + 2]});
    return s;
  }

  // A read of `r` in `form` whose `bytes` go to `deliver` when the recording has run.
  void readInto(const PixelRect& r, TileReadForm form, std::size_t bytes,
                std::function<void(const std::uint8_t*)> deliver) {
    const auto hold = recorder->hold();
    counted([&] {
      recorder->makeRoom(bytes);
      const detail::CommandRecorder::Staged out = recorder->results(bytes, std::move(deliver));
      frame->read(target, r, form, out.buffer, out.offset);
    });
  }

  ~Impl() {
    if (context == nullptr)
      return;
    // Commands recorded for this framebuffer must run before it goes: they are in the shared
    // frame, beside other devices' commands.
    try {
      recorder->finish();
    } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw
    }
    {
      const auto hold = recorder->hold();
      frame->removeTarget(target);
    }
    meshes.reset();
    context->destroyDeviceBuffer(framebuffer);
  }
};

VulkanComputeDevice::VulkanComputeDevice(int width, int height)
    : RenderStateDevice(width, height), impl_(std::make_unique<Impl>()) {
  raster::checkFramebufferSize(width, height);
  Impl& d = *impl_;
  d.width = width;
  d.height = height;
  d.state = &state_;
  d.frame = &detail::tileFrame();  // makes the pipelines, the context and the recorder too
  d.context = &detail::VulkanContext::instance(ShaderArithmetic::Native64);
  d.recorder = &detail::sharedRecorder(ShaderArithmetic::Native64);
  const VkDeviceSize bytes =
      VkDeviceSize{4} * static_cast<VkDeviceSize>(width) * static_cast<VkDeviceSize>(height);
  d.framebuffer = d.context->createDeviceBuffer(
      bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  // The start state of CpuDevice: depth 2^24 - 1, stencil 0 everywhere (recorded before any
  // command of this framebuffer, so before the frame that runs them).
  const auto hold = d.recorder->hold();
  d.target = d.frame->addTarget(d.framebuffer.buffer, width, height);
  d.meshes = std::make_unique<detail::TileMeshes>(*d.context, *d.recorder);
  d.recorder->record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, d.framebuffer.buffer, 0, VK_WHOLE_SIZE, raster::kDepthMax << 8);
  });
}

VulkanComputeDevice::~VulkanComputeDevice() = default;

int VulkanComputeDevice::width() const {
  return impl_->width;
}

int VulkanComputeDevice::height() const {
  return impl_->height;
}

std::string VulkanComputeDevice::renderer() const {
  return impl_->context->deviceName();
}

VulkanComputeDevice::MeshCounters VulkanComputeDevice::meshCounters() const {
  const detail::TileMeshes::Counters kept = impl_->meshes->counters();
  MeshCounters counters;
  counters.uploads = kept.uploads;
  counters.reuses = kept.reuses;
  counters.posedDraws = impl_->posedDraws;
  counters.residentMeshes = kept.residentMeshes;
  return counters;
}

void VulkanComputeDevice::keepDrawStages() {
  impl_->keepStages = true;
}

VulkanComputeDevice::DrawStages VulkanComputeDevice::lastDrawStages() {
  finish();
  if (!impl_->lastStages->has_value())
    throw std::logic_error("lastDrawStages: no draw drew anything since keepDrawStages()");
  return **impl_->lastStages;
}

void VulkanComputeDevice::clearDepth(double depth) {
  if (!std::isfinite(depth))
    throw std::invalid_argument("clearDepth: value is not finite");
  // The depth write mask applies to clears: with it off, a depth clear changes nothing.
  if (!state_.depthWrite || state_.scissor.empty())
    return;
  const auto hold = impl_->recorder->hold();
  impl_->frame->clearDepth(impl_->target, state_.scissor, raster::quantizeDepth(depth));
}

void VulkanComputeDevice::clearStencil(std::uint8_t value) {
  if (state_.stencilWriteMask == 0 || state_.scissor.empty())
    return;
  const auto hold = impl_->recorder->hold();
  impl_->frame->clearStencil(impl_->target, state_.scissor, value, state_.stencilWriteMask);
}

void VulkanComputeDevice::drawTriangles(std::span<const raster::WindowVertex> vertices,
                                        std::span<const std::uint32_t> indices) {
  Impl& d = *impl_;
  const auto hold = d.recorder->hold();
  d.counted([&] { d.drawList(d.meshes->upload({vertices, indices}, 0, true, {})); });
}

void VulkanComputeDevice::drawMesh(const raster::TriangleSource& source) {
  Impl& d = *impl_;
  const std::uint64_t key = source.contentKey();
  const PixelRect& scissor = state_.scissor;
  const auto hold = d.recorder->hold();
  d.counted([&] {
    if (const std::optional<raster::PosedMesh> posed = source.posedMesh()) {
      d.drawPosed(*posed, key);
      return;
    }
    if (const std::optional<detail::TileMeshes::List> kept = d.meshes->find(key, scissor)) {
      d.drawList(*kept);
      return;
    }
    // As CpuDevice: only the triangles that meet the scissor when the source can tell them.
    const std::optional<raster::TriangleDraw> near = source.trianglesMeeting(scissor);
    const raster::TriangleDraw draw = near ? *near : source.allTriangles();
    d.drawList(d.meshes->upload(draw, key, !near, scissor));
  });
}

raster::PendingRead<raster::PosedBox> VulkanComputeDevice::posedBoxesLater(
    std::span<const raster::PosedMesh> meshes) {
  Impl& d = *impl_;
  if (meshes.empty())
    return raster::PendingRead<raster::PosedBox>::ready({});
  raster::PendingRead<raster::PosedBox> read = raster::PendingRead<raster::PosedBox>::waiting();
  const auto hold = d.recorder->hold();
  d.counted([&] {
    d.meshes->releaseExpired();
    const std::size_t n = meshes.size();
    std::vector<detail::TileFrame::BoxRequest> blocks(n);
    for (std::size_t i = 0; i < n; ++i) {
      const detail::TileMeshes::Posed r = d.meshes->posed(meshes[i]);
      blocks[i].local = r.local;
      blocks[i].vertexCount = r.vertices;
      packPose(meshes[i].transform.pose, blocks[i].pose.data());
    }
    const VkDeviceSize bytes = VkDeviceSize{n} * detail::kTileBoxBytes;
    d.recorder->makeRoom(bytes);
    const detail::CommandRecorder::Staged out =
        d.recorder->results(bytes, [n, read](const std::uint8_t* data) mutable {
          std::vector<raster::PosedBox> boxes(n);
          for (std::size_t i = 0; i < n; ++i) {
            double words[detail::kTileBoxBytes / sizeof(double)];
            std::memcpy(words, data + detail::kTileBoxBytes * i, sizeof words);
            std::copy(words, words + 3, boxes[i].min.begin());
            std::copy(words + 3, words + 6, boxes[i].max.begin());
            boxes[i].orderMatters = words[6] != 0.0;
          }
          read.deliver(std::move(boxes));
        });
    d.frame->boxes(blocks, out.buffer, out.offset);
  });
  return read;
}

raster::PendingRead<std::uint8_t> VulkanComputeDevice::readStencilLater(const PixelRect& rect) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  if (r.empty())
    return raster::PendingRead<std::uint8_t>::ready({});
  raster::PendingRead<std::uint8_t> read = raster::PendingRead<std::uint8_t>::waiting();
  const auto pixels = static_cast<std::size_t>(r.area());
  d.readInto(r, TileReadForm::StencilBytes, (pixels + 3) / 4 * 4,
             [read, pixels](const std::uint8_t* bytes) mutable {
               read.deliver(std::vector<std::uint8_t>(bytes, bytes + pixels));
             });
  return read;
}

raster::PendingRead<std::uint32_t> VulkanComputeDevice::readDepthLater(const PixelRect& rect) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  if (r.empty())
    return raster::PendingRead<std::uint32_t>::ready({});
  raster::PendingRead<std::uint32_t> read = raster::PendingRead<std::uint32_t>::waiting();
  const auto pixels = static_cast<std::size_t>(r.area());
  d.readInto(r, TileReadForm::DepthWords, 4 * pixels,
             [read, pixels](const std::uint8_t* bytes) mutable {
               std::vector<std::uint32_t> depth(pixels);
               std::memcpy(depth.data(), bytes, 4 * pixels);
               read.deliver(std::move(depth));
             });
  return read;
}

std::shared_ptr<const raster::KeptDepth> VulkanComputeDevice::keepDepthLater(
    const PixelRect& rect) {
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
    d.frame->read(d.target, r, TileReadForm::DepthFloats, region.buffer, region.offset);
  });
  return kept;
}

raster::PendingRead<raster::PixelSummary> VulkanComputeDevice::summarizeLater(
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
          read.deliver({summaryFromBytes(bytes, r, withDepth, "Vulkan compute device")});
        });
    // The reads write rows from the bottom, as GL's copies.
    const SummaryParameters parameters =
        summaryParameters(r, classes, withDepth, true, region.offset,
                          withDepth ? kept->region().offset : 0, out.offset);
    d.frame->read(d.target, r, TileReadForm::StencilBytes, region.buffer, region.offset);
    if (withDepth)
      d.frame->read(d.target, r, TileReadForm::DepthFloats, region.buffer,
                    region.offset + inputs.farOffset());
    d.recorder->record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
      vkCmdUpdateBuffer(cmd, region.buffer, region.offset + inputs.tableOffset(), inputs.tableBytes,
                        classes.classOf.data());
    });
    const VkBuffer nearBuffer = withDepth ? kept->region().buffer : region.buffer;
    // The dispatch comes just before the submission, with every other summary's.
    detail::summaryPipeline(ShaderArithmetic::Native64)
        .add(nearBuffer, region.buffer, out.buffer, parameters);
  });
  return read;
}

void VulkanComputeDevice::finish() {
  impl_->counted([&] { impl_->recorder->finish(); });
  const auto hold = impl_->recorder->hold();
  impl_->meshes->releaseExpired();
}

bool VulkanComputeDevice::defers() const {
  return true;
}

raster::TransferCounters VulkanComputeDevice::transfers() const {
  return impl_->transfers;
}

std::vector<std::uint8_t> VulkanComputeDevice::readStencil(const PixelRect& rect) const {
  // The interface's read-backs are const; running the recording changes no state it shows.
  auto& self = const_cast<VulkanComputeDevice&>(*this);
  raster::PendingRead<std::uint8_t> read = self.readStencilLater(rect);
  self.finish();
  return read.take();
}

std::vector<std::uint32_t> VulkanComputeDevice::readDepth(const PixelRect& rect) const {
  auto& self = const_cast<VulkanComputeDevice&>(*this);
  raster::PendingRead<std::uint32_t> read = self.readDepthLater(rect);
  self.finish();
  return read.take();
}

}  // namespace recode::backends
