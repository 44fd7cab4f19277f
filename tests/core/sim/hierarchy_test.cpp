// Object trees, the broad phase and the descent: on random scenes of random trees (rigid and
// jointed, many frames) sort and sweep plus tree descent report exactly the leaf pairs that
// testing every pair of leaves of different objects reports; boxes nest; the incremental
// sort keeps finding exactly the overlapping pairs as objects move.

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "recode/geometry/generators.hpp"
#include "recode/sim/broad_phase.hpp"
#include "recode/sim/hierarchy.hpp"
#include "recode/sim/leaf_block.hpp"

using namespace recode::core;

namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Eigen::Vector3d randomVector(std::mt19937_64& rng, double lo, double hi) {
  return {uniform(rng, lo, hi), uniform(rng, lo, hi), uniform(rng, lo, hi)};
}

TriangleMesh randomBlock(std::mt19937_64& rng) {
  switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
    case 0:
      return makeBox(randomVector(rng, 0.05, 0.6));
    case 1:
      return makeCone(uniform(rng, 0.1, 0.5), uniform(rng, 0.2, 1.2), 7);
    default:
      return makeEllipsoid(uniform(rng, 0.1, 0.8), uniform(rng, 0.05, 0.3), uniform(rng, 0.1, 0.5),
                           6, 3);
  }
}

// A random tree: depth up to `depth`, 1-3 children per node, random placements; with
// `jointed`, some nodes turn about a hinge or drift so that subtrees are not rigid.
SceneObject randomNode(std::mt19937_64& rng, int depth, bool jointed, const std::string& name) {
  SceneObject node;
  node.name = name;
  node.position = randomVector(rng, -0.8, 0.8);
  node.rotationDeg = randomVector(rng, -180, 180);
  if (jointed && uniform(rng, 0, 1) < 0.4) {
    Joint j;
    j.axis = randomVector(rng, -1, 1).normalized();
    j.angleDeg = uniform(rng, -30, 30);
    j.rateDeg = uniform(rng, -9, 9);
    j.minDeg = -60;
    j.maxDeg = 60;
    node.joint = j;
  }
  if (jointed && uniform(rng, 0, 1) < 0.2) {
    Motion m;
    m.velocity = randomVector(rng, -0.05, 0.05);
    m.angularVelocityDeg = randomVector(rng, -5, 5);
    node.motion = m;
  }
  if (depth == 0 || uniform(rng, 0, 1) < 0.3) {
    node.localMesh = randomBlock(rng);
    return node;
  }
  const int n = std::uniform_int_distribution<int>(1, 3)(rng);
  for (int i = 0; i < n; ++i) {
    std::string childName = name;  // (appended piecewise: GCC 12 warns wrongly on a + b + c)
    childName += '.';
    childName += std::to_string(i);
    node.children.push_back(randomNode(rng, depth - 1, jointed, childName));
  }
  return node;
}

std::vector<SceneObject> randomObjects(std::mt19937_64& rng, int count, double spread,
                                       bool jointed) {
  std::vector<SceneObject> objects;
  for (int i = 0; i < count; ++i) {
    std::string name = "o";
    name += std::to_string(i);
    SceneObject root = randomNode(rng, 3, jointed, name);
    root.position = randomVector(rng, -spread, spread);
    Motion m;
    m.velocity = randomVector(rng, -0.15, 0.15);
    m.angularVelocityDeg = randomVector(rng, -6, 6);
    root.motion = m;
    objects.push_back(root);
  }
  return objects;
}

using Found = std::set<std::tuple<int, int, int, int>>;  // object a, object b, leaf a, leaf b

// Every leaf of every object against every leaf of every later object.
Found allLeafPairs(const std::vector<ObjectTree>& trees) {
  Found found;
  for (std::size_t a = 0; a < trees.size(); ++a)
    for (std::size_t b = a + 1; b < trees.size(); ++b)
      for (int la : trees[a].leaves())
        for (int lb : trees[b].leaves())
          if (nodeBoxesOverlap(trees[a].nodes()[static_cast<std::size_t>(la)],
                               trees[b].nodes()[static_cast<std::size_t>(lb)]))
            found.emplace(static_cast<int>(a), static_cast<int>(b), la, lb);
  return found;
}

