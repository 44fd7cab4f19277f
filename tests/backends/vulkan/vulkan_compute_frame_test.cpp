// The compute device's frame (backends/vulkan/src/tile_frame.hpp): how a framebuffer's commands
// are cut into epochs, and frames of many devices and epochs, with reads and summaries between
// their draws, run in one submission against the CPU device command by command. Runs on
// whatever Vulkan driver the loader finds (lavapipe here).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "compute_device_test_support.hpp"
#include "recode/backends/vulkan_compute_device.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/fixed_point.hpp"
#include "tile_frame_epochs.hpp"

using namespace recode;
using backends::VulkanComputeDevice;
using backends::detail::cutIntoEpochs;
using backends::detail::EpochCommand;
using backends::detail::EpochSpan;
using backends::detail::TileCommandKind;
using raster::CompareFunc;
using raster::PixelRect;
using raster::StencilOp;

namespace {

EpochCommand clearDepth(PixelRect r) {
  return {TileCommandKind::ClearDepth, r, false};
}
EpochCommand clearStencil(PixelRect r, bool allBits = true) {
  return {TileCommandKind::ClearStencil, r, allBits};
}
EpochCommand draw(PixelRect r) {
  return {TileCommandKind::Draw, r, false};
}
EpochCommand read(PixelRect r) {
  return {TileCommandKind::Read, r, false};
}

}  // namespace

TEST_CASE("a pair test's commands are an epoch of their own; overlapping ones are not alone",
          "[vulkan-compute][frame]") {
  const PixelRect a{0, 0, 40, 30}, b{20, 10, 60, 50}, c{70, 70, 90, 90};
  // Each: clear depth and all stencil bits over its MOR, draws and reads inside it.
  const std::vector<EpochCommand> commands = {
      clearDepth(a),   clearStencil(a), draw(a), draw({5, 5, 30, 20}),   read(a),
      clearStencil(b), clearDepth(b),   draw(b), read({20, 10, 30, 20}), clearDepth(c),
      clearStencil(c), draw(c),         read(c)};
  const std::vector<EpochSpan> epochs = cutIntoEpochs(commands);
  REQUIRE(epochs.size() == 3);
  CHECK(epochs[0].begin == 0);
  CHECK(epochs[0].end == 5);
  CHECK(epochs[1].begin == 5);
  CHECK(epochs[1].end == 9);
  CHECK(epochs[2].end == commands.size());
  for (const EpochSpan& e : epochs)
    CHECK_FALSE(e.loads);
  CHECK(epochs[0].footprint == a);
  CHECK(epochs[1].footprint == b);
  // a and b share pixels: the resolve stage decides them; c shares none and stores itself.
  CHECK_FALSE(epochs[0].alone);
  CHECK_FALSE(epochs[1].alone);
  CHECK(epochs[2].alone);
}

TEST_CASE("commands before any reset start from the framebuffer, over all they touch",
          "[vulkan-compute][frame]") {
  const std::vector<EpochCommand> commands = {draw({0, 0, 8, 8}), read({4, 4, 20, 12}),
                                              clearDepth({0, 0, 30, 30}),
                                              clearStencil({0, 0, 30, 30}), draw({1, 1, 2, 2})};
  const std::vector<EpochSpan> epochs = cutIntoEpochs(commands);
  REQUIRE(epochs.size() == 2);
  CHECK(epochs[0].loads);
  CHECK(epochs[0].footprint == PixelRect{0, 0, 20, 12});
  CHECK_FALSE(epochs[1].loads);
  CHECK(epochs[1].footprint == PixelRect{0, 0, 30, 30});
}

