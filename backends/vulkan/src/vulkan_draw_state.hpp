#pragma once
// The interface's fragment state as Vulkan dynamic state, and the clears inside a rendering: what
// the exact and the native Vulkan devices record alike before their draws and for their clears.

#include <vulkan/vulkan_core.h>

#include <cstdint>

#include "recode/raster/state.hpp"

namespace recode::backends::detail {

// The interface's depth and stencil state: the depth test always on ("off" is ALWAYS), both
// faces sharing the compare function, masks and reference, each face its own ops.
void setDepthStencilState(VkCommandBuffer cmd, const raster::RenderState& state);

// Clears `aspect` to `value` over `rect` of the open rendering (vkCmdClearAttachments: in
// rasterization order with the draws, no pipeline state, write masks ignored).
void clearAttachmentRect(VkCommandBuffer cmd, VkImageAspectFlags aspect,
                         VkClearDepthStencilValue value, const VkRect2D& rect);

// GL's masked stencil clear, s = (value & mask) | (s & ~mask), as a draw of the bound pipeline's
// four-vertex rectangle over the whole framebuffer (the scissor set limits it): stencil REPLACE
// with the clear value as reference under the write mask, depth neither tested nor written.
void drawMaskedStencilClear(VkCommandBuffer cmd, std::uint8_t value, std::uint8_t writeMask);

}  // namespace recode::backends::detail
