// Replayed draws (draw_recording.hpp): a CpuDevice that records a source's first draw and
// replays it for later ones must leave both buffers exactly as a device that draws every time
// afresh, whatever state, cull mode and scissor the later draws use, including scissors the
// recording does not serve and more sources than the device keeps.

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include "recode/raster/cpu_device.hpp"
#include "recode/raster/draw_recording.hpp"
#include "recode/raster/fixed_point.hpp"
#include "recode/raster/triangle_source.hpp"

namespace {

using namespace recode::raster;

// A fixed set of triangles, with a content key (the replaying device's) or without (0: the
// fresh device's, which then draws every time).
class FixedSource final : public TriangleSource {
 public:
  FixedSource(std::vector<WindowVertex> vertices, std::vector<std::uint32_t> indices, bool keyed)
      : vertices_(std::move(vertices)),
        indices_(std::move(indices)),
        key_(keyed ? newTriangleSourceKey() : 0) {}
  [[nodiscard]] TriangleDraw allTriangles() const override { return {vertices_, indices_}; }
  [[nodiscard]] std::uint64_t contentKey() const override { return key_; }

 private:
  std::vector<WindowVertex> vertices_;
  std::vector<std::uint32_t> indices_;
  std::uint64_t key_;
};

struct Mesh {
  std::vector<WindowVertex> vertices;
  std::vector<std::uint32_t> indices;
};

// Triangles of every size over a w x h frame and a little beyond it, some of zero area.
Mesh randomMesh(std::mt19937_64& rng, int w, int h) {
  std::uniform_int_distribution<int> count(1, 40), kind(0, 9);
  std::uniform_real_distribution<double> x(-10.0, w + 10.0), y(-10.0, h + 10.0), unit(0.0, 1.0);
  std::normal_distribution<double> offset(0.0, 6.0);
  Mesh m;
  const int n = count(rng);
  for (int t = 0; t < n; ++t) {
    const double cx = x(rng), cy = y(rng);
    const double spread = kind(rng) == 0 ? 8.0 : 1.0;  // some large triangles
    for (int k = 0; k < 3; ++k) {
      m.vertices.push_back({snapToSubpixel(cx + spread * offset(rng)),
                            snapToSubpixel(cy + spread * offset(rng)),
                            static_cast<float>(unit(rng))});
      m.indices.push_back(static_cast<std::uint32_t>(m.indices.size()));
    }
    if (kind(rng) == 1)  // zero area: the last corner on the first
      m.vertices.back() = m.vertices[m.vertices.size() - 3];
  }
  return m;
}

// A random rectangle inside `outer` (possibly empty).
PixelRect rectInside(std::mt19937_64& rng, const PixelRect& outer) {
  if (outer.empty())
    return outer;
  std::uniform_int_distribution<int> px(outer.x0, outer.x1), py(outer.y0, outer.y1);
  int x0 = px(rng), x1 = px(rng), y0 = py(rng), y1 = py(rng);
  if (x0 > x1)
    std::swap(x0, x1);
  if (y0 > y1)
    std::swap(y0, y1);
  return {x0, y0, x1, y1};
}

// Anywhere in the w x h framebuffer.
PixelRect randomRect(std::mt19937_64& rng, int w, int h) {
  return rectInside(rng, {0, 0, w, h});
}

// The same random state on both devices.
void setRandomState(std::mt19937_64& rng, CpuDevice& a, CpuDevice& b) {
  std::uniform_int_distribution<int> func(0, 7), op(0, 7), byte(0, 255), coin(0, 1), cull(0, 3);
  const auto depthFunc = static_cast<CompareFunc>(func(rng));
  const bool depthWrite = coin(rng) == 1;
  const auto stencilFunc = static_cast<CompareFunc>(func(rng));
  const auto ref = static_cast<std::uint8_t>(byte(rng));
  const auto valueMask = static_cast<std::uint8_t>(coin(rng) ? 0xFF : byte(rng));
  const auto writeMask = static_cast<std::uint8_t>(coin(rng) ? 0xFF : byte(rng));
  const StencilOps front{static_cast<StencilOp>(op(rng)), static_cast<StencilOp>(op(rng)),
                         static_cast<StencilOp>(op(rng))};
  const StencilOps back{static_cast<StencilOp>(op(rng)), static_cast<StencilOp>(op(rng)),
                        static_cast<StencilOp>(op(rng))};
  // Half the draws cull nothing, so that recordings are made.
  const int c = cull(rng);
  const CullMode mode = c == 1 ? CullMode::Front : c == 2 ? CullMode::Back : CullMode::None;
  for (CpuDevice* d : {&a, &b}) {
    d->setDepthFunc(depthFunc);
    d->setDepthWriteMask(depthWrite);
    d->setStencilFunc(stencilFunc, ref, valueMask);
    d->setStencilWriteMask(writeMask);
    d->setStencilOps(Face::Front, front);
    d->setStencilOps(Face::Back, back);
    d->setCullMode(mode);
  }
}

}  // namespace

