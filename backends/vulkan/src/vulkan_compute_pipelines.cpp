// The compute device's pipelines and their shared layout.
#include "vulkan_compute_pipelines.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <stdexcept>
#include <string>

#include "vulkan_context.hpp"
#include "vulkan_pipeline.hpp"

namespace recode::backends::detail {

namespace {
// glslangValidator --vn writes each module as `const uint32_t k_<stage>[] = {...};`.
using std::uint32_t;
#include "tile_box.comp.h"
#include "tile_raster.comp.h"
#include "tile_resolve.comp.h"
#include "tile_scan.comp.h"
#include "tile_scan_serial.comp.h"
#include "tile_scatter.comp.h"
#include "tile_setup.comp.h"
#include "tile_sort.comp.h"
#include "tile_vertex.comp.h"

constexpr std::uint32_t kMaxGroupsPerRow = 65535;  // maxComputeWorkGroupCount's smallest bound

}  // namespace

TilePipelines::TilePipelines(const VulkanContext& context) {
  push_ = context.pushDescriptorSet();
  if (push_ == nullptr)
    throw std::runtime_error("Vulkan compute device: the driver of " + context.deviceName() +
                             " lacks VK_KHR_push_descriptor, which the vulkan-compute device "
                             "binds its buffers with");
  const VkDevice device = context.device();
  const ComputePipeline layout =
      createComputeLayout(device, kTileBindings, sizeof(TileFrameConstants),
                          VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR);
  setLayout_ = layout.setLayout;
  layout_ = layout.layout;
  const auto createStage = [&](std::span<const std::uint32_t> words, const char* name) {
    return createComputeStage(device, layout_, words,
                              (std::string("vkCreateComputePipelines (") + name + ")").c_str());
  };
  vertex = createStage(k_tile_vertex_comp, "tile_vertex");
  box = createStage(k_tile_box_comp, "tile_box");
  setup = createStage(k_tile_setup_comp, "tile_setup");
  scan = createStage(k_tile_scan_comp, "tile_scan");
  scanSerial = createStage(k_tile_scan_serial_comp, "tile_scan_serial");
  scatter = createStage(k_tile_scatter_comp, "tile_scatter");
  sort = createStage(k_tile_sort_comp, "tile_sort");
  raster = createStage(k_tile_raster_comp, "tile_raster");
  resolve = createStage(k_tile_resolve_comp, "tile_resolve");
}

void TilePipelines::pushBuffers(VkCommandBuffer cmd, std::span<const TileBuffer> buffers) const {
  std::array<VkDescriptorBufferInfo, kTileBindings> infos{};
  std::array<VkWriteDescriptorSet, kTileBindings> writes{};
  std::array<bool, kTileBindings> given{};
  for (const TileBuffer& b : buffers) {
    const auto n = static_cast<std::uint32_t>(b.binding);
    if (n >= kTileBindings || given[n])
      throw std::logic_error("TilePipelines: binding " + std::to_string(n) + " given twice");
    given[n] = true;
    infos[n] = {b.buffer, b.offset, b.range};
    writes[n].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[n].dstBinding = n;
    writes[n].descriptorCount = 1;
    writes[n].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[n].pBufferInfo = &infos[n];
  }
  for (std::uint32_t n = 0; n < kTileBindings; ++n)
    if (!given[n])
      throw std::logic_error("TilePipelines: no buffer for binding " + std::to_string(n));
  push_(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, kTileBindings, writes.data());
}

void TilePipelines::bind(VkCommandBuffer cmd, VkPipeline pipeline,
                         const TileFrameConstants& constants) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof constants, &constants);
}

void TilePipelines::dispatch(VkCommandBuffer cmd, VkPipeline pipeline,
                             const TileFrameConstants& constants, std::uint32_t groupsX,
                             std::uint32_t groupsY) const {
  bind(cmd, pipeline, constants);
  vkCmdDispatch(cmd, groupsX, groupsY, 1);
}

void TilePipelines::dispatchIndirect(VkCommandBuffer cmd, VkPipeline pipeline,
                                     const TileFrameConstants& constants, VkBuffer args,
                                     VkDeviceSize offset) const {
  bind(cmd, pipeline, constants);
  vkCmdDispatchIndirect(cmd, args, offset);
}

std::pair<std::uint32_t, std::uint32_t> TilePipelines::groupGrid(std::uint64_t groups) {
  const auto perRow =
      static_cast<std::uint32_t>(std::clamp<std::uint64_t>(groups, 1, kMaxGroupsPerRow));
  return {perRow, static_cast<std::uint32_t>((groups + perRow - 1) / perRow)};
}

std::pair<std::uint32_t, std::uint32_t> TilePipelines::linearGroups(std::uint64_t count) {
  return groupGrid((count + 63) / 64);
}

const TilePipelines& tilePipelines() {
  // Leaked, as the context.
  static const TilePipelines* made =
      new TilePipelines(VulkanContext::instance(ShaderArithmetic::Native64));
  return *made;
}

void computeBarrier(VkCommandBuffer cmd) {
  VkMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                          VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                           VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                       0, 1, &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace recode::backends::detail
