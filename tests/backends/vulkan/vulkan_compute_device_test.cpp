// What is the compute device's own (backends::VulkanComputeDevice): the paths of its tile
// rasterizer that the conformance suite's small draws rarely reach (a block whose list holds
// thousands of triangles, lists that overflow the bins and fall back to every triangle, a
// triangle over thousands of blocks), its triangle lists kept on the device per content key and
// scissor, and each stage's output against the reference's own. The contract itself is the
// conformance suite's (tests/backends/device_conformance_test.cpp). Runs on whatever Vulkan driver
// the loader finds (lavapipe here).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <random>
#include <vector>

#include "compute_device_test_support.hpp"
#include "recode/backends/vulkan_compute_device.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/triangle_setup.hpp"
#include "recode/raster/triangle_source.hpp"

using namespace recode;
using backends::VulkanComputeDevice;
using raster::CompareFunc;
using raster::Face;
using raster::PixelRect;
using raster::StencilOp;
using raster::WindowVertex;
using test::countingState;
using test::expectSameBuffers;

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

// `d` drawn in countingState (under `scissor` when there is one) on the compute device and on the
// CPU device, which must then hold the same buffers.
void expectSameDraw(const Draw& d, int width, int height,
                    std::optional<PixelRect> scissor = std::nullopt) {
  VulkanComputeDevice device(width, height);
  raster::CpuDevice reference(width, height);
  for (raster::DepthStencilDevice* target :
       {static_cast<raster::DepthStencilDevice*>(&device),
        static_cast<raster::DepthStencilDevice*>(&reference)}) {
    countingState(*target);
    if (scissor)
      target->setScissor(*scissor);
    target->drawTriangles(d.vertices, d.indices);
  }
  expectSameBuffers(device, reference);
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

TEST_CASE("a block's list of thousands of triangles is drawn in index order", "[vulkan-compute]") {
  // 3,000 triangles inside one 8x8 block: the sort stage's heap holds all of them.
  std::mt19937 rng(48);
  expectSameDraw(randomTriangles(rng, 3000, 16.0f, 16.0f, 24.0f, 24.0f), 40, 40);
}

TEST_CASE("blocks whose lists overflow the bins are drawn from every triangle, in order",
          "[vulkan-compute]") {
  // 1,500 triangles over the whole 256 x 256 frame: about 1,500 x 1,024 entries, far more than
  // the lists hold (4 a triangle, 2 a block), so most blocks take the fallback.
  std::mt19937 rng(49);
  expectSameDraw(randomTriangles(rng, 1500, -300.0f, -300.0f, 560.0f, 560.0f), 256, 256);
}

TEST_CASE(
    "a block's list of more entries than a CPU driver's loop limit is drawn in full, in order",
    "[vulkan-compute]") {
  // 70,000 slivers over one 8x8 block: more list entries than llvmpipe lets one invocation loop
  // over (65,535 iterations), so the sort and the raster stage each take several rounds there.
  std::mt19937 rng(52);
  Draw slivers;
  std::uniform_real_distribution<float> ux(16.0f, 24.0f), uz(0.0f, 1.0f);
  for (std::uint32_t t = 0; t < 70000; ++t) {
    const float x = ux(rng);
    const float z = uz(rng);
    // A sliver a tenth of a pixel wide from the block's bottom to its top, at a slant.
    slivers.vertices.push_back({raster::snapToSubpixel(x), 15.5f, z});
    slivers.vertices.push_back({raster::snapToSubpixel(x + 0.1f), 15.5f, uz(rng)});
    slivers.vertices.push_back({raster::snapToSubpixel(x + 0.05f), 24.5f, z});
    for (std::uint32_t k = 0; k < 3; ++k)
      slivers.indices.push_back(3 * t + k);
  }
  expectSameDraw(slivers, 40, 40);
}

TEST_CASE("overflowing lists whose fallback draws more triangles than a CPU driver's loop limit",
          "[vulkan-compute]") {
  // 8,000 triangles each over the whole 64 x 64 frame, of either facing: their 512,000 entries
  // pass the lists' capacity, so every block draws all 8,000 on all eight rows (72,000 loop
  // iterations), past what one invocation may loop over on llvmpipe: the raster stage takes
  // rounds there.
  std::mt19937 rng(53);
  std::uniform_real_distribution<float> jitter(-500.0f, 500.0f), uz(0.0f, 1.0f);
  Draw big;
  for (std::uint32_t t = 0; t < 8000; ++t) {
    const WindowVertex corners[3] = {
        {raster::snapToSubpixel(-1000.0f + jitter(rng)), -1000.0f, uz(rng)},
        {raster::snapToSubpixel(3000.0f + jitter(rng)), -1000.0f, uz(rng)},
        {-1000.0f, raster::snapToSubpixel(3000.0f + jitter(rng)), uz(rng)}};
    for (const WindowVertex& v : corners)
      big.vertices.push_back(v);
    const bool back = (t % 3) == 0;
    big.indices.insert(big.indices.end(),
                       {3 * t, back ? 3 * t + 2 : 3 * t + 1, back ? 3 * t + 1 : 3 * t + 2});
  }
  expectSameDraw(big, 64, 64);
}

TEST_CASE("a scissor off the block grid and triangles from the guard band", "[vulkan-compute]") {
  std::mt19937 rng(50);
  expectSameDraw(randomTriangles(rng, 400, -32768.0f, -32768.0f, 32768.0f, 32768.0f), 77, 53,
                 PixelRect{3, 5, 70, 50});
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

namespace {

std::uint64_t bitsOf(double d) {
  std::uint64_t b = 0;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

}  // namespace

TEST_CASE(
    "each stage's output is the reference's own: the set-up, and lists in index order "
    "that hold every triangle covering a centre of their block",
    "[vulkan-compute]") {
  std::mt19937 rng(52);
  Draw d = randomTriangles(rng, 300, -20.0f, -20.0f, 120.0f, 90.0f);
  // A few zero-area triangles: a repeated vertex, and three on a line.
  d.vertices[4] = d.vertices[3];
  d.vertices[8] = {0.5f * (d.vertices[6].x + d.vertices[7].x),
                   0.5f * (d.vertices[6].y + d.vertices[7].y), 0.5f};
  d.vertices[8].x = raster::snapToSubpixel(d.vertices[8].x);
  d.vertices[8].y = raster::snapToSubpixel(d.vertices[8].y);
  VulkanComputeDevice device(100, 80);
  const PixelRect scissor{3, 5, 97, 70};
  device.setScissor(scissor);
  device.setCullMode(raster::CullMode::Back);
  device.keepDrawStages();
  device.drawTriangles(d.vertices, d.indices);
  const VulkanComputeDevice::DrawStages stages = device.lastDrawStages();
  REQUIRE(stages.triangles.size() == 300);
  // Set-up: raster::setupTriangle's snapped vertices, facing, bounds and depth plane, culled
  // and clipped to the scissor as the reference's pipeline does.
  std::vector<std::optional<raster::TriangleSetup>> reference;
  int drawn = 0;
  for (std::size_t t = 0; t < 300; ++t) {
    INFO("triangle " << t);
    const raster::FixedVertex v[3] = {raster::snapVertex(d.vertices[3 * t]),
                                      raster::snapVertex(d.vertices[3 * t + 1]),
                                      raster::snapVertex(d.vertices[3 * t + 2])};
    std::optional<raster::TriangleSetup> setup = raster::setupTriangle(v[0], v[1], v[2]);
    const VulkanComputeDevice::SetUpTriangle& got = stages.triangles[t];
    if (setup && !setup->frontFacing)
      setup.reset();  // culled
    const PixelRect candidates = setup ? setup->bounds.intersect(scissor) : PixelRect{};
    if (candidates.empty()) {
      CHECK(got.candidates.empty());
      reference.push_back(std::nullopt);
      continue;
    }
    ++drawn;
    CHECK(got.candidates == candidates);
    for (int k = 0; k < 3; ++k) {
      CHECK(got.fixed[2 * k] == v[k].x);
      CHECK(got.fixed[2 * k + 1] == v[k].y);
    }
    CHECK(got.frontFacing == setup->frontFacing);
    CHECK(static_cast<double>(got.z0) == setup->depth.z0);
    CHECK(bitsOf(got.dzdx) == bitsOf(setup->depth.dzdx));
    CHECK(bitsOf(got.dzdy) == bitsOf(setup->depth.dzdy));
    reference.push_back(setup);
  }
  CHECK(drawn > 50);
  // Binning: every list in strictly increasing index order, each entry's candidates meeting the
  // block, and every triangle that covers a centre of the block inside the scissor listed.
  REQUIRE(stages.blockLists.size() ==
          static_cast<std::size_t>(stages.gridWidth) * static_cast<std::size_t>(stages.gridHeight));
  long long listed = 0;
  for (int by = 0; by < stages.gridHeight; ++by) {
    for (int bx = 0; bx < stages.gridWidth; ++bx) {
      const std::size_t b = static_cast<std::size_t>(by * stages.gridWidth + bx);
      INFO("block " << bx << ", " << by);
      REQUIRE_FALSE(stages.overflowed[b]);
      const std::vector<std::uint32_t>& list = stages.blockLists[b];
      CHECK(std::adjacent_find(list.begin(), list.end(), std::greater_equal<>()) == list.end());
      const PixelRect block = PixelRect{stages.gridX0 + 8 * bx, stages.gridY0 + 8 * by, 0, 0};
      const PixelRect area =
          PixelRect{block.x0, block.y0, block.x0 + 8, block.y0 + 8}.intersect(scissor);
      for (std::size_t t = 0; t < 300; ++t) {
        const bool inList = std::find(list.begin(), list.end(), t) != list.end();
        if (inList)
          CHECK_FALSE(stages.triangles[t].candidates.intersect(area).empty());
        bool covers = false;
        for (int y = area.y0; reference[t] && y < area.y1; ++y)
          for (int x = area.x0; x < area.x1; ++x) {
            const std::int64_t cx = 256 * std::int64_t{x} + 128;
            const std::int64_t cy = 256 * std::int64_t{y} + 128;
            covers = covers ||
                     std::all_of(reference[t]->edges.begin(), reference[t]->edges.end(),
                                 [&](const raster::EdgeFunction& e) { return e.at(cx, cy) >= 0; });
          }
        if (covers) {
          INFO("triangle " << t);
          CHECK(inList);
        }
      }
      listed += static_cast<long long>(list.size());
    }
  }
  CHECK(listed > 300);
}
