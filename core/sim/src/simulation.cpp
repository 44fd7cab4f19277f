// One frame of a scene: pose, boxes, sort and sweep, tree descent, pair algorithm per leaf pair.
#include "recode/sim/simulation.hpp"

#include "device_leaf_boxes.hpp"
#include "frame_leaf_blocks.hpp"
#include "pair_tests.hpp"
#include "recode/refine/proven_apart.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

namespace recode::core {

namespace {

using Clock = std::chrono::steady_clock;

double microseconds(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::micro>(to - from).count();
}

// n rounded up to a multiple of kPairFrameGranule, at most the largest framebuffer.
int roundUpToGranule(int n) {
  const int rounded = (n + kPairFrameGranule - 1) / kPairFrameGranule * kPairFrameGranule;
  return std::min(rounded, raster::kMaxFramebufferSize);
}

// The object pairs whose root AABBs overlap, in increasing order, as the sort and sweep over
// those AABBs would list them, without making the AABB of an object that is near no other: the
// sweep runs on the boxes around the objects' OBBs (which hold the AABBs), and only the objects
// of a pair it finds get their AABBs (every vertex transformed), by which its pairs are then
// filtered. Every object's OBBs are brought up to its pose; the AABBs of the others are left
// stale (nothing reads them this frame). The AABBs are made on the runner's threads: each
// object's own, and with large meshes they are the frame's largest serial step.
std::vector<std::pair<int, int>> overlappingObjects(
    std::vector<ObjectTree>& objects, SweepAndPrune& broadPhase, PairTestRunner& runner,
    const std::function<void(const std::vector<std::size_t>&)>& leafBoxesFirst) {
  std::vector<Aabb> around;
  around.reserve(objects.size());
  for (ObjectTree& object : objects) {
    object.updateObbs();
    around.push_back(object.boxAroundObb());
  }
  std::vector<std::pair<int, int>> pairs = broadPhase.update(around);
  std::vector<bool> needed(objects.size(), false);
  for (const auto& [a, b] : pairs)
    needed[static_cast<std::size_t>(a)] = needed[static_cast<std::size_t>(b)] = true;
  std::vector<std::size_t> inPairs;
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (needed[i])
      inPairs.push_back(i);
  // A device that keeps the blocks makes the stale leaves' boxes first; updateAabbs then makes
  // the rest (every leaf's, without one) and the nodes above.
  if (leafBoxesFirst)
    leafBoxesFirst(inPairs);
  runner.forEach(inPairs.size(), [&](std::size_t k) { objects[inPairs[k]].updateAabbs(); });
  std::erase_if(pairs, [&objects](const std::pair<int, int>& p) {
    return !aabbsOverlap(objects[static_cast<std::size_t>(p.first)].root().worldAabb,
                         objects[static_cast<std::size_t>(p.second)].root().worldAabb);
  });
  return pairs;
}

// Builds every leaf's triangle hierarchy on the runner's threads, so that no frame pays for
// one: a block that first meets another mid-run would otherwise build its hierarchy inside
// that frame's collision time, a spike in the frames where blocks come into contact (as a
// BVH model is built when it is made, not at its first query).
void buildTriangleHierarchies(const std::vector<ObjectTree>& objects, PairTestRunner& runner) {
  std::vector<std::pair<std::size_t, int>> leaves;
  for (std::size_t o = 0; o < objects.size(); ++o)
    for (const int leaf : objects[o].leaves())
      leaves.emplace_back(o, leaf);
  runner.forEach(leaves.size(), [&](std::size_t k) {
    (void)objects[leaves[k].first].triangleHierarchy(leaves[k].second);
  });
}

const HierarchyNode& nodeOf(const std::vector<ObjectTree>& objects, int object, int index) {
  return objects[static_cast<std::size_t>(object)].nodes()[static_cast<std::size_t>(index)];
}

// A leaf as the skip-apart test reads it: its own mesh, its world pose and its world box.
PosedBlock posedLeaf(const std::vector<ObjectTree>& objects, int object, int leaf) {
  const HierarchyNode& n = nodeOf(objects, object, leaf);
  return {n.localMesh, n.world, n.worldAabb, n.localExtent};
}

// Counts one pair test into the report, `skipped` when the skip-apart mode proved it apart
// and drew nothing; a contact keeps its result (the runner has cleared its case map).
void addPairTest(FrameReport& report, const PairTask& task, PairResult result, bool skipped) {
  ++report.pairTests;
  report.pairTestsSkipped += skipped ? 1 : 0;
  report.stencilPixelsRead += result.stencilPixelsRead;
  report.depthPixelsRead += result.depthPixelsRead;
  if (result.collide)
    report.contacts.push_back({task.objectA, task.objectB, task.leaves.leafA, task.leaves.leafB,
                               std::move(result), task.request.frame.axis});
}

// Called in a handler: rethrows the exception being handled, an invalid_argument with the
// frame and the two blocks named.
[[noreturn]] void rethrowNamingPair(const std::vector<ObjectTree>& objects, int frame,
                                    const PairTask& task) {
  try {
    throw;
  } catch (const std::invalid_argument& e) {
    const auto path = [&](int object, int leaf) {
      return objects[static_cast<std::size_t>(object)].nodes()[static_cast<std::size_t>(leaf)].path;
    };
    throw std::invalid_argument("frame " + std::to_string(frame) + ", blocks \"" +
                                path(task.objectA, task.leaves.leafA) + "\" and \"" +
                                path(task.objectB, task.leaves.leafB) + "\": " + e.what());
  }
}

// The error of a frame over RunOptions::maxPairTestsPerFrame; `listed` counts the tests listed
// when the limit was crossed (the frame's total is not known: listing stops there).
std::string tooManyPairTests(int frame, std::size_t listed, long long limit) {
  return "frame " + std::to_string(frame) + ": at least " + std::to_string(listed) +
         " block pairs have overlapping boxes, over the limit of " + std::to_string(limit) +
         " pair tests per frame (a frame holds all its tests at once; raise it with "
         "--max-pair-tests, or space the objects out)";
}

// The tasks the skip-apart mode proves apart (1) from each leaf's own mesh and pose, before any
// world mesh is made or device cleared for them; none in the other modes.
std::vector<char> provenApartTasks(const std::vector<ObjectTree>& objects,
                                   const std::vector<PairTask>& tasks, const RunOptions& options,
                                   PairTestRunner& runner) {
  std::vector<char> skipped(tasks.size(), 0);
  if (options.pairMode == PairMode::SkipApart)
    runner.forEach(tasks.size(), [&](std::size_t i) {
      skipped[i] = provenApart(posedLeaf(objects, tasks[i].objectA, tasks[i].leaves.leafA),
                               posedLeaf(objects, tasks[i].objectB, tasks[i].leaves.leafB),
                               tasks[i].request.frame);
    });
  return skipped;
}

// The drawn leaves' world blocks, each made once (or kept from the last frame), attached to
// the tasks that draw them.
void attachWorldBlocks(FrameLeafBlocks& blocks, const std::vector<ObjectTree>& objects,
                       PairTestRunner& runner, std::vector<PairTask>& drawn) {
  blocks.start();
  std::vector<std::pair<std::size_t, std::size_t>> slots;  // each drawn task's two blocks
  slots.reserve(drawn.size());
  for (const PairTask& task : drawn)
    slots.emplace_back(blocks.need(task.objectA, task.leaves.leafA),
                       blocks.need(task.objectB, task.leaves.leafB));
  blocks.make(objects, runner);
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    drawn[i].blockA = blocks.at(slots[i].first);
    drawn[i].blockB = blocks.at(slots[i].second);
  }
}

// Every task's result into the report, in task order: a skipped pair's result is made here, a
// drawn one is the next of `outcomes` (the drawn tasks' in order); the tests a device error
// left unrun come after the last outcome. An outcome's error is rethrown naming its pair.
void collectOutcomes(const std::vector<ObjectTree>& objects, int frame,
                     const std::vector<PairTask>& tasks, const std::vector<char>& skipped,
                     std::vector<PairOutcome>& outcomes, FrameReport& report) {
  std::size_t next = 0;
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    const PairTask& task = tasks[i];
    if (skipped[i]) {
      addPairTest(report, task,
                  skippedResult(nodeOf(objects, task.objectA, task.leaves.leafA).worldAabb,
                                nodeOf(objects, task.objectB, task.leaves.leafB).worldAabb,
                                task.request.frame),
                  true);
      continue;
    }
    if (next == outcomes.size())
      break;
    PairOutcome& outcome = outcomes[next++];
    if (outcome.error) {
      try {
        std::rethrow_exception(outcome.error);
      } catch (...) {
        rethrowNamingPair(objects, frame, task);
      }
    }
    addPairTest(report, task, std::move(outcome.result), false);
  }
}

}  // namespace

