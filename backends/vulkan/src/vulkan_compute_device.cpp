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
#include "vulkan_compute_pipelines.hpp"
#include "vulkan_context.hpp"
#include "vulkan_recorder.hpp"
#include "vulkan_summary.hpp"

namespace recode::backends {

namespace {

using detail::TileReadForm;
using raster::PixelRect;

// Offsets of the regions a mesh's parts start at: the largest minStorageBufferOffsetAlignment
// the specification allows.
constexpr VkDeviceSize kBindAlignment = 256;

VkDeviceSize aligned(VkDeviceSize bytes) {
  return (bytes + kBindAlignment - 1) / kBindAlignment * kBindAlignment;
}

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
  detail::DeviceBuffer framebuffer;  // a word a pixel, rows from the bottom
  // Buffers replaced while a recording that may use them was open: freed once it has run.
  std::vector<std::pair<detail::DeviceBuffer, std::uint64_t>> retired;

  // A block's triangles on the device: the draw of a content key under a scissor (or whole,
  // when the source could not narrow it), serving every later draw of the key under a scissor
  // inside `rect`. Keys are never reused in a process, so an entry never serves another block.
  struct Mesh {
    std::uint64_t key = 0;  // 0: serves nothing (free, or a draw without a key)
    bool whole = false;
    PixelRect rect;
    std::uint32_t triangles = 0;
    VkDeviceSize indexOffset = 0;
    detail::DeviceBuffer buffer;  // vertices from 0, indices from indexOffset
    std::uint64_t lastUse = 0;
    // The recording whose frame last drew from the buffer: while it is open, new bytes go to a
    // new buffer (the frame draws when the recording is submitted, from what the buffer holds).
    std::uint64_t drawnIn = ~std::uint64_t{0};
  };
  static constexpr std::size_t kKeptMeshes = 8;
  std::array<Mesh, kKeptMeshes> meshes{};

  // A posed block's mesh on the device (raster::PosedMesh), kept while its source says it lives:
  // the object-space vertices from 0 and the indices from indexOffset; never written again.
  struct Resident {
    std::weak_ptr<const void> alive;
    std::uint32_t vertices = 0;
    std::uint32_t triangles = 0;
    VkDeviceSize indexOffset = 0;
    detail::DeviceBuffer buffer;
    VkDeviceAddress address = 0;
  };
  // By meshKey (an entry stays where it is while others come and go).
  std::unordered_map<std::uint64_t, Resident> residents;
  std::uint64_t clock = 0;
  MeshCounters meshCounters;
  long long posedDraws = 0;
  bool keepStages = false;
  std::shared_ptr<std::optional<DrawStages>> lastStages =
      std::make_shared<std::optional<DrawStages>>();

  // Runs `call` on the recorder, counting what it made the recorder do as this device's.
  template <typename Call>
  decltype(auto) counted(Call&& call) {
    return detail::countedOn(*recorder, transfers, std::forward<Call>(call));
  }

  void freeRetired() {
    const std::uint64_t run = recorder->recordingsRun();
    std::erase_if(retired, [&](std::pair<detail::DeviceBuffer, std::uint64_t>& r) {
      if (r.second >= run)
        return false;
      context->destroyDeviceBuffer(r.first);
      return true;
    });
  }

