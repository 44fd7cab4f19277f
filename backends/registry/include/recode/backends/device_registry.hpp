#pragma once
// The depth/stencil devices by kind and name: the one list the programs, the bench, the tests
// and the collision API's users choose a device from. Each entry says what the device is,
// whether it promises the CPU reference's bits, whether this build has it and, when not, what
// to install; makeDevice and deviceFactory make one.

#include <memory>
#include <span>
#include <string_view>

#include "recode/raster/device.hpp"
#include "recode/sim/simulation.hpp"

namespace recode::backends {

enum class DeviceKind {
  Cpu,       // raster::CpuDevice, the reference
  Gl,        // GlDevice: fixed-function OpenGL on OSMesa (llvmpipe; its depth is not bit-exact)
  GlExact,   // GlExactDevice: OpenGL 4.5 shaders that apply the contract (EGL, else OSMesa)
  Vulkan,    // VulkanDevice: the same contract on Vulkan 1.3
  Vulkan32,  // VulkanDevice, ShaderArithmetic::Emulated32: the same bits, 32-bit shaders only
  VulkanCompute,  // VulkanComputeDevice: the contract as a tile rasterizer in compute shaders
  VulkanNative,   // VulkanNativeDevice: Vulkan's own rasterizer and depth (not bit-exact)
};

struct DeviceInfo {
  DeviceKind kind = DeviceKind::Cpu;
  // "cpu", "gl", "gl-exact", "vulkan", "vulkan-32", "vulkan-compute", "vulkan-native"
  std::string_view name;
  std::string_view description;  // one line
  bool exact = false;            // promises raster::CpuDevice's bits (docs/rasterization.md)
  bool built = false;            // this build can make it
  std::string_view missing;      // what to install and reconfigure when it is not built
};

// Every kind, in the enumeration's order.
[[nodiscard]] std::span<const DeviceInfo> deviceRegistry();
[[nodiscard]] const DeviceInfo& deviceInfo(DeviceKind kind);
[[nodiscard]] std::string_view toString(DeviceKind kind);  // its name

// The kind of a name; throws std::invalid_argument naming the choices for anything else.
[[nodiscard]] DeviceKind parseDeviceKind(std::string_view name);

// A fresh width x height device of that kind (depth 1.0, stencil 0, GL's default state).
// Throws std::runtime_error when the kind is not in this build (naming what to install) or no
// driver gives a context; std::invalid_argument for a size outside 1..16384.
[[nodiscard]] std::unique_ptr<raster::DepthStencilDevice> makeDevice(DeviceKind kind, int width,
                                                                     int height);

// A factory for core::RunOptions::deviceFactory and the collision API's DevicePool: each device
// it makes has drawn one small colliding pair with every pass RECODE uses, so that a GPU driver
// has compiled its shaders (and the exact devices made their shared context) before any timed
// frame. Throws as makeDevice when the kind is not in this build.
[[nodiscard]] core::DeviceFactory warmDeviceFactory(DeviceKind kind);

// What a run or a DevicePool should be given to draw on `kind`: empty for Cpu (the caller's own
// CPU devices, which a run may use from several threads), else warmDeviceFactory(kind). Throws
// as makeDevice when the kind is not in this build.
[[nodiscard]] core::DeviceFactory deviceFactoryFor(DeviceKind kind);

}  // namespace recode::backends