TEST_CASE("a reset that is not one joins the epoch before it", "[vulkan-compute][frame]") {
  const PixelRect r{0, 0, 16, 16};
  SECTION("a stencil clear of some bits only") {
    const std::vector<EpochSpan> epochs = cutIntoEpochs(
        {clearDepth(r), clearStencil(r), draw(r), clearDepth(r), clearStencil(r, false), draw(r)});
    REQUIRE(epochs.size() == 1);
    CHECK(epochs[0].end == 6);
  }
  SECTION("clears of two rectangles") {
    const std::vector<EpochSpan> epochs = cutIntoEpochs(
        {clearDepth(r), clearStencil(r), draw(r), clearDepth(r), clearStencil({0, 0, 8, 16})});
    REQUIRE(epochs.size() == 1);
  }
  SECTION("a depth clear alone") {
    const std::vector<EpochSpan> epochs =
        cutIntoEpochs({clearDepth(r), clearStencil(r), draw(r), clearDepth(r), draw(r)});
    REQUIRE(epochs.size() == 1);
  }
}

TEST_CASE("an epoch that reaches outside its reset joins those before it until one holds it",
          "[vulkan-compute][frame]") {
  const PixelRect big{0, 0, 64, 64}, small{8, 8, 24, 24}, other{40, 40, 60, 60};
  SECTION("inside the epoch before: joined to it, which stays a reset epoch") {
    const std::vector<EpochSpan> epochs =
        cutIntoEpochs({clearDepth(big), clearStencil(big), draw(big), clearDepth(small),
                       clearStencil(small), draw({0, 0, 30, 30})});
    REQUIRE(epochs.size() == 1);
    CHECK_FALSE(epochs[0].loads);
    CHECK(epochs[0].footprint == big);
  }
  SECTION("outside every epoch: all joined into one that starts from the framebuffer") {
    const std::vector<EpochSpan> epochs =
        cutIntoEpochs({clearDepth(small), clearStencil(small), draw(small), clearDepth(other),
                       clearStencil(other), draw(big)});
    REQUIRE(epochs.size() == 1);
    CHECK(epochs[0].loads);
    CHECK(epochs[0].footprint == big);
    CHECK(epochs[0].end == 6);
  }
}