  detail::DeviceBuffer storage(VkDeviceSize bytes) {
    return context->createDeviceBuffer(bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                  VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                                  VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  }

  // The entry to draw `draw` from, for `key` under `rect`: uploaded now, validated first.
  Mesh& upload(const raster::TriangleDraw& draw, std::uint64_t key, bool whole,
               const PixelRect& rect) {
    raster::checkDraw(draw.vertices, draw.indices);
    Mesh& mesh = *std::min_element(meshes.begin(), meshes.end(), [](const Mesh& a, const Mesh& b) {
      return a.lastUse < b.lastUse;
    });
    const VkDeviceSize vertexBytes = draw.vertices.size_bytes();
    const VkDeviceSize indexBytes = draw.indices.size_bytes();
    mesh.key = 0;  // serves nothing until its bytes are recorded
    mesh.triangles = static_cast<std::uint32_t>(draw.indices.size() / 3);
    mesh.indexOffset = aligned(std::max<VkDeviceSize>(vertexBytes, 4));
    mesh.lastUse = ++clock;
    ++meshCounters.uploads;
    if (mesh.triangles == 0)
      return mesh;
    recorder->makeRoom(vertexBytes + indexBytes);
    const VkDeviceSize bytes = mesh.indexOffset + indexBytes;
    if (mesh.buffer.buffer == VK_NULL_HANDLE || mesh.buffer.size < bytes ||
        mesh.drawnIn == recorder->recordingsRun()) {
      freeRetired();
      if (mesh.buffer.buffer != VK_NULL_HANDLE)
        retired.emplace_back(mesh.buffer, recorder->recordingsRun());
      mesh.buffer = storage(std::max(bytes, mesh.buffer.size));
    }
    const detail::CommandRecorder::Staged vertices =
        recorder->upload(draw.vertices.data(), vertexBytes);
    const detail::CommandRecorder::Staged indices =
        recorder->upload(draw.indices.data(), indexBytes);
    recorder->record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
      const VkBufferCopy vertexCopy{vertices.offset, 0, vertexBytes};
      vkCmdCopyBuffer(cmd, vertices.buffer, mesh.buffer.buffer, 1, &vertexCopy);
      const VkBufferCopy indexCopy{indices.offset, mesh.indexOffset, indexBytes};
      vkCmdCopyBuffer(cmd, indices.buffer, mesh.buffer.buffer, 1, &indexCopy);
    });
    mesh.key = key;
    mesh.whole = whole;
    mesh.rect = rect;
    return mesh;
  }

  // Lets go of the meshes whose blocks are gone, once no recording that may use them is open.
  void releaseExpired() {
    std::erase_if(residents, [&](const std::pair<const std::uint64_t, Resident>& entry) {
      if (!entry.second.alive.expired())
        return false;
      retired.emplace_back(entry.second.buffer, recorder->recordingsRun());
      return true;
    });
  }

