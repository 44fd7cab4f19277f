// The shared Vulkan context: a headless instance (no surface, no window-system extension, no
// layers), the physical device, one graphics queue and the submission helper.

#include "vulkan_context.hpp"

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "vulkan_pipeline.hpp"

namespace recode::backends::detail {

namespace {

constexpr const char* kInstallHint =
    "install a Vulkan driver (Debian: apt-get install mesa-vulkan-drivers for lavapipe, "
    "Mesa's CPU driver; or the GPU vendor's driver)";

// Why a physical device cannot serve, or empty when it can; sets the queue family it would use.
std::string unsuitable(VkPhysicalDevice physical, ShaderArithmetic arithmetic,
                       std::uint32_t& family) {
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(physical, &properties);
  if (properties.apiVersion < VK_API_VERSION_1_3)
    return "Vulkan 1.3 is missing";
  VkPhysicalDeviceFeatures features{};
  vkGetPhysicalDeviceFeatures(physical, &features);
  if (arithmetic == ShaderArithmetic::Native64 &&
      (!features.shaderFloat64 || !features.shaderInt64))
    return "shaderFloat64 or shaderInt64 is missing (the vulkan-32 device needs neither)";
  VkPhysicalDeviceVulkan13Features v13{};
  v13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
  VkPhysicalDeviceFeatures2 features2{};
  features2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  features2.pNext = &v13;
  vkGetPhysicalDeviceFeatures2(physical, &features2);
  if (!v13.dynamicRendering)
    return "dynamicRendering is missing";
  if (!v13.maintenance4)  // required of Vulkan 1.3 devices; checked for a driver that forgets
    return "maintenance4 is missing";
  VkPhysicalDeviceVulkan12Features v12{};
  v12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
  features2.pNext = &v12;
  vkGetPhysicalDeviceFeatures2(physical, &features2);
  if (arithmetic == ShaderArithmetic::Native64 && !v12.bufferDeviceAddress)
    return "bufferDeviceAddress is missing";  // required of Vulkan 1.3 devices too
  VkFormatProperties format{};
  vkGetPhysicalDeviceFormatProperties(physical, kExactDepthStencilFormat, &format);
  const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                      VK_FORMAT_FEATURE_TRANSFER_SRC_BIT |
                                      VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
  if ((format.optimalTilingFeatures & needed) != needed)
    return "D32_SFLOAT_S8_UINT is not a depth/stencil attachment with transfers";
  if (properties.limits.maxFramebufferWidth < 16384 ||
      properties.limits.maxFramebufferHeight < 16384)
    return "16384-pixel framebuffers are not supported";
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i) {
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
      family = i;
      return {};
    }
  }
  return "no graphics queue";
}

// Hardware first: a discrete GPU, then an integrated or virtual one, then a CPU driver.
int preference(VkPhysicalDevice physical) {
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(physical, &properties);
  switch (properties.deviceType) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 3;
    default:
      return 4;
  }
}

}  // namespace

void vkCheck(VkResult result, const char* what) {
  if (result != VK_SUCCESS)
    throw std::runtime_error(std::string("Vulkan device: ") + what + " failed (VkResult " +
                             std::to_string(static_cast<int>(result)) + ")");
}

VulkanContext& VulkanContext::instance(ShaderArithmetic arithmetic) {
  // Leaked on purpose, see the header. Static locals, so each is made once even when threads race.
  if (arithmetic == ShaderArithmetic::Native64) {
    static VulkanContext* native = new VulkanContext(ShaderArithmetic::Native64);
    return *native;
  }
  static VulkanContext* emulated = new VulkanContext(ShaderArithmetic::Emulated32);
  return *emulated;
}

VulkanContext::VulkanContext(ShaderArithmetic arithmetic) : arithmetic_(arithmetic) {
  createInstance();
  choosePhysicalDevice();
  createDevice();
}

void VulkanContext::createInstance() {
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "recode";
  app.apiVersion = VK_API_VERSION_1_3;
  VkInstanceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  info.pApplicationInfo = &app;
  const VkResult result = vkCreateInstance(&info, nullptr, &instance_);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw std::runtime_error(std::string("Vulkan device: no Vulkan driver found; ") + kInstallHint);
  vkCheck(result, "vkCreateInstance");
}