double runPixelSize(const ViewSpec& view, const Aabb& bounds, const FrameOverrides& overrides) {
  // A given pixel size must fit the scene's screen (its window, else the default window over
  // every object at frame 0), as for `recode pair`.
  const auto fitting = [&](double pixelSize) {
    checkPixelSizeFits(pixelSize,
                       view.window ? *view.window : defaultWindow(view.axis, bounds, std::nullopt));
    return pixelSize;
  };
  if (overrides.pixelSize)
    return fitting(*overrides.pixelSize);
  if (!overrides.width && view.pixelSize)
    return fitting(*view.pixelSize);
  const FrameSpec screen = resolveFrame(view, bounds, overrides);
  const ViewWindow& w = screen.window;
  return std::max((w.umax - w.umin) / screen.width, (w.vmax - w.vmin) / screen.height);
}

Simulation::Simulation(const Scene& scene, RunOptions options) : options_(std::move(options)) {
  // A run decides every pair with RECODE's passes, which need convex blocks.
  requireConvexBlocks(scene, "a simulation (recode run, the hierarchy page of recode explain)");
  if (options_.threads < 0)
    throw std::invalid_argument("the run's thread count " + std::to_string(options_.threads) +
                                " is negative (0: all hardware threads)");
  if (options_.maxPairTestsPerFrame < 1)
    throw std::invalid_argument("the run's limit of pair tests per frame " +
                                std::to_string(options_.maxPairTestsPerFrame) + " is not positive");
  if (options_.batchDevicesPerSize < 1 || options_.batchDevicesPerSize > kMaxBatchDevicesPerSize)
    throw std::invalid_argument("the run's devices per frame size " +
                                std::to_string(options_.batchDevicesPerSize) + " is not in 1.." +
                                std::to_string(kMaxBatchDevicesPerSize));
  pairTests_ = std::make_unique<PairTestRunner>(options_);
  leafBlocks_ = std::make_unique<FrameLeafBlocks>();
  axis_ = scene.view.axis;
  objects_.reserve(scene.objects.size());
  Aabb bounds;
  for (const SceneObject& object : scene.objects) {
    objects_.emplace_back(object);
    bounds.extend(objects_.back().root().worldAabb);
  }
  buildTriangleHierarchies(objects_, *pairTests_);
  pixelSize_ = runPixelSize(scene.view, bounds, options_.overrides);
  if (options_.drawOnScreen)
    screen_ = resolveFrame(scene.view, bounds, options_.overrides);
  if (options_.drawOnScreen && options_.viewAxisRule != ViewAxisRule::Scene)
    throw std::invalid_argument(std::string("the view axis rule '") +
                                std::string(toString(options_.viewAxisRule)) +
                                "' needs frames around each pair; drawing on the scene's screen "
                                "keeps the scene's axis (use the view axis rule 'scene')");
  if (!(pixelSize_ > 0.0) || !std::isfinite(pixelSize_))
    throw std::invalid_argument("the run's pixel size " + std::to_string(pixelSize_) +
                                " is not a positive finite number");
}

Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;