bool inside(const Aabb& inner, const Aabb& outer) {
  return (inner.min.array() >= outer.min.array()).all() &&
         (inner.max.array() <= outer.max.array()).all();
}

bool inside(const Obb& inner, const Obb& outer) {
  for (const Eigen::Vector3d& c : inner.corners()) {
    const Eigen::Vector3d local = outer.axes.transpose() * (c - outer.center);
    if ((local.cwiseAbs().array() > outer.halfExtents.array()).any())
      return false;
  }
  return true;
}

}  // namespace

TEST_CASE("hierarchy: broad phase and descent find exactly the brute-force leaf pairs",
          "[hierarchy]") {
  const bool jointed = GENERATE(false, true);
  std::mt19937_64 rng(jointed ? 31 : 17);
  long long total = 0, boxTests = 0, bruteTests = 0;
  for (int scene = 0; scene < 12; ++scene) {
    const std::vector<SceneObject> objects = randomObjects(rng, 14, 2.5, jointed);
    std::vector<ObjectTree> trees(objects.begin(), objects.end());
    SweepAndPrune broadPhase;
    for (int frame = 0; frame < 30; ++frame) {
      std::vector<Aabb> roots;
      for (ObjectTree& t : trees) {
        t.pose(frame);
        roots.push_back(t.root().worldAabb);
      }
      Found found;
      for (const auto& [a, b] : broadPhase.update(roots)) {
        std::vector<LeafPair> leaves;
        boxTests += descendPair(trees[static_cast<std::size_t>(a)],
                                trees[static_cast<std::size_t>(b)], leaves);
        REQUIRE(std::is_sorted(leaves.begin(), leaves.end(), [](auto& x, auto& y) {
          return std::pair(x.leafA, x.leafB) < std::pair(y.leafA, y.leafB);
        }));
        for (const LeafPair& lp : leaves)
          REQUIRE(found.emplace(a, b, lp.leafA, lp.leafB).second);  // no pair twice
      }
      const Found expected = allLeafPairs(trees);
      for (std::size_t a = 0; a < trees.size(); ++a)
        for (std::size_t b = a + 1; b < trees.size(); ++b)
          bruteTests += static_cast<long long>(trees[a].leaves().size() * trees[b].leaves().size());
      INFO("scene " << scene << ", frame " << frame);
      REQUIRE(found == expected);
      total += static_cast<long long>(found.size());
    }
  }
  // The scenes are busy enough to mean something, and the descent prunes.
  CHECK(total > 300);
  CHECK(boxTests < bruteTests);
}

TEST_CASE("hierarchy: every node's boxes contain its children's, frame after frame",
          "[hierarchy]") {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    ObjectTree tree(randomNode(rng, 4, trial % 2 == 1, "t"));
    for (int frame = 0; frame < 20; frame += 3) {
      tree.pose(frame);
      for (const HierarchyNode& node : tree.nodes()) {
        if (node.isLeaf()) {
          // The leaf's AABB is its vertices' box; its OBB contains every vertex.
          Aabb box;
          const TriangleMesh world = tree.worldMesh(static_cast<int>(&node - &tree.nodes()[0]));
          for (const Eigen::Vector3d& v : world.vertices) {
            box.extend(v);
            const Eigen::Vector3d local =
                node.worldObb.axes.transpose() * (v - node.worldObb.center);
            REQUIRE((local.cwiseAbs().array() <= node.worldObb.halfExtents.array() + 1e-12).all());
          }
          CHECK(box.min == node.worldAabb.min);
          CHECK(box.max == node.worldAabb.max);
          continue;
        }
        for (int c : node.children) {
          const HierarchyNode& child = tree.nodes()[static_cast<std::size_t>(c)];
          REQUIRE(inside(child.worldAabb, node.worldAabb));
          REQUIRE(inside(child.worldObb, node.worldObb));
          REQUIRE(child.path.starts_with(node.path + "/"));
        }
      }
    }
  }
}

