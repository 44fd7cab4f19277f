// A frame's pair tests on several threads give the same report as on one: every field of every
// FrameReport but the wall-clock times, compared exactly (doubles bit for bit), on built-in
// scenes with many pair tests per frame, contacts and contact regions.

#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "recode/raster/cpu_device.hpp"
#include "recode/scene/experiment_scenes.hpp"
#include "recode/sim/simulation.hpp"

using namespace recode;
using namespace recode::core;

namespace {

// Doubles as their bits, so that equal text means equal values, NaNs and signed zeros included.
void put(std::ostringstream& out, double v) {
  out << std::bit_cast<std::uint64_t>(v) << ' ';
}

void put(std::ostringstream& out, const Eigen::Vector3d& v) {
  put(out, v.x());
  put(out, v.y());
  put(out, v.z());
}

void put(std::ostringstream& out, const raster::PixelRect& r) {
  out << r.x0 << ' ' << r.y0 << ' ' << r.x1 << ' ' << r.y1 << ' ';
}

// One line per contact after one for the counters; PairResult::timing and the report's times
// are left out, as they are wall clock.
std::string describe(const FrameReport& r) {
  std::ostringstream out;
  out << "frame " << r.frame << " objectPairs " << r.objectPairs << " boxTests " << r.boxTests
      << " pairTests " << r.pairTests << " skipped " << r.pairTestsSkipped << " stencil "
      << r.stencilPixelsRead << " depth " << r.depthPixelsRead << " contacts " << r.contacts.size()
      << '\n';
  for (const LeafContact& c : r.contacts) {
    const PairResult& p = c.result;
    out << c.objectA << ' ' << c.objectB << ' ' << c.leafA << ' ' << c.leafB << " | " << p.collide
        << p.boxesOverlap << ' ';
    put(out, p.mor);
    for (long long n : p.caseCounts)
      out << n << ' ';
    out << p.interferingPixels << ' ' << p.caseMap.data.size() << ' ';
    put(out, p.contactRect);
    for (const Eigen::Vector3d& point : p.contact.points)
      put(out, point);
    put(out, p.contact.box.min);
    put(out, p.contact.box.max);
    out << p.contact.pixels << ' ' << p.contact.collapsedPixels << ' ';
    put(out, p.contact.area);
    put(out, p.contact.maxDepth);
    out << p.stencilPixelsRead << ' ' << p.depthPixelsRead << ' ';
    put(out, p.depthMin);
    put(out, p.depthMax);
    out << '\n';
  }
  return out.str();
}

// Every step-th frame of the scene's own frames.
std::vector<std::string> runScene(const Scene& scene, int threads, int step,
                                  DeviceFactory factory = {}, PairMode mode = PairMode::Reference) {
  const int frames = scene.frames.value_or(kDefaultRunFrames);
  RunOptions options;
  options.threads = threads;
  options.pairMode = mode;
  options.deviceFactory = std::move(factory);
  Simulation sim(scene, options);
  std::vector<std::string> reports;
  for (int k = 0; k < frames; k += step)
    reports.push_back(describe(sim.runFrame(k)));
  return reports;
}

struct Case {
  const char* scene;
  int trianglesPerBlock;  // 0: the built-in's default
  int step;
};

}  // namespace

TEST_CASE("a frame's report is the same on 1, 2 and 4 threads", "[run][threads]") {
  const Case cases[] = {
      {"random-cones", 0, 2},        {"hand-grasp", 0, 2},   {"comb-translate-aligned", 0, 1},
      {"comb-rotate-aligned", 0, 3}, {"hierarchy-9", 48, 1},
  };
  long long contacts = 0;
  for (const Case& c : cases) {
    const Scene scene = c.trianglesPerBlock > 0
                            ? builtinExperimentScene(c.scene, c.trianglesPerBlock)
                            : builtinExperimentScene(c.scene);
    const std::vector<std::string> sequential = runScene(scene, 1, c.step);
    for (const std::string& r : sequential)
      contacts += r.find("contacts 0\n") == std::string::npos;
    for (int threads : {2, 4}) {
      const std::vector<std::string> parallel = runScene(scene, threads, c.step);
      INFO(c.scene << " on " << threads << " threads");
      REQUIRE(parallel.size() == sequential.size());
      for (std::size_t i = 0; i < parallel.size(); ++i)
        REQUIRE(parallel[i] == sequential[i]);
    }
  }
  CHECK(contacts > 20);  // frames with contact: the comparison covers contact regions
}

