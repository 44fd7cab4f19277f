// RECODE's simulation behind the bench's detector interface, on any of the devices.
#include "recode/verify/recode_detector.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace recode::verify {

namespace {

core::RunOptions withDevice(core::RunOptions options, backends::DeviceKind device) {
  if (device != backends::DeviceKind::Cpu)
    options.deviceFactory = backends::warmDeviceFactory(device);
  return options;
}

}  // namespace

RecodeDetector::RecodeDetector(const core::Scene& scene, core::RunOptions options,
                               backends::DeviceKind device, std::string name)
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
