// One frame of a scene: pose, boxes, sort and sweep, tree descent, pair algorithm per leaf pair.
#include "recode/sim/simulation.hpp"

#include "recode/raster/cpu_device.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
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

// Every object's boxes brought up to its pose; returns the roots' boxes for the broad phase.
std::vector<Aabb> updateRootBoxes(std::vector<ObjectTree>& objects) {
  std::vector<Aabb> roots;
  roots.reserve(objects.size());
  for (ObjectTree& object : objects) {
    object.updateBounds();
    roots.push_back(object.root().worldAabb);
  }
  return roots;
}

// World meshes of the leaves drawn this frame, made once per leaf.
class LeafMeshes {
 public:
  explicit LeafMeshes(const std::vector<ObjectTree>& objects) : objects_(objects) {}

  const TriangleMesh& of(int object, int leaf) {
    auto [it, added] = meshes_.try_emplace({object, leaf});
    if (added)
      it->second = objects_[static_cast<std::size_t>(object)].worldMesh(leaf);
    return it->second;
  }

 private:
  const std::vector<ObjectTree>& objects_;
  std::map<std::pair<int, int>, TriangleMesh> meshes_;
};

// Counts one pair test into the report; a contact keeps its result without the case map, to
// keep reports small.
void addPairTest(FrameReport& report, int ia, int ib, const LeafPair& lp, PairResult result) {
  ++report.pairTests;
  report.stencilPixelsRead += result.stencilPixelsRead;
  report.depthPixelsRead += result.depthPixelsRead;
  if (result.collide) {
    result.caseMap = {};
    report.contacts.push_back({ia, ib, lp.leafA, lp.leafB, std::move(result)});
  }
}

}  // namespace

double runPixelSize(const ViewSpec& view, const Aabb& bounds, const FrameOverrides& overrides) {
  if (overrides.pixelSize)
    return *overrides.pixelSize;
  if (!overrides.width && view.pixelSize)
    return *view.pixelSize;
  const FrameSpec screen = resolveFrame(view, bounds, overrides);
  const ViewWindow& w = screen.window;
  return std::max((w.umax - w.umin) / screen.width, (w.vmax - w.vmin) / screen.height);
}

Simulation::Simulation(const Scene& scene, RunOptions options) : options_(std::move(options)) {
  axis_ = scene.view.axis;
  objects_.reserve(scene.objects.size());
  Aabb bounds;
  for (const SceneObject& object : scene.objects) {
    objects_.emplace_back(object);
    bounds.extend(objects_.back().root().worldAabb);
  }
  pixelSize_ = runPixelSize(scene.view, bounds, options_.overrides);
  if (options_.drawOnScreen)
    screen_ = resolveFrame(scene.view, bounds, options_.overrides);
  if (!(pixelSize_ > 0.0) || !std::isfinite(pixelSize_))
    throw std::invalid_argument("the run's pixel size " + std::to_string(pixelSize_) +
                                " is not a positive finite number");
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

raster::DepthStencilDevice& Simulation::deviceFor(int width, int height, double& setupUs) {
  // A handful of sizes serve most runs; a run whose pairs keep changing size stays bounded.
  if (devices_.size() > 16 && !devices_.contains({width, height}))
    devices_.clear();
  auto& slot = devices_[{width, height}];
  if (!slot) {
    const Clock::time_point start = Clock::now();
    if (options_.deviceFactory)
      slot = options_.deviceFactory(width, height);
    else
      slot = std::make_unique<raster::CpuDevice>(width, height);
    if (!slot)
      throw std::logic_error("the run's device factory returned no device");
    setupUs += microseconds(start, Clock::now());
  }
  return *slot;
}

FrameReport Simulation::runFrame(int frame) {
  FrameReport report;
  report.frame = frame;
  const Clock::time_point start = Clock::now();
  for (ObjectTree& object : objects_)
    object.setFrame(frame);
  const Clock::time_point posed = Clock::now();

  const std::vector<std::pair<int, int>> candidates = broadPhase_.update(updateRootBoxes(objects_));
  report.objectPairs = static_cast<long long>(candidates.size());

  LeafMeshes meshes(objects_);
  std::vector<LeafPair> leafPairs;
  for (const auto& [ia, ib] : candidates) {
    const ObjectTree& a = objects_[static_cast<std::size_t>(ia)];
    const ObjectTree& b = objects_[static_cast<std::size_t>(ib)];
    leafPairs.clear();
    report.boxTests += descendPair(a, b, leafPairs);
    for (const LeafPair& lp : leafPairs) {
      const HierarchyNode& na = a.nodes()[static_cast<std::size_t>(lp.leafA)];
      const HierarchyNode& nb = b.nodes()[static_cast<std::size_t>(lp.leafB)];
      PairResult result;
      try {
        PairRequest request;
        request.frame = pairFrame(na.worldAabb, nb.worldAabb);
        request.mor = options_.mor;
        request.contact = options_.contact;
        raster::DepthStencilDevice& device =
            deviceFor(request.frame.width, request.frame.height, report.deviceSetupUs);
        result = collidePair(device, meshes.of(ia, lp.leafA), meshes.of(ib, lp.leafB), request);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("frame " + std::to_string(frame) + ", blocks \"" + na.path +
                                    "\" and \"" + nb.path + "\": " + e.what());
      }
      addPairTest(report, ia, ib, lp, std::move(result));
    }
  }
  const Clock::time_point done = Clock::now();
  report.collisionUs = microseconds(posed, done) - report.deviceSetupUs;
  report.frameUs = microseconds(start, done) - report.deviceSetupUs;
  return report;
}

}  // namespace recode::core
