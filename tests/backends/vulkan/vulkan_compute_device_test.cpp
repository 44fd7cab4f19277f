// What is the compute device's own (backends::VulkanComputeDevice): the paths of its tile
// rasterizer that the conformance suite's small draws rarely reach (a block whose list is longer
// than the raster stage sorts at once, lists that overflow the bins and fall back to every
// triangle, a triangle over thousands of blocks), and its triangle lists kept on the device per
// content key and scissor. The contract itself is the conformance suite's
// (tests/backends/device_conformance_test.cpp). Runs on whatever Vulkan driver the loader finds
// (lavapipe here).

#include <catch2/catch.hpp>

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "recode/backends/vulkan_compute_device.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/triangle_source.hpp"

using namespace recode;
using backends::VulkanComputeDevice;
using raster::CompareFunc;
using raster::Face;
using raster::PixelRect;
using raster::StencilOp;
using raster::WindowVertex;

namespace {

struct Draw {
  std::vector<WindowVertex> vertices;
  std::vector<std::uint32_t> indices;
};

// `count` triangles of random depth planes, each with its corners at random sub-pixel positions
// in [x0, x1) x [y0, y1).
Draw randomTriangles(std::mt19937& rng, int count, float x0, float y0, float x1, float y1) {
  std::uniform_real_distribution<float> ux(x0, x1), uy(y0, y1), uz(0.0f, 1.0f);
  Draw d;
  for (int t = 0; t < 3 * count; ++t) {
    d.vertices.push_back(
        {raster::snapToSubpixel(ux(rng)), raster::snapToSubpixel(uy(rng)), uz(rng)});
    d.indices.push_back(static_cast<std::uint32_t>(t));
  }
  return d;
}

// The state under which every fragment's order shows: LEQUAL with depth writes, and a stencil
// that counts front fragments that pass and inverts on back ones that fail.
void countingState(raster::DepthStencilDevice& device) {
  device.setDepthFunc(CompareFunc::LEqual);
  device.setStencilFunc(CompareFunc::Always, 0, 0xFF);
  device.setStencilOps(Face::Front, {StencilOp::Keep, StencilOp::Invert, StencilOp::IncrWrap});
  device.setStencilOps(Face::Back, {StencilOp::Keep, StencilOp::Invert, StencilOp::DecrWrap});
}

void expectSameBuffers(const raster::DepthStencilDevice& device,
                       const raster::CpuDevice& reference) {
  const PixelRect all{0, 0, reference.width(), reference.height()};
  CHECK(device.readDepth(all) == reference.readDepth(all));
  CHECK(device.readStencil(all) == reference.readStencil(all));
}

// A block source with a content key whose trianglesMeeting lists everything (a valid narrowing),
// counting how often it is asked.
class KeyedSource final : public raster::TriangleSource {
 public:
  explicit KeyedSource(const Draw& draw) : draw_(draw), key_(raster::newTriangleSourceKey()) {}
  [[nodiscard]] raster::TriangleDraw allTriangles() const override {
    ++asked;
    return {draw_.vertices, draw_.indices};
  }
  [[nodiscard]] std::optional<raster::TriangleDraw> trianglesMeeting(
      const PixelRect&) const override {
    ++asked;
    return raster::TriangleDraw{draw_.vertices, draw_.indices};
  }
  [[nodiscard]] std::uint64_t contentKey() const override { return key_; }
  mutable int asked = 0;

 private:
  const Draw& draw_;
  std::uint64_t key_;
};

}  // namespace

TEST_CASE("a block's list longer than the raster stage sorts at once keeps index order",
          "[vulkan-compute]") {
  // 3,000 triangles inside one 8x8 block: the list is drawn in windows of 1,024 indices.
  std::mt19937 rng(48);
  const Draw d = randomTriangles(rng, 3000, 16.0f, 16.0f, 24.0f, 24.0f);
  VulkanComputeDevice device(40, 40);
  raster::CpuDevice reference(40, 40);
  countingState(device);
  countingState(reference);
  device.drawTriangles(d.vertices, d.indices);
  reference.drawTriangles(d.vertices, d.indices);
  expectSameBuffers(device, reference);
}

