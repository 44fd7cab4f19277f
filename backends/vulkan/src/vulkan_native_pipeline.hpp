#pragma once
// The native Vulkan device's graphics pipelines, made once per depth/stencil format and shared by
// every native device: the draw pipeline takes indexed triangle lists of (x, y, z) floats through
// native_vk.vert and has no fragment stage, so coverage and depth are the driver's own; the clear
// pipeline draws clear_vk.vert's rectangle, also without a fragment stage, for the masked stencil
// clears. Everything a device changes is dynamic state (vulkan_pipeline.hpp).

#include <vulkan/vulkan_core.h>

namespace recode::backends::detail {

// native_vk.vert's push constants, in its `Window` block layout.
struct WindowPushConstants {
  float centre[2];  // the viewport's centre in GL window coordinates
  float scale[2];   // 2/P, 2/Q for a P x Q viewport
};

struct NativePipelines {
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline draw = VK_NULL_HANDLE;
  VkPipeline clear = VK_NULL_HANDLE;
};

// Both pipelines for attachments of `depthStencilFormat`; throws std::runtime_error on a Vulkan
// failure.
[[nodiscard]] NativePipelines createNativePipelines(VkDevice device, VkFormat depthStencilFormat);

}  // namespace recode::backends::detail
