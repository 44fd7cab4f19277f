// The simulation's private frame machinery (core/sim/src): the devices PairTestRunner makes
// for a frame's sizes as their tests accumulate, and the slots FrameLeafBlocks gives the leaves
// a frame draws.

#include <catch2/catch.hpp>

#include <vector>

#include "frame_leaf_blocks.hpp"
#include "pair_tests.hpp"
#include "recode/geometry/generators.hpp"

using namespace recode;
using namespace recode::core;

namespace {

// `count` tasks whose frames are width x height (reserveDevices reads nothing else).
std::vector<PairTask> tasksOfSize(int width, int height, int count) {
  std::vector<PairTask> tasks(static_cast<std::size_t>(count));
  for (PairTask& task : tasks) {
    task.request.frame.width = width;
    task.request.frame.height = height;
  }
  return tasks;
}

}  // namespace

TEST_CASE("pair tests: a size gets one more device once its devices ran 32 tests each",
          "[run][pool]") {
  RunOptions options;
  options.threads = 2;
  for (const int firstFrame : {32, 31}) {
    PairTestRunner runner(options);
    if (runner.concurrency() < 2) {
      WARN("one hardware thread: a size never gets a second device");
      return;
    }
    INFO(firstFrame << " tests in the first frame");
    // The first frame of a size gets one device whatever its count (making one costs more
    // than the tests it would share). Making a device of 512 x 512 pixels takes time; reserving
    // none takes exactly none.
    PairTestRunner::DeviceSetup setup = runner.reserveDevices(tasksOfSize(512, 512, firstFrame));
    CHECK(setup.usable == static_cast<std::size_t>(firstFrame));
    CHECK(setup.us > 0.0);
    // kTestsPerExtraDevice (32) tests on its one device earn the size a second device for a
    // frame with two of its tests; 31 do not.
    setup = runner.reserveDevices(tasksOfSize(512, 512, 2));
    CHECK(setup.usable == 2);
    if (firstFrame >= PairTestRunner::kTestsPerExtraDevice)
      CHECK(setup.us > 0.0);
    else
      CHECK(setup.us == 0.0);
  }
}

TEST_CASE("frame leaf blocks: a frame's slots count from 0 in the order the leaves are needed",
          "[run]") {
  std::vector<ObjectTree> objects;
  for (const double x : {0.0, 3.0}) {
    SceneObject cube;
    cube.name = "cube";
    cube.localMesh = makeBox(0.5, 0.5, 0.5);
    cube.position = {x, 0.0, 0.0};
    objects.emplace_back(cube);
  }
  RunOptions options;
  options.threads = 1;
  PairTestRunner runner(options);
  FrameLeafBlocks blocks;
  blocks.start();
  CHECK(blocks.need(0, 0) == 0);
  CHECK(blocks.need(1, 0) == 1);
  CHECK(blocks.need(0, 0) == 0);  // the same leaf, the same slot
  blocks.make(objects, runner);
  CHECK(blocks.at(0)->box().min == objects[0].root().worldAabb.min);
  CHECK(blocks.at(1)->box().min == objects[1].root().worldAabb.min);
  // The next frame draws the second cube alone: its slot is 0.
  blocks.start();
  CHECK(blocks.need(1, 0) == 0);
  blocks.make(objects, runner);
  CHECK(blocks.at(0)->box().min == objects[1].root().worldAabb.min);
  CHECK(blocks.at(0)->box().max == objects[1].root().worldAabb.max);
}
