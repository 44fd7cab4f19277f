// Scissor, clears, culling, read-back layout and the errors of the CPU device.

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "raster_test_support.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/forwarding_device.hpp"

using namespace recode::raster;
using recode::test::drawTriangle;
using recode::test::setCountingState;

namespace {
int count(const std::vector<std::uint8_t>& v, std::uint8_t value) {
  int n = 0;
  for (std::uint8_t s : v)
    n += s == value;
  return n;
}
}  // namespace

TEST_CASE("scissor limits drawing and clears; read-back is bottom-up row-major", "[state]") {
  CpuDevice dev(16, 16);
  dev.setScissor({3, 4, 9, 7});
  dev.clearStencil(7);
  dev.clearDepth(0.0);
  const auto all = dev.readStencil({0, 0, 16, 16});
  REQUIRE(all.size() == 256);
  CHECK(count(all, 7) == 6 * 3);
  CHECK(all[4 * 16 + 3] == 7);  // (3, 4): first inside
  CHECK(all[4 * 16 + 2] == 0);
  CHECK(all[6 * 16 + 8] == 7);  // (8, 6): last inside
  CHECK(all[7 * 16 + 8] == 0);
  CHECK(dev.depthBuffer()[4 * 16 + 3] == 0u);
  CHECK(dev.depthBuffer()[0] == kDepthMax);

  setCountingState(dev);
  drawTriangle(dev, {-4, -4, 0.5f}, {40, -4, 0.5f}, {-4, 40, 0.5f});  // covers everything
  const auto after = dev.readStencil({0, 0, 16, 16});
  CHECK(count(after, 8) == 18);
  CHECK(count(after, 0) == 256 - 18);

  // A read-back rectangle: rows from the bottom, clamped to the framebuffer.
  const auto part = dev.readStencil({2, 3, 5, 5});
  REQUIRE(part.size() == 6);
  CHECK(part == std::vector<std::uint8_t>{0, 0, 0, 0, 8, 8});
  CHECK(dev.readStencil({14, 14, 20, 20}).size() == 4);
  CHECK(dev.readStencil({5, 5, 5, 9}).empty());

  // The scissor is clamped to the framebuffer.
  dev.setScissor({-5, -5, 100, 3});
  CHECK(dev.scissor() == PixelRect{0, 0, 16, 3});
}

TEST_CASE("write masks apply to clears as in GL", "[state]") {
  CpuDevice dev(4, 4);
  dev.clearStencil(0xF0);
  dev.setStencilWriteMask(0x0F);
  dev.clearStencil(0xFF);
  CHECK(dev.stencilBuffer()[0] == 0xFF);
  dev.clearStencil(0x00);
  CHECK(dev.stencilBuffer()[0] == 0xF0);
  dev.setDepthWriteMask(false);
  dev.clearDepth(0.0);
  CHECK(dev.depthBuffer()[0] == kDepthMax);
  dev.setDepthWriteMask(true);
  dev.clearDepth(0.25);
  CHECK(dev.depthBuffer()[0] == quantizeDepth(0.25));
}

TEST_CASE("culling by the facing of the snapped triangle", "[state]") {
  const WindowVertex a{0, 0, 0.5f}, b{8, 0, 0.5f}, c{0, 8, 0.5f};
  for (const CullMode mode : {CullMode::None, CullMode::Front, CullMode::Back}) {
    CpuDevice dev(8, 8);
    setCountingState(dev);
    // Front faces add 1, back faces invert, so the stencil says which were drawn.
    dev.setStencilOps(Face::Front, {StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap});
    dev.setStencilOps(Face::Back, {StencilOp::Keep, StencilOp::Keep, StencilOp::Invert});
    dev.setCullMode(mode);
    drawTriangle(dev, a, b, c);  // counter-clockwise: front
    const std::uint8_t afterFront = dev.stencilBuffer()[0];
    drawTriangle(dev, a, c, b);  // clockwise: back
    const std::uint8_t afterBack = dev.stencilBuffer()[0];
    INFO("cull " << toString(mode));
    CHECK(afterFront == (mode == CullMode::Front ? 0 : 1));
    const std::uint8_t expectedBack =
        mode == CullMode::Back ? afterFront : static_cast<std::uint8_t>(~afterFront);
    CHECK(afterBack == expectedBack);
    CHECK(dev.counters().trianglesCulled == (mode == CullMode::None ? 0u : 1u));
  }
}