int Simulation::threads() const {
  return pairTests_->concurrency();
}

void Simulation::updateAllBounds() {
  for (ObjectTree& object : objects_)
    object.updateAabbs();
}

std::size_t Simulation::triangleCount() const {
  std::size_t n = 0;
  for (const ObjectTree& object : objects_)
    n += object.triangleCount();
  return n;
}

FrameSpec granularPairFrame(ViewAxis axis, double pixelSize, const Aabb& a, const Aabb& b) {
  Aabb both = a;
  both.extend(b);
  FrameSpec f = frameFromPixelSize(axis, defaultWindow(axis, both, std::nullopt), pixelSize);
  const int width = roundUpToGranule(f.width), height = roundUpToGranule(f.height);
  const double du = 0.5 * (width - f.width) * pixelSize;
  const double dv = 0.5 * (height - f.height) * pixelSize;
  f.window = {f.window.umin - du, f.window.vmin - dv, f.window.umax + du, f.window.vmax + dv};
  f.width = width;
  f.height = height;
  return f;
}

FrameSpec Simulation::pairFrame(const Aabb& a, const Aabb& b) const {
  if (screen_)
    return *screen_;
  return granularPairFrame(axis_, pixelSize_, a, b);
}

FrameSpec Simulation::leafPairFrame(const HierarchyNode& a, const HierarchyNode& b) const {
  if (screen_ || options_.viewAxisRule == ViewAxisRule::Scene)
    return pairFrame(a.worldAabb, b.worldAabb);
  const ViewAxis axis = chooseViewAxis(
      options_.viewAxisRule, axis_, {a.worldAabb, b.worldAabb, a.worldObb, b.worldObb, pixelSize_});
  return granularPairFrame(axis, pixelSize_, a.worldAabb, b.worldAabb);
}

