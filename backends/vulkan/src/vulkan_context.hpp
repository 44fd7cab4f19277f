#pragma once
// What every exact Vulkan device of the process shares: the instance, the chosen physical
// device, a logical device with one graphics queue, one command buffer with its fence, and
// host-visible buffers for proxy records and read-backs. Made on first use and deliberately
// never destroyed (tearing a driver down during static destruction is a known source of crashes
// at exit). Single-threaded, like the devices: every operation records the command buffer,
// submits it and waits.

#include <vulkan/vulkan_core.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

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

class VulkanContext {
 public:
  // The process's context; the first call makes it and throws std::runtime_error when no
  // driver or no suitable physical device exists, saying what to install or what is missing.
  static VulkanContext& instance();

  [[nodiscard]] VkDevice device() const { return device_; }
  [[nodiscard]] const std::string& deviceName() const { return name_; }

  // Device-local memory for an image or buffer with these requirements.
  [[nodiscard]] VkDeviceMemory allocate(const VkMemoryRequirements& requirements,
                                        VkMemoryPropertyFlags properties) const;

  // `buffer` grown (recreated) to hold at least `bytes`, with `usage`. Its old contents are lost.
  void reserve(HostBuffer& buffer, VkDeviceSize bytes, VkBufferUsageFlags usage) const;

  // Records `commands` into the shared command buffer, submits it and waits for it to finish.
  // Every submission starts with a full memory barrier, so each sees everything the previous
  // ones wrote (attachments, transfers, host writes to the mapped buffers).
  void submit(const std::function<void(VkCommandBuffer)>& commands);

  // The shared buffers: proxy records (vertex input) and read-backs (transfer destination).
  HostBuffer proxies;
  HostBuffer readback;

 private:
  VulkanContext();
  void createInstance();
  void choosePhysicalDevice();
  void createDevice();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory_{};
  std::uint32_t queueFamily_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  std::string name_;
};

}  // namespace recode::backends::detail
