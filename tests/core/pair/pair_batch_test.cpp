// collidePairs against collidePair on the CPU reference, through a device that defers its
// read-backs as a GPU device does (reads are taken when asked, delivered by finish()): the batch
// must give every pair's result, timing aside, for both contact schedules, on one device or one
// per frame size; and the comparison must notice a contact pass skipped for one pair.

#include <catch2/catch.hpp>

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "pair_test_support.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/pair/pair_batch.hpp"
#include "recode/pair/pair_result_compare.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/forwarding_device.hpp"

using namespace recode;
using recode::test::moved;

namespace {

// A CpuDevice whose read-backs wait for finish(): each is read when asked (so it sees the
// buffers as the commands so far left them, as a recorded copy does) and handed over later.
class DeferringDevice : public raster::ForwardingDevice {
 public:
  DeferringDevice(int width, int height)
      : ForwardingDevice(std::make_unique<raster::CpuDevice>(width, height)) {}

  raster::PendingRead<std::uint8_t> readStencilLater(const raster::PixelRect& rect) override {
    auto read = raster::PendingRead<std::uint8_t>::waiting();
    stencils_.emplace_back(read, inner().readStencil(rect));
    return read;
  }
  raster::PendingRead<std::uint32_t> readDepthLater(const raster::PixelRect& rect) override {
    auto read = raster::PendingRead<std::uint32_t>::waiting();
    depths_.emplace_back(read, inner().readDepth(rect));
    return read;
  }
  void finish() override {
    ++finishes;
    for (auto& [read, values] : stencils_)
      read.deliver(std::move(values));
    for (auto& [read, values] : depths_)
      read.deliver(std::move(values));
    stencils_.clear();
    depths_.clear();
  }
  [[nodiscard]] bool defers() const override { return true; }
  // The interface's own summaries, from the read-backs above (not the CpuDevice's, which are
  // ready at once): so the derived read-backs wait for finish() as a GPU's would.
  std::shared_ptr<const raster::KeptDepth> keepDepthLater(const raster::PixelRect& rect) override {
    return DepthStencilDevice::keepDepthLater(rect);
  }
  raster::PendingRead<raster::PixelSummary> summarizeLater(
      const raster::PixelRect& rect, const raster::StencilClasses& classes,
      const raster::KeptDepth* nearEnd) override {
    ++summaries;
    return DepthStencilDevice::summarizeLater(rect, classes, nearEnd);
  }

  int finishes = 0;
  int summaries = 0;

 private:
  std::vector<std::pair<raster::PendingRead<std::uint8_t>, std::vector<std::uint8_t>>> stencils_;
  std::vector<std::pair<raster::PendingRead<std::uint32_t>, std::vector<std::uint32_t>>> depths_;
};

// Drops the draws of the `skipped`-th near contact pass (0-based; the passes that clear depth to
// 0 with the stencil write mask 0), as a back end that lost one pair's pass would.
class SkippingDevice final : public DeferringDevice {
 public:
  SkippingDevice(int width, int height, int skipped)
      : DeferringDevice(width, height), skipped_(skipped) {}

  void setStencilWriteMask(std::uint8_t mask) override {
    writeMask_ = mask;
    DeferringDevice::setStencilWriteMask(mask);
  }
  void clearDepth(double depth) override {
    dropping_ = depth == 0.0 && writeMask_ == 0 && nearPasses_++ == skipped_;
    DeferringDevice::clearDepth(depth);
  }
  void drawTriangles(std::span<const raster::WindowVertex> vertices,
                     std::span<const std::uint32_t> indices) override {
    if (!dropping_)
      DeferringDevice::drawTriangles(vertices, indices);
  }
  raster::PendingRead<std::uint32_t> readDepthLater(const raster::PixelRect& rect) override {
    dropping_ = false;
    return DeferringDevice::readDepthLater(rect);
  }

 private:
  int skipped_;
  int nearPasses_ = 0;
  std::uint8_t writeMask_ = 0xFF;
  bool dropping_ = false;
};

// Cones and boxes near one another: some apart, some touching, some deep in each other, in
// frames of two sizes.
struct Batch {
  std::vector<core::TriangleMesh> meshes;  // what the blocks refer to
  std::vector<core::PairBlock> blocks;
  std::vector<core::PairJob> jobs;
};

Batch makeBatch() {
  Batch batch;
  const core::TriangleMesh cone = core::makeCone(0.5, 1.0, 24);
  const core::TriangleMesh box = core::makeBox(0.4, 0.3, 0.5);
  const double offsets[] = {2.0, 0.7, 0.35, 0.0, 1.2, 0.55};
  batch.meshes.reserve(2 * std::size(offsets));
  batch.blocks.reserve(2 * std::size(offsets));
  for (const double dx : offsets) {
    batch.meshes.push_back(cone);
    batch.meshes.push_back(moved(box, {dx, 0.1, 0.2}));
  }
  for (const core::TriangleMesh& mesh : batch.meshes)
    batch.blocks.emplace_back(mesh);
  for (std::size_t i = 0; i < std::size(offsets); ++i) {
    core::PairRequest request;
    const int width = i % 2 == 0 ? 48 : 40;
    request.frame = recode::test::frameZ(-1.5, -1.5, 3.0, 1.5, width, 32);
    request.normal = i % 3 == 0;
    request.mor = i == 4 ? core::MorMode::Full : core::MorMode::Min;
    batch.jobs.push_back({&batch.blocks[2 * i], &batch.blocks[2 * i + 1], request});
  }
  return batch;
}

std::vector<core::PairResult> oneByOne(const std::vector<core::PairJob>& jobs) {
  std::vector<core::PairResult> results;
  for (const core::PairJob& job : jobs) {
    raster::CpuDevice device(job.request.frame.width, job.request.frame.height);
    results.push_back(core::collidePair(device, *job.a, *job.b, job.request));
  }
  return results;
}

}  // namespace