TEST_CASE("hierarchy: the box around the root's OBB holds the root's AABB, near and far away",
          "[hierarchy]") {
  // What a frame's broad phase relies on to leave out the AABBs of objects near no other: the
  // sweep over these boxes finds every pair the sweep over the AABBs finds. Far from the origin
  // the vertices' rounding is large against a small block's own size.
  std::mt19937_64 rng(11);
  long long checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    SceneObject object = randomNode(rng, 3, trial % 2 == 1, "t");
    if (trial % 4 >= 2)
      object.position = randomVector(rng, -1e7, 1e7);
    ObjectTree tree(object);
    for (int frame = 0; frame < 30; frame += 3) {
      tree.pose(frame);
      const Aabb around = tree.boxAroundObb();
      INFO("trial " << trial << ", frame " << frame);
      REQUIRE(inside(tree.root().worldAabb, around));
      // updateObbs alone gives the same OBBs as updateBounds.
      const std::vector<HierarchyNode> posed = tree.nodes();
      tree.updateObbs();
      for (std::size_t i = 0; i < posed.size(); ++i) {
        REQUIRE(tree.nodes()[i].worldObb.center == posed[i].worldObb.center);
        REQUIRE(tree.nodes()[i].worldObb.halfExtents == posed[i].worldObb.halfExtents);
      }
      ++checked;
    }
  }
  CHECK(checked == 400);
}

TEST_CASE("hierarchy: rigid subtrees keep their fitted box, jointed ones do not", "[hierarchy]") {
  SceneObject arm;
  arm.name = "arm";
  SceneObject upper;
  upper.name = "upper";
  upper.localMesh = makeBox(1.0, 0.1, 0.1);
  upper.position = {1.0, 0.0, 0.0};
  SceneObject lower = upper;
  lower.name = "lower";
  lower.position = {3.0, 0.0, 0.0};
  arm.children = {upper, lower};
  {
    ObjectTree rigid(arm);
    CHECK(rigid.root().rigid);
    // The root's box was fitted to the two bars: 4 x 0.2 x 0.2 along x.
    CHECK(rigid.root().localObb.volume() == Approx(4.0 * 0.2 * 0.2).epsilon(1e-6));
  }
  Joint hinge;
  hinge.axis = Eigen::Vector3d::UnitZ();
  hinge.rateDeg = 10.0;
  arm.children[1].joint = hinge;
  ObjectTree jointed(arm);
  CHECK_FALSE(jointed.root().rigid);
  CHECK(jointed.nodes()[2].rigid);  // a leaf is rigid in itself
  jointed.pose(9);                  // lower bar turned 90 degrees about its centre
  const Aabb box = jointed.root().worldAabb;
  CHECK(box.min.x() == Approx(0.0));
  CHECK(box.max.x() == Approx(3.1));
  CHECK(box.max.y() == Approx(1.0));
}