namespace {

// A device under test and its reference, and the reads they owe.
struct Pair {
  std::unique_ptr<VulkanComputeDevice> device;
  std::unique_ptr<raster::CpuDevice> reference;
  std::vector<std::pair<raster::PendingRead<std::uint8_t>, std::vector<std::uint8_t>>> stencils;
  std::vector<std::pair<raster::PendingRead<std::uint32_t>, std::vector<std::uint32_t>>> depths;
  std::vector<std::pair<raster::PendingRead<raster::PixelSummary>, raster::PixelSummary>> summaries;
};

template <class Call>
void onBoth(Pair& p, const Call& call) {
  call(static_cast<raster::DepthStencilDevice&>(*p.device));
  call(static_cast<raster::DepthStencilDevice&>(*p.reference));
}

PixelRect randomRect(std::mt19937& rng, int width, int height) {
  std::uniform_int_distribution<int> x(0, width - 1), y(0, height - 1);
  const int x0 = x(rng), x1 = x(rng), y0 = y(rng), y1 = y(rng);
  return {std::min(x0, x1), std::min(y0, y1), std::max(x0, x1) + 1, std::max(y0, y1) + 1};
}

PixelRect randomRectIn(std::mt19937& rng, const PixelRect& r) {
  const PixelRect inner = randomRect(rng, r.width(), r.height());
  return {r.x0 + inner.x0, r.y0 + inner.y0, r.x0 + inner.x1, r.y0 + inner.y1};
}

// One random command of an epoch over `r` on both devices: a draw in a random state, a read, a
// summary, or a clear of some bits.
void randomCommand(std::mt19937& rng, Pair& p, const PixelRect& r) {
  std::uniform_int_distribution<int> pick(0, 9), func(0, 7), op(0, 7), byte(0, 255);
  const int what = pick(rng);
  if (what <= 5) {
    const auto f = static_cast<CompareFunc>(func(rng));
    const auto sf = static_cast<CompareFunc>(func(rng));
    const auto ref = static_cast<std::uint8_t>(byte(rng));
    const auto mask = static_cast<std::uint8_t>(byte(rng));
    const raster::StencilOps front{static_cast<StencilOp>(op(rng)), static_cast<StencilOp>(op(rng)),
                                   static_cast<StencilOp>(op(rng))};
    const raster::StencilOps back{static_cast<StencilOp>(op(rng)), static_cast<StencilOp>(op(rng)),
                                  static_cast<StencilOp>(op(rng))};
    const bool depthWrite = pick(rng) < 7;
    const auto writeMask = static_cast<std::uint8_t>(pick(rng) < 5 ? 0xFF : byte(rng));
    const auto cull = static_cast<raster::CullMode>(pick(rng) % 3);
    const PixelRect scissor = randomRectIn(rng, r);
    std::uniform_real_distribution<float> ux(static_cast<float>(r.x0) - 4.0f,
                                             static_cast<float>(r.x1) + 4.0f);
    std::uniform_real_distribution<float> uy(static_cast<float>(r.y0) - 4.0f,
                                             static_cast<float>(r.y1) + 4.0f);
    std::uniform_real_distribution<float> uz(0.0f, 1.0f);
    std::vector<raster::WindowVertex> vertices;
    std::vector<std::uint32_t> indices;
    const int triangles = 1 + pick(rng) * 3;
    for (int t = 0; t < 3 * triangles; ++t) {
      vertices.push_back(
          {raster::snapToSubpixel(ux(rng)), raster::snapToSubpixel(uy(rng)), uz(rng)});
      indices.push_back(static_cast<std::uint32_t>(t));
    }
    onBoth(p, [&](raster::DepthStencilDevice& d) {
      d.setScissor(scissor);
      d.setDepthFunc(f);
      d.setDepthWriteMask(depthWrite);
      d.setStencilFunc(sf, ref, mask);
      d.setStencilOps(raster::Face::Front, front);
      d.setStencilOps(raster::Face::Back, back);
      d.setStencilWriteMask(writeMask);
      d.setCullMode(cull);
      d.drawTriangles(vertices, indices);
    });
  } else if (what == 6) {
    const PixelRect rect = randomRectIn(rng, r);
    p.stencils.emplace_back(p.device->readStencilLater(rect), p.reference->readStencil(rect));
  } else if (what == 7) {
    const PixelRect rect = randomRectIn(rng, r);
    p.depths.emplace_back(p.device->readDepthLater(rect), p.reference->readDepth(rect));
  } else if (what == 8) {
    // A summary of the stencil, with the depth kept now as its near end and the depth at the
    // summary as its far end: both read at their own places among the commands.
    const PixelRect rect = randomRectIn(rng, r);
    raster::StencilClasses classes;
    for (int v = 0; v < 256; ++v)
      classes.classOf[static_cast<std::size_t>(v)] = static_cast<std::uint8_t>(v % 4);
    classes.marked = 0b0110;
    const auto keptOnDevice = p.device->keepDepthLater(rect);
    const auto keptOnReference = p.reference->keepDepthLater(rect);
    randomCommand(rng, p, r);  // something between the near end and the summary
    p.summaries.emplace_back(
        p.device->summarizeLater(rect, classes, keptOnDevice.get()),
        p.reference->summarizeLater(rect, classes, keptOnReference.get()).take().front());
  } else {
    const auto value = static_cast<std::uint8_t>(byte(rng));
    const auto writeMask = static_cast<std::uint8_t>(byte(rng));
    const PixelRect scissor = randomRectIn(rng, r);
    onBoth(p, [&](raster::DepthStencilDevice& d) {
      d.setScissor(scissor);
      d.setStencilWriteMask(writeMask);
      d.clearStencil(value);
    });
  }
}

// A pair test's shape: its MOR cleared (depth and every stencil bit), then commands inside it.
// Now and then one reaches outside (the frame must then join epochs), or the clears are left
// out (the epoch starts from what the framebuffer holds).
void randomEpoch(std::mt19937& rng, Pair& p) {
  std::uniform_int_distribution<int> pick(0, 9), count(1, 6);
  const int width = p.reference->width(), height = p.reference->height();
  const PixelRect mor = randomRect(rng, width, height);
  if (pick(rng) != 0) {
    std::uniform_real_distribution<double> depth(0.0, 1.0);
    const double q = depth(rng);
    const auto s = static_cast<std::uint8_t>(pick(rng));
    onBoth(p, [&](raster::DepthStencilDevice& d) {
      d.setScissor(mor);
      d.setDepthWriteMask(true);
      d.setStencilWriteMask(0xFF);
      d.clearDepth(q);
      d.clearStencil(s);
    });
  }
  const int commands = count(rng);
  for (int c = 0; c < commands; ++c)
    randomCommand(rng, p, pick(rng) == 0 ? PixelRect{0, 0, width, height} : mor);
}

// Every read of `p` delivered and equal to the reference's, and the framebuffers equal.
void expectSameFrame(Pair& p) {
  for (auto& [read, expected] : p.stencils)
    CHECK(read.take() == expected);
  for (auto& [read, expected] : p.depths)
    CHECK(read.take() == expected);
  for (auto& [read, expected] : p.summaries)
    CHECK(read.take().front() == expected);
  p.stencils.clear();
  p.depths.clear();
  p.summaries.clear();
  test::expectSameBuffers(*p.device, *p.reference);
}

}  // namespace