TEST_CASE("a batch gives each pair collidePair's result on a deferring device", "[pair][batch]") {
  const Batch batch = makeBatch();
  const std::vector<core::PairResult> expected = oneByOne(batch.jobs);
  int colliding = 0;
  for (const core::PairResult& r : expected)
    colliding += r.collide ? 1 : 0;
  REQUIRE(colliding >= 3);
  REQUIRE(colliding < static_cast<int>(expected.size()));

  for (const core::ContactSchedule schedule :
       {core::ContactSchedule::AfterVerdict, core::ContactSchedule::Speculative}) {
    const bool speculative = schedule == core::ContactSchedule::Speculative;
    INFO((speculative ? "speculative" : "after the verdict"));
    std::map<int, std::unique_ptr<DeferringDevice>> bySize;
    std::vector<raster::DepthStencilDevice*> devices;
    for (const core::PairJob& job : batch.jobs) {
      auto& d = bySize[job.request.frame.width];
      if (!d)
        d = std::make_unique<DeferringDevice>(job.request.frame.width, job.request.frame.height);
      devices.push_back(d.get());
    }
    const std::vector<core::PairResult> got = core::collidePairs(devices, batch.jobs, schedule);
    REQUIRE(got.size() == expected.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      INFO("pair " << i);
      const std::optional<std::string> difference = core::firstDifference(got[i], expected[i]);
      CHECK(difference.value_or("") == "");
    }
    // Each device finished once a round: the stencil round, and after the verdict the contact
    // round.
    for (const auto& [width, device] : bySize)
      CHECK(device->finishes == (speculative ? 1 : 2));
  }
}

TEST_CASE("a batch that leaves the pixels out concludes from summaries, with the same results",
          "[pair][batch]") {
  Batch batch = makeBatch();
  for (std::size_t i = 0; i < batch.jobs.size(); ++i) {
    batch.jobs[i].request.keepPixels = false;
    batch.jobs[i].request.contact = i != 5;  // one pair without the contact passes
  }
  const std::vector<core::PairResult> expected = oneByOne(batch.jobs);
  int contacts = 0;
  for (const core::PairResult& r : expected) {
    CHECK(r.caseMap.data.empty());
    CHECK(r.contact.points.empty());
    contacts += r.collide && !r.contact.box.isEmpty() ? 1 : 0;
  }
  REQUIRE(contacts >= 2);
  for (const core::ContactSchedule schedule :
       {core::ContactSchedule::AfterVerdict, core::ContactSchedule::Speculative}) {
    const bool speculative = schedule == core::ContactSchedule::Speculative;
    INFO((speculative ? "speculative" : "after the verdict"));
    const core::FrameSpec& frame = batch.jobs.front().request.frame;
    std::vector<core::PairJob> jobs = batch.jobs;
    for (core::PairJob& job : jobs)
      job.request.frame = frame;  // one device for all
    const std::vector<core::PairResult> want = oneByOne(jobs);
    DeferringDevice device(frame.width, frame.height);
    const std::vector<core::PairResult> got = core::collidePairs(device, jobs, schedule);
    for (std::size_t i = 0; i < got.size(); ++i) {
      INFO("pair " << i);
      CHECK(core::firstDifference(got[i], want[i]).value_or("") == "");
    }
    // Summarised: every drawn pair but those asking for the normal; after the verdict those
    // that interfere and asked for the contact once more (over their contact rectangles).
    int drawn = 0, summarised = 0;
    for (std::size_t i = 0; i < want.size(); ++i) {
      const core::PairRequest& request = jobs[i].request;
      const bool wasDrawn = !want[i].mor.empty();
      drawn += wasDrawn ? 1 : 0;
      if (!wasDrawn || (request.contact && request.normal))
        continue;
      ++summarised;
      if (!speculative && request.contact && want[i].collide)
        ++summarised;
    }
    REQUIRE(drawn >= 4);
    CHECK(device.summaries == summarised);
    CHECK(summarised >= 1);
  }
  // A contact pass skipped for one pair shows in its summary too: the second near pass, which
  // speculatively is the second drawn pair's and after the verdict the second interfering
  // pair's; both interfere here.
  std::vector<core::PairJob> jobs = batch.jobs;
  for (core::PairJob& job : jobs) {
    job.request.frame = jobs.front().request.frame;
    job.request.normal = false;
    job.request.contact = true;
  }
  const std::vector<core::PairResult> want = oneByOne(jobs);
  for (const core::ContactSchedule schedule :
       {core::ContactSchedule::AfterVerdict, core::ContactSchedule::Speculative}) {
    INFO((schedule == core::ContactSchedule::Speculative ? "speculative" : "after the verdict"));
    SkippingDevice skipping(jobs.front().request.frame.width, jobs.front().request.frame.height, 1);
    const std::vector<core::PairResult> got = core::collidePairs(skipping, jobs, schedule);
    int differing = 0;
    for (std::size_t i = 0; i < got.size(); ++i)
      differing += core::firstDifference(got[i], want[i]).has_value() ? 1 : 0;
    CHECK(differing == 1);
  }
}

