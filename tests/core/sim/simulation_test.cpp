// core::Simulation on scenes of a few boxes built here, one frame each: what a contact keeps
// (no case map; its points only when asked), how a frame's pair tests reach a device that
// defers its commands (one batch: two submissions), the run's thread count, and the report's
// counters worked out from the boxes.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <oneapi/tbb/info.h>

#include "recode/geometry/generators.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/raster/forwarding_device.hpp"
#include "recode/raster/posed_boxes.hpp"
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

// A CpuDevice that reduces the world boxes of posed meshes on the host
// (raster::PosedBoxReducer), counting the boxes it made.
class ReducingDevice : public raster::ForwardingDevice, public raster::PosedBoxReducer {
 public:
  ReducingDevice(int width, int height, long long& reduced)
      : ForwardingDevice(std::make_unique<raster::CpuDevice>(width, height)), reduced_(&reduced) {}

  [[nodiscard]] raster::PendingRead<raster::PosedBox> posedBoxesLater(
      std::span<const raster::PosedMesh> meshes) override {
    std::vector<raster::PosedBox> boxes;
    for (const raster::PosedMesh& mesh : meshes) {
      raster::PosedBox box;
      box.min.fill(INFINITY);
      box.max.fill(-INFINITY);
      for (std::size_t i = 0; i + 2 < mesh.localXyz.size(); i += 3) {
        const std::array<double, 3> w = raster::poseVertex(
            mesh.transform.pose, {mesh.localXyz[i], mesh.localXyz[i + 1], mesh.localXyz[i + 2]});
        for (std::size_t k = 0; k < 3; ++k) {
          box.min[k] = std::min(box.min[k], w[k]);
          box.max[k] = std::max(box.max[k], w[k]);
          box.orderMatters = box.orderMatters || std::isnan(w[k]);
        }
      }
      for (std::size_t k = 0; k < 3; ++k)
        box.orderMatters = box.orderMatters || box.min[k] == 0.0 || box.max[k] == 0.0;
      boxes.push_back(box);
    }
    *reduced_ += static_cast<long long>(boxes.size());
    return raster::PendingRead<raster::PosedBox>::ready(std::move(boxes));
  }

 private:
  long long* reduced_;
};

// A CpuDevice whose every draw throws, as a device that fails mid-test.
class FailingDevice : public raster::ForwardingDevice {
 public:
  FailingDevice(int width, int height)
      : ForwardingDevice(std::make_unique<raster::CpuDevice>(width, height)) {}
  void drawTriangles(std::span<const raster::WindowVertex>,
                     std::span<const std::uint32_t>) override {
    throw std::invalid_argument("the device failed");
  }
};

// A frame's pair frame before rounding: the default window over both boxes at `pixelSize`.
FrameSpec unroundedPairFrame(ViewAxis axis, double pixelSize, const Aabb& a, const Aabb& b) {
  Aabb both = a;
  both.extend(b);
  return frameFromPixelSize(axis, defaultWindow(axis, both, std::nullopt), pixelSize);
}

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

TEST_CASE("simulation: a device that reduces the leaves' boxes gives the host's boxes and reports",
          "[run][small][device]") {
  // Cube 1 comes at cube 0 by 0.25 a frame: they touch at frame 4 and overlap after. From the
  // frame after the factory first made a device, the moving leaves' boxes come from the
  // factory's reducing device.
  Scene scene = cubesAlongX({0.0, 2.0});
  Motion m;
  m.velocity = {-0.25, 0.0, 0.0};
  scene.objects[1].motion = m;
  long long reduced = 0;
  RunOptions options;
  options.deviceFactory = [&reduced](int w, int h) -> std::unique_ptr<raster::DepthStencilDevice> {
    return std::make_unique<ReducingDevice>(w, h, reduced);
  };
  Simulation onDevice(scene, options);
  Simulation onHost(scene, RunOptions{});
  long long contacts = 0;
  for (int k = 0; k < 8; ++k) {
    const FrameReport d = onDevice.runFrame(k);
    const FrameReport h = onHost.runFrame(k);
    INFO("frame " << k);
    CHECK(d.objectPairs == h.objectPairs);
    CHECK(d.pairTests == h.pairTests);
    REQUIRE(d.contacts.size() == h.contacts.size());
    for (std::size_t i = 0; i < d.contacts.size(); ++i)
      CHECK(d.contacts[i].result.interferingPixels == h.contacts[i].result.interferingPixels);
    contacts += static_cast<long long>(d.contacts.size());
    for (std::size_t o = 0; o < 2; ++o) {
      CHECK(onDevice.objects()[o].root().worldAabb.min == onHost.objects()[o].root().worldAabb.min);
      CHECK(onDevice.objects()[o].root().worldAabb.max == onHost.objects()[o].root().worldAabb.max);
    }
  }
  CHECK(contacts > 0);
  CHECK(reduced > 0);  // the device made boxes
}

