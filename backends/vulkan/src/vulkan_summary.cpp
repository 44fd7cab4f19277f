// The summary compute pipeline and its descriptor sets.
#include "vulkan_summary.hpp"

#include "vulkan_context.hpp"
#include "vulkan_spirv.hpp"

namespace recode::backends::detail {

namespace {

constexpr std::uint32_t kBindings = 4;  // near scratch, scratch, results, parameters
constexpr std::uint32_t kSetsPerPool = 64;

}  // namespace

SummaryPipeline::SummaryPipeline(VkDevice device, CommandRecorder& recorder)
    : device_(device), recorder_(recorder) {
  // Both arithmetics share the module: it uses 32-bit integers only.
  pipeline_ = createComputePipeline(
      device_, spirvModules(ShaderArithmetic::Native64).summaryCompute, kBindings,
      sizeof(std::uint32_t), "vkCreateComputePipelines (the summary shader)");
  recorder_.addSubmitHooks(1, [this](VkCommandBuffer cmd) { dispatchPending(cmd); });
}

VkDescriptorSet SummaryPipeline::descriptorSet(const Buffers& key) {
  if (const auto found = sets_.find(key); found != sets_.end())
    return found->second;
  if (pools_.empty() || setsInPool_ == kSetsPerPool) {
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kBindings * kSetsPerPool};
    VkDescriptorPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    poolInfo.maxSets = kSetsPerPool;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    vkCheck(vkCreateDescriptorPool(device_, &poolInfo, nullptr, &pool), "vkCreateDescriptorPool");
    pools_.push_back(pool);
    setsInPool_ = 0;
  }
  const VkDescriptorSet set = allocateStorageSet(device_, pools_.back(), pipeline_, key);
  ++setsInPool_;
  sets_.emplace(key, set);
  return set;
}

void SummaryPipeline::add(VkBuffer nearScratch, VkBuffer scratch, VkBuffer results,
                          const SummaryParameters& parameters) {
  pending_[{nearScratch, scratch, results}].push_back(parameters);
}

void SummaryPipeline::dispatchPending(VkCommandBuffer cmd) {
  if (pending_.empty())
    return;
  // The copies, made by the commands before (transfers, or the compute device's reads), ahead of
  // the shader that reads them.
  VkMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  barrier.srcAccessMask =
      VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_HOST_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
  vkCmdPipelineBarrier(cmd,
                       VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT |
                           VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0,
                       nullptr);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.pipeline);
  for (const auto& [buffers, summaries] : pending_) {
    const CommandRecorder::Staged parameters =
        recorder_.upload(summaries.data(), summaries.size() * sizeof(SummaryParameters));
    const VkDescriptorSet set =
        descriptorSet({buffers[0], buffers[1], buffers[2], parameters.buffer});
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.layout, 0, 1, &set, 0,
                            nullptr);
    const auto firstWord = static_cast<std::uint32_t>(parameters.offset / 4);
    vkCmdPushConstants(cmd, pipeline_.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(firstWord),
                       &firstWord);
    vkCmdDispatch(cmd, static_cast<std::uint32_t>(summaries.size()), 1, 1);
  }
  raster::TransferCounters dispatched;
  dispatched.dispatches = static_cast<long long>(pending_.size());
  recorder_.count(dispatched);
  pending_.clear();
}

SummaryPipeline& summaryPipeline(ShaderArithmetic arithmetic) {
  // Leaked, as the contexts.
  if (arithmetic == ShaderArithmetic::Native64) {
    static SummaryPipeline* native =
        new SummaryPipeline(VulkanContext::instance(ShaderArithmetic::Native64).device(),
                            sharedRecorder(ShaderArithmetic::Native64));
    return *native;
  }
  static SummaryPipeline* emulated =
      new SummaryPipeline(VulkanContext::instance(ShaderArithmetic::Emulated32).device(),
                          sharedRecorder(ShaderArithmetic::Emulated32));
  return *emulated;
}

}  // namespace recode::backends::detail
