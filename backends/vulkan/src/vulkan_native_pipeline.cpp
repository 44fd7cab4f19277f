#include "vulkan_native_pipeline.hpp"

#include "vulkan_pipeline.hpp"
#include "vulkan_spirv.hpp"

namespace recode::backends::detail {

NativePipelines createNativePipelines(VkDevice device, VkFormat depthStencilFormat) {
  NativePipelines out;
  out.layout =
      createPushConstantLayout(device, VK_SHADER_STAGE_VERTEX_BIT, sizeof(WindowPushConstants));
  // Its stages need no 64-bit arithmetic: either arithmetic's modules serve.
  const SpirvModules spirv = spirvModules(ShaderArithmetic::Emulated32);
  const VkVertexInputBindingDescription binding{0, 3 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription position{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
  VkPipelineVertexInputStateCreateInfo input{};
  input.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  input.vertexBindingDescriptionCount = 1;
  input.pVertexBindingDescriptions = &binding;
  input.vertexAttributeDescriptionCount = 1;
  input.pVertexAttributeDescriptions = &position;
  GraphicsPipelineDesc draw;
  draw.vertex = spirv.nativeVertex;
  draw.input = &input;
  draw.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  draw.depthStencilFormat = depthStencilFormat;
  out.draw = createGraphicsPipeline(device, out.layout, draw);
  GraphicsPipelineDesc clear;
  clear.vertex = spirv.clearVertex;
  clear.depthStencilFormat = depthStencilFormat;
  out.clear = createGraphicsPipeline(device, out.layout, clear);
  return out;
}

}  // namespace recode::backends::detail
