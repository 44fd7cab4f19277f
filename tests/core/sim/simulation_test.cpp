// core::Simulation on scenes of a few boxes built here, one frame each: what a contact keeps
// (no case map; its points only when asked), how a frame's pair tests reach a device that
// defers its commands (one batch: two submissions), the run's thread count, and the report's
// counters worked out from the boxes.

#include <catch2/catch.hpp>

#include <memory>
#include <utility>
#include <vector>

#include <oneapi/tbb/info.h>

#include "recode/geometry/generators.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/forwarding_device.hpp"
#include "recode/sim/simulation.hpp"

using namespace recode;
using namespace recode::core;

namespace {

// Cubes of side 1 centred at (x, 0, 0) for each x, one block per object, drawn along z at a
// pixel size of 0.05.
Scene cubesAlongX(const std::vector<double>& xs) {
  Scene scene;
  scene.view.pixelSize = 0.05;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    SceneObject cube;
    cube.name = "cube " + std::to_string(i);
    cube.localMesh = makeBox(0.5, 0.5, 0.5);
    cube.position = {xs[i], 0.0, 0.0};
    scene.objects.push_back(cube);
  }
  return scene;
}

// A CpuDevice whose read-backs wait for finish(), as a GPU device's do; its transfer counters
// count the submissions waited on (each finish(), and each read-back taken at once, as a GPU
// device submits its commands to read), each waited on for 0.5 microseconds.
class DeferringDevice : public raster::ForwardingDevice {
 public:
  DeferringDevice(int width, int height)
      : ForwardingDevice(std::make_unique<raster::CpuDevice>(width, height)) {}

  [[nodiscard]] std::vector<std::uint8_t> readStencil(
      const raster::PixelRect& rect) const override {
    ++finishes_;
    return ForwardingDevice::readStencil(rect);
  }
  [[nodiscard]] std::vector<std::uint32_t> readDepth(const raster::PixelRect& rect) const override {
    ++finishes_;
    return ForwardingDevice::readDepth(rect);
  }
  raster::PendingRead<std::uint8_t> readStencilLater(const raster::PixelRect& rect) override {
    auto read = raster::PendingRead<std::uint8_t>::waiting();
    stencils_.emplace_back(read, ForwardingDevice::readStencil(rect));
    return read;
  }
  raster::PendingRead<std::uint32_t> readDepthLater(const raster::PixelRect& rect) override {
    auto read = raster::PendingRead<std::uint32_t>::waiting();
    depths_.emplace_back(read, ForwardingDevice::readDepth(rect));
    return read;
  }
  void finish() override {
    ++finishes_;
    for (auto& [read, values] : stencils_)
      read.deliver(std::move(values));
    for (auto& [read, values] : depths_)
      read.deliver(std::move(values));
    stencils_.clear();
    depths_.clear();
  }
  [[nodiscard]] bool defers() const override { return true; }
  std::shared_ptr<const raster::KeptDepth> keepDepthLater(const raster::PixelRect& rect) override {
    return DepthStencilDevice::keepDepthLater(rect);
  }
  raster::PendingRead<raster::PixelSummary> summarizeLater(
      const raster::PixelRect& rect, const raster::StencilClasses& classes,
      const raster::KeptDepth* nearEnd) override {
    return DepthStencilDevice::summarizeLater(rect, classes, nearEnd);
  }
  [[nodiscard]] raster::TransferCounters transfers() const override {
    raster::TransferCounters counters;
    counters.submissions = finishes_;
    counters.waitUs = 0.5 * static_cast<double>(finishes_);
    return counters;
  }

 private:
  mutable long long finishes_ = 0;
  std::vector<std::pair<raster::PendingRead<std::uint8_t>, std::vector<std::uint8_t>>> stencils_;
  std::vector<std::pair<raster::PendingRead<std::uint32_t>, std::vector<std::uint32_t>>> depths_;
};

const DeviceFactory deferring = [](int w, int h) -> std::unique_ptr<raster::DepthStencilDevice> {
  return std::make_unique<DeferringDevice>(w, h);
};

}  // namespace

TEST_CASE("simulation: a contact keeps no case map and keeps its points only when asked",
          "[run][small]") {
  // Cubes at x = 0, 0.8, 1.6: the first and second overlap by 0.2 along x, as do the second
  // and third; the first and third are 0.6 apart.
  const Scene scene = cubesAlongX({0.0, 0.8, 1.6});
  for (const bool keep : {true, false}) {
    RunOptions options;
    options.threads = 1;
    options.keepContactPoints = keep;
    Simulation sim(scene, options);
    const FrameReport r = sim.runFrame(0);
    INFO("keepContactPoints " << keep);
    CHECK(r.objectPairs == 2);
    CHECK(r.pairTests == 2);
    REQUIRE(r.contacts.size() == 2);
    for (const LeafContact& c : r.contacts) {
      CHECK(c.result.caseMap.data.empty());
      CHECK(c.result.contact.pixels > 0);
      // One point per interfering pixel, or none.
      CHECK(c.result.contact.points.size() ==
            (keep ? static_cast<std::size_t>(c.result.contact.pixels) : 0));
    }
  }
}

TEST_CASE("simulation: on a device that defers its commands a frame's pair tests are one batch",
          "[run][small][device]") {
  // The two interfering pairs of cubesAlongX({0, 0.8, 1.6}) have frames of one size, so one
  // device: batched (pair_batch.hpp, ContactSchedule::AfterVerdict) the frame waits twice, once
  // for the stencils' verdicts and once for the contact passes; pair by pair (collidePair) it
  // waits three times a pair: the stencil, the near and the far contact depths.
  const Scene scene = cubesAlongX({0.0, 0.8, 1.6});
  // The skip-apart mode batches as the reference does (these pairs are not apart: all drawn).
  for (const PairMode mode : {PairMode::Reference, PairMode::SkipApart}) {
    for (const bool batch : {true, false}) {
      RunOptions options;
      options.deviceFactory = deferring;
      options.batch = batch;
      options.pairMode = mode;
      Simulation sim(scene, options);
      // The frame run twice: the second's counts are its own, not the device's since made.
      (void)sim.runFrame(0);
      const FrameReport r = sim.runFrame(0);
      INFO(toString(mode) << " mode, batch " << batch);
      REQUIRE(r.contacts.size() == 2);
      CHECK(r.pairTestsSkipped == 0);
      const long long waits = batch ? 2 : 3 * 2;
      CHECK(r.submissions == waits);
      CHECK(r.deviceWaitUs == 0.5 * static_cast<double>(waits));
      // The same contacts as on the CPU reference.
      const FrameReport cpu = Simulation(scene, RunOptions{}).runFrame(0);
      REQUIRE(cpu.contacts.size() == 2);
      for (std::size_t i = 0; i < 2; ++i)
        CHECK(r.contacts[i].result.interferingPixels == cpu.contacts[i].result.interferingPixels);
    }
  }
}

TEST_CASE("simulation: a run's threads are the hardware threads oneTBB sees or at most N",
          "[run][threads]") {
  const int hardware = tbb::info::default_concurrency();
  RunOptions options;
  options.threads = 0;
  CHECK(pairTestThreads(options) == hardware);
  options.threads = 2;
  CHECK(pairTestThreads(options) == std::min(2, hardware));
  options.threads = 1;
  CHECK(pairTestThreads(options) == 1);
}