TEST_CASE("replayed draws write what fresh draws write", "[raster][replay]") {
  std::mt19937_64 rng(20261124);
  std::uniform_int_distribution<int> size(9, 140), pick(0, 2), action(0, 9);
  std::uniform_real_distribution<double> depth(0.0, 1.0);
  std::uint64_t replayedDraws = 0, draws = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int w = size(rng), h = size(rng);
    CpuDevice replaying(w, h), fresh(w, h);
    // Three sources: one more than the device keeps, so recordings are also evicted.
    std::vector<FixedSource> keyed, unkeyed;
    for (int s = 0; s < 3; ++s) {
      const Mesh m = randomMesh(rng, w, h);
      keyed.emplace_back(m.vertices, m.indices, true);
      unkeyed.emplace_back(m.vertices, m.indices, false);
    }
    PixelRect scissor = randomRect(rng, w, h);
    for (int step = 0; step < 12; ++step) {
      const int a = action(rng);
      if (a == 0) {  // clears under a new scissor
        scissor = randomRect(rng, w, h);
        const double d = depth(rng);
        const auto s = static_cast<std::uint8_t>(pick(rng) * 100);
        for (CpuDevice* dev : {&replaying, &fresh}) {
          dev->setScissor(scissor);
          dev->clearDepth(d);
          dev->clearStencil(s);
        }
        continue;
      }
      // Mostly a rectangle inside the last one (what a replay serves, when the last one was
      // recorded), sometimes any.
      scissor = a < 8 ? rectInside(rng, scissor) : randomRect(rng, w, h);
      if (a == 9)
        scissor = {0, 0, w, h};
      replaying.setScissor(scissor);
      fresh.setScissor(scissor);
      setRandomState(rng, replaying, fresh);
      const int s = pick(rng);
      const std::uint64_t replayedBefore = replaying.counters().trianglesReplayed;
      replaying.drawMesh(keyed[static_cast<std::size_t>(s)]);
      replayedDraws += replaying.counters().trianglesReplayed > replayedBefore;
      fresh.drawMesh(unkeyed[static_cast<std::size_t>(s)]);
      ++draws;
      INFO("trial " << trial << ", step " << step << ", source " << s);
      REQUIRE(std::vector<std::uint32_t>(replaying.depthBuffer().begin(),
                                         replaying.depthBuffer().end()) ==
              std::vector<std::uint32_t>(fresh.depthBuffer().begin(), fresh.depthBuffer().end()));
      REQUIRE(
          std::vector<std::uint8_t>(replaying.stencilBuffer().begin(),
                                    replaying.stencilBuffer().end()) ==
          std::vector<std::uint8_t>(fresh.stencilBuffer().begin(), fresh.stencilBuffer().end()));
    }
    REQUIRE(replaying.counters().fragments == fresh.counters().fragments);
    REQUIRE(fresh.counters().trianglesReplayed == 0);
  }
  // The replays were exercised, not only fresh draws.
  INFO(replayedDraws << " of " << draws << " draws replayed");
  CHECK(replayedDraws > draws / 10);
}

