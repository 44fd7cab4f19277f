// VulkanComputeDevice: the contract as a tile rasterizer in compute shaders
// (shaders/compute/). The host validates a draw and copies its window vertices and indices to
// the device as they are; each draw then records five dispatches (set-up, the blocks' prefix
// sum, binning, sorting each block's list, the blocks' fragments) and the framebuffer stays a
// storage buffer that clears, read-backs and summaries address directly. Everything is recorded
// into the shared recording of the 64-bit Vulkan context (vulkan_recorder.hpp) and run by finish().

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
#include "vulkan_compute_pipelines.hpp"
#include "vulkan_context.hpp"
#include "vulkan_recorder.hpp"
#include "vulkan_summary.hpp"

namespace recode::backends {

namespace {

using detail::TileBinding;
using detail::TileBuffer;
using detail::TileDrawConstants;
using raster::PixelRect;

// Offsets of the regions a dispatch binds: the largest minStorageBufferOffsetAlignment the
// specification allows, so no device needs asking.
constexpr VkDeviceSize kBindAlignment = 256;

VkDeviceSize aligned(VkDeviceSize bytes) {
  return (bytes + kBindAlignment - 1) / kBindAlignment * kBindAlignment;
}

// The form a read writes (tile_read.comp).
enum class ReadForm : std::uint32_t { DepthWords = 0, StencilBytes = 1, DepthFloats = 2 };

// What a draw's work buffer holds, for `triangles` triangles under a scissor of `blocks` 8x8
// blocks: the set-up triangles, the blocks' counts, offsets and cursors, and the lists.
struct WorkLayout {
  WorkLayout(std::uint32_t triangles, std::uint32_t blocks)
      : pairCapacity(4 * triangles + 2 * blocks + 4096) {
    countsOffset = aligned(VkDeviceSize{triangles} * detail::kTileWordsPerTriangle * 4);
    offsetsOffset = countsOffset + aligned(VkDeviceSize{blocks} * 4);
    cursorsOffset = offsetsOffset + aligned(VkDeviceSize{blocks} * 4);
    pairsOffset = cursorsOffset + aligned(VkDeviceSize{blocks} * 4);
    bytes = pairsOffset + VkDeviceSize{pairCapacity} * 4;
  }
  // Entries the blocks' lists hold in all: a block whose list would pass the end is drawn from
  // every triangle of the draw instead (tile_raster.comp), so this bounds memory, not results.
  std::uint32_t pairCapacity;
  VkDeviceSize countsOffset = 0;
  VkDeviceSize offsetsOffset = 0;
  VkDeviceSize cursorsOffset = 0;
  VkDeviceSize pairsOffset = 0;
  VkDeviceSize bytes = 0;
};

// The interface's state as the shaders read it (tile_common.glsl's Draw).
TileDrawConstants stateConstants(const raster::RenderState& s, int width, int height) {
  TileDrawConstants c;
  c.scissor[0] = s.scissor.x0;
  c.scissor[1] = s.scissor.y0;
  c.scissor[2] = s.scissor.x1;
  c.scissor[3] = s.scissor.y1;
  c.width = static_cast<std::uint32_t>(width);
  c.height = static_cast<std::uint32_t>(height);
  const auto bits = [](auto value) { return static_cast<std::uint32_t>(value); };
  c.tests = bits(s.depthFunc) | (s.depthWrite ? 8u : 0u) | (bits(s.stencilFunc) << 4) |
            (bits(s.cull) << 7);
  c.stencil =
      bits(s.stencilRef) | (bits(s.stencilValueMask) << 8) | (bits(s.stencilWriteMask) << 16);
  const auto ops = [&](const raster::StencilOps& o) {
    return bits(o.stencilFail) | (bits(o.depthFail) << 3) | (bits(o.depthPass) << 6);
  };
  c.ops = ops(s.frontOps) | (ops(s.backOps) << 9);
  return c;
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
  const detail::TilePipelines* pipelines = nullptr;
  detail::CommandRecorder* recorder = nullptr;
  raster::TransferCounters transfers;
  detail::DeviceBuffer framebuffer;  // a word a pixel, rows from the bottom
  detail::DeviceBuffer work;         // the draw being recorded's WorkLayout (draws take turns)
  detail::DeviceBuffer boxWork;      // posed boxes: the poses, then the boxes (posedBoxesLater)
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
  };
  static constexpr std::size_t kKeptMeshes = 8;
  std::array<Mesh, kKeptMeshes> meshes{};

