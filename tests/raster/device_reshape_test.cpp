// CpuDevice::reshape: a device used at one size and reshaped is a new device of the new size
// (buffers, state, counters, no recorded draw left), whatever it did before, and it keeps its
// memory; bestDeviceToReshape picks the device that allocates least.

#include <catch2/catch.hpp>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "raster_test_support.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/triangle_source.hpp"

using namespace recode::raster;

namespace {

// Two triangles over most of a w x h frame, with a content key, so that a device records its
// first draw and replays later ones.
class KeyedQuad final : public TriangleSource {
 public:
  KeyedQuad(int w, int h)
      : vertices_{{snapToSubpixel(0.3), snapToSubpixel(0.6), 0.25f},
                  {snapToSubpixel(w - 0.4), snapToSubpixel(0.2), 0.5f},
                  {snapToSubpixel(w - 0.1), snapToSubpixel(h - 0.3), 0.75f},
                  {snapToSubpixel(0.2), snapToSubpixel(h - 0.7), 0.4f}} {}
  [[nodiscard]] TriangleDraw allTriangles() const override { return {vertices_, indices_}; }
  [[nodiscard]] std::uint64_t contentKey() const override { return key_; }

 private:
  std::vector<WindowVertex> vertices_;
  std::vector<std::uint32_t> indices_{0, 1, 2, 0, 2, 3};
  std::uint64_t key_ = newTriangleSourceKey();
};

// Leaves every piece of state away from its default, the buffers written and a draw recorded.
void useHard(CpuDevice& dev, const TriangleSource& source) {
  dev.clearDepth(0.25);
  dev.clearStencil(0x5A);
  dev.setCullMode(CullMode::None);
  dev.setDepthFunc(CompareFunc::Always);
  dev.setStencilFunc(CompareFunc::Always, 3, 0xFF);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Invert});
  dev.drawMesh(source);  // recorded under the whole frame: no cull
  dev.setScissor({1, 1, dev.width() - 1, dev.height() - 1});
  dev.setDepthWriteMask(false);
  dev.setStencilWriteMask(0x0F);
  dev.setCullMode(CullMode::Back);
  dev.setStencilFunc(CompareFunc::Never, 9, 0x03);
  dev.setDepthFunc(CompareFunc::Greater);
}

// Commands that depend on every default: the scissor (the whole frame), the depth test and
// write, the stencil write mask (the clear), func and ops, and the cull mode.
void drawFromDefaults(CpuDevice& dev, const TriangleSource& source) {
  dev.drawMesh(source);
  dev.clearStencil(0xF0);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap});
  dev.drawMesh(source);
}

}  // namespace

TEST_CASE("a reshaped CpuDevice is a new device of the new size", "[state][reshape]") {
  struct Size {
    int width, height;
  };
  for (const Size to : {Size{16, 16}, Size{40, 33}, Size{3, 2}, Size{24, 10}}) {
    INFO(to.width << "x" << to.height);
    CpuDevice used(24, 10);
    const KeyedQuad before(24, 10);
    useHard(used, before);
    used.reshape(to.width, to.height);
    CpuDevice fresh(to.width, to.height);

    CHECK(used.width() == to.width);
    CHECK(used.height() == to.height);
    CHECK(used.scissor() == fresh.scissor());
    CHECK(std::vector(used.depthBuffer().begin(), used.depthBuffer().end()) ==
          std::vector(fresh.depthBuffer().begin(), fresh.depthBuffer().end()));
    CHECK(std::vector(used.stencilBuffer().begin(), used.stencilBuffer().end()) ==
          std::vector(fresh.stencilBuffer().begin(), fresh.stencilBuffer().end()));
    CHECK(used.counters().fragments == 0);

    // The draw recorded before must not serve the same source now: its blocks lie in the old
    // frame.
    used.drawMesh(before);
    fresh.drawMesh(before);
    CHECK(used.counters().trianglesReplayed == 0);

    const KeyedQuad after(to.width, to.height);
    drawFromDefaults(used, after);
    drawFromDefaults(fresh, after);
    CHECK(std::vector(used.depthBuffer().begin(), used.depthBuffer().end()) ==
          std::vector(fresh.depthBuffer().begin(), fresh.depthBuffer().end()));
    CHECK(std::vector(used.stencilBuffer().begin(), used.stencilBuffer().end()) ==
          std::vector(fresh.stencilBuffer().begin(), fresh.stencilBuffer().end()));
    CHECK(used.counters().fragments == fresh.counters().fragments);
    CHECK(fresh.counters().fragments > 0);
  }
}

TEST_CASE("reshape keeps the memory, or refuses a bad size and changes nothing",
          "[state][reshape]") {
  CpuDevice dev(24, 10);
  dev.reshape(3, 2);
  CHECK(dev.pixelCapacity() >= 24 * 10);  // a smaller frame allocates nothing
  dev.reshape(20, 12);
  CHECK(dev.pixelCapacity() >= 24 * 10);

  dev.clearStencil(3);
  CHECK_THROWS_AS(dev.reshape(0, 4), std::invalid_argument);
  CHECK_THROWS_AS(dev.reshape(4, kMaxFramebufferSize + 1), std::invalid_argument);
  CHECK(dev.width() == 20);
  CHECK(dev.height() == 12);
  CHECK(dev.stencilBuffer().size() == 20u * 12u);
  CHECK(dev.stencilBuffer()[0] == 3);
}

TEST_CASE("the device to reshape is the least memory that holds the size, else the most",
          "[state][reshape]") {
  const CpuDevice small(10, 10), middle(30, 20), large(100, 100);
  const std::vector<const CpuDevice*> devices{&large, &small, &middle};
  CHECK(bestDeviceToReshape(devices, 9, 9) == 1);      // small holds it
  CHECK(bestDeviceToReshape(devices, 20, 20) == 2);    // middle (600) holds 400
  CHECK(bestDeviceToReshape(devices, 50, 50) == 0);    // only large
  CHECK(bestDeviceToReshape(devices, 200, 200) == 0);  // none: the largest grows least
  CHECK(bestDeviceToReshape({}, 8, 8) == 0);           // none at all: the end
}
