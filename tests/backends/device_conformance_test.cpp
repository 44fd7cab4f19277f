// One conformance suite for every device that promises the reference's bits: each built device
// of the registry whose entry is exact (the CPU device itself, the exact GL device on every
// context platform this build has, Vulkan with 64-bit and with 32-bit shader arithmetic) runs the
// same cases against raster::CpuDevice with no tolerance: the golden vectors, random sloped streams
// compared after every command, the generated pair suite over each pair's MOR, masked and scissored
// clears, two devices' states kept apart, and the errors. A new back end added to the registry is
// held to all of them. What is specific to one API (GL's shared context, Vulkan's flipped origin)
// stays in that device's own test file.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "closed_mesh_support.hpp"
#include "exact_test_streams.hpp"
#include "recode/backends/device_registry.hpp"
#include "recode/pair/layered_pair.hpp"
#include "recode/pair/pair_batch.hpp"
#include "recode/pair/pair_result_compare.hpp"
#include "recode/raster/command_stream.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/golden.hpp"
#include "recode/verify/exact_parity.hpp"
#include "recode/verify/pair_suite.hpp"
#if RECODE_HAVE_GL_EXACT
#include "recode/backends/gl_exact_device.hpp"
#endif

using namespace recode;
using raster::WindowVertex;
using verify::testing::describe;

namespace {

struct ConformingDevice {
  std::string label;  // the registry's name, with the GL platform
  core::DeviceFactory make;
};

// Every exact device this build has; the exact GL device once per context platform to test here
// (verify::testing::exactGlPlatformsHere).
std::vector<ConformingDevice> conformingDevices() {
  std::vector<ConformingDevice> list;
  for (const backends::DeviceInfo& d : backends::deviceRegistry()) {
    if (!d.exact || !d.built)
      continue;
#if RECODE_HAVE_GL_EXACT
    if (d.kind == backends::DeviceKind::GlExact) {
      std::vector<std::string> unavailable;
      for (const backends::GlPlatform p : verify::testing::exactGlPlatformsHere(unavailable)) {
        list.push_back({"gl-exact/" + std::string(backends::toString(p)), [p](int w, int h) {
                          return std::make_unique<backends::GlExactDevice>(w, h, p);
                        }});
      }
      for (const std::string& why : unavailable)
        WARN(why);
      continue;
    }
#endif
    const backends::DeviceKind kind = d.kind;
    list.push_back(
        {std::string(d.name), [kind](int w, int h) { return backends::makeDevice(kind, w, h); }});
  }
  return list;
}

}  // namespace

TEST_CASE("the conforming devices are every exact device of this build", "[conformance]") {
  const std::vector<ConformingDevice> devices = conformingDevices();
  std::vector<std::string> labels;
  for (const ConformingDevice& d : devices)
    labels.push_back(d.label);
  INFO("devices: " << labels.size());
  CHECK(std::count(labels.begin(), labels.end(), "cpu") == 1);
#if RECODE_HAVE_VULKAN
  CHECK(std::count(labels.begin(), labels.end(), "vulkan") == 1);
  CHECK(std::count(labels.begin(), labels.end(), "vulkan-32") == 1);
  CHECK(std::count(labels.begin(), labels.end(), "vulkan-compute") == 1);
#endif
#if RECODE_HAVE_GL_EXACT
  CHECK(std::count_if(labels.begin(), labels.end(),
                      [](const std::string& l) { return l.rfind("gl-exact/", 0) == 0; }) >= 1);
#endif
  // Not exact, not held to this: the native pipelines.
  CHECK(std::count(labels.begin(), labels.end(), "gl") == 0);
  CHECK(std::count(labels.begin(), labels.end(), "vulkan-native") == 0);
}

TEST_CASE("every golden vector replays bit for bit on every conforming device",
          "[conformance][golden]") {
  const auto files = verify::testing::goldenFiles();
  REQUIRE(files.size() >= 7);
  for (const ConformingDevice& d : conformingDevices()) {
    INFO("device " << d.label);
    for (const auto& path : files) {
      INFO(path.filename().string());
      const raster::CommandFile file = raster::readCommandFile(path.string());
      REQUIRE(file.hasExpected);
      const raster::GoldenVector& g = file.content;
      const auto device = d.make(g.stream.width, g.stream.height);
      raster::replay(g.stream.commands, *device);
      const raster::PixelRect all{0, 0, g.stream.width, g.stream.height};
      CHECK(device->readDepth(all) == g.depth);
      CHECK(device->readStencil(all) == g.stencil);
    }
  }
}