TEST_CASE("zero-area triangles draw nothing", "[state]") {
  CpuDevice dev(8, 8);
  setCountingState(dev);
  drawTriangle(dev, {1.5f, 1.5f, 0.5f}, {5.5f, 5.5f, 0.5f}, {3.5f, 3.5f, 0.5f});  // collinear
  drawTriangle(dev, {1.5f, 1.5f, 0.5f}, {1.5f, 1.5f, 0.5f}, {6.5f, 2.5f, 0.5f});  // repeated
  // Distinct floats that snap to the same 1/256 point are degenerate after snapping.
  drawTriangle(dev, {2.0f, 2.0f, 0.5f}, {2.001f, 2.0f, 0.5f}, {2.0f, 7.0f, 0.5f});
  CHECK(count(dev.readStencil({0, 0, 8, 8}), 0) == 64);
  CHECK(dev.counters().trianglesDegenerate == 3u);
}

TEST_CASE("bad input is rejected with a message and leaves the buffers alone", "[state]") {
  CHECK_THROWS_WITH(CpuDevice(0, 10), Catch::Contains("outside 1..16384"));
  CHECK_THROWS_WITH(CpuDevice(16385, 10), Catch::Contains("16385x10"));
  CHECK_THROWS_WITH(CpuDevice(10, -3), Catch::Contains("10x-3"));

  CpuDevice dev(8, 8);
  setCountingState(dev);
  const WindowVertex good{0, 0, 0.5f}, g2{8, 0, 0.5f}, g3{0, 8, 0.5f};
  const float nan = std::numeric_limits<float>::quiet_NaN();
  CHECK_THROWS_WITH(drawTriangle(dev, good, g2, {nan, 1, 0.5f}), Catch::Contains("not finite"));
  CHECK_THROWS_WITH(drawTriangle(dev, good, g2, {40000.0f, 1, 0.5f}),
                    Catch::Contains("beyond the +-32768"));
  CHECK_THROWS_WITH(drawTriangle(dev, good, g2, {1, 1, 1.5f}), Catch::Contains("outside [0, 1]"));
  const WindowVertex v[3] = {good, g2, g3};
  const std::uint32_t badIndex[3] = {0, 1, 3};
  CHECK_THROWS_WITH(dev.drawTriangles(v, badIndex), Catch::Contains("index 3 at position 2"));
  const std::uint32_t twoIndices[2] = {0, 1};
  CHECK_THROWS_WITH(dev.drawTriangles(v, twoIndices), Catch::Contains("not a multiple of 3"));
  // A draw whose last triangle is bad draws nothing at all.
  const WindowVertex v4[4] = {good, g2, g3, {nan, 0, 0}};
  const std::uint32_t mixed[6] = {0, 1, 2, 0, 1, 3};
  CHECK_THROWS(dev.drawTriangles(v4, mixed));
  CHECK(count(dev.readStencil({0, 0, 8, 8}), 0) == 64);
  CHECK_THROWS_WITH(dev.clearDepth(std::numeric_limits<double>::infinity()),
                    Catch::Contains("not finite"));
}

TEST_CASE("vertices are snapped to 1/256 pixel with round half to even", "[state]") {
  CHECK(snapToFixed(1.0f) == 256);
  CHECK(snapToFixed(1.0f / 512.0f) == 0);    // 0.5 sub-pixel step -> even (0)
  CHECK(snapToFixed(3.0f / 512.0f) == 2);    // 1.5 -> 2
  CHECK(snapToFixed(-3.0f / 512.0f) == -2);  // -1.5 -> -2
  CHECK(snapToFixed(5.0f / 512.0f) == 2);    // 2.5 -> 2
  CHECK(snapToFixed(-32768.0f) == -8388608);
  CHECK(snapToSubpixel(0.3) == 77.0f / 256.0f);  // 76.8 -> 77
}