FrameReport Simulation::runFrame(int frame) {
  FrameReport report;
  report.frame = frame;
  const Clock::time_point start = Clock::now();
  for (ObjectTree& object : objects_)
    object.setFrame(frame);
  const Clock::time_point posed = Clock::now();

  // Once the factory has made a device for a pair test, and it is one that reduces boxes where
  // it keeps the blocks: a device of its own for the leaves' boxes from this frame on, with
  // every leaf's mesh put on it now (counted as device set-up, as making devices is).
  if (!boxDeviceTried_ && options_.deviceFactory && options_.leafBoxesOnDevice &&
      pairTests_->anyDevice() != nullptr) {
    boxDeviceTried_ = true;
    if (dynamic_cast<const raster::PosedBoxReducer*>(pairTests_->anyDevice()) != nullptr) {
      const Clock::time_point t = Clock::now();
      boxDevice_ = options_.deviceFactory(8, 8);
      boxReducer_ = dynamic_cast<raster::PosedBoxReducer*>(boxDevice_.get());
      if (boxReducer_ == nullptr)
        boxDevice_.reset();
      else
        detail::keepLeafMeshes(objects_, *boxDevice_, *boxReducer_);
      report.deviceSetupUs += microseconds(t, Clock::now());
    }
  }
  const raster::TransferCounters boxesBefore =
      boxDevice_ ? boxDevice_->transfers() : raster::TransferCounters{};
  std::function<void(const std::vector<std::size_t>&)> leafBoxesFirst;
  if (boxReducer_ != nullptr)
    leafBoxesFirst = [this](const std::vector<std::size_t>& which) {
      detail::reduceLeafBoxes(objects_, which, *boxDevice_, *boxReducer_);
    };
  const std::vector<std::pair<int, int>> candidates =
      overlappingObjects(objects_, broadPhase_, *pairTests_, leafBoxesFirst);
  const raster::TransferCounters boxesAfter =
      boxDevice_ ? boxDevice_->transfers() : raster::TransferCounters{};
  report.objectPairs = static_cast<long long>(candidates.size());
  const std::vector<PairTask> tasks = listPairTasks(candidates, frame, report);
  const std::vector<char> skipped = provenApartTasks(objects_, tasks, options_, *pairTests_);
  std::vector<PairTask> drawn;
  for (std::size_t i = 0; i < tasks.size(); ++i)
    if (!skipped[i])
      drawn.push_back(tasks[i]);
  attachWorldBlocks(*leafBlocks_, objects_, *pairTests_, drawn);

  const PairTestRunner::DeviceSetup setup = pairTests_->reserveDevices(drawn);
  report.deviceSetupUs += setup.us;
  const raster::TransferCounters before = pairTests_->transfers();
  std::vector<PairOutcome> outcomes = pairTests_->run(drawn, setup.usable);
  const raster::TransferCounters after = pairTests_->transfers();
  // The boxes' round is the frame's too.
  report.submissions =
      after.submissions - before.submissions + boxesAfter.submissions - boxesBefore.submissions;
  report.readbackBytes = after.readbackBytes - before.readbackBytes + boxesAfter.readbackBytes -
                         boxesBefore.readbackBytes;
  report.deviceWaitUs = after.waitUs - before.waitUs + boxesAfter.waitUs - boxesBefore.waitUs;
  raster::TransferCounters counted = after.since(before);
  counted += boxesAfter.since(boxesBefore);
  report.dispatches = counted.dispatches;
  report.stageUs = counted.stageUs;
  collectOutcomes(objects_, frame, tasks, skipped, outcomes, report);
  if (setup.error) {
    try {
      std::rethrow_exception(setup.error);
    } catch (...) {
      rethrowNamingPair(objects_, frame, drawn[setup.usable]);
    }
  }
  const Clock::time_point done = Clock::now();
  report.collisionUs = microseconds(posed, done) - report.deviceSetupUs;
  report.frameUs = microseconds(start, done) - report.deviceSetupUs;
  return report;
}

