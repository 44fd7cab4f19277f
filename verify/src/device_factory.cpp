#include "recode/verify/device_factory.hpp"

#include <stdexcept>

#include "recode/raster/cpu_device.hpp"
#if RECODE_HAVE_OSMESA
#include "recode/verify/gl_device.hpp"
#endif
#if RECODE_HAVE_GL_EXACT
#include "recode/verify/gl_exact_device.hpp"
#endif
#if RECODE_HAVE_VULKAN
#include "recode/verify/vulkan_device.hpp"
#endif

namespace recode::verify {

DeviceKind parseDeviceKind(const std::string& name) {
  if (name == "cpu")
    return DeviceKind::Cpu;
  if (name == "gl")
    return DeviceKind::Gl;
  if (name == "gl-exact")
    return DeviceKind::GlExact;
  if (name == "vulkan")
    return DeviceKind::Vulkan;
  throw std::invalid_argument("unknown device \"" + name +
                              "\" (devices: cpu, gl, gl-exact, vulkan)");
}

std::string_view toString(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::Cpu:
      return "cpu";
    case DeviceKind::Gl:
      return "gl";
    case DeviceKind::GlExact:
      return "gl-exact";
    case DeviceKind::Vulkan:
      return "vulkan";
  }
  return "?";
}

std::unique_ptr<raster::DepthStencilDevice> makeDevice(DeviceKind kind, int width, int height) {
  switch (kind) {
    case DeviceKind::Cpu:
      return std::make_unique<raster::CpuDevice>(width, height);
    case DeviceKind::Gl:
#if RECODE_HAVE_OSMESA
      return std::make_unique<GlDevice>(width, height);
#else
      throw std::runtime_error(
          "the GL device needs OSMesa, which this build does not have: install libosmesa6-dev "
          "and configure with -DRECODE_WITH_OSMESA=ON");
#endif
    case DeviceKind::GlExact:
#if RECODE_HAVE_GL_EXACT
      return std::make_unique<GlExactDevice>(width, height);
#else
      throw std::runtime_error(
          "the exact GL device needs OSMesa or EGL, which this build does not have: install "
          "libosmesa6-dev or libegl-dev and reconfigure");
#endif
    case DeviceKind::Vulkan:
#if RECODE_HAVE_VULKAN
      return std::make_unique<VulkanDevice>(width, height);
#else
      throw std::runtime_error(
          "the Vulkan device needs Vulkan, which this build does not have: install "
          "libvulkan-dev, mesa-vulkan-drivers and glslang-tools and reconfigure");
#endif
  }
  throw std::invalid_argument("makeDevice: unknown device kind");
}

}  // namespace recode::verify
