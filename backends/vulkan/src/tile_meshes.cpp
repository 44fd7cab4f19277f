// The vulkan-compute device's meshes on the device (tile_meshes.hpp).

#include "tile_meshes.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "recode/raster/device_checks.hpp"
#include "tile_frame_layout.hpp"
#include "vulkan_recorder.hpp"

namespace recode::backends::detail {

namespace {

// Where a mesh's indices start: after its vertices (at least a word), bound apart by the frame.
VkDeviceSize indexOffsetAfter(VkDeviceSize vertexBytes) {
  return tileAligned(std::max<VkDeviceSize>(vertexBytes, 4));
}

}  // namespace

TileMeshes::TileMeshes(VulkanContext& context, CommandRecorder& recorder)
    : context_(context), recorder_(recorder) {}

TileMeshes::~TileMeshes() {
  for (auto& [buffer, recording] : retired_)
    context_.destroyDeviceBuffer(buffer);
  for (Kept& k : kept_)
    context_.destroyDeviceBuffer(k.buffer);
  for (auto& [key, r] : residents_)
    context_.destroyDeviceBuffer(r.buffer);
}

DeviceBuffer TileMeshes::storage(VkDeviceSize bytes) {
  return context_.createDeviceBuffer(bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                                VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
}

void TileMeshes::retire(DeviceBuffer& buffer) {
  if (buffer.buffer != VK_NULL_HANDLE)
    retired_.emplace_back(buffer, recorder_.recordingsRun());
  buffer = {};
}

void TileMeshes::freeRetired() {
  const std::uint64_t run = recorder_.recordingsRun();
  std::erase_if(retired_, [&](std::pair<DeviceBuffer, std::uint64_t>& r) {
    if (r.second >= run)
      return false;
    context_.destroyDeviceBuffer(r.first);
    return true;
  });
}

TileMeshes::List TileMeshes::listOf(Kept& kept) {
  kept.lastUse = ++clock_;
  if (kept.triangles == 0)
    return {};
  kept.drawnIn = recorder_.recordingsRun();
  return {kept.address, kept.address + kept.indexOffset, kept.triangles};
}

std::optional<TileMeshes::List> TileMeshes::find(std::uint64_t key,
                                                 const raster::PixelRect& scissor) {
  if (key == 0)
    return std::nullopt;
  for (Kept& k : kept_) {
    if (k.key == key && (k.whole || k.rect.intersect(scissor) == scissor)) {
      ++reuses_;
      return listOf(k);
    }
  }
  return std::nullopt;
}

TileMeshes::List TileMeshes::upload(const raster::TriangleDraw& draw, std::uint64_t key, bool whole,
                                    const raster::PixelRect& rect) {
  raster::checkDraw(draw.vertices, draw.indices);
  Kept& k = *std::min_element(kept_.begin(), kept_.end(),
                              [](const Kept& a, const Kept& b) { return a.lastUse < b.lastUse; });
  const VkDeviceSize vertexBytes = draw.vertices.size_bytes();
  const VkDeviceSize indexBytes = draw.indices.size_bytes();
  k.key = 0;  // serves nothing until its bytes are recorded
  k.triangles = static_cast<std::uint32_t>(draw.indices.size() / 3);
  k.indexOffset = indexOffsetAfter(vertexBytes);
  ++uploads_;
  if (k.triangles == 0)
    return listOf(k);
  recorder_.makeRoom(vertexBytes + indexBytes);
  const VkDeviceSize bytes = k.indexOffset + indexBytes;
  if (k.buffer.buffer == VK_NULL_HANDLE || k.buffer.size < bytes ||
      k.drawnIn == recorder_.recordingsRun()) {
    freeRetired();
    const VkDeviceSize size = std::max(bytes, k.buffer.size);
    retire(k.buffer);
    k.buffer = storage(size);
    k.address = context_.address(k.buffer.buffer);
  }
  const CommandRecorder::Staged vertices = recorder_.upload(draw.vertices.data(), vertexBytes);
  const CommandRecorder::Staged indices = recorder_.upload(draw.indices.data(), indexBytes);
  recorder_.record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
    const VkBufferCopy vertexCopy{vertices.offset, 0, vertexBytes};
    vkCmdCopyBuffer(cmd, vertices.buffer, k.buffer.buffer, 1, &vertexCopy);
    const VkBufferCopy indexCopy{indices.offset, k.indexOffset, indexBytes};
    vkCmdCopyBuffer(cmd, indices.buffer, k.buffer.buffer, 1, &indexCopy);
  });
  k.key = key;
  k.whole = whole;
  k.rect = rect;
  return listOf(k);
}

void TileMeshes::releaseExpired() {
  for (auto at = residents_.begin(); at != residents_.end();) {
    if (at->second.alive.expired()) {
      retire(at->second.buffer);
      at = residents_.erase(at);
    } else {
      ++at;
    }
  }
}

TileMeshes::Posed TileMeshes::posed(const raster::PosedMesh& mesh) {
  if (const auto found = residents_.find(mesh.meshKey); found != residents_.end())
    return found->second.where;
  if (mesh.localXyz.size() % 3 != 0)
    throw std::invalid_argument("drawMesh: a posed mesh's coordinates are not three a vertex (" +
                                std::to_string(mesh.localXyz.size()) + " doubles)");
  raster::checkIndices(mesh.localXyz.size() / 3, mesh.indices);
  Resident r;
  r.alive = mesh.alive;
  const VkDeviceSize localBytes = mesh.localXyz.size_bytes();
  const VkDeviceSize indexBytes = mesh.indices.size_bytes();
  const VkDeviceSize indexOffset = indexOffsetAfter(localBytes);
  ++uploads_;
  freeRetired();
  r.buffer = storage(indexOffset + std::max<VkDeviceSize>(indexBytes, 4));
  const VkDeviceAddress address = context_.address(r.buffer.buffer);
  r.where = {address, address + indexOffset, static_cast<std::uint32_t>(mesh.localXyz.size() / 3),
             static_cast<std::uint32_t>(mesh.indices.size() / 3)};
  recorder_.makeRoom(localBytes + indexBytes);
  const CommandRecorder::Staged local = recorder_.upload(mesh.localXyz.data(), localBytes);
  const CommandRecorder::Staged indices = recorder_.upload(mesh.indices.data(), indexBytes);
  recorder_.record(VK_NULL_HANDLE, [&](VkCommandBuffer cmd) {
    if (localBytes > 0) {
      const VkBufferCopy localCopy{local.offset, 0, localBytes};
      vkCmdCopyBuffer(cmd, local.buffer, r.buffer.buffer, 1, &localCopy);
    }
    if (indexBytes > 0) {
      const VkBufferCopy indexCopy{indices.offset, indexOffset, indexBytes};
      vkCmdCopyBuffer(cmd, indices.buffer, r.buffer.buffer, 1, &indexCopy);
    }
  });
  return residents_.emplace(mesh.meshKey, std::move(r)).first->second.where;
}

TileMeshes::Counters TileMeshes::counters() const {
  return {uploads_, reuses_, static_cast<long long>(residents_.size())};
}

}  // namespace recode::backends::detail