void VulkanContext::choosePhysicalDevice() {
  std::uint32_t count = 0;
  vkCheck(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices");
  if (count == 0)
    throw std::runtime_error(std::string("Vulkan device: no physical device found; ") +
                             kInstallHint);
  std::vector<VkPhysicalDevice> physicals(count);
  vkCheck(vkEnumeratePhysicalDevices(instance_, &count, physicals.data()),
          "vkEnumeratePhysicalDevices");
  std::string reasons;
  int best = std::numeric_limits<int>::max();
  for (VkPhysicalDevice physical : physicals) {
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(physical, &properties);
    std::uint32_t family = 0;
    const std::string why = unsuitable(physical, arithmetic_, family);
    if (!why.empty()) {
      reasons += std::string("; ") + properties.deviceName + ": " + why;
      continue;
    }
    if (preference(physical) < best) {
      best = preference(physical);
      physical_ = physical;
      queueFamily_ = family;
      name_ = properties.deviceName;
      limits_ = properties.limits;
      cpuDriver_ = properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
      timestampPeriodNs_ = static_cast<double>(properties.limits.timestampPeriod);
    }
  }
  if (physical_ == VK_NULL_HANDLE)
    throw std::runtime_error("Vulkan device: no physical device has what the exact device needs" +
                             reasons);
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  std::uint32_t families = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, nullptr);
  std::vector<VkQueueFamilyProperties> familyProperties(families);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, familyProperties.data());
  timestamps_ = queueFamily_ < families && familyProperties[queueFamily_].timestampValidBits > 0 &&
                timestampPeriodNs_ > 0.0;
}

