// The exact Vulkan device against the reference, with no tolerance: the golden vectors, random
// streams compared after every command, the generated pair suite, the y flip and the facing
// (GL's bottom-left origin and winding on Vulkan's top-left framebuffer), masked clears, and the
// errors. Runs on whatever Vulkan driver the loader finds (lavapipe here); without one the
// device throws and these tests fail, as they should.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "exact_test_streams.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/golden.hpp"
#include "recode/verify/exact_parity.hpp"
#include "recode/verify/pair_suite.hpp"
#include "recode/verify/vulkan_device.hpp"

using namespace recode;
using raster::CompareFunc;
using raster::Face;
using raster::StencilOp;
using raster::WindowVertex;
using verify::VulkanDevice;
using verify::testing::describe;

TEST_CASE("every golden vector replays bit for bit on the Vulkan device", "[vulkan][golden]") {
  const auto files = verify::testing::goldenFiles();
  REQUIRE(files.size() >= 7);
  for (const auto& path : files) {
    INFO(path.filename().string());
    const raster::CommandFile file = raster::readCommandFile(path.string());
    REQUIRE(file.hasExpected);
    const raster::GoldenVector& g = file.content;
    VulkanDevice device(g.stream.width, g.stream.height);
    raster::replay(g.stream.commands, device);
    const raster::PixelRect all{0, 0, g.stream.width, g.stream.height};
    CHECK(device.readDepth(all) == g.depth);
    CHECK(device.readStencil(all) == g.stencil);
  }
}

TEST_CASE("random sloped streams agree with the CPU device after every command on Vulkan",
          "[vulkan][random]") {
  std::mt19937 rng(20261124);
  verify::ExactParityCounts total;
  for (int s = 0; s < 60; ++s) {
    const int width = 8 + static_cast<int>(rng() % 90);
    const int height = 8 + static_cast<int>(rng() % 70);
    const raster::CommandStream stream = verify::testing::randomStream(rng, width, height);
    raster::CpuDevice reference(width, height);
    VulkanDevice candidate(width, height);
    const auto report = verify::compareStreamExactly(stream, reference, candidate);
    INFO("stream " << s << ": " << describe(report));
    CHECK(report.ok());
    total += report.counts;
  }
  CHECK(total.pixels > 1000000);
  CHECK(total.identical == total.pixels);
}

TEST_CASE("the generated pair suite is bit-identical on the Vulkan device", "[vulkan][suite]") {
  const auto suite = verify::generatePairSuite();
  REQUIRE(suite.size() == 504);
  verify::ExactParityCounts total;
  int compared = 0;
  for (const verify::SuitePair& pair : suite) {
    core::PairRequest request;
    request.frame = pair.frame;
    const auto report = verify::compareOnVulkan(pair.a, pair.b, request);
    INFO(pair.label << ": " << describe(report));
    CHECK(report.ok());
    total += report.counts;
    compared += report.counts.pixels > 0;
  }
  CHECK(compared > 250);
  CHECK(total.different == 0);
}

TEST_CASE("the Vulkan device keeps GL's bottom-left origin and winding", "[vulkan]") {
  // A triangle in the bottom-left corner only, front-facing (counter-clockwise in GL window
  // coordinates): its pixels are in the first rows read back, and it takes the front ops.
  VulkanDevice device(8, 6);
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

TEST_CASE("Vulkan clears honour the scissor and both write masks", "[vulkan]") {
  VulkanDevice device(5, 4);
  raster::CpuDevice reference(5, 4);
  for (raster::DepthStencilDevice* d : {static_cast<raster::DepthStencilDevice*>(&device),
                                        static_cast<raster::DepthStencilDevice*>(&reference)}) {
    d->clearStencil(0xF0);
    d->setScissor({1, 1, 4, 3});
    d->setStencilWriteMask(0x3C);
    d->clearStencil(0x0F);  // (0x0F & 0x3C) | (0xF0 & ~0x3C) = 0xCC inside the scissor
    d->clearDepth(0.5);
    d->setDepthWriteMask(false);
    d->clearDepth(0.0);  // no effect: depth writes are off
    d->setStencilWriteMask(0);
    d->clearStencil(0x00);  // no effect: nothing writable
  }
  const raster::PixelRect all{0, 0, 5, 4};
  const auto stencil = device.readStencil(all);
  CHECK(stencil == reference.readStencil(all));
  CHECK(device.readDepth(all) == reference.readDepth(all));
  CHECK(stencil[1 * 5 + 1] == 0xCC);
  CHECK(stencil[0] == 0xF0);
}

TEST_CASE("Vulkan devices do not share state", "[vulkan]") {
  VulkanDevice a(6, 4);
  VulkanDevice b(5, 7);
  a.setStencilFunc(CompareFunc::Always, 9, 0xFF);
  a.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Replace});
  a.setScissor({0, 0, 2, 2});
  b.setDepthFunc(CompareFunc::Never);
  b.setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::IncrWrap, StencilOp::Keep});
  const WindowVertex quad[4] = {{-1, -1, 0.5f}, {9, -1, 0.5f}, {9, 9, 0.5f}, {-1, 9, 0.5f}};
  const std::uint32_t indices[6] = {0, 1, 2, 0, 2, 3};
  a.drawTriangles(quad, indices);
  b.drawTriangles(quad, indices);
  a.drawTriangles(quad, indices);
  const auto stencilA = a.readStencil({0, 0, 6, 4});
  const auto stencilB = b.readStencil({0, 0, 5, 7});
  CHECK(std::count(stencilA.begin(), stencilA.end(), 9) == 4);  // its scissor, its ref
  CHECK(std::count(stencilA.begin(), stencilA.end(), 0) == 20);
  CHECK(std::all_of(stencilB.begin(), stencilB.end(), [](auto s) { return s == 1; }));
  const auto depthB = b.readDepth({0, 0, 5, 7});
  CHECK(std::all_of(depthB.begin(), depthB.end(), [](auto d) { return d == 16777215u; }));
}

TEST_CASE("the Vulkan device rejects what the CPU device rejects", "[vulkan][errors]") {
  CHECK_THROWS_AS(VulkanDevice(0, 4), std::invalid_argument);
  CHECK_THROWS_AS(VulkanDevice(16385, 4), std::invalid_argument);
  VulkanDevice device(4, 4);
  const WindowVertex v[3] = {{0, 0, 0.5f}, {4, 0, 1.5f}, {0, 4, 0.5f}};
  const std::uint32_t bad[3] = {0, 1, 3};
  const std::uint32_t good[3] = {0, 1, 2};
  const std::uint32_t partial[2] = {0, 1};
  CHECK_THROWS_AS(device.drawTriangles(v, bad), std::invalid_argument);
  CHECK_THROWS_AS(device.drawTriangles(v, good), std::invalid_argument);  // z = 1.5
  CHECK_THROWS_AS(device.drawTriangles(v, partial), std::invalid_argument);
  CHECK_THROWS_AS(device.clearDepth(std::nan("")), std::invalid_argument);
  const auto depth = device.readDepth({0, 0, 4, 4});
  CHECK(std::all_of(depth.begin(), depth.end(), [](auto d) { return d == 16777215u; }));
  CHECK(device.readStencil({5, 5, 9, 9}).empty());  // outside the framebuffer: nothing
}
