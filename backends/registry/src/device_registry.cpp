#include "recode/backends/device_registry.hpp"

#include <array>
#include <stdexcept>
#include <string>

#include "recode/geometry/generators.hpp"
#include "recode/pair/pair.hpp"
#include "recode/raster/cpu_device.hpp"
#if RECODE_HAVE_GL_DEVICE
#include "recode/backends/gl_device.hpp"
#endif
#if RECODE_HAVE_GL_EXACT
#include "recode/backends/gl_exact_device.hpp"
#endif
#if RECODE_HAVE_VULKAN
#include "recode/backends/vulkan_compute_device.hpp"
#include "recode/backends/vulkan_device.hpp"
#include "recode/backends/vulkan_native_device.hpp"
#endif

namespace recode::backends {

namespace {

#if RECODE_HAVE_GL_DEVICE
constexpr bool kGlBuilt = true;
#else
constexpr bool kGlBuilt = false;
#endif
#if RECODE_HAVE_GL_EXACT
constexpr bool kGlExactBuilt = true;
#else
constexpr bool kGlExactBuilt = false;
#endif
#if RECODE_HAVE_VULKAN
constexpr bool kVulkanBuilt = true;
#else
constexpr bool kVulkanBuilt = false;
#endif

constexpr std::array<DeviceInfo, 7> kDevices = {{
    {DeviceKind::Cpu, "cpu", "the CPU reference (raster::CpuDevice): the contract's bits", true,
     true, ""},
    {DeviceKind::Gl, "gl",
     "fixed-function OpenGL on OSMesa or EGL (GlDevice): the same commands, the driver's float "
     "depth",
     false, kGlBuilt, "install libosmesa6-dev or libegl-dev and reconfigure"},
    {DeviceKind::GlExact, "gl-exact",
     "OpenGL 4.5 shaders that apply the contract (GlExactDevice), on EGL or OSMesa", true,
     kGlExactBuilt, "install libegl-dev or libosmesa6-dev and reconfigure"},
    {DeviceKind::Vulkan, "vulkan",
     "Vulkan 1.3 shaders that apply the contract (VulkanDevice), headless", true, kVulkanBuilt,
     "install libvulkan-dev, mesa-vulkan-drivers and glslang-tools and reconfigure"},
    {DeviceKind::Vulkan32, "vulkan-32",
     "the Vulkan device with 32-bit shader arithmetic only (no shaderFloat64, no shaderInt64)",
     true, kVulkanBuilt,
     "install libvulkan-dev, mesa-vulkan-drivers and glslang-tools and reconfigure"},
    {DeviceKind::VulkanCompute, "vulkan-compute",
     "the contract as a tile rasterizer in Vulkan compute shaders only (VulkanComputeDevice)", true,
     kVulkanBuilt, "install libvulkan-dev, mesa-vulkan-drivers and glslang-tools and reconfigure"},
    {DeviceKind::VulkanNative, "vulkan-native",
     "Vulkan 1.3's own rasterizer and depth/stencil attachment, headless (VulkanNativeDevice): the "
     "same commands, the driver's coverage and depth",
     false, kVulkanBuilt,
     "install libvulkan-dev, mesa-vulkan-drivers and glslang-tools and reconfigure"},
}};

[[noreturn]] void notBuilt(const DeviceInfo& info) {
  throw std::runtime_error("the " + std::string(info.name) +
                           " device is not in this build: " + std::string(info.missing));
}

// Two unit boxes overlapping by half a unit near the frame's corner, drawn with every pass
// RECODE uses (contact passes included), so each state combination has been seen once.
void warmUp(raster::DepthStencilDevice& device) {
  core::TriangleMesh a = core::makeBox(1.0, 1.0, 1.0);
  core::TriangleMesh b = a;
  for (Eigen::Vector3d& v : a.vertices)
    v += Eigen::Vector3d(2.0, 2.0, 2.0);
  for (Eigen::Vector3d& v : b.vertices)
    v += Eigen::Vector3d(3.5, 3.5, 3.5);
  core::PairRequest request;
  request.frame.axis = core::ViewAxis::Z;
  request.frame.width = device.width();
  request.frame.height = device.height();
  request.frame.window = {0.0, 0.0, static_cast<double>(device.width()),
                          static_cast<double>(device.height())};
  request.contact = true;
  (void)core::collidePair(device, a, b, request);
}

}  // namespace

std::span<const DeviceInfo> deviceRegistry() {
  return kDevices;
}

const DeviceInfo& deviceInfo(DeviceKind kind) {
  for (const DeviceInfo& info : kDevices)
    if (info.kind == kind)
      return info;
  throw std::invalid_argument("unknown device kind " + std::to_string(static_cast<int>(kind)));
}

std::string_view toString(DeviceKind kind) {
  return deviceInfo(kind).name;
}

DeviceKind parseDeviceKind(std::string_view name) {
  std::string choices;
  for (const DeviceInfo& info : kDevices) {
    if (info.name == name)
      return info.kind;
    choices += (choices.empty() ? "" : ", ") + std::string(info.name);
  }
  throw std::invalid_argument("unknown device \"" + std::string(name) + "\" (devices: " + choices +
                              ")");
}

std::unique_ptr<raster::DepthStencilDevice> makeDevice(DeviceKind kind, int width, int height) {
  const DeviceInfo& info = deviceInfo(kind);
  if (!info.built)
    notBuilt(info);
  switch (kind) {
    case DeviceKind::Cpu:
      return std::make_unique<raster::CpuDevice>(width, height);
#if RECODE_HAVE_GL_DEVICE
    case DeviceKind::Gl:
      return std::make_unique<GlDevice>(width, height);
#endif
#if RECODE_HAVE_GL_EXACT
    case DeviceKind::GlExact:
      return std::make_unique<GlExactDevice>(width, height);
#endif
#if RECODE_HAVE_VULKAN
    case DeviceKind::Vulkan:
      return std::make_unique<VulkanDevice>(width, height);
    case DeviceKind::Vulkan32:
      return std::make_unique<VulkanDevice>(width, height, ShaderArithmetic::Emulated32);
    case DeviceKind::VulkanCompute:
      return std::make_unique<VulkanComputeDevice>(width, height);
    case DeviceKind::VulkanNative:
      return std::make_unique<VulkanNativeDevice>(width, height);
#endif
    default:
      notBuilt(info);
  }
}

core::DeviceFactory warmDeviceFactory(DeviceKind kind) {
  const DeviceInfo& info = deviceInfo(kind);
  if (!info.built)
    notBuilt(info);
  return [kind](int width, int height) {
    std::unique_ptr<raster::DepthStencilDevice> device = makeDevice(kind, width, height);
    warmUp(*device);
    return device;
  };
}

core::DeviceFactory deviceFactoryFor(DeviceKind kind) {
  if (kind == DeviceKind::Cpu)
    return {};
  return warmDeviceFactory(kind);
}

}  // namespace recode::backends
