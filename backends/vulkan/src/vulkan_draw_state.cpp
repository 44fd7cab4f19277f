#include "vulkan_draw_state.hpp"

#include "vulkan_enums.hpp"

namespace recode::backends::detail {

void setDepthStencilState(VkCommandBuffer cmd, const raster::RenderState& state) {
  vkCmdSetDepthTestEnable(cmd, VK_TRUE);
  vkCmdSetDepthWriteEnable(cmd, state.depthWrite ? VK_TRUE : VK_FALSE);
  vkCmdSetDepthCompareOp(cmd, vkCompareOp(state.depthFunc));
  vkCmdSetStencilTestEnable(cmd, VK_TRUE);
  const VkCompareOp compare = vkCompareOp(state.stencilFunc);
  const auto ops = [&](VkStencilFaceFlags face, const raster::StencilOps& o) {
    vkCmdSetStencilOp(cmd, face, vkStencilOp(o.stencilFail), vkStencilOp(o.depthPass),
                      vkStencilOp(o.depthFail), compare);
  };
  ops(VK_STENCIL_FACE_FRONT_BIT, state.frontOps);
  ops(VK_STENCIL_FACE_BACK_BIT, state.backOps);
  vkCmdSetStencilCompareMask(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, state.stencilValueMask);
  vkCmdSetStencilWriteMask(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, state.stencilWriteMask);
  vkCmdSetStencilReference(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, state.stencilRef);
}

void clearAttachmentRect(VkCommandBuffer cmd, VkImageAspectFlags aspect,
                         VkClearDepthStencilValue value, const VkRect2D& rect) {
  VkClearAttachment attachment{};
  attachment.aspectMask = aspect;
  attachment.clearValue.depthStencil = value;
  const VkClearRect clearRect{rect, 0, 1};
  vkCmdClearAttachments(cmd, 1, &attachment, 1, &clearRect);
}

void drawMaskedStencilClear(VkCommandBuffer cmd, std::uint8_t value, std::uint8_t writeMask) {
  vkCmdSetDepthTestEnable(cmd, VK_FALSE);
  vkCmdSetDepthWriteEnable(cmd, VK_FALSE);
  vkCmdSetDepthCompareOp(cmd, VK_COMPARE_OP_ALWAYS);
  vkCmdSetStencilTestEnable(cmd, VK_TRUE);
  vkCmdSetStencilOp(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, VK_STENCIL_OP_REPLACE,
                    VK_STENCIL_OP_REPLACE, VK_STENCIL_OP_REPLACE, VK_COMPARE_OP_ALWAYS);
  vkCmdSetStencilCompareMask(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, 0xFF);
  vkCmdSetStencilWriteMask(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, writeMask);
  vkCmdSetStencilReference(cmd, VK_STENCIL_FACE_FRONT_AND_BACK, value);
  vkCmdDraw(cmd, 4, 1, 0, 0);
}

}  // namespace recode::backends::detail
