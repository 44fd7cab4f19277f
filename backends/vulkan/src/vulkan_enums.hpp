#pragma once
// The device interface's compare functions and stencil ops as Vulkan enums. Kept apart so that
// the device and its tests of the mapping need not include each other.

#include <vulkan/vulkan_core.h>

#include "recode/raster/state.hpp"

namespace recode::backends::detail {

// Throw std::invalid_argument for a value outside the enum.
[[nodiscard]] VkCompareOp vkCompareOp(raster::CompareFunc func);
[[nodiscard]] VkStencilOp vkStencilOp(raster::StencilOp op);

}  // namespace recode::backends::detail