  // A posed block's mesh on the device (raster::PosedMesh), kept while its source says it lives:
  // the object-space vertices from 0, the indices from indexOffset, the window vertices of the
  // last pose and view from windowOffset, and that draw's transform from transformOffset.
  struct Resident {
    std::weak_ptr<const void> alive;
    std::uint32_t vertices = 0;
    std::uint32_t triangles = 0;
    VkDeviceSize indexOffset = 0;
    VkDeviceSize windowOffset = 0;
    VkDeviceSize transformOffset = 0;
    // The content key whose window vertices the buffer holds (0: none yet): its later draws
    // skip the vertex stage.
    std::uint64_t windowsOf = 0;
    detail::DeviceBuffer buffer;
  };
  // By meshKey (an entry stays where it is while others come and go).
  std::unordered_map<std::uint64_t, Resident> residents;
  std::uint64_t clock = 0;
  MeshCounters meshCounters;
  long long posedDraws = 0;
  bool keepStages = false;
  std::shared_ptr<std::optional<DrawStages>> lastStages =
      std::make_shared<std::optional<DrawStages>>();
  // The window vertices the posed draw being recorded copies back (keepDrawStages), for its
  // DrawStages; null for a draw of window vertices.
  std::shared_ptr<std::vector<raster::WindowVertex>> drawWindows;

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

