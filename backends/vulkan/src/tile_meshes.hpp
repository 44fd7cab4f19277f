#pragma once
// The vulkan-compute device's meshes on the device, and how long they live: the triangle lists it
// keeps per content key and scissor, and the posed blocks' object-space meshes it keeps while
// their sources live. The frame (tile_frame.hpp) draws from them by address when the recording is
// submitted, so a buffer the open recording draws from is never written again: a refill goes to
// a new buffer, and a buffer let go is freed only once the recording that may use it has run.
// Every call is made under the recorder's lock.

#include <vulkan/vulkan_core.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "recode/raster/triangle_source.hpp"
#include "vulkan_context.hpp"

namespace recode::backends::detail {

class CommandRecorder;

class TileMeshes {
 public:
  TileMeshes(VulkanContext& context, CommandRecorder& recorder);
  // Frees every buffer: call once the recordings that draw from them have run.
  ~TileMeshes();
  TileMeshes(const TileMeshes&) = delete;
  TileMeshes& operator=(const TileMeshes&) = delete;

  // A triangle list on the device: window vertices (three floats each) and indices by address.
  struct List {
    VkDeviceAddress vertices = 0;
    VkDeviceAddress indices = 0;
    std::uint32_t triangles = 0;  // 0: nothing to draw
  };
  // The list kept for `key` (not 0) under a scissor holding `scissor`, if there is one.
  [[nodiscard]] std::optional<List> find(std::uint64_t key, const raster::PixelRect& scissor);
  // `draw` validated (raster::checkDraw) and uploaded, kept for `key` under `rect` (or for any
  // scissor when `whole`); the least recently used of kKeptLists gives way.
  [[nodiscard]] List upload(const raster::TriangleDraw& draw, std::uint64_t key, bool whole,
                            const raster::PixelRect& rect);

  // A posed block's object-space mesh on the device: uploaded (indices validated) the first time
  // its meshKey is seen, kept until its `alive` expires.
  struct Posed {
    VkDeviceAddress local = 0;  // three doubles a vertex
    VkDeviceAddress indices = 0;
    std::uint32_t vertices = 0;
    std::uint32_t triangles = 0;
  };
  [[nodiscard]] Posed posed(const raster::PosedMesh& mesh);
  // Lets go of the posed meshes whose blocks are gone.
  void releaseExpired();

  struct Counters {
    long long uploads = 0;
    long long reuses = 0;
    long long residentMeshes = 0;
  };
  [[nodiscard]] Counters counters() const;

  static constexpr std::size_t kKeptLists = 8;

 private:
  struct Kept {
    std::uint64_t key = 0;  // 0: serves nothing (free, or a draw without a key)
    bool whole = false;
    raster::PixelRect rect;
    std::uint32_t triangles = 0;
    VkDeviceSize indexOffset = 0;
    DeviceBuffer buffer;          // vertices from 0, indices from indexOffset
    VkDeviceAddress address = 0;  // the buffer's, taken when it is made
    std::uint64_t lastUse = 0;
    // The recording whose frame last drew from the buffer: while it is open, new bytes go to a
    // new buffer.
    std::uint64_t drawnIn = ~std::uint64_t{0};
  };
  struct Resident {
    std::weak_ptr<const void> alive;
    Posed where;
    DeviceBuffer buffer;
  };
  List listOf(Kept& kept);
  DeviceBuffer storage(VkDeviceSize bytes);
  void retire(DeviceBuffer& buffer);
  void freeRetired();

  VulkanContext& context_;
  CommandRecorder& recorder_;
  std::array<Kept, kKeptLists> kept_{};
  std::unordered_map<std::uint64_t, Resident> residents_;  // by meshKey
  // Buffers let go while a recording that may use them was open: freed once it has run.
  std::vector<std::pair<DeviceBuffer, std::uint64_t>> retired_;
  std::uint64_t clock_ = 0;
  long long uploads_ = 0;
  long long reuses_ = 0;
};

}  // namespace recode::backends::detail