TEST_CASE("a batch on a device that runs commands as they come is collidePair in turn",
          "[pair][batch]") {
  const Batch batch = makeBatch();
  const std::vector<core::PairResult> expected = oneByOne(batch.jobs);
  std::vector<std::unique_ptr<raster::CpuDevice>> owned;
  std::vector<raster::DepthStencilDevice*> devices;
  for (const core::PairJob& job : batch.jobs) {
    owned.push_back(
        std::make_unique<raster::CpuDevice>(job.request.frame.width, job.request.frame.height));
    devices.push_back(owned.back().get());
  }
  const std::vector<core::PairResult> got = core::collidePairs(devices, batch.jobs);
  for (std::size_t i = 0; i < got.size(); ++i) {
    INFO("pair " << i);
    CHECK(core::firstDifference(got[i], expected[i]).value_or("") == "");
  }
}

TEST_CASE("the comparison notices a contact pass skipped for one pair", "[pair][batch]") {
  Batch batch = makeBatch();
  for (core::PairJob& job : batch.jobs)
    job.request.frame = batch.jobs.front().request.frame;  // one device for all
  const std::vector<core::PairResult> expected = oneByOne(batch.jobs);
  // The second pair that interferes loses its near contact pass (passes run in job order).
  std::size_t victim = 0;
  int seen = 0;
  for (std::size_t i = 0; i < expected.size(); ++i)
    if (expected[i].collide && seen++ == 1)
      victim = i;
  REQUIRE(seen >= 2);
  const core::FrameSpec& frame = batch.jobs.front().request.frame;
  SkippingDevice device(frame.width, frame.height, 1);
  const std::vector<core::PairResult> got = core::collidePairs(device, batch.jobs);
  for (std::size_t i = 0; i < got.size(); ++i) {
    INFO("pair " << i);
    const std::optional<std::string> difference = core::firstDifference(got[i], expected[i]);
    if (i == victim) {
      REQUIRE(difference.has_value());
      CHECK(difference->rfind("contact.", 0) == 0);
    } else {
      CHECK(difference.value_or("") == "");
    }
  }
}

TEST_CASE("a batch's total time holds each pair's share of the waits", "[pair][batch]") {
  // A device whose finish() takes at least 5 ms: one pair that interferes waits for it twice
  // (the stencil round, then the contact round after the verdict), alone, so its total holds
  // both waits whole on top of its own recording and concluding.
  class SlowDevice final : public DeferringDevice {
   public:
    using DeferringDevice::DeferringDevice;
    void finish() override {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      DeferringDevice::finish();
    }
  };
  const Batch batch = makeBatch();
  const core::PairJob& job = batch.jobs[3];  // the box at the cone's centre
  SlowDevice device(job.request.frame.width, job.request.frame.height);
  const std::vector<core::PairResult> got = core::collidePairs(device, std::span(&job, 1));
  REQUIRE(got.size() == 1);
  REQUIRE(got[0].collide);
  CHECK(device.finishes == 2);
  CHECK(got[0].timing.totalUs >= 2 * 5000.0);
}

TEST_CASE("a batch checks its jobs and leaves no device with work pending", "[pair][batch]") {
  Batch batch = makeBatch();
  DeferringDevice wrongSize(10, 10);
  CHECK_THROWS_AS(core::collidePairs(wrongSize, batch.jobs), std::invalid_argument);
  CHECK(wrongSize.finishes == 1);  // what was recorded before the error ran

  batch.jobs[1].b = nullptr;
  const core::FrameSpec& frame = batch.jobs.front().request.frame;
  DeferringDevice device(frame.width, frame.height);
  CHECK_THROWS_WITH(core::collidePairs(device, batch.jobs), "collidePairs: job 1 has no block B");
  std::vector<raster::DepthStencilDevice*> tooFew{&device};
  batch.jobs[1].b = batch.jobs[1].a;
  CHECK_THROWS_WITH(core::collidePairs(tooFew, batch.jobs), "collidePairs: 6 jobs but 1 devices");
}
