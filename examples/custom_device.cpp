// The device seam: a DepthStencilDevice of our own, here a ForwardingDevice that counts draws and
// hands every command to the CPU reference device, given to the API through a device factory.
// A GPU back end plugs in the same way (docs/architecture.md, "The device seam").
#include <cstdio>
#include <memory>
#include <numbers>

#include "recode/api/collision.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/forwarding_device.hpp"

namespace {

namespace raster = recode::raster;

// Everything goes to the CPU device it owns (ForwardingDevice); only the draws are counted.
class CountingDevice final : public raster::ForwardingDevice {
 public:
  CountingDevice(int width, int height, long long& draws)
      : ForwardingDevice(std::make_unique<raster::CpuDevice>(width, height)), draws_(draws) {}

  void drawTriangles(std::span<const raster::WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override {
    ++draws_;
    ForwardingDevice::drawTriangles(vertices, indices);
  }

 private:
  long long& draws_;
};

}  // namespace

int main() {
  const auto cone = recode::CollisionGeometry::single(
      recode::ConvexBlock::fromMesh(recode::core::makeCone(1.0, 2.0, 32), "cone"));
  recode::CollisionObject lower(cone), upper(cone);
  Eigen::Isometry3d pose(Eigen::Translation3d(0.05, 0.0, 3.75));
  pose.rotate(Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()));
  upper.setTransform(pose);

  // The seam: a factory the pool calls once per frame size it needs.
  long long draws = 0;
  recode::DevicePool counting([&draws](int width, int height) {
    return std::make_unique<CountingDevice>(width, height, draws);
  });
  recode::CollisionRequest request;
  recode::CollisionResult mine, reference;
  recode::collide(lower, upper, request, mine, counting);
  recode::collide(lower, upper, request, reference);  // the built-in CPU devices

  const bool same = mine.collide == reference.collide &&
                    mine.interferingPixels == reference.interferingPixels &&
                    mine.contact.points == reference.contact.points;
  std::printf("collide: %s, %lld pixels, devices made: %zu, draws: %lld\n",
              mine.collide ? "yes" : "no", mine.interferingPixels, counting.size(), draws);
  std::printf("same result as the CPU device: %s\n", same ? "yes" : "no");
  return same ? 0 : 1;
}
