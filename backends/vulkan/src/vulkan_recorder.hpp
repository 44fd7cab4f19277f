#pragma once
// The command recording every Vulkan device of the process shares (sharedRecorder()): every
// clear, draw and read-back of any device is recorded into one command buffer, and finish()
// submits it once and waits, then hands every read-back its values. So a frame's pair tests
// cost one submission whatever the sizes of their devices (core::collidePairs), and a plain
// read-back, which needs its values now, costs one for everything recorded before it. Every
// operation holds the recorder's lock, so devices on different threads may share it (each
// command is recorded whole; which thread's finish() runs it does not matter).
// Draws (clears are draws too) that follow one another share one rendering, in primitive order;
// anything else that touches an image touched since the last full memory barrier is separated
// from what came before by a new one, so each command sees what the ones before wrote, as when
// every command was a submission of its own.

#include <vulkan/vulkan_core.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

#include "recode/raster/device.hpp"
#include "vulkan_context.hpp"

namespace recode::backends::detail {

class CommandRecorder {
 public:
  explicit CommandRecorder(VulkanContext& context);
  ~CommandRecorder();
  CommandRecorder(const CommandRecorder&) = delete;
  CommandRecorder& operator=(const CommandRecorder&) = delete;

  // Appends `commands` to the recording (starting one when none is open), outside any rendering,
  // after a full memory barrier when they touch `image` and a command since the last barrier
  // did too (or when `image` is null: commands that say nothing of what they touch). So the
  // commands of devices with images of their own need no barrier between one device's and
  // another's: a batch that draws every pair on a device of its own, then reads every pair,
  // costs two barriers, not two a pair. Commands on fresh buffer regions (read-backs,
  // scratch) need none.
  void record(VkImage image, const std::function<void(VkCommandBuffer)>& commands);

  // Appends draws to the rendering that is open, or opens one first with `beginRendering`
  // (which records vkCmdBeginRendering). Consecutive draws share one rendering and need no
  // barrier: depth and stencil tests and writes of one rendering happen in primitive order,
  // draw after draw (the Vulkan specification's rasterization order), which is the order the
  // contract and GL give. The rendering is closed by the next record, read-back or finish, and
  // by draws to another `target` (the attachment's view: devices share the recorder, and one
  // device's draws must never land in another's rendering).
  void render(VkImage image, VkImageView target,
              const std::function<void(VkCommandBuffer)>& beginRendering,
              const std::function<void(VkCommandBuffer)>& draws);

  // Copies `bytes` of host data into staging memory that lives until the recording has run;
  // returns the buffer and offset to bind (as vertices or indices). Runs the recording first when
  // the staged bytes would pass kFlushBytes, so memory stays bounded however large the batch.
  struct Staged {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
  };
  [[nodiscard]] Staged stage(const void* data, std::size_t bytes);

  // Records a copy of `region` of `aspect` of `image` into host memory; `deliver` gets its
  // bytes (as the buffer holds them: tightly packed rows, top row first) when the recording
  // has run.
  void readBack(VkImage image, VkImageAspectFlags aspect, const VkBufferImageCopy& region,
                std::size_t bytes, std::function<void(const std::uint8_t*)> deliver);

  // Device-local memory that the recording's own commands write and later commands read (the
  // copies a compute shader summarises), and host-visible memory a shader writes its results
  // to, `deliver` getting them when the recording has run (counted as read-back bytes). Neither
  // runs the recording: a caller that allocates several regions and records their commands does
  // it under hold(), after makeRoom() for them all. A scratch region lives until the recording
  // has run, or, while someone holds scratch (holdScratch), until a finish() when nobody does.
  struct Scratch {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
  };
  [[nodiscard]] Scratch scratch(std::size_t bytes);
  [[nodiscard]] Staged results(std::size_t bytes, std::function<void(const std::uint8_t*)> deliver);
  // Host-visible memory holding `bytes` of host data a shader reads (its parameters), for the
  // recording being made; not a read-back.
  [[nodiscard]] Staged upload(const void* data, std::size_t bytes);
  // Opens a recording when none is open, so that finish() runs its hooks: for work that only a
  // hook records (the compute device's frame).
  void open();
  // Hooks finish() calls, in increasing `order`: `beforeSubmit` with the command buffer just
  // before it is submitted, outside any rendering (the compute device's frame records its
  // stages there, order 0, then the summaries their dispatch, order 1), and `afterRun` once the
  // submission has run, before the read-backs are delivered (may be empty).
  void addSubmitHooks(int order, std::function<void(VkCommandBuffer)> beforeSubmit,
                      std::function<void()> afterRun = {});
  // Adds what a hook did (dispatches, stage times) to the recorder's counters.
  void count(const raster::TransferCounters& more);
  void holdScratch();
  void releaseScratch();
  // Runs the recording first when `bytes` more would pass kFlushBytes.
  void makeRoom(std::size_t bytes);
  // The recorder's lock, for a sequence of calls no other thread may come between.
  [[nodiscard]] std::unique_lock<std::recursive_mutex> hold() {
    return std::unique_lock<std::recursive_mutex>(lock_);
  }