void VulkanContext::createDevice() {
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{};
  queue.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queue.queueFamilyIndex = queueFamily_;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  // Dynamic rendering (no render pass), maintenance4 (SPIR-V 1.6 compute stages declare their
  // workgroup size with LocalSizeId, which needs it: the summary shader), and for Native64 the
  // contract's doubles and 64-bit edge functions; Emulated32 asks for neither, which is its point.
  VkPhysicalDeviceVulkan13Features v13{};
  v13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
  v13.dynamicRendering = VK_TRUE;
  v13.maintenance4 = VK_TRUE;
  // Buffer device addresses (required of Vulkan 1.3 devices) for Native64: the compute device's
  // frame reaches every draw's vertices and every framebuffer through them
  // (tile_frame.hpp), so one dispatch serves all of a frame's draws.
  const VkBool32 native = arithmetic_ == ShaderArithmetic::Native64 ? VK_TRUE : VK_FALSE;
  VkPhysicalDeviceVulkan12Features v12{};
  v12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
  v12.bufferDeviceAddress = native;
  v13.pNext = &v12;
  addresses_ = native == VK_TRUE;
  VkPhysicalDeviceFeatures2 features{};
  features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  features.pNext = &v13;
  features.features.shaderFloat64 = native;
  features.features.shaderInt64 = native;
  // Push descriptors where the driver has them: the compute device binds its buffers with them
  // (vulkan_compute_pipelines.hpp) and refuses to start without; the other devices do not use them.
  std::uint32_t extensionCount = 0;
  vkCheck(vkEnumerateDeviceExtensionProperties(physical_, nullptr, &extensionCount, nullptr),
          "vkEnumerateDeviceExtensionProperties");
  std::vector<VkExtensionProperties> extensions(extensionCount);
  vkCheck(
      vkEnumerateDeviceExtensionProperties(physical_, nullptr, &extensionCount, extensions.data()),
      "vkEnumerateDeviceExtensionProperties");
  bool pushDescriptors = false;
  for (const VkExtensionProperties& e : extensions)
    if (std::string_view(e.extensionName) == VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME)
      pushDescriptors = true;
  const char* const pushDescriptorName = VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME;
  VkDeviceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  info.pNext = &features;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = pushDescriptors ? 1 : 0;
  info.ppEnabledExtensionNames = &pushDescriptorName;
  vkCheck(vkCreateDevice(physical_, &info, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
  if (pushDescriptors)
    pushDescriptorSet_ = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
        vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
}

VkFormatFeatureFlags VulkanContext::optimalFeatures(VkFormat format) const {
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(physical_, format, &properties);
  return properties.optimalTilingFeatures;
}

VkDeviceMemory VulkanContext::allocate(const VkMemoryRequirements& requirements,
                                       VkMemoryPropertyFlags properties, bool addressed) const {
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if ((requirements.memoryTypeBits & (1u << i)) &&
        (memory_.memoryTypes[i].propertyFlags & properties) == properties) {
      VkMemoryAllocateFlagsInfo flags{};
      flags.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO;
      flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
      VkMemoryAllocateInfo info{};
      info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
      info.pNext = addressed ? &flags : nullptr;
      info.allocationSize = requirements.size;
      info.memoryTypeIndex = i;
      VkDeviceMemory memory = VK_NULL_HANDLE;
      vkCheck(vkAllocateMemory(device_, &info, nullptr, &memory), "vkAllocateMemory");
      return memory;
    }
  }
  throw std::runtime_error("Vulkan device: no memory type with the properties needed");
}

VkBuffer VulkanContext::createBuffer(VkDeviceSize bytes, VkBufferUsageFlags usage,
                                     VkMemoryPropertyFlags properties,
                                     VkDeviceMemory& memory) const {
  // Every buffer of a context with addresses can be reached by one: storage buffers are
  // the compute device's, and addressing costs nothing until used.
  if (addresses_ && (usage & VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) != 0)
    usage |= VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = bytes;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  vkCheck(vkCreateBuffer(device_, &info, nullptr, &buffer), "vkCreateBuffer");
  VkMemoryRequirements requirements{};
  vkGetBufferMemoryRequirements(device_, buffer, &requirements);
  memory =
      allocate(requirements, properties, (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) != 0);
  vkCheck(vkBindBufferMemory(device_, buffer, memory, 0), "vkBindBufferMemory");
  return buffer;
}

HostBuffer VulkanContext::createHostBuffer(VkDeviceSize bytes, VkBufferUsageFlags usage) const {
  HostBuffer buffer;
  buffer.buffer = createBuffer(
      bytes, usage, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
      buffer.memory);
  vkCheck(vkMapMemory(device_, buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped), "vkMapMemory");
  buffer.size = bytes;
  return buffer;
}

void VulkanContext::destroyHostBuffer(HostBuffer& buffer) const {
  if (buffer.buffer == VK_NULL_HANDLE)
    return;
  vkDestroyBuffer(device_, buffer.buffer, nullptr);
  vkFreeMemory(device_, buffer.memory, nullptr);  // unmaps it too
  buffer = {};
}

DeviceBuffer VulkanContext::createDeviceBuffer(VkDeviceSize bytes, VkBufferUsageFlags usage) const {
  DeviceBuffer buffer;
  buffer.buffer = createBuffer(bytes, usage, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, buffer.memory);
  buffer.size = bytes;
  return buffer;
}

VkDeviceAddress VulkanContext::address(VkBuffer buffer) const {
  if (!addresses_)
    throw std::logic_error("Vulkan context: buffer addresses are enabled for Native64 only");
  VkBufferDeviceAddressInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO;
  info.buffer = buffer;
  return vkGetBufferDeviceAddress(device_, &info);
}

void VulkanContext::destroyDeviceBuffer(DeviceBuffer& buffer) const {
  if (buffer.buffer == VK_NULL_HANDLE)
    return;
  vkDestroyBuffer(device_, buffer.buffer, nullptr);
  vkFreeMemory(device_, buffer.memory, nullptr);
  buffer = {};
}

VkCommandPool VulkanContext::createCommandPool() const {
  VkCommandPoolCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  info.queueFamilyIndex = queueFamily_;
  VkCommandPool pool = VK_NULL_HANDLE;
  vkCheck(vkCreateCommandPool(device_, &info, nullptr, &pool), "vkCreateCommandPool");
  return pool;
}

VkFence VulkanContext::createFence() const {
  VkFenceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  VkFence fence = VK_NULL_HANDLE;
  vkCheck(vkCreateFence(device_, &info, nullptr, &fence), "vkCreateFence");
  return fence;
}

void VulkanContext::submitAndWait(VkCommandBuffer commands, VkFence fence) {
  VkSubmitInfo submitInfo{};
  submitInfo.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submitInfo.commandBufferCount = 1;
  submitInfo.pCommandBuffers = &commands;
  {
    const std::lock_guard<std::mutex> lock(queueLock_);
    vkCheck(vkQueueSubmit(queue_, 1, &submitInfo, fence), "vkQueueSubmit");
  }
  vkCheck(vkWaitForFences(device_, 1, &fence, VK_TRUE, std::numeric_limits<std::uint64_t>::max()),
          "vkWaitForFences");
  vkCheck(vkResetFences(device_, 1, &fence), "vkResetFences");
}

}  // namespace recode::backends::detail