TEST_CASE("random sloped streams agree with the CPU device after every command on every device",
          "[conformance][random]") {
  for (const ConformingDevice& d : conformingDevices()) {
    INFO("device " << d.label);
    std::mt19937 rng(20261124);
    verify::ExactParityCounts total;
    for (int s = 0; s < 60; ++s) {
      const int width = 8 + static_cast<int>(rng() % 90);
      const int height = 8 + static_cast<int>(rng() % 70);
      const raster::CommandStream stream = verify::testing::randomStream(rng, width, height);
      raster::CpuDevice reference(width, height);
      const auto candidate = d.make(width, height);
      const auto report = verify::compareStreamExactly(stream, reference, *candidate);
      INFO("stream " << s << ": " << describe(report));
      CHECK(report.ok());
      total += report.counts;
    }
    CHECK(total.pixels > 1000000);
    CHECK(total.identical == total.pixels);
  }
}

TEST_CASE("the generated pair suite is bit-identical on every conforming device",
          "[conformance][suite]") {
  const auto suite = verify::generatePairSuite();
  REQUIRE(suite.size() == 504);
  for (const ConformingDevice& d : conformingDevices()) {
    INFO("device " << d.label);
    verify::ExactParityCounts total;
    int compared = 0;
    for (const verify::SuitePair& pair : suite) {
      core::PairRequest request;
      request.frame = pair.frame;
      const auto report = verify::comparePairExactly(pair.a, pair.b, request, d.make);
      INFO(pair.label << ": " << describe(report));
      CHECK(report.ok());
      total += report.counts;
      compared += report.counts.pixels > 0;
    }
    CHECK(compared > 250);
    CHECK(total.different == 0);
  }
}

namespace {

// The generated pair suite as batch jobs (blocks alive as long as the batch), a mix of MORs and
// normals, and the reference's results one pair at a time.
struct SuiteBatch {
  std::vector<verify::SuitePair> suite = verify::generatePairSuite();
  std::vector<core::PairBlock> blocks;
  std::vector<core::PairJob> jobs;
  std::vector<core::PairResult> expected;

  explicit SuiteBatch(const std::function<void(std::size_t, core::PairRequest&)>& adjust) {
    blocks.reserve(2 * suite.size());
    for (std::size_t i = 0; i < suite.size(); ++i) {
      const verify::SuitePair& pair = suite[i];
      blocks.emplace_back(pair.a);
      blocks.emplace_back(pair.b);
      core::PairRequest request;
      request.frame = pair.frame;
      request.normal = i % 4 == 0;
      request.mor = i % 5 == 0 ? core::MorMode::Max : core::MorMode::Min;
      adjust(i, request);
      jobs.push_back({&blocks[2 * i], &blocks[2 * i + 1], request});
      raster::CpuDevice reference(pair.frame.width, pair.frame.height);
      expected.push_back(core::collidePair(reference, pair.a, pair.b, request));
    }
  }

  // Runs the batch on `d` (one device per frame size, as the frame loop holds them) and
  // returns the pairs that differ from the reference; `transfers` gets the devices' counters.
  int differences(const ConformingDevice& d, core::ContactSchedule schedule,
                  raster::TransferCounters& transfers) const {
    std::map<std::pair<int, int>, std::unique_ptr<raster::DepthStencilDevice>> bySize;
    std::vector<raster::DepthStencilDevice*> devices;
    for (const core::PairJob& job : jobs) {
      auto& device = bySize[{job.request.frame.width, job.request.frame.height}];
      if (!device)
        device = d.make(job.request.frame.width, job.request.frame.height);
      devices.push_back(device.get());
    }
    std::map<raster::DepthStencilDevice*, raster::TransferCounters> before;
    for (const auto& [size, device] : bySize)
      before[device.get()] = device->transfers();
    const std::vector<core::PairResult> got = core::collidePairs(devices, jobs, schedule);
    REQUIRE(got.size() == expected.size());
    transfers = {};
    for (const auto& [size, device] : bySize) {
      transfers.submissions += device->transfers().submissions - before[device.get()].submissions;
      transfers.readbackBytes +=
          device->transfers().readbackBytes - before[device.get()].readbackBytes;
    }
    int different = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
      const std::optional<std::string> difference = core::firstDifference(got[i], expected[i]);
      INFO(suite[i].label << ": " << difference.value_or("same"));
      CHECK(!difference);
      different += difference ? 1 : 0;
    }
    return different;
  }
};

}  // namespace

TEST_CASE("a batch of the generated pair suite gives collidePair's results on every device",
          "[conformance][suite][batch]") {
  const SuiteBatch batch([](std::size_t, core::PairRequest&) {});
  int colliding = 0;
  for (const core::PairResult& r : batch.expected)
    colliding += r.collide ? 1 : 0;
  REQUIRE(colliding > 100);
  for (const ConformingDevice& d : conformingDevices()) {
    INFO("device " << d.label);
    raster::TransferCounters transfers;
    CHECK(batch.differences(d, core::ContactSchedule::AfterVerdict, transfers) == 0);
  }
}

