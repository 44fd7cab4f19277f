#pragma once
// The Vulkan devices' shaders as SPIR-V words, compiled from backends/vulkan/shaders at
// build time (backends/vulkan/CMakeLists.txt) and embedded here.

#include <cstdint>
#include <span>

#include "recode/backends/vulkan_shader_arithmetic.hpp"

namespace recode::backends::detail {

struct SpirvModules {
  std::span<const std::uint32_t> exactVertex;    // exact_vk.vert (exact32_vk.vert): the proxy
  std::span<const std::uint32_t> exactFragment;  // exact_vk.frag (exact32_vk.frag): coverage, depth
  std::span<const std::uint32_t> clearVertex;    // clear_vk.vert: a full-framebuffer rectangle
  std::span<const std::uint32_t> clearFragment;  // clear_vk.frag: the clear depth
  std::span<const std::uint32_t> summaryCompute;  // summary_vk.comp: integers only, serves both
  std::span<const std::uint32_t> nativeVertex;    // native_vk.vert: the native device's one stage
};

// The modules of devices with that shader arithmetic: Emulated32's exact stages declare neither
// the Float64 nor the Int64 capability (tests/backends/vulkan checks the words); the clear
// stages, the summary's compute stage and the native device's vertex stage need neither and
// serve both.
[[nodiscard]] SpirvModules spirvModules(ShaderArithmetic arithmetic);

}  // namespace recode::backends::detail
