// CommandRecorder: a device's commands recorded into one command buffer, run by finish().
#include "vulkan_recorder.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>
#include <utility>

namespace recode::backends::detail {

namespace {

// New chunks are at least this large, so a batch of small draws makes few buffers.
constexpr VkDeviceSize kChunkBytes = VkDeviceSize{4} << 20;
// Scratch chunks are larger: a frame's summaries copy every drawn pair's MOR into them.
constexpr VkDeviceSize kScratchChunkBytes = VkDeviceSize{64} << 20;
// Offsets are kept to this alignment: more than vertex input or a depth/stencil copy asks.
constexpr VkDeviceSize kAlignment = 64;

// Results and uploads share their chunks: shaders read and write them, and the compute device
// copies its uploads on to device-local memory and its stages' outputs into results.
constexpr VkBufferUsageFlags kResultsUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                             VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                             VK_BUFFER_USAGE_TRANSFER_DST_BIT;

// Everything before happens-before everything after, host writes to mapped memory included.
void fullBarrier(VkCommandBuffer cmd) {
  VkMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT | VK_ACCESS_HOST_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                       VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace

CommandRecorder::CommandRecorder(VulkanContext& context) : context_(context) {
  pool_ = context_.createCommandPool();
  VkCommandBufferAllocateInfo allocate{};
  allocate.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  allocate.commandPool = pool_;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  vkCheck(vkAllocateCommandBuffers(context_.device(), &allocate, &commands_),
          "vkAllocateCommandBuffers");
  fence_ = context_.createFence();
}

CommandRecorder::~CommandRecorder() {
  closeRendering();
  if (recording_)
    vkEndCommandBuffer(commands_);  // never submitted: the device is going away
  for (Chunks<HostBuffer>* chunks : {&staging_, &readbacks_, &results_})
    for (HostBuffer& buffer : chunks->buffers)
      context_.destroyHostBuffer(buffer);
  for (DeviceBuffer& buffer : scratch_.buffers)
    context_.destroyDeviceBuffer(buffer);
  vkDestroyFence(context_.device(), fence_, nullptr);
  vkDestroyCommandPool(context_.device(), pool_, nullptr);  // frees the command buffer too
}

void CommandRecorder::begin() {
  if (recording_)
    return;
  vkCheck(vkResetCommandBuffer(commands_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkCheck(vkBeginCommandBuffer(commands_, &info), "vkBeginCommandBuffer");
  recording_ = true;
}

void CommandRecorder::open() {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  begin();
}

void CommandRecorder::closeRendering() {
  if (!renderingOpen_)
    return;
  vkCmdEndRendering(commands_);
  renderingOpen_ = false;
}

void CommandRecorder::record(VkImage image, const std::function<void(VkCommandBuffer)>& commands) {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  begin();
  closeRendering();
  if (image == VK_NULL_HANDLE ||
      std::find(touched_.begin(), touched_.end(), image) != touched_.end()) {
    fullBarrier(commands_);
    touched_.clear();
  }
  if (image != VK_NULL_HANDLE)
    touched_.push_back(image);
  commands(commands_);
}

void CommandRecorder::render(VkImage image, VkImageView target,
                             const std::function<void(VkCommandBuffer)>& beginRendering,
                             const std::function<void(VkCommandBuffer)>& draws) {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  if (!renderingOpen_ || renderingTarget_ != target) {
    record(image, beginRendering);  // closes the open rendering first
    renderingOpen_ = true;
    renderingTarget_ = target;
  }
  draws(commands_);
}

template <class Buffer, class Make>
CommandRecorder::Region<Buffer> CommandRecorder::allocate(Chunks<Buffer>& chunks, std::size_t bytes,
                                                          VkDeviceSize chunkBytes,
                                                          const Make& make) {
  const VkDeviceSize size =
      (static_cast<VkDeviceSize>(bytes) + kAlignment - 1) / kAlignment * kAlignment;
  while (chunks.current < chunks.buffers.size() &&
         chunks.used + size > chunks.buffers[chunks.current].size) {
    ++chunks.current;
    chunks.used = 0;
  }
  if (chunks.current == chunks.buffers.size())
    chunks.buffers.push_back(make(std::max(size, chunkBytes)));
  const Region<Buffer> region{&chunks.buffers[chunks.current], chunks.used};
  chunks.used += size;
  pendingBytes_ += bytes;
  return region;
}

CommandRecorder::Region<HostBuffer> CommandRecorder::allocateHost(Chunks<HostBuffer>& chunks,
                                                                  std::size_t bytes,
                                                                  VkBufferUsageFlags usage) {
  return allocate(chunks, bytes, kChunkBytes,
                  [&](VkDeviceSize size) { return context_.createHostBuffer(size, usage); });
}

CommandRecorder::Staged CommandRecorder::copyIn(Chunks<HostBuffer>& chunks,
                                                VkBufferUsageFlags usage, const void* data,
                                                std::size_t bytes) {
  const Region<HostBuffer> region = allocateHost(chunks, bytes, usage);
  std::memcpy(static_cast<std::uint8_t*>(region.buffer->mapped) + region.offset, data, bytes);
  return {region.buffer->buffer, region.offset};
}

void CommandRecorder::deliverAfterRun(const Region<HostBuffer>& region, std::size_t bytes,
                                      std::function<void(const std::uint8_t*)> deliver) {
  copies_.push_back({static_cast<const std::uint8_t*>(region.buffer->mapped) + region.offset,
                     std::move(deliver)});
  counters_.readbackBytes += static_cast<long long>(bytes);
}

CommandRecorder::Staged CommandRecorder::stage(const void* data, std::size_t bytes) {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  if (pendingBytes_ + bytes > kFlushBytes)
    finish();
  return copyIn(staging_, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                data, bytes);
}

void CommandRecorder::readBack(VkImage image, VkImageAspectFlags aspect,
                               const VkBufferImageCopy& region, std::size_t bytes,
                               std::function<void(const std::uint8_t*)> deliver) {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  if (pendingBytes_ + bytes > kFlushBytes)
    finish();
  const Region<HostBuffer> slot = allocateHost(readbacks_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  VkBufferImageCopy copy = region;
  copy.bufferOffset = slot.offset;
  copy.imageSubresource.aspectMask = aspect;
  record(image, [&](VkCommandBuffer cmd) {
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_GENERAL, slot.buffer->buffer, 1, &copy);
  });
  deliverAfterRun(slot, bytes, std::move(deliver));
}

CommandRecorder::Scratch CommandRecorder::scratch(std::size_t bytes) {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  const Region<DeviceBuffer> region =
      allocate(scratch_, bytes, kScratchChunkBytes, [&](VkDeviceSize size) {
        return context_.createDeviceBuffer(
            size, VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      });
  return {region.buffer->buffer, region.offset};
}

CommandRecorder::Staged CommandRecorder::results(std::size_t bytes,
                                                 std::function<void(const std::uint8_t*)> deliver) {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  const Region<HostBuffer> region = allocateHost(results_, bytes, kResultsUsage);
  deliverAfterRun(region, bytes, std::move(deliver));
  return {region.buffer->buffer, region.offset};
}

CommandRecorder::Staged CommandRecorder::upload(const void* data, std::size_t bytes) {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  return copyIn(results_, kResultsUsage, data, bytes);
}

void CommandRecorder::addSubmitHooks(int order, std::function<void(VkCommandBuffer)> beforeSubmit,
                                     std::function<void()> afterRun) {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  const auto at = std::find_if(hooks_.begin(), hooks_.end(),
                               [order](const SubmitHooks& h) { return h.order > order; });
  hooks_.insert(at, SubmitHooks{order, std::move(beforeSubmit), std::move(afterRun)});
}

void CommandRecorder::count(const raster::TransferCounters& more) {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  counters_ += more;
}

void CommandRecorder::holdScratch() {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  ++scratchHolds_;
}

void CommandRecorder::releaseScratch() {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  --scratchHolds_;
}

void CommandRecorder::makeRoom(std::size_t bytes) {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  if (pendingBytes_ + bytes > kFlushBytes)
    finish();
}

void CommandRecorder::finish() {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  if (!recording_)
    return;
  closeRendering();
  for (const SubmitHooks& h : hooks_)
    h.beforeSubmit(commands_);
  // Everything recorded is visible to the host once the fence says it is done.
  VkMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                       1, &barrier, 0, nullptr, 0, nullptr);
  recording_ = false;
  touched_.clear();
  std::vector<PendingCopy> copies = std::move(copies_);
  copies_.clear();
  pendingBytes_ = 0;
  for (Chunks<HostBuffer>* chunks : {&staging_, &readbacks_, &results_}) {
    chunks->current = 0;
    chunks->used = 0;
  }
  if (scratchHolds_ == 0) {  // else a held region lives on into the next recording
    scratch_.current = 0;
    scratch_.used = 0;
  }
  vkCheck(vkEndCommandBuffer(commands_), "vkEndCommandBuffer");
  ++recordingsRun_;  // the staging above is free again, whatever the submission does
  const auto submitted = std::chrono::steady_clock::now();
  context_.submitAndWait(commands_, fence_);
  counters_.waitUs +=
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - submitted)
          .count();
  ++counters_.submissions;
  for (const SubmitHooks& h : hooks_)
    if (h.afterRun)
      h.afterRun();
  // Every read-back gets its values even when one of them throws; the first error is passed on.
  std::exception_ptr error;
  for (PendingCopy& copy : copies) {
    try {
      copy.deliver(copy.bytes);
    } catch (...) {
      if (!error)
        error = std::current_exception();
    }
  }
  if (error)
    std::rethrow_exception(error);
}

raster::TransferCounters CommandRecorder::counters() const {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  return counters_;
}

std::uint64_t CommandRecorder::recordingsRun() const {
  const std::lock_guard<std::recursive_mutex> hold(lock_);
  return recordingsRun_;
}

CommandRecorder& sharedRecorder(ShaderArithmetic arithmetic) {
  // Leaked, as the contexts.
  if (arithmetic == ShaderArithmetic::Native64) {
    static CommandRecorder* native =
        new CommandRecorder(VulkanContext::instance(ShaderArithmetic::Native64));
    return *native;
  }
  static CommandRecorder* emulated =
      new CommandRecorder(VulkanContext::instance(ShaderArithmetic::Emulated32));
  return *emulated;
}

}  // namespace recode::backends::detail
