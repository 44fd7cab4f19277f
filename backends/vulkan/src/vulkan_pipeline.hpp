#pragma once
// The graphics pipelines of the Vulkan devices. The exact Vulkan device's two, shared by every
// exact device: the exact pipeline draws proxy rectangles (per-instance ProxyTriangle records)
// through the contract's shaders; the clear pipeline draws one rectangle writing the clear depth,
// so that clears honour the scissor and both write masks. Everything a device changes is dynamic
// state (Vulkan 1.3), so these two serve every state. The native device's are made by
// createGraphicsPipeline too (vulkan_native_pipeline.hpp).

#include <vulkan/vulkan_core.h>

#include <cstdint>
#include <span>

#include "recode/backends/vulkan_shader_arithmetic.hpp"

namespace recode::backends::detail {

// The push constants both pipelines read, in the shaders' `Frame` block layout.
struct FramePushConstants {
  float framebufferSize[2];  // width, height in pixels
  float clearDepth;          // q 2^-24, the clear pipeline's depth
};

struct ExactPipelines {
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline exact = VK_NULL_HANDLE;
  VkPipeline clear = VK_NULL_HANDLE;
};

// The depth/stencil attachment format both pipelines render to.
inline constexpr VkFormat kExactDepthStencilFormat = VK_FORMAT_D32_SFLOAT_S8_UINT;

// Made once per logical device, with that arithmetic's shaders; throws std::runtime_error on a
// Vulkan failure.
[[nodiscard]] ExactPipelines createExactPipelines(VkDevice device, ShaderArithmetic arithmetic);

// What sets one graphics pipeline of the Vulkan devices apart; the rest is common to them all:
// every piece of state the device interface changes is dynamic (with the viewport and scissor),
// fill mode, one sample, no colour attachment, VK_FRONT_FACE_COUNTER_CLOCKWISE.
struct GraphicsPipelineDesc {
  std::span<const std::uint32_t> vertex;
  std::span<const std::uint32_t> fragment;  // empty: no fragment stage (the driver's own depth)
  const VkPipelineVertexInputStateCreateInfo* input = nullptr;  // null: no vertex input
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
  VkFormat depthStencilFormat = kExactDepthStencilFormat;
};

// A graphics pipeline of `desc` in `layout`, for dynamic rendering; throws std::runtime_error on
// a Vulkan failure.
[[nodiscard]] VkPipeline createGraphicsPipeline(VkDevice device, VkPipelineLayout layout,
                                                const GraphicsPipelineDesc& desc);

// A pipeline layout with one push-constant block of `bytes` read by `stages`.
[[nodiscard]] VkPipelineLayout createPushConstantLayout(VkDevice device, VkShaderStageFlags stages,
                                                        std::uint32_t bytes);

// A compute pipeline whose shader reads `storageBuffers` storage buffers at bindings 0, 1, ...
// of set 0 and a push-constant block of `pushBytes`: the summary pipeline's shape, and the
// compute tests'.
struct ComputePipeline {
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
};

// The set layout (`storageBuffers` storage buffers at bindings 0, 1, ..., with `flags`) and the
// pipeline layout (with a push-constant block of `pushBytes`) of compute stages; `pipeline` is
// left null. Throws std::runtime_error on a Vulkan failure.
[[nodiscard]] ComputePipeline createComputeLayout(VkDevice device, std::uint32_t storageBuffers,
                                                  std::uint32_t pushBytes,
                                                  VkDescriptorSetLayoutCreateFlags flags);
// A compute stage of `spirv` in `layout`; throws std::runtime_error on a Vulkan failure, naming
// `what`.
[[nodiscard]] VkPipeline createComputeStage(VkDevice device, VkPipelineLayout layout,
                                            std::span<const std::uint32_t> spirv, const char* what);

// Both, for a shader with a layout of its own. Throws std::runtime_error on a Vulkan failure,
// naming `what`.
[[nodiscard]] ComputePipeline createComputePipeline(VkDevice device,
                                                    std::span<const std::uint32_t> spirv,
                                                    std::uint32_t storageBuffers,
                                                    std::uint32_t pushBytes, const char* what);
void destroyComputePipeline(VkDevice device, ComputePipeline& pipeline);

// A descriptor set of `pipeline`'s layout from `pool`, with buffers[i], whole, at binding i.
[[nodiscard]] VkDescriptorSet allocateStorageSet(VkDevice device, VkDescriptorPool pool,
                                                 const ComputePipeline& pipeline,
                                                 std::span<const VkBuffer> buffers);

}  // namespace recode::backends::detail
