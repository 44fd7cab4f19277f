#include "vulkan_pipeline.hpp"

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "recode/backends/exact_proxy.hpp"
#include "vulkan_context.hpp"
#include "vulkan_spirv.hpp"

namespace recode::backends::detail {

namespace {

VkShaderModule createModule(VkDevice device, std::span<const std::uint32_t> words) {
  VkShaderModuleCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  info.codeSize = words.size_bytes();
  info.pCode = words.data();
  VkShaderModule module = VK_NULL_HANDLE;
  vkCheck(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
  return module;
}

// Every piece of state the device interface can change, plus the viewport and scissor, which
// depend on the device's size.
constexpr std::array kDynamicStates = {
    VK_DYNAMIC_STATE_VIEWPORT,
    VK_DYNAMIC_STATE_SCISSOR,
    VK_DYNAMIC_STATE_CULL_MODE,
    VK_DYNAMIC_STATE_DEPTH_TEST_ENABLE,
    VK_DYNAMIC_STATE_DEPTH_WRITE_ENABLE,
    VK_DYNAMIC_STATE_DEPTH_COMPARE_OP,
    VK_DYNAMIC_STATE_STENCIL_TEST_ENABLE,
    VK_DYNAMIC_STATE_STENCIL_OP,
    VK_DYNAMIC_STATE_STENCIL_COMPARE_MASK,
    VK_DYNAMIC_STATE_STENCIL_WRITE_MASK,
    VK_DYNAMIC_STATE_STENCIL_REFERENCE,
};

// The proxy records as per-instance attributes, in the layout of ProxyTriangle. Emulated32's
// shaders read z as the floats' bits (a UINT format: the bytes unchanged), never as floats.
struct ProxyInput {
  explicit ProxyInput(ShaderArithmetic arithmetic) {
    if (arithmetic == ShaderArithmetic::Emulated32)
      attributes[3].format = VK_FORMAT_R32G32B32_UINT;
  }
  VkVertexInputBindingDescription binding{0, sizeof(ProxyTriangle), VK_VERTEX_INPUT_RATE_INSTANCE};
  std::array<VkVertexInputAttributeDescription, 6> attributes{{
      {0, 0, VK_FORMAT_R32G32B32A32_SINT, offsetof(ProxyTriangle, pixelRect)},
      {1, 0, VK_FORMAT_R32G32B32A32_SINT, offsetof(ProxyTriangle, fixedV0V1)},
      {2, 0, VK_FORMAT_R32G32_SINT, offsetof(ProxyTriangle, fixedV2)},
      {3, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(ProxyTriangle, z)},
      {4, 0, VK_FORMAT_R32_SINT, offsetof(ProxyTriangle, frontFacing)},
      {5, 0, VK_FORMAT_R32G32B32A32_UINT, offsetof(ProxyTriangle, slopeBits)},
  }};
};

// The exact pipelines' stages: the proxy records as instance input, or (the clear pipeline) none.
VkPipeline createPipeline(VkDevice device, VkPipelineLayout layout,
                          std::span<const std::uint32_t> vertexWords,
                          std::span<const std::uint32_t> fragmentWords, bool proxyInput,
                          ShaderArithmetic arithmetic) {
  const ProxyInput proxy(arithmetic);
  VkPipelineVertexInputStateCreateInfo input{};
  input.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  if (proxyInput) {
    input.vertexBindingDescriptionCount = 1;
    input.pVertexBindingDescriptions = &proxy.binding;
    input.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(proxy.attributes.size());
    input.pVertexAttributeDescriptions = proxy.attributes.data();
  }
  GraphicsPipelineDesc desc;
  desc.vertex = vertexWords;
  desc.fragment = fragmentWords;
  desc.input = &input;
  return createGraphicsPipeline(device, layout, desc);
}

}  // namespace

VkPipeline createGraphicsPipeline(VkDevice device, VkPipelineLayout layout,
                                  const GraphicsPipelineDesc& desc) {
  const VkShaderModule vertex = createModule(device, desc.vertex);
  const VkShaderModule fragment =
      desc.fragment.empty() ? VK_NULL_HANDLE : createModule(device, desc.fragment);
  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  for (auto& stage : stages) {
    stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stage.pName = "main";
  }
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertex;
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fragment;

  VkPipelineVertexInputStateCreateInfo noInput{};
  noInput.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  VkPipelineInputAssemblyStateCreateInfo assembly{};
  assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  assembly.topology = desc.topology;
  VkPipelineViewportStateCreateInfo viewport{};
  viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  // The cull mode is dynamic state (the exact devices cull on the CPU, from the exact facing,
  // and set NONE; the native device sets the interface's). The devices' viewports have a
  // negative height (GL's y up), which keeps GL's winding, so a triangle counter-clockwise in GL
  // window coordinates is front-facing and takes the front stencil ops.
  VkPipelineRasterizationStateCreateInfo raster{};
  raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{};
  multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depthStencil{};  // all of it dynamic
  depthStencil.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
  depthStencil.maxDepthBounds = 1.0f;
  VkPipelineColorBlendStateCreateInfo blend{};  // no colour attachment
  blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
  VkPipelineDynamicStateCreateInfo dynamic{};
  dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
  dynamic.dynamicStateCount = static_cast<std::uint32_t>(kDynamicStates.size());
  dynamic.pDynamicStates = kDynamicStates.data();
  // Dynamic rendering: the attachment formats instead of a render pass.
  VkPipelineRenderingCreateInfo rendering{};
  rendering.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO;
  rendering.depthAttachmentFormat = desc.depthStencilFormat;
  rendering.stencilAttachmentFormat = desc.depthStencilFormat;

  VkGraphicsPipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  info.pNext = &rendering;
  info.stageCount = fragment == VK_NULL_HANDLE ? 1 : 2;
  info.pStages = stages.data();
  info.pVertexInputState = desc.input != nullptr ? desc.input : &noInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depthStencil;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  const VkResult result =
      vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  vkDestroyShaderModule(device, vertex, nullptr);
  if (fragment != VK_NULL_HANDLE)
    vkDestroyShaderModule(device, fragment, nullptr);
  vkCheck(result, "vkCreateGraphicsPipelines");
  return pipeline;
}

VkPipelineLayout createPushConstantLayout(VkDevice device, VkShaderStageFlags stages,
                                          std::uint32_t bytes) {
  VkPushConstantRange range{};
  range.stageFlags = stages;
  range.size = bytes;
  VkPipelineLayoutCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  info.pushConstantRangeCount = 1;
  info.pPushConstantRanges = &range;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  vkCheck(vkCreatePipelineLayout(device, &info, nullptr, &layout), "vkCreatePipelineLayout");
  return layout;
}

ExactPipelines createExactPipelines(VkDevice device, ShaderArithmetic arithmetic) {
  ExactPipelines out;
  out.layout =
      createPushConstantLayout(device, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                               sizeof(FramePushConstants));
  const SpirvModules spirv = spirvModules(arithmetic);
  out.exact =
      createPipeline(device, out.layout, spirv.exactVertex, spirv.exactFragment, true, arithmetic);
  out.clear =
      createPipeline(device, out.layout, spirv.clearVertex, spirv.clearFragment, false, arithmetic);
  return out;
}

ComputePipeline createComputeLayout(VkDevice device, std::uint32_t storageBuffers,
                                    std::uint32_t pushBytes,
                                    VkDescriptorSetLayoutCreateFlags flags) {
  ComputePipeline made;
  std::vector<VkDescriptorSetLayoutBinding> bindings(storageBuffers);
  for (std::uint32_t i = 0; i < storageBuffers; ++i) {
    bindings[i].binding = i;
    bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo setInfo{};
  setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  setInfo.flags = flags;
  setInfo.bindingCount = storageBuffers;
  setInfo.pBindings = bindings.data();
  vkCheck(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &made.setLayout),
          "vkCreateDescriptorSetLayout");
  const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes};
  VkPipelineLayoutCreateInfo layoutInfo{};
  layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &made.setLayout;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &range;
  vkCheck(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &made.layout),
          "vkCreatePipelineLayout");
  return made;
}