TEST_CASE(
    "frames of many devices and epochs, interleaved, in one submission each, equal the "
    "CPU device command by command",
    "[vulkan-compute][frame]") {
  std::mt19937 rng(57);
  const std::vector<std::pair<int, int>> sizes = {{37, 29}, {64, 64}, {90, 17}};
  std::vector<Pair> pairs;
  for (const auto& [w, h] : sizes)
    pairs.push_back({std::make_unique<VulkanComputeDevice>(w, h),
                     std::make_unique<raster::CpuDevice>(w, h),
                     {},
                     {},
                     {}});
  for (int frame = 0; frame < 12; ++frame) {
    INFO("frame " << frame);
    const raster::TransferCounters before = pairs[0].device->transfers();
    std::uniform_int_distribution<std::size_t> which(0, pairs.size() - 1);
    for (int epoch = 0; epoch < 24; ++epoch)
      randomEpoch(rng, pairs[which(rng)]);
    pairs[0].device->finish();
    // Every device's commands ran in the one submission the first device's finish() made, as
    // a fixed set of dispatches.
    CHECK(pairs[0].device->transfers().since(before).submissions == 1);
    CHECK(pairs[0].device->transfers().since(before).dispatches <= 12);
    for (Pair& p : pairs)
      expectSameFrame(p);
  }
}

TEST_CASE("a read between two draws of one epoch sees exactly the first",
          "[vulkan-compute][frame]") {
  VulkanComputeDevice device(24, 16);
  raster::CpuDevice reference(24, 16);
  const std::vector<raster::WindowVertex> first = {
      {0.0f, 0.0f, 0.5f}, {24.0f, 0.0f, 0.5f}, {0.0f, 16.0f, 0.5f}};
  const std::vector<raster::WindowVertex> second = {
      {24.0f, 16.0f, 0.25f}, {0.0f, 16.0f, 0.25f}, {24.0f, 0.0f, 0.25f}};
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  const PixelRect all{0, 0, 24, 16};
  for (raster::DepthStencilDevice* d : {static_cast<raster::DepthStencilDevice*>(&device),
                                        static_cast<raster::DepthStencilDevice*>(&reference)}) {
    d->clearDepth(1.0);
    d->clearStencil(0);
    test::countingState(*d);
  }
  device.drawTriangles(first, indices);
  reference.drawTriangles(first, indices);
  raster::PendingRead<std::uint8_t> stencilBetween = device.readStencilLater(all);
  raster::PendingRead<std::uint32_t> depthBetween = device.readDepthLater(all);
  const std::vector<std::uint8_t> expectedStencil = reference.readStencil(all);
  const std::vector<std::uint32_t> expectedDepth = reference.readDepth(all);
  device.drawTriangles(second, indices);
  reference.drawTriangles(second, indices);
  device.finish();
  const std::vector<std::uint8_t> stencil = stencilBetween.take();
  CHECK(stencil == expectedStencil);
  CHECK(depthBetween.take() == expectedDepth);
  // The first triangle alone: about half the pixels counted once, and the second draw changed
  // some of them afterwards.
  CHECK(std::count(stencil.begin(), stencil.end(), std::uint8_t{1}) > 100);
  CHECK(reference.readStencil(all) != expectedStencil);
  test::expectSameBuffers(device, reference);
}

