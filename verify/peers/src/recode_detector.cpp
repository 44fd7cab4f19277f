// RECODE's simulation behind the bench's detector interface, on the CPU or the GL device.
#include "recode/verify/recode_detector.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "recode/geometry/generators.hpp"
#include "recode/pair/pair.hpp"

#if RECODE_HAVE_OSMESA
#include "recode/verify/gl_device.hpp"
#endif

namespace recode::verify {

namespace {

core::RunOptions withDevice(core::RunOptions options, RecodeDevice device) {
  if (device == RecodeDevice::Gl)
    options.deviceFactory = warmGlDeviceFactory();
  return options;
}

#if RECODE_HAVE_OSMESA
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
#endif

}  // namespace

core::DeviceFactory warmGlDeviceFactory() {
#if RECODE_HAVE_OSMESA
  return [](int width, int height) -> std::unique_ptr<raster::DepthStencilDevice> {
    auto device = std::make_unique<GlDevice>(width, height);
    warmUp(*device);
    return device;
  };
#else
  throw std::runtime_error(
      "RECODE on the GL device needs OSMesa: this build has none (install libosmesa6-dev and "
      "configure with RECODE_WITH_OSMESA=ON)");
#endif
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