// snapToFixed rounds with one conversion instruction where it can; it must give nearbyint's
// integer for every coordinate the device accepts, halves (round half to even) and negatives
// included.
TEST_CASE("snapToFixed is nearbyint of 256 x over the whole window range", "[state]") {
  const auto expected = [](float x) {
    return static_cast<std::int64_t>(std::nearbyint(static_cast<double>(x) * kSubpixelOne));
  };
  std::vector<float> values = {0.0f,
                               -0.0f,
                               kMaxWindowCoordinate,
                               -kMaxWindowCoordinate,
                               std::numeric_limits<float>::denorm_min(),
                               1e-30f,
                               -1e-30f};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> anywhere(-kMaxWindowCoordinate, kMaxWindowCoordinate);
  std::uniform_int_distribution<int> steps(-(1 << 22), 1 << 22);
  for (int i = 0; i < 200000; ++i) {
    values.push_back(anywhere(rng));
    // Half a sub-pixel step past a step, where round half to even decides.
    values.push_back((static_cast<float>(steps(rng)) + 0.5f) / 256.0f);
  }
  int differ = 0, halves = 0;
  for (const float x : values) {
    differ += snapToFixed(x) != expected(x);
    halves += std::fabs(std::fmod(static_cast<double>(x) * kSubpixelOne, 1.0)) == 0.5;
  }
  CHECK(differ == 0);
  CHECK(halves > 100000);  // the ties were really tested
}

TEST_CASE("an unknown state value is refused before any state changes", "[state]") {
  // RenderStateDevice's checks, which every device built on it shares.
  CpuDevice dev(8, 8);
  dev.setDepthFunc(CompareFunc::Greater);
  dev.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Incr, StencilOp::Invert});
  dev.setCullMode(CullMode::Back);
  const RenderState before = dev.state();
  const auto badFunc = static_cast<CompareFunc>(8);
  CHECK_THROWS_WITH(dev.setDepthFunc(badFunc), "setDepthFunc: unknown compare function 8");
  CHECK_THROWS_WITH(dev.setStencilFunc(badFunc, 1, 0xFF),
                    "setStencilFunc: unknown compare function 8");
  CHECK_THROWS_WITH(
      dev.setStencilOps(Face::Front, {StencilOp::Keep, static_cast<StencilOp>(8), StencilOp::Keep}),
      "setStencilOps: unknown stencil op 8");
  CHECK_THROWS_WITH(dev.setStencilOps(static_cast<Face>(3), {}), "setStencilOps: unknown face 3");
  CHECK_THROWS_WITH(dev.setCullMode(static_cast<CullMode>(3)), "setCullMode: unknown cull mode 3");
  const RenderState& after = dev.state();
  CHECK(after.depthFunc == before.depthFunc);
  CHECK(after.stencilFunc == before.stencilFunc);
  CHECK(after.stencilRef == before.stencilRef);
  CHECK(after.frontOps.depthFail == before.frontOps.depthFail);
  CHECK(after.backOps.depthPass == before.backOps.depthPass);
  CHECK(after.cull == before.cull);
}

TEST_CASE("a forwarding device hands every command on and draws blocks whole", "[state]") {
  // The same commands on a CpuDevice directly and through a ForwardingDevice, which owns one.
  CpuDevice direct(16, 16);
  ForwardingDevice forwarding(std::make_unique<CpuDevice>(16, 16));
  for (DepthStencilDevice* dev :
       {static_cast<DepthStencilDevice*>(&direct), static_cast<DepthStencilDevice*>(&forwarding)}) {
    dev->setScissor({1, 2, 14, 13});
    dev->clearStencil(3);
    dev->clearDepth(0.75);
    setCountingState(*dev);
    dev->setStencilWriteMask(0x7F);
    drawTriangle(*dev, {1, 1, 0.2f}, {15, 2, 0.2f}, {8, 15, 0.6f});
    dev->setCullMode(CullMode::Front);
    drawTriangle(*dev, {2, 14, 0.4f}, {14, 14, 0.4f}, {8, 1, 0.4f});
  }
  CHECK(forwarding.width() == 16);
  CHECK(forwarding.height() == 16);
  CHECK(forwarding.readStencil({0, 0, 16, 16}) == direct.readStencil({0, 0, 16, 16}));
  CHECK(forwarding.readDepth({0, 0, 16, 16}) == direct.readDepth({0, 0, 16, 16}));
  const auto& inner = dynamic_cast<const CpuDevice&>(forwarding.inner());
  CHECK(inner.state().stencilWriteMask == 0x7F);
  CHECK(inner.scissor().x0 == 1);
  CHECK_THROWS_AS(ForwardingDevice(std::unique_ptr<DepthStencilDevice>{}), std::invalid_argument);
}
