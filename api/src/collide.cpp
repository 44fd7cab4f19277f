// collide(): the descent of two block trees, then the pair algorithm per block pair, merged into
// one result.
#include <chrono>
#include <utility>

#include "recode/api/collision.hpp"
#include "recode/refine/adaptive.hpp"
#include "recode/refine/proven_apart.hpp"
#include "recode/sim/leaf_block.hpp"

namespace recode {

namespace {

using Clock = std::chrono::steady_clock;

// Adds one block pair's contact region to the object pair's.
void merge(core::ContactRegion& into, const core::ContactRegion& from) {
  into.points.insert(into.points.end(), from.points.begin(), from.points.end());
  into.box.extend(from.box);
  into.pixels += from.pixels;
  into.area += from.area;
  into.maxDepth = std::max(into.maxDepth, from.maxDepth);
  into.collapsedPixels += from.collapsedPixels;
}

struct PairAnswer {
  core::PairResult pair;
  core::FrameSpec frame;
  int level = 0;
  bool atLimit = false;
};

// One block pair in the request's mode.
PairAnswer decidePair(raster::DepthStencilDevice& device, const core::PairBlock& a,
                      const core::PairBlock& b, const core::PairRequest& pair,
                      core::PairMode mode) {
  PairAnswer out;
  out.frame = pair.frame;
  switch (mode) {
    case core::PairMode::Reference:
    case core::PairMode::SkipApart:  // collide() has ruled the pair in
      out.pair = core::collidePair(device, a, b, pair);
      return out;
    case core::PairMode::Conservative:
      out.pair = core::collideConservative(device, a.mesh(), b.mesh(), pair).pair;
      return out;
    case core::PairMode::Adaptive:
      break;
  }
  thread_local core::AdaptivePairTester tester;
  core::AdaptiveResult r = tester.collide(device, a, b, pair);
  out.atLimit = r.verdict == core::PairVerdict::ApartAtLimit;
  if (r.contact) {
    out.pair = std::move(*r.contact);
    out.frame = r.contactFrame;
    out.level = r.contactLevel;
  } else if (r.reference) {
    out.pair = std::move(*r.reference);
  }
  out.pair.collide = r.verdict == core::PairVerdict::Collide;
  return out;
}

}  // namespace

bool collide(const CollisionObject& a, const CollisionObject& b, const CollisionRequest& request,
             CollisionResult& result, DevicePool& devices) {
  result.clear();
  const Clock::time_point start = Clock::now();
  const double setupBefore = devices.setupUs();
  std::vector<core::LeafPair> leafPairs;
  result.boxTests = core::descendPair(a.tree(), b.tree(), leafPairs);
  for (const core::LeafPair& lp : leafPairs) {
    const core::HierarchyNode& na = a.tree().nodes()[static_cast<std::size_t>(lp.leafA)];
    const core::HierarchyNode& nb = b.tree().nodes()[static_cast<std::size_t>(lp.leafB)];
    core::PairRequest pair;
    pair.frame = chooseFrame(na.worldAabb, nb.worldAabb, request);
    pair.mor = request.mor;
    pair.contact = request.contact;
    pair.normal = request.normal;
    // Proven apart from the leaves' own meshes and poses: no world mesh is made for a skipped
    // pair.
    if (request.mode == core::PairMode::SkipApart &&
        core::provenApart(core::PosedBlock{na.localMesh, na.world, na.worldAabb, na.localExtent},
                          core::PosedBlock{nb.localMesh, nb.world, nb.worldAabb, nb.localExtent},
                          pair.frame)) {
      ++result.blockPairsSkipped;
      continue;
    }
    const core::LeafBlock blockA(a.tree(), lp.leafA);
    const core::LeafBlock blockB(b.tree(), lp.leafB);
    raster::DepthStencilDevice& device = devices.device(pair.frame.width, pair.frame.height);
    PairAnswer answer = decidePair(device, blockA.block, blockB.block, pair, request.mode);
    core::PairResult& r = answer.pair;
    ++result.blockPairsDrawn;
    result.apartAtLimit += answer.atLimit ? 1 : 0;
    if (!r.collide)
      continue;
    result.collide = true;
    result.interferingPixels += r.interferingPixels;
    merge(result.contact, r.contact);
    result.contacts.push_back({static_cast<std::size_t>(a.geometry().blockOfNode(lp.leafA)),
                               static_cast<std::size_t>(b.geometry().blockOfNode(lp.leafB)),
                               answer.frame, std::move(r), answer.level});
  }
  result.deviceSetupUs = devices.setupUs() - setupBefore;
  result.collisionUs = std::chrono::duration<double, std::micro>(Clock::now() - start).count() -
                       result.deviceSetupUs;
  return result.collide;
}

bool collide(const CollisionObject& a, const CollisionObject& b, const CollisionRequest& request,
             CollisionResult& result) {
  // One pool per thread: calls from one thread reuse its CPU devices, threads share none.
  thread_local DevicePool cpuDevices;
  return collide(a, b, request, result, cpuDevices);
}

}  // namespace recode