  // `buffer` with room for `bytes`: a larger one (the old one retired) when it has too little.
  void reserve(detail::DeviceBuffer& buffer, VkDeviceSize bytes) {
    if (buffer.buffer != VK_NULL_HANDLE && buffer.size >= bytes)
      return;
    freeRetired();
    if (buffer.buffer != VK_NULL_HANDLE)
      retired.emplace_back(buffer, recorder->recordingsRun());
    buffer = context->createDeviceBuffer(std::max(bytes, buffer.size * 2),
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
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
    reserve(mesh.buffer, mesh.indexOffset + indexBytes);
    recorder->makeRoom(vertexBytes + indexBytes);
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
    r.windowOffset = r.indexOffset + aligned(std::max<VkDeviceSize>(indexBytes, 4));
    r.transformOffset = r.windowOffset + aligned(VkDeviceSize{r.vertices} * 12 + 4);
    const VkDeviceSize transformBytes = detail::kTileTransformDoubles * 8;
    ++meshCounters.uploads;
    freeRetired();
    r.buffer = context->createDeviceBuffer(r.transformOffset + transformBytes,
                                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                               VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                               VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
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

  // Records the vertex stage of `posed` into its resident mesh's window vertices, unless they
  // are already those of `contentKey` (a source's draws all have the same pose and view).
  void recordVertexStage(Resident& r, const raster::PosedMesh& posed, std::uint64_t contentKey) {
    if (contentKey != 0 && r.windowsOf == contentKey)
      return;
    r.windowsOf = 0;
    const raster::VertexTransform& t = posed.transform;
    std::array<double, detail::kTileTransformDoubles> words{};
    packPose(t.pose, words.data());
    const raster::WindowMapping& m = t.window;
    const std::array<double, 8> mapping{m.umin,   m.urange, m.width,    m.vmin,
                                        m.vrange, m.height, m.depthMax, m.depthRange};
    std::copy(mapping.begin(), mapping.end(), words.begin() + 12);
    for (int k = 0; k < 3; ++k) {
      const int axis = m.axes[static_cast<std::size_t>(k)];
      if (axis < 0 || axis > 2)
        throw std::invalid_argument("drawMesh: a posed draw's window mapping names axis " +
                                    std::to_string(axis) + " (must be 0, 1 or 2)");
      words[static_cast<std::size_t>(20 + k)] = axis;
    }
    recorder->makeRoom(sizeof words);
    const detail::CommandRecorder::Staged staged = recorder->upload(words.data(), sizeof words);
    TileDrawConstants c;
    c.triangleCount = r.vertices;
    const TileBuffer local{TileBinding::LocalVertices, r.buffer.buffer, 0, r.indexOffset};
    const TileBuffer transform{TileBinding::VertexTransform, r.buffer.buffer, r.transformOffset,
                               sizeof words};
    const TileBuffer windows{TileBinding::Vertices, r.buffer.buffer, r.windowOffset,
                             r.transformOffset - r.windowOffset};
    recorder->record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
      // The last draw of this mesh may still read its transform and window vertices.
      detail::computeBarrier(cmd);
      const VkBufferCopy copy{staged.offset, r.transformOffset, sizeof words};
      vkCmdCopyBuffer(cmd, staged.buffer, r.buffer.buffer, 1, &copy);
      detail::computeBarrier(cmd);
      pipelines->dispatchLinear(cmd, pipelines->vertex, {local, transform, windows}, c, r.vertices);
    });
    r.windowsOf = contentKey;
  }

  // Records the boxes of `blocks` at their poses: the poses into boxWork, a workgroup a block,
  // and the boxes (eight doubles each) copied back for `read`.
  void recordBoxes(std::span<const raster::PosedMesh> blocks,
                   raster::PendingRead<raster::PosedBox> read) {
    releaseExpired();
    const std::size_t n = blocks.size();
    std::vector<const Resident*> kept;
    std::vector<double> poses(12 * n);
    for (std::size_t i = 0; i < n; ++i) {
      kept.push_back(&resident(blocks[i]));
      packPose(blocks[i].transform.pose, poses.data() + 12 * i);
    }
    const VkDeviceSize poseBytes = poses.size() * sizeof(double);
    const VkDeviceSize boxesOffset = aligned(poseBytes);
    const VkDeviceSize boxBytes = VkDeviceSize{n} * 8 * sizeof(double);
    reserve(boxWork, boxesOffset + boxBytes);
    recorder->makeRoom(poseBytes + boxBytes);
    const detail::CommandRecorder::Staged staged = recorder->upload(poses.data(), poseBytes);
    const detail::CommandRecorder::Staged out =
        recorder->results(boxBytes, [n, read](const std::uint8_t* bytes) mutable {
          std::vector<raster::PosedBox> boxes(n);
          for (std::size_t i = 0; i < n; ++i) {
            double words[8];
            std::memcpy(words, bytes + 64 * i, sizeof words);
            std::copy(words, words + 3, boxes[i].min.begin());
            std::copy(words + 3, words + 6, boxes[i].max.begin());
            boxes[i].orderMatters = words[6] != 0.0;
          }
          read.deliver(std::move(boxes));
        });
    const TileBuffer posesBuffer{TileBinding::VertexTransform, boxWork.buffer, 0,
                                 std::max<VkDeviceSize>(poseBytes, 8)};
    const TileBuffer boxesBuffer{TileBinding::Output, boxWork.buffer, boxesOffset, boxBytes};
    recorder->record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
      detail::computeBarrier(cmd);
      const VkBufferCopy copy{staged.offset, 0, poseBytes};
      vkCmdCopyBuffer(cmd, staged.buffer, boxWork.buffer, 1, &copy);
      detail::computeBarrier(cmd);
      for (std::size_t i = 0; i < n; ++i) {
        const Resident& r = *kept[i];
        TileDrawConstants c;
        c.triangleCount = r.vertices;
        c.outWord = static_cast<std::uint32_t>(i);
        const TileBuffer local{TileBinding::LocalVertices, r.buffer.buffer, 0, r.indexOffset};
        pipelines->dispatch(cmd, pipelines->box, {local, posesBuffer, boxesBuffer}, c, 1, 1);
      }
      detail::computeBarrier(cmd);
      const VkBufferCopy back{boxesOffset, out.offset, boxBytes};
      vkCmdCopyBuffer(cmd, boxWork.buffer, out.buffer, 1, &back);
    });
  }

  // A posed draw: the vertex stage on the device, then the tile rasterizer over every triangle
  // of the block (set-up leaves out those whose pixels miss the scissor).
  void drawPosed(const raster::PosedMesh& posed, std::uint64_t contentKey) {
    releaseExpired();
    Resident& r = resident(posed);
    ++posedDraws;
    if (r.triangles == 0 || state->scissor.empty())
      return;
    recordVertexStage(r, posed, contentKey);
    if (keepStages)
      copyWindowsBack(r);
    Mesh entry;
    entry.triangles = r.triangles;
    entry.indexOffset = r.indexOffset;
    drawTiles(entry, r.buffer.buffer, r.windowOffset, r.transformOffset - r.windowOffset);
  }

