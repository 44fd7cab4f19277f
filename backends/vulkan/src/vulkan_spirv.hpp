#pragma once
// The exact Vulkan device's shaders as SPIR-V words, compiled from backends/vulkan/shaders at
// build time (backends/vulkan/CMakeLists.txt) and embedded here.

#include <cstdint>
#include <span>

namespace recode::backends::detail {

struct SpirvModules {
  std::span<const std::uint32_t> exactVertex;    // exact_vk.vert: the proxy rectangle
  std::span<const std::uint32_t> exactFragment;  // exact_vk.frag: coverage and depth
  std::span<const std::uint32_t> clearVertex;    // clear_vk.vert: a full-framebuffer rectangle
  std::span<const std::uint32_t> clearFragment;  // clear_vk.frag: the clear depth
};

[[nodiscard]] SpirvModules spirvModules();

}  // namespace recode::backends::detail