std::vector<PairTask> Simulation::listPairTasks(const std::vector<std::pair<int, int>>& candidates,
                                                int frame, FrameReport& report) const {
  // In the order of the sequential loop (candidates, then each descent's leaf pairs): the
  // results are read back in this order whatever threads ran them.
  std::vector<PairTask> tasks;
  std::vector<LeafPair> leafPairs;
  for (const auto& [ia, ib] : candidates) {
    const ObjectTree& a = objects_[static_cast<std::size_t>(ia)];
    const ObjectTree& b = objects_[static_cast<std::size_t>(ib)];
    leafPairs.clear();
    // One more than the limit allows is enough to know the frame is over it.
    const auto room = static_cast<std::size_t>(options_.maxPairTestsPerFrame) - tasks.size() + 1;
    report.boxTests += descendPair(a, b, leafPairs, room);
    if (static_cast<long long>(tasks.size() + leafPairs.size()) > options_.maxPairTestsPerFrame)
      throw std::invalid_argument(
          tooManyPairTests(frame, tasks.size() + leafPairs.size(), options_.maxPairTestsPerFrame));
    for (const LeafPair& lp : leafPairs) {
      PairTask task{ia, ib, lp, nullptr, nullptr, {}, true};
      try {
        task.request.frame = leafPairFrame(a.nodes()[static_cast<std::size_t>(lp.leafA)],
                                           b.nodes()[static_cast<std::size_t>(lp.leafB)]);
      } catch (...) {
        rethrowNamingPair(objects_, frame, task);
      }
      task.request.mor = options_.mor;
      task.request.contact = options_.contact;
      task.keepContactPoints = options_.keepContactPoints;
      // The report keeps no case map; the points only when asked to.
      task.request.keepPixels = options_.keepContactPoints || !options_.deviceSummaries;
      tasks.push_back(task);
    }
  }
  return tasks;
}

}  // namespace recode::core