TEST_CASE("simulation: a pair test's device error names the frame and the two blocks",
          "[run][small][device]") {
  RunOptions options;
  options.deviceFactory = [](int w, int h) -> std::unique_ptr<raster::DepthStencilDevice> {
    return std::make_unique<FailingDevice>(w, h);
  };
  Simulation sim(cubesAlongX({0.0, 0.8}), options);
  CHECK_THROWS_WITH(sim.runFrame(3),
                    Catch::StartsWith("frame 3, blocks \"cube 0\" and \"cube 1\": ") &&
                        Catch::Contains("the device failed"));
}

TEST_CASE("simulation: a pair's frame is rounded up to whole granules about its centre",
          "[run][small]") {
  // Boxes of growing width at a pixel size of 0.01: the unrounded frames take every width
  // modulo kPairFrameGranule, and each is rounded up to the next multiple (never down), the
  // window grown equally on both sides so that the pixels stay square.
  const double pixelSize = 0.01;
  Aabb a;
  a.extend(Eigen::Vector3d(0, 0, 0));
  a.extend(Eigen::Vector3d(0.1, 0.1, 0.1));
  int residues = 0;
  for (int step = 0; step < 64; ++step) {
    Aabb b;
    b.extend(Eigen::Vector3d(0, 0, 0));
    b.extend(Eigen::Vector3d(0.2 + 0.0093 * step, 0.1, 0.1));
    const FrameSpec raw = unroundedPairFrame(ViewAxis::Z, pixelSize, a, b);
    const FrameSpec f = granularPairFrame(ViewAxis::Z, pixelSize, a, b);
    INFO("unrounded width " << raw.width);
    residues += raw.width % kPairFrameGranule == 1 ? 1 : 0;
    CHECK(f.width == (raw.width + kPairFrameGranule - 1) / kPairFrameGranule * kPairFrameGranule);
    CHECK(f.height == (raw.height + kPairFrameGranule - 1) / kPairFrameGranule * kPairFrameGranule);
    CHECK(f.width >= raw.width);
    CHECK((f.window.umax - f.window.umin) == Approx(f.width * pixelSize));
    CHECK((f.window.umin + f.window.umax) == Approx(raw.window.umin + raw.window.umax));
  }
  CHECK(residues > 0);  // a width one pixel over a granule was rounded up
}

TEST_CASE("simulation: the limit of pair tests per frame counts every leaf pair listed",
          "[run][small]") {
  // Object 0: a cube at x = -0.8. Object 1: a cube at the origin. Object 2: two cubes at
  // (0.8, 0) and (0.8, 0.9) along (x, y), each overlapping object 1's cube by 0.2 along x (the
  // second also 0.1 along y) and 0.6 away from object 0's. Object pairs (0, 1) with one leaf
  // pair, then (1, 2) with two: three pair tests.
  Scene scene = cubesAlongX({-0.8, 0.0});
  SceneObject pairOfCubes;
  pairOfCubes.name = "two cubes";
  for (const double y : {0.0, 0.9}) {
    SceneObject cube = scene.objects[1];
    cube.name = "cube at y " + std::to_string(y);
    cube.position = {0.0, y, 0.0};
    pairOfCubes.children.push_back(cube);
  }
  pairOfCubes.position = {0.8, 0.0, 0.0};
  scene.objects.push_back(pairOfCubes);
  RunOptions options;
  options.threads = 1;
  options.maxPairTestsPerFrame = 3;
  CHECK(Simulation(scene, options).runFrame(0).pairTests == 3);
  // Objects 1 and 2 alone: their two leaf pairs are within a limit of 2.
  Scene two = scene;
  two.objects.erase(two.objects.begin());
  options.maxPairTestsPerFrame = 2;
  CHECK(Simulation(two, options).runFrame(0).pairTests == 2);
  // A limit of 1: the first object pair lists one test, the second one more (one over the
  // limit is enough to know the frame is over it), so the error names 2.
  options.maxPairTestsPerFrame = 1;
  CHECK_THROWS_WITH(Simulation(scene, options).runFrame(0),
                    Catch::StartsWith("frame 0: at least 2 block pairs have overlapping boxes, "
                                      "over the limit of 1 pair tests per frame"));
}

TEST_CASE("simulation: the triangle count is the sum over every object's leaves", "[small]") {
  // Two cubes of 12 triangles each, and an object whose two children are a cube and a cone of
  // 5 segments, 2 x 5 = 10 triangles (the parent has no mesh of its own): 12 + 12 + 12 + 10.
  Scene scene = cubesAlongX({0.0, 3.0});
  SceneObject group;
  group.name = "group";
  SceneObject cube = scene.objects[0];
  cube.name = "child cube";
  cube.position = {6.0, 0.0, 0.0};
  group.children.push_back(cube);
  SceneObject cone;
  cone.name = "child cone";
  cone.localMesh = makeCone(0.5, 1.0, 5);
  cone.position = {9.0, 0.0, 0.0};
  group.children.push_back(cone);
  scene.objects.push_back(group);
  RunOptions options;
  options.threads = 1;
  CHECK(Simulation(scene, options).triangleCount() == 46);
}
