// The device seam: a DepthStencilDevice of our own, here a thin wrapper that counts draws and
// hands every command to the CPU reference device, given to the API through a device factory.
// A GPU back end plugs in the same way (docs/architecture.md, "The device seam").
#include <cstdio>
#include <memory>
#include <numbers>

#include "recode/api/collision.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/raster/cpu_device.hpp"

namespace {

namespace raster = recode::raster;

class CountingDevice final : public raster::DepthStencilDevice {
 public:
  CountingDevice(int width, int height, long long& draws) : cpu_(width, height), draws_(draws) {}

  int width() const override { return cpu_.width(); }
  int height() const override { return cpu_.height(); }
  void setScissor(const raster::PixelRect& rect) override { cpu_.setScissor(rect); }
  void clearDepth(double depth) override { cpu_.clearDepth(depth); }
  void clearStencil(std::uint8_t value) override { cpu_.clearStencil(value); }
  void setDepthFunc(raster::CompareFunc func) override { cpu_.setDepthFunc(func); }
  void setDepthWriteMask(bool write) override { cpu_.setDepthWriteMask(write); }
  void setStencilFunc(raster::CompareFunc func, std::uint8_t ref, std::uint8_t mask) override {
    cpu_.setStencilFunc(func, ref, mask);
  }
  void setStencilOps(raster::Face face, const raster::StencilOps& ops) override {
    cpu_.setStencilOps(face, ops);
  }
  void setStencilWriteMask(std::uint8_t mask) override { cpu_.setStencilWriteMask(mask); }
  void setCullMode(raster::CullMode mode) override { cpu_.setCullMode(mode); }
  void drawTriangles(std::span<const raster::WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override {
    ++draws_;
    cpu_.drawTriangles(vertices, indices);
  }
  std::vector<std::uint8_t> readStencil(const raster::PixelRect& rect) const override {
    return cpu_.readStencil(rect);
  }
  std::vector<std::uint32_t> readDepth(const raster::PixelRect& rect) const override {
    return cpu_.readDepth(rect);
  }

 private:
  raster::CpuDevice cpu_;
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
