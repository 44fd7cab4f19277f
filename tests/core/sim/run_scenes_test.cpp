// recode run's engine on the built-in experiments: the comb's tips meet all at once and
// nothing is drawn before; every finger of the hands reaches the ball and stops within one
// frame of first contact; the broad phase and descent lose no interfering pair (against the
// pair algorithm run on every pair of blocks); the run's pixel size and pair frames follow
// their documented rules.

#include <catch2/catch.hpp>

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>

#include "comb_test_support.hpp"
#include "recode/raster/cpu_device.hpp"
#include "recode/scene/experiment_scenes.hpp"
#include "recode/scene/motion.hpp"
#include "recode/sim/simulation.hpp"

using namespace recode;
using namespace recode::core;

namespace {

const HierarchyNode& nodeOf(const Simulation& sim, int object, int node) {
  return sim.objects()[static_cast<std::size_t>(object)].nodes()[static_cast<std::size_t>(node)];
}

}  // namespace

TEST_CASE("comb-translate-aligned: nothing tested before the tips meet, then five contacts",
          "[run][comb]") {
  const Scene scene = builtinExperimentScene("comb-translate-aligned");
  // The contact frame from the scene's own numbers (comb_test_support.hpp).
  const int contactFrame = test::combContactFrame(scene);
  REQUIRE(contactFrame > 0);

  Simulation sim(scene, RunOptions{});
  for (int k = 0; k < contactFrame; ++k) {
    const FrameReport r = sim.runFrame(k);
    INFO("frame " << k);
    CHECK(r.pairTests == 0);
    CHECK(r.contacts.empty());
  }
  const FrameReport hit = sim.runFrame(contactFrame);
  CHECK(hit.pairTests == 5);
  REQUIRE(hit.contacts.size() == 5);
  for (std::size_t i = 0; i < 5; ++i) {
    const LeafContact& c = hit.contacts[i];
    CHECK(nodeOf(sim, c.objectA, c.leafA).path == "comb A/cone " + std::to_string(i));
    CHECK(nodeOf(sim, c.objectB, c.leafB).path == "comb B/cone " + std::to_string(i));
    CHECK(c.result.interferingPixels > 0);
  }
}

TEST_CASE("hand-grasp: every finger reaches the ball and stops within one frame of contact",
          "[run][hand]") {
  // The default tessellation and the paper's coarsest level (about 1,860 triangles).
  const int triangles = GENERATE(0, 56);
  const Scene scene = builtinExperimentScene(
      "hand-grasp", triangles ? std::optional<int>(triangles) : std::nullopt);
  REQUIRE(scene.frames.has_value());
  Simulation sim(scene, RunOptions{});
  int ball = -1;
  for (std::size_t i = 0; i < sim.objects().size(); ++i)
    if (sim.objects()[i].name() == "ball")
      ball = static_cast<int>(i);
  REQUIRE(ball >= 0);

  // A finger is "<hand>/<finger>"; its blocks' paths start with that.
  const auto fingerOf = [](const std::string& path) {
    const std::size_t first = path.find('/');
    return path.substr(0, path.find('/', first + 1));
  };
  std::map<std::string, int> firstContact;  // finger -> first frame RECODE sees it touch
  std::set<std::string> atEnd;              // fingers touching the ball in the last frame
  const int last = *scene.frames - 1;
  for (int k = 0; k <= last; ++k) {
    const FrameReport r = sim.runFrame(k);
    for (const LeafContact& c : r.contacts) {
      // Only fingers meet the ball; the hands never touch each other.
      REQUIRE((c.objectA == ball || c.objectB == ball));
      const int hand = c.objectA == ball ? c.objectB : c.objectA;
      const int leaf = c.objectA == ball ? c.leafB : c.leafA;
      const std::string finger = fingerOf(nodeOf(sim, hand, leaf).path);
      REQUIRE(finger.find("palm") == std::string::npos);
      firstContact.try_emplace(finger, k);
      if (k == last)
        atEnd.insert(finger);
    }
  }
  // Two hands of five fingers, all on the ball at the end.
  CHECK(atEnd.size() == 10);
  CHECK(firstContact.size() == 10);
  // After RECODE first sees a finger touch, each of its joints turns at most one frame's
  // worth more: the finger passes into the ball by no more than one frame's motion.
  int checkedJoints = 0;
  for (const ObjectTree& hand : sim.objects()) {
    for (const HierarchyNode& node : hand.nodes()) {
      if (!node.placement.joint)
        continue;
      const std::string finger = fingerOf(node.path);
      REQUIRE(firstContact.contains(finger));
      const Joint& j = *node.placement.joint;
      const double more =
          jointAngleDegrees(j, last) - jointAngleDegrees(j, firstContact.at(finger));
      INFO(node.path << ": first contact at frame " << firstContact.at(finger));
      CHECK(more >= 0.0);
      CHECK(more <= j.rateDeg + 1e-9);
      ++checkedJoints;
    }
  }
  CHECK(checkedJoints == 30);  // 2 hands x 5 fingers x 3 knuckles
}