  // Submits the recording, waits for it and delivers the read-backs; nothing when none is open.
  void finish();

  // Submissions and read-back bytes of every device so far.
  [[nodiscard]] raster::TransferCounters counters() const;

  // Recordings run so far: staged memory handed out while this was n stays valid (may be drawn
  // again) for as long as it is still n, and no longer.
  [[nodiscard]] std::uint64_t recordingsRun() const;

  // Staged and read-back bytes after which a recording is run before it grows further.
  static constexpr std::size_t kFlushBytes = std::size_t{256} << 20;

 private:
  // Buffers of one kind handed out front to back and reused after each submission.
  template <class Buffer>
  struct Chunks {
    std::vector<Buffer> buffers;
    std::size_t current = 0;
    VkDeviceSize used = 0;
  };
  // A region of `bytes` in `chunks`: its buffer and offset, aligned for vertex input, image
  // copies and storage buffers; a new chunk of at least `chunkBytes` is made by `make(size)` when
  // none has room.
  template <class Buffer>
  struct Region {
    const Buffer* buffer = nullptr;
    VkDeviceSize offset = 0;
  };
  template <class Buffer, class Make>
  Region<Buffer> allocate(Chunks<Buffer>& chunks, std::size_t bytes, VkDeviceSize chunkBytes,
                          const Make& make);
  // A host-visible region of `bytes` with that usage.
  Region<HostBuffer> allocateHost(Chunks<HostBuffer>& chunks, std::size_t bytes,
                                  VkBufferUsageFlags usage);
  // `bytes` of host data copied into a host-visible region with that usage.
  Staged copyIn(Chunks<HostBuffer>& chunks, VkBufferUsageFlags usage, const void* data,
                std::size_t bytes);
  // A host-visible region whose bytes `deliver` gets when the recording has run (read back).
  void deliverAfterRun(const Region<HostBuffer>& region, std::size_t bytes,
                       std::function<void(const std::uint8_t*)> deliver);
  void begin();
  void closeRendering();

  struct PendingCopy {
    const std::uint8_t* bytes = nullptr;
    std::function<void(const std::uint8_t*)> deliver;
  };

  mutable std::recursive_mutex lock_;  // recursive: finish() is called from stage and readBack
  VulkanContext& context_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  bool recording_ = false;
  bool renderingOpen_ = false;
  VkImageView renderingTarget_ = VK_NULL_HANDLE;  // of the open rendering
  Chunks<HostBuffer> staging_;
  Chunks<HostBuffer> readbacks_;
  Chunks<HostBuffer> results_;
  Chunks<DeviceBuffer> scratch_;
  int scratchHolds_ = 0;
  struct SubmitHooks {
    int order = 0;
    std::function<void(VkCommandBuffer)> beforeSubmit;
    std::function<void()> afterRun;
  };
  std::vector<SubmitHooks> hooks_;  // by order
  std::vector<VkImage> touched_;    // images commands touched since the last barrier
  std::size_t pendingBytes_ = 0;
  std::vector<PendingCopy> copies_;
  raster::TransferCounters counters_;
  std::uint64_t recordingsRun_ = 0;
};

// Runs `call` and adds what it made `recorder` do (submissions, read-back bytes, time waited) to
// `counters`: a device's share of the recorder it shares, so that the counters of a process's
// devices add up to the recorder's. Returns what `call` returns.
template <typename Call>
decltype(auto) countedOn(CommandRecorder& recorder, raster::TransferCounters& counters,
                         Call&& call) {
  const raster::TransferCounters before = recorder.counters();
  struct Count {
    CommandRecorder& recorder;
    raster::TransferCounters& counters;
    const raster::TransferCounters& before;
    ~Count() { counters += recorder.counters().since(before); }
  } count{recorder, counters, before};
  return call();
}

// The process's recorder for devices of that arithmetic (on that arithmetic's context), made
// with the context on first use and never destroyed (as the context).
[[nodiscard]] CommandRecorder& sharedRecorder(ShaderArithmetic arithmetic);

}  // namespace recode::backends::detail