VkPipeline createComputeStage(VkDevice device, VkPipelineLayout layout,
                              std::span<const std::uint32_t> spirv, const char* what) {
  const VkShaderModule module = createModule(device, spirv);
  VkComputePipelineCreateInfo pipelineInfo{};
  pipelineInfo.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  pipelineInfo.stage.module = module;
  pipelineInfo.stage.pName = "main";
  pipelineInfo.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  const VkResult result =
      vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline);
  vkDestroyShaderModule(device, module, nullptr);
  vkCheck(result, what);
  return pipeline;
}

ComputePipeline createComputePipeline(VkDevice device, std::span<const std::uint32_t> spirv,
                                      std::uint32_t storageBuffers, std::uint32_t pushBytes,
                                      const char* what) {
  ComputePipeline made = createComputeLayout(device, storageBuffers, pushBytes, 0);
  made.pipeline = createComputeStage(device, made.layout, spirv, what);
  return made;
}

void destroyComputePipeline(VkDevice device, ComputePipeline& pipeline) {
  vkDestroyPipeline(device, pipeline.pipeline, nullptr);
  vkDestroyPipelineLayout(device, pipeline.layout, nullptr);
  vkDestroyDescriptorSetLayout(device, pipeline.setLayout, nullptr);
  pipeline = {};
}

VkDescriptorSet allocateStorageSet(VkDevice device, VkDescriptorPool pool,
                                   const ComputePipeline& pipeline,
                                   std::span<const VkBuffer> buffers) {
  VkDescriptorSetAllocateInfo allocate{};
  allocate.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  allocate.descriptorPool = pool;
  allocate.descriptorSetCount = 1;
  allocate.pSetLayouts = &pipeline.setLayout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  vkCheck(vkAllocateDescriptorSets(device, &allocate, &set), "vkAllocateDescriptorSets");
  std::vector<VkDescriptorBufferInfo> infos(buffers.size());
  std::vector<VkWriteDescriptorSet> writes(buffers.size());
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    infos[i] = {buffers[i], 0, VK_WHOLE_SIZE};
    writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[i].dstSet = set;
    writes[i].dstBinding = static_cast<std::uint32_t>(i);
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &infos[i];
  }
  vkUpdateDescriptorSets(device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0,
                         nullptr);
  return set;
}

}  // namespace recode::backends::detail
