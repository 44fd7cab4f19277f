#pragma once
// The compute device's pipelines (shaders/compute/, docs/backends.md "The compute device"): the
// tile rasterizer's five stages, the vertex stage of a posed draw, posed blocks' boxes, the clears
// and the read-backs.
// All share one pipeline layout: eleven storage buffers bound by push descriptors
// (VK_KHR_push_descriptor), so a dispatch names its buffers as it is recorded and no descriptor set
// outlives it, and the `Draw` push constants of tile_common.glsl.

#include <vulkan/vulkan_core.h>

#include <cstdint>
#include <initializer_list>

namespace recode::backends::detail {

class VulkanContext;

// The bindings of the shared layout (tile_common.glsl and the stages declare the same numbers).
enum class TileBinding : std::uint32_t {
  Vertices = 0,     // a draw's window vertices, three floats each
  Indices = 1,      // its indices, three a triangle
  Triangles = 2,    // set-up triangles, kTileWordsPerTriangle words each
  BlockCounts = 3,  // triangles a block's list holds
  BlockOffsets = 4,
  BlockCursors = 5,
  Pairs = 6,             // the blocks' lists, one after the other
  Framebuffer = 7,       // a word a pixel: q << 8 | stencil
  Output = 8,            // a read's destination
  LocalVertices = 9,     // a posed draw's object-space vertices, three doubles each
  VertexTransform = 10,  // its pose and window mapping (tile_vertex.comp)
};
inline constexpr std::uint32_t kTileBindings = 11;
// Doubles of a VertexTransform as tile_vertex.comp reads it.
inline constexpr std::uint32_t kTileTransformDoubles = 23;
inline constexpr std::uint32_t kTileWordsPerTriangle = 16;

// The push constants, in the layout of tile_common.glsl's `Draw`.
struct TileDrawConstants {
  std::int32_t scissor[4] = {0, 0, 0, 0};
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t triangleCount = 0;
  std::uint32_t tests = 0;
  std::uint32_t stencil = 0;
  std::uint32_t ops = 0;
  std::uint32_t gridWidth = 0;
  std::uint32_t gridHeight = 0;
  std::uint32_t pairCapacity = 0;
  std::uint32_t outWord = 0;
  std::uint32_t blocksPerGroup = 1;
};
static_assert(sizeof(TileDrawConstants) == 60, "tile_common.glsl's Draw is 15 words");

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

  VkPipeline vertex = VK_NULL_HANDLE;  // a posed draw's vertex stage
  VkPipeline box = VK_NULL_HANDLE;     // a posed block's world box
  VkPipeline setup = VK_NULL_HANDLE;
  VkPipeline scan = VK_NULL_HANDLE;
  VkPipeline scanSerial = VK_NULL_HANDLE;  // the same in one invocation, for CPU drivers
  VkPipeline scatter = VK_NULL_HANDLE;
  VkPipeline sort = VK_NULL_HANDLE;
  VkPipeline raster = VK_NULL_HANDLE;
  VkPipeline clear = VK_NULL_HANDLE;
  VkPipeline read = VK_NULL_HANDLE;

  // Binds `pipeline`, pushes `buffers` and `constants`, and dispatches `groups` workgroups.
  void dispatch(VkCommandBuffer cmd, VkPipeline pipeline, std::initializer_list<TileBuffer> buffers,
                const TileDrawConstants& constants, std::uint32_t groupsX,
                std::uint32_t groupsY) const;
  // The same for `count` invocations of a 64-wide stage that reads linearInvocation(): rows of
  // at most 65535 workgroups. Nothing when count is 0.
  void dispatchLinear(VkCommandBuffer cmd, VkPipeline pipeline,
                      std::initializer_list<TileBuffer> buffers, const TileDrawConstants& constants,
                      std::uint64_t count) const;

 private:
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  PFN_vkCmdPushDescriptorSetKHR push_ = nullptr;
};

// The pipelines of the 64-bit context, made on first use and never destroyed (as the context).
[[nodiscard]] const TilePipelines& tilePipelines();

// Everything a compute stage wrote is visible to the stages and transfers after it.
void computeBarrier(VkCommandBuffer cmd);

}  // namespace recode::backends::detail
