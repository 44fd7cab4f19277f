// The common bookkeeping of the bench's scene detectors (scene_leaves.hpp).
#include "scene_leaves.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace recode::verify {

SceneLeaves::SceneLeaves(const std::vector<core::ObjectTree>& objects) {
  for (std::size_t o = 0; o < objects.size(); ++o) {
    nodeCounts_.push_back(objects[o].nodes().size());
    for (const int leaf : objects[o].leaves())
      leaves_.push_back({static_cast<int>(o), leaf});
  }
}

const core::HierarchyNode& SceneLeaves::node(const std::vector<core::ObjectTree>& objects,
                                             const LeafRef& leaf) {
  return objects[static_cast<std::size_t>(leaf.object)]
      .nodes()[static_cast<std::size_t>(leaf.leaf)];
}

void SceneLeaves::checkSameShape(const std::vector<core::ObjectTree>& objects) const {
  if (objects.size() != nodeCounts_.size())
    throw std::invalid_argument("scene detector: made from " + std::to_string(nodeCounts_.size()) +
                                " objects, handed " + std::to_string(objects.size()));
  for (std::size_t o = 0; o < objects.size(); ++o)
    if (objects[o].nodes().size() != nodeCounts_[o])
      throw std::invalid_argument(
          "scene detector: object " + std::to_string(o) + " ('" + objects[o].name() + "') has " +
          std::to_string(objects[o].nodes().size()) +
          " nodes, the detector was made from one with " + std::to_string(nodeCounts_[o]));
  for (const LeafRef& leaf : leaves_)
    if (!node(objects, leaf).isLeaf())
      throw std::invalid_argument("scene detector: node " + std::to_string(leaf.leaf) +
                                  " of object " + std::to_string(leaf.object) +
                                  " is no longer a leaf");
}

LeafPairId orderedPair(const LeafRef& a, const LeafRef& b) {
  if (a.object < b.object)
    return {a.object, a.leaf, b.object, b.leaf};
  return {b.object, b.leaf, a.object, a.leaf};
}

void sortUnique(std::vector<LeafPairId>& pairs) {
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

Detection finishDetection(std::vector<LeafPairId> pairs,
                          std::chrono::steady_clock::time_point start) {
  const auto stop = std::chrono::steady_clock::now();
  Detection detection;
  detection.pairs = std::move(pairs);
  sortUnique(detection.pairs);
  detection.collisionUs = std::chrono::duration<double, std::micro>(stop - start).count();
  return detection;
}

}  // namespace recode::verify