TEST_CASE("simulation: no interfering pair is lost by the broad phase and descent",
          "[run][random]") {
  Scene scene = builtinExperimentScene("random-cones");
  scene.objects.resize(40);  // 780 object pairs, each run through the pair algorithm below
  Simulation sim(scene, RunOptions{});
  long long found = 0;
  for (int k : {0, 37, 81}) {
    const FrameReport r = sim.runFrame(k);
    std::set<std::pair<int, int>> reported;
    for (const LeafContact& c : r.contacts)
      reported.emplace(c.objectA, c.objectB);
    // Every pair of objects (each one block) through collidePair, boxes or not.
    std::set<std::pair<int, int>> expected;
    const auto& objects = sim.objects();
    for (std::size_t a = 0; a < objects.size(); ++a)
      for (std::size_t b = a + 1; b < objects.size(); ++b) {
        const int la = objects[a].leaves()[0], lb = objects[b].leaves()[0];
        PairRequest request;
        request.frame = sim.pairFrame(objects[a].nodes()[static_cast<std::size_t>(la)].worldAabb,
                                      objects[b].nodes()[static_cast<std::size_t>(lb)].worldAabb);
        raster::CpuDevice device(request.frame.width, request.frame.height);
        if (collidePair(device, objects[a].worldMesh(la), objects[b].worldMesh(lb), request)
                .collide)
          expected.emplace(static_cast<int>(a), static_cast<int>(b));
      }
    INFO("frame " << k);
    CHECK(reported == expected);
    found += static_cast<long long>(expected.size());
  }
  CHECK(found > 0);
}

TEST_CASE("simulation: a frame's object pairs are the sweep's over every root AABB", "[run]") {
  // runFrame sweeps boxes around the OBBs and makes the AABBs only of the objects in a pair it
  // finds; the pairs it keeps must be exactly those of the root AABBs of every object, posed
  // apart here, and updateAllBounds must then give every object the AABB a full pose gives.
  const Scene scene = builtinExperimentScene("random-cones", 16);
  RunOptions options;
  options.threads = 1;
  Simulation sim(scene, options);
  std::vector<ObjectTree> posed(scene.objects.begin(), scene.objects.end());
  long long pairs = 0;
  for (int frame = 0; frame < 100; frame += 7) {
    const FrameReport report = sim.runFrame(frame);
    long long expected = 0;
    for (ObjectTree& tree : posed)
      tree.pose(frame);
    for (std::size_t a = 0; a < posed.size(); ++a)
      for (std::size_t b = a + 1; b < posed.size(); ++b)
        expected += aabbsOverlap(posed[a].root().worldAabb, posed[b].root().worldAabb) ? 1 : 0;
    INFO("frame " << frame);
    REQUIRE(report.objectPairs == expected);
    pairs += expected;
    sim.updateAllBounds();
    for (std::size_t i = 0; i < posed.size(); ++i) {
      REQUIRE(sim.objects()[i].root().worldAabb.min == posed[i].root().worldAabb.min);
      REQUIRE(sim.objects()[i].root().worldAabb.max == posed[i].root().worldAabb.max);
    }
  }
  CHECK(pairs > 20);  // the frames have pairs to find
}

TEST_CASE("simulation: the run's pixel size and the frames of pairs", "[run]") {
  Aabb bounds;
  bounds.extend(Eigen::Vector3d(-1, -2, 0));
  bounds.extend(Eigen::Vector3d(3, 2, 1));
  ViewSpec view;  // axis z: the image plane is (x, y), 4 x 4 units
  // Default: an 800 x 800 screen over the bounds grown by 5% of 4 on each side: 4.4 / 800.
  CHECK(runPixelSize(view, bounds, {}) == Approx(4.4 / 800));
  view.resolution = std::array<int, 2>{440, 220};  // square pixels: the wider of 4.4/440, 4.4/220
  CHECK(runPixelSize(view, bounds, {}) == Approx(4.4 / 220));
  view.window = ViewWindow{0, 0, 10, 5};
  view.resolution = std::array<int, 2>{100, 100};
  CHECK(runPixelSize(view, bounds, {}) == Approx(0.1));
  view.pixelSize = 0.25;  // (a scene file gives one or the other; the pixel size wins here)
  CHECK(runPixelSize(view, bounds, {}) == 0.25);
  FrameOverrides o;
  o.pixelSize = 0.5;
  CHECK(runPixelSize(view, bounds, o) == 0.5);
  FrameOverrides width;
  width.width = 50;  // the screen's width, over the scene's window: 10 / 50
  CHECK(runPixelSize(view, bounds, width) == Approx(0.2));

  Scene scene = builtinExperimentScene("comb-translate-aligned");
  const Simulation sim(scene, RunOptions{});
  CHECK(sim.pixelSize() == 0.002);
  CHECK(sim.axis() == ViewAxis::Y);
  Aabb a, b;
  a.extend(Eigen::Vector3d(0, 0, 0));
  a.extend(Eigen::Vector3d(1, 1, 1));
  b.extend(Eigen::Vector3d(0.5, -3, 0.5));
  b.extend(Eigen::Vector3d(1.2, 0, 0.7));
  const FrameSpec f = sim.pairFrame(a, b);
  CHECK(f.axis == ViewAxis::Y);
  CHECK(f.width % kPairFrameGranule == 0);
  CHECK(f.height % kPairFrameGranule == 0);
  // Square pixels of the run's size.
  CHECK((f.window.umax - f.window.umin) / f.width == Approx(0.002));
  CHECK((f.window.vmax - f.window.vmin) / f.height == Approx(0.002));
  // Along y the image plane is (z, x): the window covers z in [0, 1] and x in [0, 1.2].
  CHECK(f.window.umin < 0.0);
  CHECK(f.window.umax > 1.0);
  CHECK(f.window.vmin < 0.0);
  CHECK(f.window.vmax > 1.2);
}