TEST_CASE("the generated pair suite without its pixels gives the same results from summaries",
          "[conformance][suite][batch][summary]") {
  // Every pair without its pixels and its normal, a third without the contact passes: each is
  // concluded from its device's summaries, in one submission speculatively (64 bytes a drawn
  // pair), in two after the verdict (64 bytes more for each pair that interferes).
  const SuiteBatch batch([](std::size_t i, core::PairRequest& request) {
    request.keepPixels = false;
    request.normal = false;
    request.contact = i % 3 != 0;
  });
  long long drawn = 0, secondRound = 0;
  for (std::size_t i = 0; i < batch.expected.size(); ++i) {
    drawn += batch.expected[i].mor.empty() ? 0 : 1;
    secondRound += batch.expected[i].collide && batch.jobs[i].request.contact ? 1 : 0;
  }
  const auto summaryBytes = static_cast<long long>(raster::kPixelSummaryBytes);
  for (const ConformingDevice& d : conformingDevices()) {
    INFO("device " << d.label);
    raster::TransferCounters speculative, afterVerdict;
    CHECK(batch.differences(d, core::ContactSchedule::Speculative, speculative) == 0);
    CHECK(batch.differences(d, core::ContactSchedule::AfterVerdict, afterVerdict) == 0);
    if (d.label.rfind("vulkan", 0) == 0 || d.label.rfind("gl-exact", 0) == 0) {
      // The frame sizes' devices share one recording (one context), and nothing but summaries
      // is read back: both reduce their buffers in a compute shader.
      CHECK(speculative.submissions == 1);
      CHECK(speculative.readbackBytes == drawn * summaryBytes);
      CHECK(afterVerdict.submissions == 2);
      CHECK(afterVerdict.readbackBytes == (drawn + secondRound) * summaryBytes);
    }
  }
}

TEST_CASE("the layered pair of closed meshes gives the CPU device's results on every device",
          "[conformance][layered]") {
  // Rings, a hollow ball and a ball in poses that collide, hold one inside the other or stay
  // apart, seen along each axis: every count and capture pass, compared through the results
  // (the per-pixel overlap lengths are the captured depths' sums, so one depth off shows).
  const core::TriangleMesh ring = core::makeTorus(2.0, 0.5, 40, 16);
  const core::TriangleMesh others[] = {
      test::shifted(core::makeSphere(0.3, 16, 8), {2.0, 0.0, 0.1}),
      test::shifted(test::makeHollowBall(1.0, 0.7, 16, 8), {1.6, 0.4, 0.3}),
      test::shifted(core::makeTorus(1.5, 0.4, 32, 12), {0.5, -0.3, 0.2}),
      test::shifted(core::makeSphere(0.5, 16, 8), {0.0, 0.1, 0.0})};
  for (const ConformingDevice& d : conformingDevices()) {
    INFO("device " << d.label);
    int n = 0;
    for (const core::TriangleMesh& b : others)
      for (const auto axis : {core::ViewAxis::X, core::ViewAxis::Y, core::ViewAxis::Z}) {
        INFO("pair " << n++);
        core::Aabb bounds = core::boundingBox(ring);
        bounds.extend(core::boundingBox(b));
        core::PairRequest request;
        request.frame.axis = axis;
        request.frame.width = request.frame.height = 96;
        request.frame.window = core::defaultWindow(axis, bounds, std::array<int, 2>{96, 96});
        raster::CpuDevice reference(96, 96);
        const auto device = d.make(96, 96);
        const core::LayeredPairResult want = core::collideLayered(reference, ring, b, request);
        const core::LayeredPairResult got = core::collideLayered(*device, ring, b, request);
        CHECK(got.mor == want.mor);
        CHECK(got.layersA == want.layersA);
        CHECK(got.layersB == want.layersB);
        CHECK(got.interferingPixels == want.interferingPixels);
        CHECK(got.interferes.data == want.interferes.data);
        CHECK(got.overlapSteps.data == want.overlapSteps.data);
        CHECK(got.containment == want.containment);
        CHECK(got.contact.collapsedPixels == want.contact.collapsedPixels);
      }
  }
}