TEST_CASE("sweep and prune: exactly the overlapping pairs, frame after frame", "[broadphase]") {
  std::mt19937_64 rng(123);
  const int n = 150;
  std::vector<Eigen::Vector3d> centre(n), velocity(n), half(n);
  for (int i = 0; i < n; ++i) {
    centre[static_cast<std::size_t>(i)] = randomVector(rng, -10, 10);
    velocity[static_cast<std::size_t>(i)] = randomVector(rng, -0.3, 0.3);
    half[static_cast<std::size_t>(i)] = randomVector(rng, 0.1, 1.2);
  }
  SweepAndPrune sap;
  long long pairsSeen = 0, swaps = 0, sweepTests = 0;
  for (int frame = 0; frame < 60; ++frame) {
    std::vector<Aabb> boxes(n);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const Eigen::Vector3d c = centre[i] + velocity[i] * frame;
      boxes[i].min = c - half[i];
      boxes[i].max = c + half[i];
    }
    if (frame == 10)
      boxes[3] = boxes[4];  // identical boxes
    if (frame == 20)
      boxes[7] = Aabb{};  // an empty box overlaps nothing
    if (frame == 30) {    // touching faces count
      boxes[8].min = boxes[9].max;
      boxes[8].max = boxes[9].max + Eigen::Vector3d::Constant(1.0);
    }
    std::vector<std::pair<int, int>> expected;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (aabbsOverlap(boxes[static_cast<std::size_t>(i)], boxes[static_cast<std::size_t>(j)]))
          expected.emplace_back(i, j);
    INFO("frame " << frame);
    REQUIRE(sap.update(boxes) == expected);
    pairsSeen += static_cast<long long>(expected.size());
    if (frame > 0)
      swaps += sap.stats().swaps;
    sweepTests += sap.stats().intervalTests;
  }
  CHECK(pairsSeen > 100);
  // Far fewer pair tests than all pairs, and the incremental sort moves little per frame.
  CHECK(sweepTests < 60LL * n * (n - 1) / 2 / 3);
  CHECK(swaps < 60LL * n);
}

// A Placement built in code has no range checks (scene files do): a pose that overflows must
// stop the run naming the node, not turn into NaN boxes that report no contact.
TEST_CASE("a pose that is not finite is refused naming the node", "[hierarchy]") {
  SceneObject spinner;
  spinner.name = "spinner";
  spinner.localMesh = makeBox(Eigen::Vector3d(1, 1, 1));
  Motion m;
  m.angularVelocityDeg = Eigen::Vector3d(1e160, 0, 0);  // its norm squares to infinity
  spinner.motion = m;
  ObjectTree tree(spinner);
  CHECK_THROWS_WITH(tree.pose(1),
                    "spinner: the pose at frame 1 is not finite (its position, "
                    "rotation_deg, motion overflow a double)");
  SceneObject hinge = spinner;
  hinge.motion.reset();
  Joint j;
  j.rateDeg = 1e308;
  j.angleDeg = 1e308;  // angle + rate * k overflows at frame 2
  hinge.joint = j;
  ObjectTree hinged(hinge);
  CHECK_NOTHROW(hinged.pose(0));
  CHECK_THROWS_WITH(hinged.pose(2), Catch::Contains("spinner: the pose at frame 2 is not finite") &&
                                        Catch::Contains("joint"));
}

TEST_CASE("hierarchy: the root has parent -1 and every other node its parent's index",
          "[hierarchy]") {
  SceneObject arm;
  arm.name = "arm";
  SceneObject bar;
  bar.name = "bar";
  bar.localMesh = makeBox(1.0, 0.1, 0.1);
  arm.children = {bar, bar};
  const ObjectTree tree(arm);
  REQUIRE(tree.nodes().size() == 3);
  CHECK(tree.root().parent == -1);
  CHECK(tree.nodes()[1].parent == 0);
  CHECK(tree.nodes()[2].parent == 0);
  CHECK(tree.root().path == "arm");
  CHECK(tree.nodes()[1].path == "arm/bar");
}

