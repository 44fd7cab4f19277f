// The device registry with the collision API: the same pair collided on every device this
// build has, chosen by the name `recode conform --device` takes ("cpu", "gl", "gl-exact",
// "vulkan"), each through a DevicePool made from the registry's factory. An exact device gives
// the CPU reference's result bit for bit; the fixed-function "gl" device only the same verdict.
//
//   example_device_by_name [NAME...]      (default: every device of the registry)
#include <cstdio>
#include <exception>
#include <numbers>
#include <string>
#include <vector>

#include "recode/api/collision.hpp"
#include "recode/backends/device_registry.hpp"
#include "recode/geometry/generators.hpp"

namespace backends = recode::backends;

int main(int argc, char** argv) {
  std::vector<std::string> names(argv + 1, argv + argc);
  if (names.empty())
    for (const backends::DeviceInfo& info : backends::deviceRegistry())
      names.emplace_back(info.name);

  const auto cone = recode::CollisionGeometry::single(
      recode::ConvexBlock::fromMesh(recode::core::makeCone(1.0, 2.0, 32), "cone"));
  recode::CollisionObject lower(cone), upper(cone);
  Eigen::Isometry3d pose(Eigen::Translation3d(0.05, 0.0, 3.75));
  pose.rotate(Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()));
  upper.setTransform(pose);
  recode::CollisionRequest request;
  recode::CollisionResult reference;
  recode::collide(lower, upper, request, reference);  // the built-in CPU devices

  int failures = 0;
  for (const std::string& name : names) {
    try {
      const backends::DeviceInfo& info = backends::deviceInfo(backends::parseDeviceKind(name));
      if (!info.built) {
        std::printf("%s: not in this build (%s)\n", name.c_str(),
                    std::string(info.missing).c_str());
        continue;
      }
      recode::DevicePool pool(backends::warmDeviceFactory(info.kind));
      recode::CollisionResult result;
      recode::collide(lower, upper, request, result, pool);
      const bool sameBits = result.collide == reference.collide &&
                            result.interferingPixels == reference.interferingPixels &&
                            result.contact.points == reference.contact.points;
      const bool ok = info.exact ? sameBits : result.collide == reference.collide;
      std::printf("%s: collide %s, %lld pixels, %s\n", name.c_str(), result.collide ? "yes" : "no",
                  result.interferingPixels,
                  info.exact ? (sameBits ? "the reference's bits" : "DIFFERS from the reference")
                             : (ok ? "the reference's verdict" : "DIFFERS from the reference"));
      failures += ok ? 0 : 1;
    } catch (const std::exception& e) {
      std::printf("%s: FAILED: %s\n", name.c_str(), e.what());
      ++failures;
    }
  }
  return failures == 0 ? 0 : 1;
}
