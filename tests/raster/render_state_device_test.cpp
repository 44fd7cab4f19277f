// RenderStateDevice (render_state_device.hpp), the base of every device that keeps its state in
// one RenderState: each of the seven setters stores its arguments and then tells the device
// which state changed (stateChanged), where a device over a graphics API passes it on; a
// refused value changes nothing and tells nothing.

#include <catch2/catch.hpp>

#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "recode/raster/render_state_device.hpp"

using namespace recode::raster;

namespace {

// A device with no buffers that writes down every stateChanged call, with the state the setter
// had stored by then.
class ChangeLog final : public RenderStateDevice {
 public:
  ChangeLog() : RenderStateDevice(8, 6) {}
  using Change = RenderStateDevice::StateChange;
  struct Entry {
    Change change;
    Face face;
    RenderState state;
  };
  std::vector<Entry> entries;

  [[nodiscard]] int width() const override { return 8; }
  [[nodiscard]] int height() const override { return 6; }
  void clearDepth(double) override {}
  void clearStencil(std::uint8_t) override {}
  void drawTriangles(std::span<const WindowVertex>, std::span<const std::uint32_t>) override {}
  [[nodiscard]] std::vector<std::uint8_t> readStencil(const PixelRect&) const override {
    return {};
  }
  [[nodiscard]] std::vector<std::uint32_t> readDepth(const PixelRect&) const override { return {}; }

 private:
  void stateChanged(Change change, Face face) override {
    entries.push_back({change, face, state_});
  }
};

}  // namespace

TEST_CASE("each state setter tells the device its change once, after storing it",
          "[state][render-state-device]") {
  using Change = ChangeLog::Change;
  ChangeLog dev;
  dev.setScissor({-2, 1, 20, 5});
  dev.setDepthFunc(CompareFunc::Greater);
  dev.setDepthWriteMask(false);
  dev.setStencilFunc(CompareFunc::Equal, 3, 0x0F);
  dev.setStencilOps(Face::Back, {StencilOp::Zero, StencilOp::Incr, StencilOp::Invert});
  dev.setStencilWriteMask(0x3F);
  dev.setCullMode(CullMode::Back);
  REQUIRE(dev.entries.size() == 7);
  const auto& e = dev.entries;
  CHECK(e[0].change == Change::Scissor);
  CHECK(e[0].state.scissor == PixelRect{0, 1, 8, 5});  // clamped to the 8 x 6 framebuffer
  CHECK(e[1].change == Change::DepthFunc);
  CHECK(e[1].state.depthFunc == CompareFunc::Greater);
  CHECK(e[2].change == Change::DepthWriteMask);
  CHECK(e[2].state.depthWrite == false);
  CHECK(e[3].change == Change::StencilFunc);
  CHECK(e[3].state.stencilRef == 3);
  CHECK(e[4].change == Change::StencilOps);
  CHECK(e[4].face == Face::Back);  // the faces the ops were set for
  CHECK(e[4].state.backOps == StencilOps{StencilOp::Zero, StencilOp::Incr, StencilOp::Invert});
  CHECK(e[5].change == Change::StencilWriteMask);
  CHECK(e[5].state.stencilWriteMask == 0x3F);
  CHECK(e[6].change == Change::CullMode);
  CHECK(e[6].state.cull == CullMode::Back);
  // The others are for both faces.
  for (std::size_t k = 0; k < e.size(); ++k)
    if (k != 4)
      CHECK(e[k].face == Face::Both);
  // A refused value is neither stored nor told.
  CHECK_THROWS_AS(dev.setDepthFunc(static_cast<CompareFunc>(8)), std::invalid_argument);
  CHECK_THROWS_AS(dev.setCullMode(static_cast<CullMode>(3)), std::invalid_argument);
  CHECK(dev.entries.size() == 7);
  CHECK(dev.state().depthFunc == CompareFunc::Greater);
}