TEST_CASE("hierarchy: a leaf's OBB is its fitted box grown by 1e-9 of its position and size",
          "[hierarchy]") {
  // A flat plate (no thickness along z), off the origin: its fitted box is 0 thick, so its
  // OBB's thickness is the slack alone, 1e-9 x (largest |centre coordinate| + largest
  // half-extent), on each side.
  SceneObject plate;
  plate.name = "plate";
  plate.localMesh.vertices = {
      {2.5, -0.25, 0.0}, {3.5, -0.25, 0.0}, {3.5, 0.25, 0.0}, {2.5, 0.25, 0.0}};
  plate.localMesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  const ObjectTree tree(plate);
  const Obb fitted = fitObb(plate.localMesh.vertices);
  REQUIRE(fitted.halfExtents.minCoeff() == 0.0);
  const double slack = 1e-9 * (fitted.center.cwiseAbs().maxCoeff() + fitted.halfExtents.maxCoeff());
  const Obb& box = tree.root().localObb;
  CHECK(box.center == fitted.center);
  CHECK(box.axes == fitted.axes);
  CHECK(box.halfExtents == (fitted.halfExtents.array() + slack).matrix());
  CHECK(box.halfExtents.minCoeff() == slack);
}

TEST_CASE(
    "hierarchy: the box around the root's OBB is its AABB grown by 1e-9 of its position "
    "and size",
    "[hierarchy]") {
  // A unit cube centred at (1, 0, 0): the OBB's box reaches about -1e-9 along x, where the
  // margin (about 2e-9: 1e-9 x (1 + 1)) is not lost to rounding.
  SceneObject cube;
  cube.name = "cube";
  cube.localMesh = makeBox(1.0, 1.0, 1.0);
  cube.position = {1.0, 0.0, 0.0};
  const ObjectTree tree(cube);
  const Aabb obbBox = tree.root().worldObb.aabb();
  const double margin =
      1e-9 * (obbBox.center().cwiseAbs().maxCoeff() + 0.5 * obbBox.extent().maxCoeff());
  const Aabb around = tree.boxAroundObb();
  CHECK(around.min == (obbBox.min.array() - margin).matrix());
  CHECK(around.max == (obbBox.max.array() + margin).matrix());
  CHECK(margin == Approx(2e-9));
}

TEST_CASE("hierarchy: a leaf's current box is there while its pose is the one it was made at",
          "[hierarchy]") {
  SceneObject cube;
  cube.name = "cube";
  cube.localMesh = makeBox(0.5, 0.5, 0.5);
  Motion m;
  m.velocity = {1.0, 0.0, 0.0};
  cube.motion = m;
  ObjectTree tree(cube);  // posed at frame 0, boxes made
  const int leaf = tree.leaves().front();
  REQUIRE(tree.currentLeafBox(leaf) == &tree.root().worldAabb);
  CHECK_FALSE(tree.leafBoxStale(leaf));
  CHECK(tree.root().worldAabb.min.x() == -0.5);
  tree.setFrame(2);  // moved 2 along x, its box not made again
  CHECK(tree.currentLeafBox(leaf) == nullptr);
  CHECK(tree.leafBoxStale(leaf));
  tree.updateAabbs();
  REQUIRE(tree.currentLeafBox(leaf) != nullptr);
  CHECK(tree.currentLeafBox(leaf)->min.x() == 1.5);
}

TEST_CASE("hierarchy: a leaf block made where the leaf's box is stale has the box of its pose",
          "[hierarchy]") {
  // recode::collide makes LeafBlocks of trees it poses itself: with the tree's box of the leaf
  // out of date, the block makes its box from the vertices at the current pose.
  SceneObject cube;
  cube.name = "cube";
  cube.localMesh = makeBox(0.5, 0.5, 0.5);
  Motion m;
  m.velocity = {1.0, 0.0, 0.0};
  cube.motion = m;
  ObjectTree tree(cube);
  tree.setFrame(3);
  const int leaf = tree.leaves().front();
  REQUIRE(tree.currentLeafBox(leaf) == nullptr);
  LeafBlock block(tree, leaf);
  CHECK(block.block.box().min == Eigen::Vector3d(2.5, -0.5, -0.5));
  CHECK(block.block.box().max == Eigen::Vector3d(3.5, 0.5, 0.5));
  // Moved on, again without the tree's boxes: the box of the new pose.
  tree.setFrame(5);
  block.moveTo(tree, leaf);
  CHECK(block.block.box().min == Eigen::Vector3d(4.5, -0.5, -0.5));
}
