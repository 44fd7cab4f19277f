#pragma once
// The exact Vulkan device's shaders as SPIR-V words, compiled from verify/vulkan/shaders at
// build time (vulkan.cmake) and embedded here.

#include <cstdint>
#include <span>

namespace recode::verify::detail {

struct SpirvModules {
  std::span<const std::uint32_t> exactVertex;    // exact_vk.vert: the proxy rectangle
  std::span<const std::uint32_t> exactFragment;  // exact_vk.frag: coverage and depth
  std::span<const std::uint32_t> clearVertex;    // clear_vk.vert: a full-framebuffer rectangle
  std::span<const std::uint32_t> clearFragment;  // clear_vk.frag: the clear depth
};

[[nodiscard]] SpirvModules spirvModules();

}  // namespace recode::verify::detail
