// RECODE's simulation behind the bench's detector interface, on any of the devices.
#include "recode/verify/recode_detector.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "recode/geometry/generators.hpp"
#include "recode/pair/pair.hpp"
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

namespace {

core::RunOptions withDevice(core::RunOptions options, RecodeDevice device) {
  if (device != RecodeDevice::Cpu)
    options.deviceFactory = warmDeviceFactory(device);
  return options;
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

template <class Device>
core::DeviceFactory warmFactory() {
  return [](int width, int height) -> std::unique_ptr<raster::DepthStencilDevice> {
    auto device = std::make_unique<Device>(width, height);
    warmUp(*device);
    return device;
  };
}

}  // namespace

core::DeviceFactory warmDeviceFactory(RecodeDevice device) {
  switch (device) {
    case RecodeDevice::Cpu:
      return warmFactory<raster::CpuDevice>();
    case RecodeDevice::Gl:
#if RECODE_HAVE_OSMESA
      return warmFactory<GlDevice>();
#else
      throw std::runtime_error(
          "RECODE on the GL device needs OSMesa: this build has none (install libosmesa6-dev "
          "and configure with RECODE_WITH_OSMESA=ON)");
#endif
    case RecodeDevice::GlExact:
#if RECODE_HAVE_GL_EXACT
      return warmFactory<GlExactDevice>();
#else
      throw std::runtime_error(
          "RECODE on the exact GL device needs OSMesa or EGL: this build has neither (install "
          "libosmesa6-dev or libegl-dev and reconfigure)");
#endif
    case RecodeDevice::Vulkan:
#if RECODE_HAVE_VULKAN
      return warmFactory<VulkanDevice>();
#else
      throw std::runtime_error(
          "RECODE on the Vulkan device needs Vulkan: this build has none (install libvulkan-dev, "
          "mesa-vulkan-drivers and glslang-tools and reconfigure)");
#endif
  }
  throw std::invalid_argument("unknown RECODE device");
}

RecodeDetector::RecodeDetector(const core::Scene& scene, core::RunOptions options,
                               RecodeDevice device, std::string name)
    : simulation_(scene, withDevice(std::move(options), device)), name_(std::move(name)) {}

Detection RecodeDetector::detect(const std::vector<core::ObjectTree>& /*objects*/, int frame) {
  last_ = simulation_.runFrame(frame);
  Detection detection;
  detection.collisionUs = last_.collisionUs;
  detection.pairs.reserve(last_.contacts.size());
  for (const core::LeafContact& c : last_.contacts)
    detection.pairs.push_back({c.objectA, c.leafA, c.objectB, c.leafB});
  std::sort(detection.pairs.begin(), detection.pairs.end());
  return detection;
}

}  // namespace recode::verify
