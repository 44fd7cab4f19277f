#pragma once
// The compute device's pipelines (shaders/compute/, docs/backends.md "The compute device"): the
// stages of a frame (tile_frame.hpp): boxes, vertex, set-up, scan, scatter, sort, raster,
// resolve. All share one pipeline layout: twenty-four storage buffers bound by push descriptors
// (VK_KHR_push_descriptor), each at a binding of its own, pushed once a frame for every stage
// (binding another pipeline of the same layout keeps them), and the `Frame` push constants of
// tile_common.glsl.

#include <vulkan/vulkan_core.h>

#include <cstdint>
#include <span>
#include <utility>

#include "tile_frame_layout.hpp"

namespace recode::backends::detail {

class VulkanContext;

// The bindings of the shared layout (tile_frame_inputs.glsl and the stages declare the same
// numbers; tile_frame_layout.hpp has the records).
enum class TileBinding : std::uint32_t {
  Targets = 0,          // TileTarget a device's framebuffer
  Epochs = 1,           // TileEpoch
  Commands = 2,         // TileCommand
  Draws = 3,            // TileDrawSource
  VertexJobs = 4,       // TileVertexJob
  Transforms = 5,       // kTileTransformDoubles doubles a vertex job
  Triangles = 6,        // TileSetUpTriangle
  BinEntries = 7,       // entries of a job's list: triangles that may cover a centre of its block
  BinOffsets = 8,       // a job's first entry in Lists
  BinCursors = 9,       // the scatter's next free entry of a job's list
  Lists = 10,           // the jobs' lists, one after another: frame triangle indices
  JobFinal = 11,        // 64 words a job: its pixels at the end of its epoch
  ReadArena = 12,       // the reads' words, before they are copied to their destinations
  ResolveRanges = 13,   // TileResolveRange
  BoxJobs = 14,         // TileBoxJob
  Boxes = 15,           // eight doubles a box job
  LaterEpochs = 16,     // the resolve ranges' later epochs
  RasterProgress = 17,  // where a raster job suspended at its budget goes on
  Carry = 18,           // 64 words a job: a suspended raster job's pixels
  Counters = 19,        // what the stages did (tile_common.glsl's kCounter...), checked by the host
  RasterRoundArgs = 20,  // three words a round: the indirect dispatch of the raster's next round
  Poses = 21,            // kTilePoseDoubles doubles a box job
  SortProgress = 22,     // where a sort job suspended at its budget goes on
  SortRoundArgs = 23,    // three words a round: the indirect dispatch of the sort's next round
};
inline constexpr std::uint32_t kTileBindings = 24;
// Every binding is pushed at once: within the smallest maxPushDescriptors a driver may have.
static_assert(kTileBindings <= 32);

// The push constants, in the layout of tile_common.glsl's `Frame`: one set for every stage of
// a frame.
struct TileFrameConstants {
  std::uint32_t vertexCount = 0;
  std::uint32_t vertexJobs = 0;
  std::uint32_t triangleCount = 0;
  std::uint32_t drawCount = 0;
  std::uint32_t jobCount = 0;
  std::uint32_t epochCount = 0;
  std::uint32_t entryCapacity = 0;
  std::uint32_t resolvePixels = 0;
  std::uint32_t resolveRanges = 0;
  std::uint32_t boxJobs = 0;
  std::uint32_t binPass = 0;
  std::uint32_t rasterBudget = 0;
  std::uint32_t sortBudget = 0;
  std::uint32_t scatterBlocks = 0;
  std::uint32_t scatterChunks = 1;
  std::uint32_t round = 0;
  std::uint32_t roundGroupsX = 0;
  std::uint32_t roundGroupsY = 0;
};
static_assert(sizeof(TileFrameConstants) == 72, "tile_common.glsl's Frame is 18 words");

// A buffer range at a binding.
struct TileBuffer {
  TileBinding binding;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkDeviceSize range = VK_WHOLE_SIZE;
};

class TilePipelines {
 public:
  // Throws std::runtime_error naming what is missing when the context's driver has no
  // VK_KHR_push_descriptor, or on a Vulkan failure.
  explicit TilePipelines(const VulkanContext& context);
  TilePipelines(const TilePipelines&) = delete;
  TilePipelines& operator=(const TilePipelines&) = delete;

  VkPipeline box = VK_NULL_HANDLE;     // posed blocks' world boxes
  VkPipeline vertex = VK_NULL_HANDLE;  // posed meshes' window vertices
  VkPipeline setup = VK_NULL_HANDLE;
  VkPipeline scan = VK_NULL_HANDLE;
  VkPipeline scanSerial = VK_NULL_HANDLE;  // the same in one invocation, for CPU drivers
  VkPipeline scatter = VK_NULL_HANDLE;
  VkPipeline sort = VK_NULL_HANDLE;
  VkPipeline raster = VK_NULL_HANDLE;
  VkPipeline resolve = VK_NULL_HANDLE;

  // Pushes `buffers`, one at each binding, for every stage recorded after it on `cmd`. Throws
  // std::logic_error when a binding is missing or given twice.
  void pushBuffers(VkCommandBuffer cmd, std::span<const TileBuffer> buffers) const;
  // Binds `pipeline`, pushes `constants`, and dispatches `groups` workgroups.
  void dispatch(VkCommandBuffer cmd, VkPipeline pipeline, const TileFrameConstants& constants,
                std::uint32_t groupsX, std::uint32_t groupsY) const;
  // The same, with the workgroup counts read from `args` at `offset` (three words) when the
  // dispatch runs.
  void dispatchIndirect(VkCommandBuffer cmd, VkPipeline pipeline,
                        const TileFrameConstants& constants, VkBuffer args,
                        VkDeviceSize offset) const;
  // `groups` workgroups (at least one) as rows of at most 65535 (x) and the rows (y), which
  // linearWorkgroup() numbers back; and the workgroups `count` invocations of a 64-wide stage
  // that reads linearInvocation() take.
  [[nodiscard]] static std::pair<std::uint32_t, std::uint32_t> groupGrid(std::uint64_t groups);
  [[nodiscard]] static std::pair<std::uint32_t, std::uint32_t> linearGroups(std::uint64_t count);

 private:
  void bind(VkCommandBuffer cmd, VkPipeline pipeline, const TileFrameConstants& constants) const;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  PFN_vkCmdPushDescriptorSetKHR push_ = nullptr;
};

// The pipelines of the 64-bit context, made on first use and never destroyed (as the context).
[[nodiscard]] const TilePipelines& tilePipelines();

// Everything a compute stage wrote is visible to the stages, indirect dispatches and transfers
// after it.
void computeBarrier(VkCommandBuffer cmd);

}  // namespace recode::backends::detail