TEST_CASE("a recording serves its own source under a scissor inside its own", "[raster][replay]") {
  DrawRecording recording;
  CHECK_FALSE(recording.serves(7, {0, 0, 8, 8}));  // nothing recorded
  recording.start(7, {10, 10, 50, 40});
  CHECK_FALSE(recording.serves(7, {10, 10, 50, 40}));  // not finished
  recording.finish();
  CHECK(recording.serves(7, {10, 10, 50, 40}));
  CHECK(recording.serves(7, {20, 15, 30, 40}));
  CHECK(recording.serves(7, {60, 60, 60, 60}));  // empty: draws nothing anyway
  CHECK_FALSE(recording.serves(8, {20, 15, 30, 40}));
  CHECK_FALSE(recording.serves(0, {20, 15, 30, 40}));
  CHECK_FALSE(recording.serves(7, {9, 10, 50, 40}));
  CHECK_FALSE(recording.serves(7, {10, 10, 50, 41}));
  recording.clear();
  CHECK_FALSE(recording.serves(7, {20, 15, 30, 40}));
}

TEST_CASE("a draw that covers more blocks than a recording keeps is not replayed",
          "[raster][replay]") {
  DrawRecording recording;
  recording.start(3, {0, 0, 64, 64});
  TriangleSetup triangle;
  recording.addTriangle(triangle);
  for (std::size_t k = 0; k <= DrawRecording::kMaxBlocks; ++k)
    recording.addBlock(0, 0, 1);
  recording.finish();
  CHECK_FALSE(recording.serves(3, {0, 0, 64, 64}));
  CHECK(recording.blocks().size() <= DrawRecording::kMaxBlocks);
}

TEST_CASE("a recording started again after it overflowed records and serves again",
          "[raster][replay]") {
  // start() forgets the previous recording, its overflow included: a slot that once held a
  // draw too large to keep is reused for the next source, which must be kept.
  DrawRecording recording;
  recording.start(3, {0, 0, 64, 64});
  TriangleSetup triangle;
  recording.addTriangle(triangle);
  for (std::size_t k = 0; k <= DrawRecording::kMaxBlocks; ++k)
    recording.addBlock(0, 0, 1);
  recording.finish();
  REQUIRE_FALSE(recording.serves(3, {0, 0, 64, 64}));
  recording.start(4, {0, 0, 64, 64});
  recording.addTriangle(triangle);
  recording.addBlock(8, 16, 0x5);
  recording.finish();
  REQUIRE(recording.blocks().size() == 1);
  CHECK(recording.blocks()[0].x == 8);
  CHECK(recording.blocks()[0].y == 16);
  CHECK(recording.blocks()[0].mask == 0x5);
  CHECK(recording.serves(4, {0, 0, 64, 64}));
}

TEST_CASE("a recording keeps only the triangles that covered a pixel", "[raster][replay]") {
  DrawRecording recording;
  recording.start(5, {0, 0, 64, 64});
  TriangleSetup triangle;
  const auto add = [&](double z0, int blocks) {
    triangle.depth.z0 = z0;
    recording.addTriangle(triangle);
    for (int k = 0; k < blocks; ++k)
      recording.addBlock(8 * k, 0, 1);
  };
  add(0.1, 0);  // covers nothing, first
  add(0.2, 2);
  add(0.3, 0);  // between two that cover pixels
  add(0.4, 0);
  add(0.5, 1);
  add(0.6, 0);  // last
  recording.finish();
  REQUIRE(recording.triangles().size() == 2);
  CHECK(recording.triangles()[0].plane.z0 == 0.2);
  CHECK(recording.triangles()[0].firstBlock == 0);
  CHECK(recording.triangles()[1].plane.z0 == 0.5);
  CHECK(recording.triangles()[1].firstBlock == 2);
  CHECK(recording.blocks().size() == 3);
  CHECK(recording.serves(5, {0, 0, 64, 64}));
}
