#pragma once
// Depth/stencil devices by name, for the programs that replay command streams on a chosen
// back end (`recode conform --device cpu|gl|gl-exact|vulkan`).

#include <memory>
#include <string>
#include <string_view>

#include "recode/raster/device.hpp"

namespace recode::verify {

enum class DeviceKind {
  Cpu,      // raster::CpuDevice, the reference
  Gl,       // GlDevice: fixed-function OpenGL on OSMesa (llvmpipe; its depth is not bit-exact)
  GlExact,  // GlExactDevice: OpenGL 4.5 shaders that apply the contract (EGL, else OSMesa)
  Vulkan,   // VulkanDevice: the same shaders on Vulkan 1.3
};

// "cpu", "gl", "gl-exact", "vulkan"; throws std::invalid_argument naming the choices for anything
// else.
[[nodiscard]] DeviceKind parseDeviceKind(const std::string& name);
[[nodiscard]] std::string_view toString(DeviceKind kind);

// A fresh width x height device of that kind (depth 1.0, stencil 0, GL's default state).
// Throws std::runtime_error when the kind is not in this build or no driver gives a context,
// naming what to install; std::invalid_argument for a size outside 1..16384.
[[nodiscard]] std::unique_ptr<raster::DepthStencilDevice> makeDevice(DeviceKind kind, int width,
                                                                     int height);

}  // namespace recode::verify