namespace {

// Two pair tests' epochs on one framebuffer, the second's rectangle inside the first's: the
// second's pixels are the last word, the first's the rest. Returns the frame's dispatches.
long long twoOverlappingEpochs(int size, const PixelRect& second) {
  VulkanComputeDevice device(size, size);
  raster::CpuDevice reference(size, size);
  const std::vector<raster::WindowVertex> triangle = {
      {1.0f, 1.0f, 0.25f}, {static_cast<float>(size) - 1.0f, 2.0f, 0.5f}, {3.0f, 200.0f, 0.75f}};
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  const PixelRect all{0, 0, size, size};
  const raster::TransferCounters before = device.transfers();
  std::vector<raster::PendingRead<std::uint8_t>> reads;
  std::vector<std::vector<std::uint8_t>> expected;
  for (const PixelRect& r : {all, second}) {
    for (raster::DepthStencilDevice* d : {static_cast<raster::DepthStencilDevice*>(&device),
                                          static_cast<raster::DepthStencilDevice*>(&reference)}) {
      d->setScissor(r);
      d->setDepthWriteMask(true);
      d->setStencilWriteMask(0xFF);
      d->clearDepth(r == all ? 1.0 : 0.75);
      d->clearStencil(r == all ? 3 : 9);
      test::countingState(*d);
      d->drawTriangles(triangle, indices);
    }
    const PixelRect corner{0, 0, std::min(size, 16), std::min(size, 16)};
    reads.push_back(device.readStencilLater(corner.intersect(r)));
    expected.push_back(reference.readStencil(corner.intersect(r)));
  }
  device.finish();
  for (std::size_t k = 0; k < reads.size(); ++k) {
    INFO("read " << k);
    CHECK(reads[k].take() == expected[k]);
  }
  const long long dispatches = device.transfers().since(before).dispatches;
  // Counted, not printed: a failure of 2^24 pixels would print for minutes.
  const std::vector<std::uint32_t> depth = device.readDepth(all);
  const std::vector<std::uint8_t> stencil = device.readStencil(all);
  const std::vector<std::uint32_t> expectedDepth = reference.readDepth(all);
  const std::vector<std::uint8_t> expectedStencil = reference.readStencil(all);
  long long different = 0;
  long long first = -1;
  for (std::size_t i = 0; i < depth.size(); ++i) {
    if (depth[i] != expectedDepth[i] || stencil[i] != expectedStencil[i]) {
      ++different;
      if (first < 0)
        first = static_cast<long long>(i);
    }
  }
  INFO("first different pixel: " << first % size << ", " << first / size);
  CHECK(different == 0);
  return dispatches;
}

}  // namespace

TEST_CASE(
    "a frame whose shared epochs would keep too many pixels for the resolve stage runs "
    "them one after another, with the same results",
    "[vulkan-compute][frame]") {
  // 64 x 64: the two epochs share pixels, so the resolve stage gives them their final values.
  const long long small = twoOverlappingEpochs(64, {8, 8, 16, 16});
  // 2,056 x 2,056: 66,050 jobs, more than a loop of llvmpipe's shaders runs (65,535
  // iterations: the serial scan takes them in chunks), with the resolve stage.
  CHECK(twoOverlappingEpochs(2056, {8, 8, 16, 16}) == small);
  // 4,096 x 4,096: the first epoch alone is 2^18 blocks, the frame's limit for pixels kept for
  // the resolve stage, so both run as one epoch that stores its own pixels: no resolve stage.
  const long long large = twoOverlappingEpochs(4096, {8, 8, 16, 16});
  CHECK(large == small - 1);
}
