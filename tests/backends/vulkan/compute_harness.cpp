#include "compute_harness.hpp"

#include <array>
#include <cstring>

#include "vulkan_context.hpp"
#include "vulkan_pipeline.hpp"

namespace recode::testing {

using backends::ShaderArithmetic;
using backends::detail::HostBuffer;
using backends::detail::vkCheck;
using backends::detail::VulkanContext;

struct ComputeHarness::Impl {
  VulkanContext& context = VulkanContext::instance(ShaderArithmetic::Emulated32);
  VkDevice device = context.device();
  backends::detail::ComputePipeline pipeline;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkCommandPool commandPool = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  std::uint32_t pushBytes = 0;
};

ComputeHarness::ComputeHarness(std::span<const std::uint32_t> spirv, std::uint32_t pushBytes)
    : impl_(new Impl) {
  Impl& h = *impl_;
  h.pushBytes = pushBytes;
  h.pipeline = backends::detail::createComputePipeline(h.device, spirv, 2, pushBytes,
                                                       "vkCreateComputePipelines");
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
  VkDescriptorPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &size;
  vkCheck(vkCreateDescriptorPool(h.device, &poolInfo, nullptr, &h.pool), "vkCreateDescriptorPool");
  h.commandPool = h.context.createCommandPool();
  h.fence = h.context.createFence();
}

ComputeHarness::~ComputeHarness() {
  Impl& h = *impl_;
  vkDestroyFence(h.device, h.fence, nullptr);
  vkDestroyCommandPool(h.device, h.commandPool, nullptr);
  vkDestroyDescriptorPool(h.device, h.pool, nullptr);
  backends::detail::destroyComputePipeline(h.device, h.pipeline);
  delete impl_;
}

std::vector<std::uint8_t> ComputeHarness::run(std::span<const std::uint8_t> input,
                                              std::size_t outputBytes, std::uint32_t count,
                                              std::span<const std::uint8_t> push) {
  Impl& h = *impl_;
  HostBuffer in = h.context.createHostBuffer(input.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  HostBuffer out = h.context.createHostBuffer(outputBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  std::memcpy(in.mapped, input.data(), input.size());

  const std::array<VkBuffer, 2> buffers{in.buffer, out.buffer};
  const VkDescriptorSet set =
      backends::detail::allocateStorageSet(h.device, h.pool, h.pipeline, buffers);

  VkCommandBufferAllocateInfo commandInfo{};
  commandInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  commandInfo.commandPool = h.commandPool;
  commandInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  commandInfo.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  vkCheck(vkAllocateCommandBuffers(h.device, &commandInfo, &cmd), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkCheck(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, h.pipeline.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, h.pipeline.layout, 0, 1, &set, 0,
                          nullptr);
  vkCmdPushConstants(cmd, h.pipeline.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, h.pushBytes,
                     push.data());
  vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
  // The host reads the results after the fence: make the shader's writes visible to it.
  VkMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &barrier, 0, nullptr, 0, nullptr);
  vkCheck(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  h.context.submitAndWait(cmd, h.fence);

  std::vector<std::uint8_t> result(outputBytes);
  std::memcpy(result.data(), out.mapped, outputBytes);
  vkFreeCommandBuffers(h.device, h.commandPool, 1, &cmd);
  vkFreeDescriptorSets(h.device, h.pool, 1, &set);
  h.context.destroyHostBuffer(in);
  h.context.destroyHostBuffer(out);
  return result;
}

}  // namespace recode::testing
