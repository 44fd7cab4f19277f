// What is the Vulkan device's own: the y flip and the facing (GL's bottom-left origin and winding
// on Vulkan's top-left framebuffer), and devices of both shader arithmetics in one process. The
// contract itself (golden vectors, random streams, the pair suite, clears, devices that keep their
// own state, errors) is the conformance suite's (tests/backends/device_conformance_test.cpp). Runs
// on whatever Vulkan driver the loader finds (lavapipe here); without one the device throws and
// these tests fail, as they should.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "exact_test_streams.hpp"
#include "recode/backends/vulkan_device.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/golden.hpp"
#include "recode/verify/exact_parity.hpp"
#include "recode/verify/pair_suite.hpp"

using namespace recode;
using backends::VulkanDevice;
using raster::CompareFunc;
using raster::Face;
using raster::StencilOp;
using raster::WindowVertex;
using verify::testing::describe;

TEST_CASE("the Vulkan device keeps GL's bottom-left origin and winding", "[vulkan]") {
  // A triangle in the bottom-left corner only, front-facing (counter-clockwise in GL window
  // coordinates): its pixels are in the first rows read back, and it takes the front ops.
  backends::VulkanDevice device(8, 6);
  device.setStencilFunc(CompareFunc::Always, 0, 0xFF);
  device.setStencilOps(Face::Front, {StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap});
  device.setStencilOps(Face::Back, {StencilOp::Keep, StencilOp::Keep, StencilOp::Invert});
  const WindowVertex ccw[3] = {{0, 0, 0.25f}, {3, 0, 0.25f}, {0, 3, 0.25f}};
  const WindowVertex cw[3] = {{8, 6, 0.75f}, {8, 3, 0.75f}, {5, 6, 0.75f}};
  const std::uint32_t indices[3] = {0, 1, 2};
  device.drawTriangles(ccw, indices);
  device.drawTriangles(cw, indices);
  raster::CpuDevice reference(8, 6);
  reference.setStencilFunc(CompareFunc::Always, 0, 0xFF);
  reference.setStencilOps(Face::Front, {StencilOp::Keep, StencilOp::Keep, StencilOp::IncrWrap});
  reference.setStencilOps(Face::Back, {StencilOp::Keep, StencilOp::Keep, StencilOp::Invert});
  reference.drawTriangles(ccw, indices);
  reference.drawTriangles(cw, indices);
  const raster::PixelRect all{0, 0, 8, 6};
  const auto stencil = device.readStencil(all);
  CHECK(stencil == reference.readStencil(all));
  CHECK(device.readDepth(all) == reference.readDepth(all));
  CHECK(stencil[0] == 1);            // pixel (0, 0): bottom-left, front-facing
  CHECK(stencil[6 * 8 - 1] == 255);  // pixel (7, 5): top-right, back-facing, inverted
  // A read-back of a sub-rectangle starts at its bottom row too.
  CHECK(device.readStencil({0, 0, 2, 1}) == std::vector<std::uint8_t>{1, 1});
}

TEST_CASE("a 64-bit and a 32-bit Vulkan device in one process keep their own commands",
          "[vulkan][vulkan-32]") {
  // Each arithmetic has its own logical device and recording: a 64-bit device's commands still
  // pending while a 32-bit device records and runs its own must neither be lost nor run on the
  // other's pipeline.
  for (const auto& path : verify::testing::goldenFiles()) {
    INFO(path.filename().string());
    const raster::CommandFile file = raster::readCommandFile(path.string());
    REQUIRE(file.hasExpected);
    const raster::GoldenVector& g = file.content;
    VulkanDevice native(g.stream.width, g.stream.height);
    VulkanDevice emulated(g.stream.width, g.stream.height, backends::ShaderArithmetic::Emulated32);
    CHECK(native.arithmetic() == backends::ShaderArithmetic::Native64);
    CHECK(emulated.arithmetic() == backends::ShaderArithmetic::Emulated32);
    raster::replay(g.stream.commands, native);  // recorded, not run
    raster::replay(g.stream.commands, emulated);
    const raster::PixelRect all{0, 0, g.stream.width, g.stream.height};
    CHECK(emulated.readDepth(all) == g.depth);
    CHECK(emulated.readStencil(all) == g.stencil);
    CHECK(native.readDepth(all) == g.depth);
    CHECK(native.readStencil(all) == g.stencil);
  }
}