TEST_CASE("a run's device factory: one device per frame size, the same contacts as the default",
          "[run][device]") {
  const Scene scene = builtinExperimentScene("comb-translate-offset");
  RunOptions withFactory;
  std::map<std::pair<int, int>, int> made;  // frame size -> devices made for it
  withFactory.deviceFactory = [&made](int width, int height) {
    ++made[{width, height}];
    return std::make_unique<raster::CpuDevice>(width, height);
  };
  Simulation byFactory(scene, withFactory);
  Simulation byDefault(scene, RunOptions{});
  long long contacts = 0;
  for (int k = 0; k < scene.frames.value_or(kDefaultRunFrames); k += 3) {  // contact from frame 30
    const FrameReport a = byFactory.runFrame(k);
    const FrameReport b = byDefault.runFrame(k);
    INFO("frame " << k);
    REQUIRE(a.contacts.size() == b.contacts.size());
    for (std::size_t i = 0; i < a.contacts.size(); ++i) {
      CHECK(a.contacts[i].leafA == b.contacts[i].leafA);
      CHECK(a.contacts[i].leafB == b.contacts[i].leafB);
      CHECK(a.contacts[i].result.interferingPixels == b.contacts[i].result.interferingPixels);
    }
    CHECK(a.stencilPixelsRead == b.stencilPixelsRead);
    contacts += static_cast<long long>(a.contacts.size());
    // A frame that made no device reports no set-up time.
    if (a.pairTests == 0)
      CHECK(a.deviceSetupUs == 0.0);
  }
  CHECK(contacts > 0);  // the comparison above compared something
  REQUIRE_FALSE(made.empty());
  for (const auto& [size, count] : made) {
    INFO(size.first << " x " << size.second);
    CHECK(count == 1);
    CHECK(size.first % kPairFrameGranule == 0);
    CHECK(size.second % kPairFrameGranule == 0);
  }
}

TEST_CASE("a device factory that returns nothing is a clear error", "[run][device]") {
  RunOptions options;
  options.deviceFactory = [](int, int) { return std::unique_ptr<raster::DepthStencilDevice>(); };
  Simulation sim(builtinExperimentScene("comb-translate-aligned"), options);
  bool threw = false;
  for (int k = 0; k < 40 && !threw; ++k) {
    try {
      (void)sim.runFrame(k);
    } catch (const std::logic_error& e) {
      threw = true;
      CHECK(std::string(e.what()).find("device factory") != std::string::npos);
    }
  }
  CHECK(threw);
}

TEST_CASE("drawOnScreen: every pair in the scene's screen; FULL reads all of it for each pair",
          "[run][screen]") {
  const Scene scene = builtinExperimentScene("hierarchy-9", 288);
  RunOptions onScreen;
  onScreen.drawOnScreen = true;
  onScreen.mor = MorMode::Full;
  Simulation screen(scene, onScreen);
  Simulation perPair(scene, RunOptions{});
  // The screen, worked out here from the scene as `recode pair` does.
  Aabb bounds;
  for (const ObjectTree& t : perPair.objects())
    bounds.extend(t.root().worldAabb);
  const FrameSpec expected = resolveFrame(scene.view, bounds, FrameOverrides{});
  CHECK(screen.pairFrame(Aabb{}, Aabb{}).width == expected.width);
  CHECK(screen.pairFrame(Aabb{}, Aabb{}).height == expected.height);
  long long contacts = 0;
  for (int k = 0; k < scene.frames.value_or(kDefaultRunFrames); ++k) {
    const FrameReport s = screen.runFrame(k);
    const FrameReport p = perPair.runFrame(k);
    INFO("frame " << k);
    CHECK(s.pairTests == p.pairTests);
    CHECK(s.stencilPixelsRead ==
          s.pairTests * static_cast<long long>(expected.width) * expected.height);
    REQUIRE(s.contacts.size() == p.contacts.size());
    for (std::size_t i = 0; i < s.contacts.size(); ++i) {
      CHECK(s.contacts[i].leafA == p.contacts[i].leafA);
      CHECK(s.contacts[i].leafB == p.contacts[i].leafB);
    }
    contacts += static_cast<long long>(s.contacts.size());
  }
  CHECK(contacts > 0);
}