  // Records the tile rasterizer's five stages for `mesh` in the current state.
  void drawMeshEntry(const Mesh& mesh) { drawTiles(mesh, mesh.buffer.buffer, 0, mesh.indexOffset); }

  // The five stages for `mesh`'s triangles, its indices at mesh.indexOffset of `buffer` and its
  // window vertices at [vertexOffset, + vertexRange).
  void drawTiles(const Mesh& mesh, VkBuffer buffer, VkDeviceSize vertexOffset,
                 VkDeviceSize vertexRange) {
    const PixelRect& scissor = state->scissor;
    if (mesh.triangles == 0 || scissor.empty())
      return;
    TileDrawConstants c = stateConstants(*state, width, height);
    c.triangleCount = mesh.triangles;
    c.gridWidth = static_cast<std::uint32_t>(((scissor.x1 - 1) >> 3) - (scissor.x0 >> 3) + 1);
    c.gridHeight = static_cast<std::uint32_t>(((scissor.y1 - 1) >> 3) - (scissor.y0 >> 3) + 1);
    const std::uint32_t blocks = c.gridWidth * c.gridHeight;
    const WorkLayout layout(mesh.triangles, blocks);
    c.pairCapacity = layout.pairCapacity;
    // Eight blocks a workgroup on a GPU; on a CPU driver, where each workgroup has a fixed cost
    // of several microseconds, a row of blocks.
    c.blocksPerGroup = context->cpuDriver() ? std::max(c.gridWidth, 8u) : 8u;
    reserve(work, layout.bytes);
    const VkBuffer w = work.buffer;
    const VkDeviceSize blockBytes = VkDeviceSize{blocks} * 4;
    const TileBuffer vertices{TileBinding::Vertices, buffer, vertexOffset, vertexRange};
    const TileBuffer indices{TileBinding::Indices, buffer, mesh.indexOffset,
                             VkDeviceSize{mesh.triangles} * 12};
    const TileBuffer triangles{TileBinding::Triangles, w, 0, layout.countsOffset};
    const TileBuffer counts{TileBinding::BlockCounts, w, layout.countsOffset, blockBytes};
    const TileBuffer offsets{TileBinding::BlockOffsets, w, layout.offsetsOffset, blockBytes};
    const TileBuffer cursors{TileBinding::BlockCursors, w, layout.cursorsOffset, blockBytes};
    const TileBuffer pairs{TileBinding::Pairs, w, layout.pairsOffset,
                           VkDeviceSize{layout.pairCapacity} * 4};
    const TileBuffer pixels{TileBinding::Framebuffer, framebuffer.buffer, 0, VK_WHOLE_SIZE};
    const detail::TilePipelines& p = *pipelines;
    recorder->record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
      vkCmdFillBuffer(cmd, w, layout.countsOffset, blockBytes, 0);
      detail::computeBarrier(cmd);
      p.dispatchLinear(cmd, p.setup, {vertices, indices, triangles, counts}, c, mesh.triangles);
      detail::computeBarrier(cmd);
      p.dispatch(cmd, context->cpuDriver() ? p.scanSerial : p.scan, {counts, offsets, cursors}, c,
                 1, 1);
      detail::computeBarrier(cmd);
      p.dispatchLinear(cmd, p.scatter, {triangles, cursors, pairs}, c, mesh.triangles);
      detail::computeBarrier(cmd);
      p.dispatchLinear(cmd, p.sort, {counts, offsets, pairs}, c, blocks);
      detail::computeBarrier(cmd);
      p.dispatch(cmd, p.raster, {triangles, counts, offsets, pairs, pixels}, c,
                 (c.gridWidth + c.blocksPerGroup - 1) / c.blocksPerGroup, c.gridHeight);
    });
    if (keepStages)
      copyStagesBack(layout, c);
  }

  // Records a copy of a posed mesh's window vertices; they become the draw's DrawStages'
  // windowVertices when the recording has run.
  void copyWindowsBack(const Resident& r) {
    drawWindows = std::make_shared<std::vector<raster::WindowVertex>>();
    const VkDeviceSize bytes = VkDeviceSize{r.vertices} * sizeof(raster::WindowVertex);
    recorder->makeRoom(bytes);
    const std::size_t count = r.vertices;
    const detail::CommandRecorder::Staged out =
        recorder->results(bytes, [count, to = drawWindows](const std::uint8_t* data) {
          to->resize(count);
          std::memcpy(to->data(), data, count * sizeof(raster::WindowVertex));
        });
    recorder->record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
      detail::computeBarrier(cmd);
      const VkBufferCopy copy{r.windowOffset, out.offset, bytes};
      vkCmdCopyBuffer(cmd, r.buffer.buffer, out.buffer, 1, &copy);
    });
  }

  // Records a copy of the work buffer as the draw left it; its bytes become lastStages when the
  // recording has run.
  void copyStagesBack(const WorkLayout& layout, const TileDrawConstants& c) {
    const VkDeviceSize bytes = std::min(layout.bytes, work.size);
    recorder->makeRoom(bytes);
    const detail::CommandRecorder::Staged out = recorder->results(
        bytes, [layout, c, last = lastStages,
                windows = std::exchange(drawWindows, nullptr)](const std::uint8_t* words) {
          *last = parseStages(words, layout, c);
          // Delivered before this: the window vertices were copied first.
          if (windows)
            (*last)->windowVertices = std::move(*windows);
        });
    recorder->record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
      const VkBufferCopy copy{0, out.offset, bytes};
      vkCmdCopyBuffer(cmd, work.buffer, out.buffer, 1, &copy);
    });
  }

  static DrawStages parseStages(const std::uint8_t* bytes, const WorkLayout& layout,
                                const TileDrawConstants& c) {
    const auto word = [&](VkDeviceSize byteOffset) {
      std::uint32_t w = 0;
      std::memcpy(&w, bytes + byteOffset, 4);
      return w;
    };
    DrawStages s;
    s.scissor = {c.scissor[0], c.scissor[1], c.scissor[2], c.scissor[3]};
    s.gridWidth = static_cast<int>(c.gridWidth);
    s.gridHeight = static_cast<int>(c.gridHeight);
    for (std::uint32_t t = 0; t < c.triangleCount; ++t) {
      const VkDeviceSize base = VkDeviceSize{t} * detail::kTileWordsPerTriangle * 4;
      SetUpTriangle tri;
      for (int k = 0; k < 6; ++k)
        tri.fixed[k] = static_cast<std::int32_t>(word(base + 4 * k));
      tri.frontFacing = word(base + 24) != 0;
      tri.candidates = {static_cast<int>(word(base + 28)), static_cast<int>(word(base + 32)),
                        static_cast<int>(word(base + 36)), static_cast<int>(word(base + 40))};
      std::memcpy(&tri.z0, bytes + base + 44, 4);
      std::memcpy(&tri.dzdx, bytes + base + 48, 8);
      std::memcpy(&tri.dzdy, bytes + base + 56, 8);
      s.triangles.push_back(tri);
    }
    const std::uint32_t blocks = c.gridWidth * c.gridHeight;
    for (std::uint32_t b = 0; b < blocks; ++b) {
      const std::uint32_t count = word(layout.countsOffset + 4 * b);
      const std::uint32_t offset = word(layout.offsetsOffset + 4 * b);
      const bool overflowed = offset + count > layout.pairCapacity;
      s.overflowed.push_back(overflowed);
      std::vector<std::uint32_t> list;
      for (std::uint32_t k = 0; k < count && !overflowed; ++k)
        list.push_back(word(layout.pairsOffset + 4 * (VkDeviceSize{offset} + k)));
      s.blockLists.push_back(std::move(list));
    }
    return s;
  }

  // Records a clear of the scissor (tile_clear.comp): `stencil` false for depth.
  void clear(bool stencil, std::uint32_t value) {
    const PixelRect& s = state->scissor;
    TileDrawConstants c = stateConstants(*state, width, height);
    c.triangleCount = value;
    c.outWord = stencil ? 1 : 0;
    const TileBuffer pixels{TileBinding::Framebuffer, framebuffer.buffer, 0, VK_WHOLE_SIZE};
    const auto hold = recorder->hold();
    recorder->record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
      pipelines->dispatch(cmd, pipelines->clear, {pixels}, c,
                          static_cast<std::uint32_t>((s.width() + 7) / 8),
                          static_cast<std::uint32_t>((s.height() + 7) / 8));
    });
  }

  // Records a copy of `r` (inside the framebuffer) in `form` into `out` from byte `offset`.
  void recordRead(const PixelRect& r, ReadForm form, VkBuffer out, VkDeviceSize offset) {
    TileDrawConstants c;
    c.scissor[0] = r.x0;
    c.scissor[1] = r.y0;
    c.scissor[2] = r.x1;
    c.scissor[3] = r.y1;
    c.width = static_cast<std::uint32_t>(width);
    c.height = static_cast<std::uint32_t>(height);
    c.triangleCount = static_cast<std::uint32_t>(form);
    c.outWord = static_cast<std::uint32_t>(offset / 4);
    const auto pixels = static_cast<std::uint64_t>(r.area());
    const std::uint64_t invocations = form == ReadForm::StencilBytes ? (pixels + 3) / 4 : pixels;
    const TileBuffer in{TileBinding::Framebuffer, framebuffer.buffer, 0, VK_WHOLE_SIZE};
    const TileBuffer to{TileBinding::Output, out, 0, VK_WHOLE_SIZE};
    recorder->record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
      pipelines->dispatchLinear(cmd, pipelines->read, {in, to}, c, invocations);
    });
  }

  // A read of `r` whose `bytes` go to `deliver` when the recording has run.
  void readInto(const PixelRect& r, ReadForm form, std::size_t bytes,
                std::function<void(const std::uint8_t*)> deliver) {
    const auto hold = recorder->hold();
    counted([&] {
      recorder->makeRoom(bytes);
      const detail::CommandRecorder::Staged out = recorder->results(bytes, std::move(deliver));
      recordRead(r, form, out.buffer, out.offset);
    });
  }

  ~Impl() {
    if (context == nullptr)
      return;
    // Commands recorded for this framebuffer must run before it goes: they are in the shared
    // recording, beside other devices' commands.
    try {
      recorder->finish();
    } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw
    }
    for (auto& [buffer, recording] : retired)
      context->destroyDeviceBuffer(buffer);
    for (Mesh& mesh : meshes)
      context->destroyDeviceBuffer(mesh.buffer);
    for (auto& [key, r] : residents)
      context->destroyDeviceBuffer(r.buffer);
    context->destroyDeviceBuffer(work);
    context->destroyDeviceBuffer(boxWork);
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
  d.pipelines = &detail::tilePipelines();  // makes the context too
  d.context = &detail::VulkanContext::instance(ShaderArithmetic::Native64);
  d.recorder = &detail::sharedRecorder(ShaderArithmetic::Native64);
  const VkDeviceSize bytes =
      VkDeviceSize{4} * static_cast<VkDeviceSize>(width) * static_cast<VkDeviceSize>(height);
  d.framebuffer = d.context->createDeviceBuffer(
      bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  // The start state of CpuDevice: depth 2^24 - 1, stencil 0 everywhere.
  const auto hold = d.recorder->hold();
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
  impl_->clear(false, raster::quantizeDepth(depth));
}

void VulkanComputeDevice::clearStencil(std::uint8_t value) {
  if (state_.stencilWriteMask == 0 || state_.scissor.empty())
    return;
  impl_->clear(true, value);
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
  d.counted([&] { d.recordBoxes(meshes, read); });
  return read;
}

raster::PendingRead<std::uint8_t> VulkanComputeDevice::readStencilLater(const PixelRect& rect) {
  Impl& d = *impl_;
  const PixelRect r = rect.intersect({0, 0, d.width, d.height});
  if (r.empty())
    return raster::PendingRead<std::uint8_t>::ready({});
  raster::PendingRead<std::uint8_t> read = raster::PendingRead<std::uint8_t>::waiting();
  const auto pixels = static_cast<std::size_t>(r.area());
  d.readInto(r, ReadForm::StencilBytes, (pixels + 3) / 4 * 4,
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
  d.readInto(r, ReadForm::DepthWords, 4 * pixels,
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
    d.recordRead(r, ReadForm::DepthFloats, region.buffer, region.offset);
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
    d.recordRead(r, ReadForm::StencilBytes, region.buffer, region.offset);
    if (withDepth)
      d.recordRead(r, ReadForm::DepthFloats, region.buffer, region.offset + inputs.farOffset());
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