TEST_CASE("clears honour the scissor and both write masks on every conforming device",
          "[conformance][clears]") {
  for (const ConformingDevice& d : conformingDevices()) {
    INFO("device " << d.label);
    const auto device = d.make(5, 4);
    raster::CpuDevice reference(5, 4);
    for (raster::DepthStencilDevice* dev :
         {device.get(), static_cast<raster::DepthStencilDevice*>(&reference)}) {
      dev->clearStencil(0xF0);
      dev->setScissor({1, 1, 4, 3});
      dev->setStencilWriteMask(0x3C);
      dev->clearStencil(0x0F);  // (0x0F & 0x3C) | (0xF0 & ~0x3C) = 0xCC inside the scissor
      dev->clearDepth(0.5);
      dev->setDepthWriteMask(false);
      dev->clearDepth(0.0);  // no effect: depth writes are off
      dev->setStencilWriteMask(0);
      dev->clearStencil(0x00);          // no effect: nothing writable
      dev->setScissor({-3, 2, 40, 9});  // clamped to the framebuffer
      dev->setStencilWriteMask(0xFF);
      dev->clearStencil(0x11);
    }
    const raster::PixelRect all{0, 0, 5, 4};
    const auto stencil = device->readStencil(all);
    CHECK(stencil == reference.readStencil(all));
    CHECK(device->readDepth(all) == reference.readDepth(all));
    CHECK(stencil[1 * 5 + 1] == 0xCC);
    CHECK(stencil[0] == 0xF0);
    CHECK(stencil[3 * 5 + 4] == 0x11);
  }
}

TEST_CASE("two devices of one kind share no state on every conforming device",
          "[conformance][state]") {
  using raster::CompareFunc, raster::Face, raster::StencilOp;
  for (const ConformingDevice& d : conformingDevices()) {
    INFO("device " << d.label);
    // Interleaved: a back end that keeps one context, pipeline or command buffer for all its
    // devices must apply each device's own state and framebuffer to each draw.
    const auto a = d.make(6, 4);
    const auto b = d.make(5, 7);
    a->setStencilFunc(CompareFunc::Always, 9, 0xFF);
    a->setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::Keep, StencilOp::Replace});
    a->setScissor({0, 0, 2, 2});
    b->setDepthFunc(CompareFunc::Never);
    b->setStencilOps(Face::Both, {StencilOp::Keep, StencilOp::IncrWrap, StencilOp::Keep});
    const WindowVertex quad[4] = {{-1, -1, 0.5f}, {9, -1, 0.5f}, {9, 9, 0.5f}, {-1, 9, 0.5f}};
    const std::uint32_t indices[6] = {0, 1, 2, 0, 2, 3};
    a->drawTriangles(quad, indices);
    b->drawTriangles(quad, indices);
    a->drawTriangles(quad, indices);
    const auto stencilA = a->readStencil({0, 0, 6, 4});
    const auto stencilB = b->readStencil({0, 0, 5, 7});
    CHECK(std::count(stencilA.begin(), stencilA.end(), 9) == 4);  // its scissor, its ref
    CHECK(std::count(stencilA.begin(), stencilA.end(), 0) == 20);
    CHECK(std::all_of(stencilB.begin(), stencilB.end(), [](auto s) { return s == 1; }));
    const auto depthB = b->readDepth({0, 0, 5, 7});
    CHECK(std::all_of(depthB.begin(), depthB.end(), [](auto z) { return z == 16777215u; }));
  }
}

TEST_CASE("every conforming device rejects what the CPU device rejects, changing nothing",
          "[conformance][errors]") {
  for (const ConformingDevice& d : conformingDevices()) {
    INFO("device " << d.label);
    CHECK_THROWS_AS(d.make(0, 4), std::invalid_argument);
    CHECK_THROWS_AS(d.make(16385, 4), std::invalid_argument);
    const auto device = d.make(4, 4);
    const WindowVertex v[3] = {{0, 0, 0.5f}, {4, 0, 1.5f}, {0, 4, 0.5f}};
    const WindowVertex far[3] = {{0, 0, 0.5f}, {40000, 0, 0.5f}, {0, 4, 0.5f}};
    const std::uint32_t bad[3] = {0, 1, 3};
    const std::uint32_t good[3] = {0, 1, 2};
    const std::uint32_t partial[2] = {0, 1};
    CHECK_THROWS_AS(device->drawTriangles(v, bad), std::invalid_argument);
    CHECK_THROWS_AS(device->drawTriangles(v, good), std::invalid_argument);  // z = 1.5
    CHECK_THROWS_AS(device->drawTriangles(v, partial), std::invalid_argument);
    CHECK_THROWS_AS(device->drawTriangles(far, good), std::invalid_argument);
    CHECK_THROWS_AS(device->clearDepth(std::nan("")), std::invalid_argument);
    CHECK_THROWS_AS(device->setDepthFunc(static_cast<raster::CompareFunc>(8)),
                    std::invalid_argument);
    CHECK_THROWS_AS(device->setCullMode(static_cast<raster::CullMode>(3)), std::invalid_argument);
    const auto depth = device->readDepth({0, 0, 4, 4});
    CHECK(std::all_of(depth.begin(), depth.end(), [](auto z) { return z == 16777215u; }));
    CHECK(device->readStencil({5, 5, 9, 9}).empty());  // outside the framebuffer: nothing
  }
}
