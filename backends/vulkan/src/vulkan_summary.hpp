#pragma once
// The Vulkan devices' pixel summaries (raster/include/recode/raster/pixel_summary.hpp): the
// compute pipeline of summary_vk.comp, one workgroup per summary, reading copies of the
// rectangle's stencil and depths that the recording made in device-local scratch and writing 16
// words to host-visible memory. So a pair test reads back 64 bytes, not its buffers, and a
// submission's summaries cost one dispatch.

#include <vulkan/vulkan_core.h>

#include <array>
#include <cstdint>
#include <map>

#include "recode/backends/summary_layout.hpp"
#include "recode/backends/vulkan_shader_arithmetic.hpp"
#include "recode/raster/device.hpp"
#include "vulkan_pipeline.hpp"
#include "vulkan_recorder.hpp"

namespace recode::backends::detail {

// The summaries of a recording: each summarizeLater records its copies in place and leaves its
// parameters here; just before the recording is submitted, one dispatch (one per set of
// buffers) summarises them all, a workgroup each. One recorder, one SummaryPipeline.
class SummaryPipeline {
 public:
  SummaryPipeline(VkDevice device, CommandRecorder& recorder);
  SummaryPipeline(const SummaryPipeline&) = delete;
  SummaryPipeline& operator=(const SummaryPipeline&) = delete;

  // A summary to dispatch before the recording is submitted: the near copy in `nearScratch`,
  // the stencil copy, the far copy and the class table in `scratch`, the words into `results`.
  // Call under the recorder's lock, after recording the copies.
  void add(VkBuffer nearScratch, VkBuffer scratch, VkBuffer results,
           const SummaryParameters& parameters);

 private:
  using Buffers = std::array<VkBuffer, 4>;  // near scratch, scratch, results, parameters
  void dispatchPending(VkCommandBuffer cmd);
  VkDescriptorSet descriptorSet(const Buffers& buffers);

  VkDevice device_;
  CommandRecorder& recorder_;
  ComputePipeline pipeline_;
  std::vector<VkDescriptorPool> pools_;
  std::uint32_t setsInPool_ = 0;
  std::map<Buffers, VkDescriptorSet> sets_;
  // What add() was given since the last submission, by (near scratch, scratch, results).
  std::map<std::array<VkBuffer, 3>, std::vector<SummaryParameters>> pending_;
};

// The pipeline of that arithmetic's context and recorder, made on first use and never destroyed
// (as the context and the recorder).
[[nodiscard]] SummaryPipeline& summaryPipeline(ShaderArithmetic arithmetic);

// A depth a Vulkan device copied into scratch for its next summary; the region is held
// (CommandRecorder::holdScratch) while this lives.
class VulkanKeptDepth final : public raster::KeptDepth {
 public:
  VulkanKeptDepth(CommandRecorder& recorder, const void* keeper, const raster::PixelRect& rect,
                  CommandRecorder::Scratch region)
      : KeptDepth(keeper, rect), recorder_(recorder), region_(region) {
    recorder_.holdScratch();
  }
  ~VulkanKeptDepth() override { recorder_.releaseScratch(); }

  [[nodiscard]] const CommandRecorder::Scratch& region() const { return region_; }

 private:
  CommandRecorder& recorder_;
  CommandRecorder::Scratch region_;
};

}  // namespace recode::backends::detail
