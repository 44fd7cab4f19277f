// collide(): the descent of two block trees, then the pair algorithm per block pair, merged into
// one result.
#include <chrono>
#include <utility>

#include "recode/api/collision.hpp"

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
    raster::DepthStencilDevice& device = devices.device(pair.frame.width, pair.frame.height);
    core::PairResult r =
        core::collidePair(device, a.tree().worldMesh(lp.leafA), b.tree().worldMesh(lp.leafB), pair);
    ++result.blockPairsDrawn;
    if (!r.collide)
      continue;
    result.collide = true;
    result.interferingPixels += r.interferingPixels;
    merge(result.contact, r.contact);
    result.contacts.push_back({static_cast<std::size_t>(a.geometry().blockOfNode(lp.leafA)),
                               static_cast<std::size_t>(b.geometry().blockOfNode(lp.leafB)),
                               pair.frame, std::move(r)});
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