TEST_CASE("blocks whose lists overflow the bins are drawn from every triangle, in order",
          "[vulkan-compute]") {
  // 1,500 triangles over the whole 256 x 256 frame: about 1,500 x 1,024 entries, far more than
  // the lists hold (4 a triangle, 2 a block), so most blocks take the fallback.
  std::mt19937 rng(49);
  const Draw d = randomTriangles(rng, 1500, -300.0f, -300.0f, 560.0f, 560.0f);
  VulkanComputeDevice device(256, 256);
  raster::CpuDevice reference(256, 256);
  countingState(device);
  countingState(reference);
  device.drawTriangles(d.vertices, d.indices);
  reference.drawTriangles(d.vertices, d.indices);
  expectSameBuffers(device, reference);
}

TEST_CASE("a scissor off the block grid and triangles from the guard band", "[vulkan-compute]") {
  std::mt19937 rng(50);
  const Draw d = randomTriangles(rng, 400, -32768.0f, -32768.0f, 32768.0f, 32768.0f);
  VulkanComputeDevice device(77, 53);
  raster::CpuDevice reference(77, 53);
  for (raster::DepthStencilDevice* target :
       {static_cast<raster::DepthStencilDevice*>(&device),
        static_cast<raster::DepthStencilDevice*>(&reference)}) {
    countingState(*target);
    target->setScissor({3, 5, 70, 50});
    target->drawTriangles(d.vertices, d.indices);
  }
  expectSameBuffers(device, reference);
}

TEST_CASE("a block's triangles stay on the device for its key's later draws, and only for them",
          "[vulkan-compute]") {
  std::mt19937 rng(51);
  const Draw first = randomTriangles(rng, 200, 0.0f, 0.0f, 64.0f, 64.0f);
  const Draw second = randomTriangles(rng, 200, 0.0f, 0.0f, 64.0f, 64.0f);
  VulkanComputeDevice device(64, 64);
  raster::CpuDevice reference(64, 64);
  KeyedSource a(first);
  KeyedSource b(second);
  countingState(device);
  countingState(reference);
  device.setScissor({0, 0, 48, 48});
  reference.setScissor({0, 0, 48, 48});
  device.drawMesh(a);
  reference.drawMesh(a);
  const int askedOnce = a.asked;
  // The same key under a scissor inside the first: drawn from the list on the device.
  device.setScissor({8, 8, 40, 40});
  reference.setScissor({8, 8, 40, 40});
  device.setCullMode(raster::CullMode::Back);
  reference.setCullMode(raster::CullMode::Back);
  device.drawMesh(a);
  reference.drawMesh(a);
  CHECK(a.asked == askedOnce);
  CHECK(device.meshCounters().uploads == 1);
  CHECK(device.meshCounters().reuses == 1);
  // Another key is another block: its own triangles, uploaded.
  device.drawMesh(b);
  reference.drawMesh(b);
  CHECK(device.meshCounters().uploads == 2);
  // A scissor the kept list does not cover: asked again.
  device.setScissor({0, 0, 64, 64});
  reference.setScissor({0, 0, 64, 64});
  device.setCullMode(raster::CullMode::None);
  reference.setCullMode(raster::CullMode::None);
  device.drawMesh(a);
  reference.drawMesh(a);
  CHECK(device.meshCounters().uploads == 3);
  expectSameBuffers(device, reference);
}

TEST_CASE("a draw of one triangle over thousands of blocks, then a read of a corner",
          "[vulkan-compute]") {
  VulkanComputeDevice device(1000, 700);
  raster::CpuDevice reference(1000, 700);
  const WindowVertex big[3] = {
      {-20000.0f, -100.0f, 0.0f}, {3000.0f, -50.0f, 1.0f}, {500.0f, 9000.0f, 0.5f}};
  const std::uint32_t indices[3] = {0, 1, 2};
  countingState(device);
  countingState(reference);
  device.drawTriangles(big, indices);
  reference.drawTriangles(big, indices);
  const PixelRect corner{990, 690, 1000, 700};
  CHECK(device.readDepth(corner) == reference.readDepth(corner));
  CHECK(device.readStencil(corner) == reference.readStencil(corner));
  expectSameBuffers(device, reference);
}
