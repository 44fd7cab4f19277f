// The simulation's private reduction of leaf boxes on a device (core/sim/src/device_leaf_boxes):
// which leaves it hands the device's reducer, and which box each of them keeps. A scene run
// cannot tell, as the host makes again any leaf box the device did not set, with the same bits.

#include <catch2/catch.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "device_leaf_boxes.hpp"
#include "recode/geometry/generators.hpp"
#include "recode/raster/cpu_device.hpp"

using namespace recode;
using namespace recode::core;

namespace {

// A reducer that records the meshes of each call and answers the i-th mesh of a call with the
// box [i + 1, i + 2]^3, recognisable and no leaf's true box; orderMatters false, so that the
// tree takes the box as it is (a faithful reducer is not the point).
class RecordingReducer : public raster::PosedBoxReducer {
 public:
  [[nodiscard]] raster::PendingRead<raster::PosedBox> posedBoxesLater(
      std::span<const raster::PosedMesh> meshes) override {
    std::vector<raster::PosedBox> boxes;
    std::vector<const void*> call;
    for (const raster::PosedMesh& mesh : meshes) {
      call.push_back(mesh.alive.lock().get());
      const double i = static_cast<double>(boxes.size());
      raster::PosedBox box;
      box.min = {i + 1.0, i + 1.0, i + 1.0};
      box.max = {i + 2.0, i + 2.0, i + 2.0};
      boxes.push_back(box);
    }
    calls.push_back(call);
    return raster::PendingRead<raster::PosedBox>::ready(std::move(boxes));
  }

  std::vector<std::vector<const void*>> calls;  // per call, the meshes (their `alive`)
};

SceneObject block(const std::string& name, bool moving) {
  SceneObject object;
  object.name = name;
  object.localMesh = makeBox(0.5, 0.5, 0.5);
  if (moving) {
    Motion m;
    m.velocity = {1.0, 0.0, 0.0};
    object.motion = m;
  }
  return object;
}

}  // namespace

TEST_CASE(
    "device leaf boxes: the reducer gets the stale leaves of the objects asked for, once, "
    "and each keeps its box",
    "[run][device]") {
  // Object 0: three leaves, the first and last moving, the middle one still; object 1: a moving
  // cube not asked for; object 2: a moving cube. At frame 2 the moving leaves' boxes (made at
  // frame 0) are stale, the still leaf's is not.
  SceneObject arm;
  arm.name = "arm";
  arm.children = {block("first", true), block("still", false), block("last", true)};
  std::vector<ObjectTree> objects;
  objects.emplace_back(arm);
  objects.emplace_back(block("skipped", true));
  objects.emplace_back(block("cube", true));
  for (ObjectTree& tree : objects)
    tree.setFrame(2);
  const std::vector<int>& armLeaves = objects[0].leaves();
  REQUIRE(armLeaves.size() == 3);
  REQUIRE(objects[0].leafBoxStale(armLeaves[0]));
  REQUIRE_FALSE(objects[0].leafBoxStale(armLeaves[1]));
  REQUIRE(objects[0].leafBoxStale(armLeaves[2]));
  const Aabb stillBox = *objects[0].currentLeafBox(armLeaves[1]);
  const int skippedLeaf = objects[1].leaves().front();
  const int cubeLeaf = objects[2].leaves().front();
  REQUIRE(objects[1].leafBoxStale(skippedLeaf));
  REQUIRE(objects[2].leafBoxStale(cubeLeaf));

  raster::CpuDevice device(8, 8);
  RecordingReducer reducer;
  detail::reduceLeafBoxes(objects, {2, 0}, device, reducer);

  // One call, with the stale leaves of the objects in the order asked ({2, 0}), each object's
  // in its leaves' order: the cube, then the arm's first and last leaves.
  struct Stale {
    std::size_t object;
    int leaf;
  };
  const std::vector<Stale> stale = {{2, cubeLeaf}, {0, armLeaves[0]}, {0, armLeaves[2]}};
  REQUIRE(reducer.calls.size() == 1);
  REQUIRE(reducer.calls[0].size() == stale.size());
  for (std::size_t i = 0; i < stale.size(); ++i) {
    INFO("stale leaf " << i);
    const ObjectTree& tree = objects[stale[i].object];
    CHECK(reducer.calls[0][i] == tree.objectSpaceMesh(stale[i].leaf).get());
    // The reducer's i-th box, [i + 1, i + 2]^3, now the leaf's box at its current pose.
    const Aabb* box = tree.currentLeafBox(stale[i].leaf);
    REQUIRE(box != nullptr);
    const double lo = static_cast<double>(i) + 1.0;
    CHECK(box->min == Eigen::Vector3d(lo, lo, lo));
    CHECK(box->max == Eigen::Vector3d(lo + 1.0, lo + 1.0, lo + 1.0));
  }
  // The still leaf keeps its box; the object not asked for stays stale.
  CHECK(objects[0].currentLeafBox(armLeaves[1])->min == stillBox.min);
  CHECK(objects[0].currentLeafBox(armLeaves[1])->max == stillBox.max);
  CHECK(objects[1].leafBoxStale(skippedLeaf));

  // Nothing stale left in the objects asked for: the reducer is not asked again.
  detail::reduceLeafBoxes(objects, {2, 0}, device, reducer);
  CHECK(reducer.calls.size() == 1);
}
