#pragma once
// What every exact Vulkan device of the process shares: the instance, the chosen physical
// device, a logical device with one graphics queue (under a lock), and the making of command
// pools, fences and host buffers for the recording (vulkan_recorder.hpp). Made on first use and
// deliberately never destroyed (tearing a driver down during static destruction is a known
// source of crashes at exit).

#include <vulkan/vulkan_core.h>

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>

#include "recode/backends/vulkan_shader_arithmetic.hpp"

namespace recode::backends::detail {

// Throws std::runtime_error naming `what` and the VkResult unless result is VK_SUCCESS.
void vkCheck(VkResult result, const char* what);

// A buffer in host-visible, host-coherent memory, mapped for its whole life.
struct HostBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
  VkDeviceSize size = 0;
};

// A buffer in device-local memory (a recording's scratch), not mapped.
struct DeviceBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
};

class VulkanContext {
 public:
  // The process's context for devices of that arithmetic (a logical device that enables
  // shaderFloat64 and shaderInt64 for Native64 only); the first call makes it and throws
  // std::runtime_error when no driver or no suitable physical device exists, saying what to
  // install or what is missing.
  static VulkanContext& instance(ShaderArithmetic arithmetic);

  [[nodiscard]] ShaderArithmetic arithmetic() const { return arithmetic_; }

  [[nodiscard]] VkDevice device() const { return device_; }
  [[nodiscard]] const std::string& deviceName() const { return name_; }
  // Whether the physical device is a CPU driver (lavapipe): work is then best handed out in
  // fewer, larger pieces.
  [[nodiscard]] bool cpuDriver() const { return cpuDriver_; }
  // The most loop iterations one shader invocation may run before the driver ends its loops
  // early without a word, or 0 when the driver sets no such limit. llvmpipe (lavapipe) counts
  // every iteration of every loop of an invocation against one limit of 65,535 and, once it is
  // spent, leaves each loop at its next test (Mesa's gallivm: LP_MAX_TGSI_LOOP_ITERATIONS in
  // lp_bld_limits.h, "shared between every loop", a guard against endless loops). Every CPU
  // driver is taken to have that limit (for one without it the cost is a few more dispatches);
  // GPU drivers have none. The compute device splits its work to stay within it
  // (tile_frame_budgets.hpp).
  [[nodiscard]] std::uint32_t loopLimit() const { return cpuDriver_ ? kCpuDriverLoopLimit : 0; }
  static constexpr std::uint32_t kCpuDriverLoopLimit = 65535;
  // The physical device's limits (the native device places its viewport within them).
  [[nodiscard]] const VkPhysicalDeviceLimits& limits() const { return limits_; }
  // What the physical device does with `format` in optimal tiling (the native device picks its
  // depth/stencil format by it).
  [[nodiscard]] VkFormatFeatureFlags optimalFeatures(VkFormat format) const;

  // Memory with these properties for an image or buffer with these requirements (`addressed`:
  // for a buffer reached by its device address).
  [[nodiscard]] VkDeviceMemory allocate(const VkMemoryRequirements& requirements,
                                        VkMemoryPropertyFlags properties,
                                        bool addressed = false) const;

  // A command pool and a fence of the caller's own (the recording's), destroyed by the caller.
  [[nodiscard]] VkCommandPool createCommandPool() const;
  [[nodiscard]] VkFence createFence() const;
  // A new host-visible, host-coherent buffer of `bytes`, mapped; destroyHostBuffer frees it.
  [[nodiscard]] HostBuffer createHostBuffer(VkDeviceSize bytes, VkBufferUsageFlags usage) const;
  void destroyHostBuffer(HostBuffer& buffer) const;
  // A new device-local buffer of `bytes`; destroyDeviceBuffer frees it.
  [[nodiscard]] DeviceBuffer createDeviceBuffer(VkDeviceSize bytes, VkBufferUsageFlags usage) const;
  void destroyDeviceBuffer(DeviceBuffer& buffer) const;
  // The device address of a storage buffer made by this context (Native64 only: every storage
  // buffer of that context can be addressed; throws std::logic_error on the other).
  [[nodiscard]] VkDeviceAddress address(VkBuffer buffer) const;
  // Nanoseconds a timestamp tick lasts, and whether the queue writes timestamps at all.
  [[nodiscard]] double timestampPeriodNs() const { return timestampPeriodNs_; }
  [[nodiscard]] bool timestamps() const { return timestamps_; }

  // vkCmdPushDescriptorSetKHR when the driver has VK_KHR_push_descriptor (enabled then), else
  // null: the compute device's way of binding its buffers.
  [[nodiscard]] PFN_vkCmdPushDescriptorSetKHR pushDescriptorSet() const {
    return pushDescriptorSet_;
  }

  // Submits a recorded command buffer to the queue (shared, so under a lock) and waits for
  // `fence`, which must be unsignalled.
  void submitAndWait(VkCommandBuffer commands, VkFence fence);

 private:
  explicit VulkanContext(ShaderArithmetic arithmetic);
  void createInstance();
  void choosePhysicalDevice();
  void createDevice();
  // A buffer of `bytes` bound to new memory with `properties` (returned in `memory`).
  [[nodiscard]] VkBuffer createBuffer(VkDeviceSize bytes, VkBufferUsageFlags usage,
                                      VkMemoryPropertyFlags properties,
                                      VkDeviceMemory& memory) const;

  ShaderArithmetic arithmetic_;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory_{};
  std::uint32_t queueFamily_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::mutex queueLock_;
  std::string name_;
  VkPhysicalDeviceLimits limits_{};
  bool cpuDriver_ = false;
  bool addresses_ = false;  // storage buffers are made addressable (Native64)
  double timestampPeriodNs_ = 0.0;
  bool timestamps_ = false;
  PFN_vkCmdPushDescriptorSetKHR pushDescriptorSet_ = nullptr;
};

}  // namespace recode::backends::detail