TEST_CASE("the thread count resolves as documented", "[run][threads]") {
  RunOptions options;
  options.threads = 0;
  const int hardware = pairTestThreads(options);
  CHECK(hardware >= 1);
  options.threads = 1;
  CHECK(pairTestThreads(options) == 1);
  // At most N: more than the machine has would not run at once.
  options.threads = hardware + 1;
  CHECK(pairTestThreads(options) == hardware);
  // A device factory may make GPU-API devices, which one thread at a time must use.
  options.threads = 4;
  options.deviceFactory = [](int, int) -> std::unique_ptr<raster::DepthStencilDevice> {
    return nullptr;
  };
  CHECK(pairTestThreads(options) == 1);
  options = {};
  options.threads = -1;
  CHECK_THROWS_AS(Simulation(builtinExperimentScene("comb-translate-aligned"), options),
                  std::invalid_argument);
}

// Without a factory the run reshapes the devices of sizes a frame does not use for the sizes it
// does (its pairs' frames change size as the blocks move); a factory of new CpuDevices makes
// every device afresh. Both must report the same.
TEST_CASE("a run on reshaped devices reports what a run on new devices does", "[run][threads]") {
  const DeviceFactory fresh = [](int w, int h) -> std::unique_ptr<raster::DepthStencilDevice> {
    return std::make_unique<raster::CpuDevice>(w, h);
  };
  for (const char* name : {"comb-translate-aligned", "random-cones"}) {
    const Scene scene = builtinExperimentScene(name);
    for (int threads : {1, 2}) {
      INFO(name << " on " << threads << " threads");
      const std::vector<std::string> reshaped = runScene(scene, threads, 1);
      const std::vector<std::string> made = runScene(scene, threads, 1, fresh);
      REQUIRE(reshaped.size() == made.size());
      for (std::size_t i = 0; i < made.size(); ++i)
        REQUIRE(reshaped[i] == made[i]);
    }
  }
}

// The skip-apart mode proves its pairs apart on the runner's threads before any is drawn: the
// report must still be the same bytes on any count, and a pair it skips gets no device.
TEST_CASE(
    "the skip-apart mode reports the same on 1, 2 and 4 threads, and makes no device for "
    "a pair it skips",
    "[run][threads]") {
  long long skipped = 0;
  for (const char* name : {"random-cones", "hand-grasp", "comb-rotate-aligned"}) {
    const Scene scene = builtinExperimentScene(name);
    const std::vector<std::string> sequential = runScene(scene, 1, 2, {}, PairMode::SkipApart);
    for (const std::string& r : sequential)
      skipped += r.find(" skipped 0 ") == std::string::npos;
    for (int threads : {2, 4}) {
      INFO(name << " on " << threads << " threads");
      const std::vector<std::string> parallel =
          runScene(scene, threads, 2, {}, PairMode::SkipApart);
      REQUIRE(parallel == sequential);
    }
  }
  CHECK(skipped > 10);  // frames with skipped pairs

  // Every pair test of the offset rotation is apart, and proven so.
  int made = 0;
  const DeviceFactory counting = [&made](int w,
                                         int h) -> std::unique_ptr<raster::DepthStencilDevice> {
    ++made;
    return std::make_unique<raster::CpuDevice>(w, h);
  };
  const Scene offset = builtinExperimentScene("comb-rotate-offset");
  const std::vector<std::string> reference = runScene(offset, 1, 4, counting);
  const int madeByReference = made;
  made = 0;
  const std::vector<std::string> skipping = runScene(offset, 1, 4, counting, PairMode::SkipApart);
  CHECK(madeByReference > 0);
  CHECK(made == 0);
  REQUIRE(skipping.size() == reference.size());
}

// A simulation keeps the world blocks it drew for the next frame (moved, not made again, when
// their leaves move; untouched when they do not). Frames run out of order and again must still
// report exactly what a new simulation reports for each.
TEST_CASE("frames run out of order, or again, report what a new simulation reports for each",
          "[run]") {
  long long contacts = 0;
  for (const char* name : {"hand-grasp", "random-cones"}) {
    const Scene scene = builtinExperimentScene(name);
    for (const PairMode mode : {PairMode::Reference, PairMode::SkipApart}) {
      RunOptions options;
      options.threads = 1;
      options.pairMode = mode;
      Simulation kept(scene, options);
      for (const int k : {30, 31, 31, 60, 32, 65, 64, 5, 60}) {
        INFO(name << " in the " << toString(mode) << " mode, frame " << k);
        const FrameReport again = kept.runFrame(k);
        contacts += static_cast<long long>(again.contacts.size());
        CHECK(describe(again) == describe(Simulation(scene, options).runFrame(k)));
      }
    }
  }
  CHECK(contacts > 20);
}