  // The resident copy of `posed`'s mesh, uploaded now when the device has none.
  Resident& resident(const raster::PosedMesh& posed) {
    if (const auto found = residents.find(posed.meshKey); found != residents.end())
      return found->second;
    if (posed.localXyz.size() % 3 != 0)
      throw std::invalid_argument("drawMesh: a posed mesh's coordinates are not three a vertex (" +
                                  std::to_string(posed.localXyz.size()) + " doubles)");
    raster::checkIndices(posed.localXyz.size() / 3, posed.indices);
    Resident r;
    r.alive = posed.alive;
    r.vertices = static_cast<std::uint32_t>(posed.localXyz.size() / 3);
    r.triangles = static_cast<std::uint32_t>(posed.indices.size() / 3);
    const VkDeviceSize localBytes = posed.localXyz.size_bytes();
    const VkDeviceSize indexBytes = posed.indices.size_bytes();
    r.indexOffset = aligned(std::max<VkDeviceSize>(localBytes, 4));
    ++meshCounters.uploads;
    freeRetired();
    r.buffer = storage(r.indexOffset + std::max<VkDeviceSize>(indexBytes, 4));
    r.address = context->address(r.buffer.buffer);
    recorder->makeRoom(localBytes + indexBytes);
    const detail::CommandRecorder::Staged local =
        recorder->upload(posed.localXyz.data(), localBytes);
    const detail::CommandRecorder::Staged indices =
        recorder->upload(posed.indices.data(), indexBytes);
    recorder->record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
      if (localBytes > 0) {
        const VkBufferCopy localCopy{local.offset, 0, localBytes};
        vkCmdCopyBuffer(cmd, local.buffer, r.buffer.buffer, 1, &localCopy);
      }
      if (indexBytes > 0) {
        const VkBufferCopy indexCopy{indices.offset, r.indexOffset, indexBytes};
        vkCmdCopyBuffer(cmd, indices.buffer, r.buffer.buffer, 1, &indexCopy);
      }
    });
    return residents.emplace(posed.meshKey, std::move(r)).first->second;
  }

  // The frame's vertex job for `posed` at its pose and view (tile_vertex.comp's 23 doubles).
  static detail::TileVertices posedVertices(const Resident& r, const raster::PosedMesh& posed,
                                            std::uint64_t contentKey) {
    detail::TileVertices v;
    v.local = r.address;
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
    releaseExpired();
    Resident& r = resident(posed);
    ++posedDraws;
    if (r.triangles == 0 || state->scissor.empty())
      return;
    frame->draw(target, *state, posedVertices(r, posed, contentKey), r.address + r.indexOffset,
                r.triangles);
    captureIfKept();
  }

  // A draw of `mesh`'s triangles in the current state.
  void drawMeshEntry(Mesh& mesh) {
    if (mesh.triangles == 0 || state->scissor.empty())
      return;
    mesh.drawnIn = recorder->recordingsRun();
    const VkDeviceAddress address = context->address(mesh.buffer.buffer);
    detail::TileVertices vertices;
    vertices.window = address;
    frame->draw(target, *state, vertices, address + mesh.indexOffset, mesh.triangles);
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
    const std::size_t count = c.triangleWords.size() / detail::kTileWordsPerTriangle;
    for (std::size_t t = 0; t < count; ++t) {
      const std::uint32_t* w = c.triangleWords.data() + t * detail::kTileWordsPerTriangle;
      SetUpTriangle tri;
      for (int k = 0; k < 6; ++k)
        tri.fixed[k] = static_cast<std::int32_t>(w[k]);
      tri.frontFacing = w[6] != 0;
      tri.candidates = {static_cast<int>(w[7]), static_cast<int>(w[8]), static_cast<int>(w[9]),
                        static_cast<int>(w[10])};
      std::memcpy(&tri.z0, w + 11, 4);
      std::memcpy(&tri.dzdx, w + 12, 8);
      std::memcpy(&tri.dzdy, w + 14, 8);
      s.triangles.push_back(tri);
    }
    // The job lists hold every draw of the epoch: this draw's entries, in its own numbering.
    const std::uint32_t end = c.firstTriangle + static_cast<std::uint32_t>(count);
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
    for (auto& [buffer, recording] : retired)
      context->destroyDeviceBuffer(buffer);
    for (Mesh& mesh : meshes)
      context->destroyDeviceBuffer(mesh.buffer);
    for (auto& [key, r] : residents)
      context->destroyDeviceBuffer(r.buffer);
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
  MeshCounters counters = impl_->meshCounters;
  counters.posedDraws = impl_->posedDraws;
  counters.residentMeshes = static_cast<long long>(impl_->residents.size());
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
  d.counted([&] { d.drawMeshEntry(d.upload({vertices, indices}, 0, true, {})); });
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
    if (key != 0) {
      for (Impl::Mesh& mesh : d.meshes) {
        if (mesh.key == key && (mesh.whole || mesh.rect.intersect(scissor) == scissor)) {
          mesh.lastUse = ++d.clock;
          ++d.meshCounters.reuses;
          d.drawMeshEntry(mesh);
          return;
        }
      }
    }
    // As CpuDevice: only the triangles that meet the scissor when the source can tell them.
    const std::optional<raster::TriangleDraw> near = source.trianglesMeeting(scissor);
    const raster::TriangleDraw draw = near ? *near : source.allTriangles();
    d.drawMeshEntry(d.upload(draw, key, !near, scissor));
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
    d.releaseExpired();
    const std::size_t n = meshes.size();
    std::vector<detail::TileFrame::BoxRequest> blocks(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Impl::Resident& r = d.resident(meshes[i]);
      blocks[i].local = r.address;
      blocks[i].vertexCount = r.vertices;
      packPose(meshes[i].transform.pose, blocks[i].pose.data());
    }
    const VkDeviceSize bytes = VkDeviceSize{n} * 8 * sizeof(double);
    d.recorder->makeRoom(bytes);
    const detail::CommandRecorder::Staged out =
        d.recorder->results(bytes, [n, read](const std::uint8_t* data) mutable {
          std::vector<raster::PosedBox> boxes(n);
          for (std::size_t i = 0; i < n; ++i) {
            double words[8];
            std::memcpy(words, data + 64 * i, sizeof words);
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
  impl_->releaseExpired();
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
