#pragma once
// What every scene detector of the bench does alike (scene_detector.hpp): list the leaves of
// the trees it was made from, refuse trees of another shape at detect(), and hand back leaf
// pairs in the interface's order with the time they took. Internal to verify/peers.

#include <chrono>
#include <cstddef>
#include <vector>

#include "recode/sim/hierarchy.hpp"
#include "recode/verify/scene_detector.hpp"

namespace recode::verify {

// One convex block: a leaf `leaf` (node index) of object `object`.
struct LeafRef {
  int object = 0;
  int leaf = 0;
};

class SceneLeaves {
 public:
  // Every leaf of every object, object by object, in ObjectTree::leaves() order.
  explicit SceneLeaves(const std::vector<core::ObjectTree>& objects);

  [[nodiscard]] const std::vector<LeafRef>& all() const { return leaves_; }
  [[nodiscard]] int size() const { return static_cast<int>(leaves_.size()); }
  [[nodiscard]] const LeafRef& operator[](int i) const {
    return leaves_[static_cast<std::size_t>(i)];
  }
  // The leaf's node in `objects` (trees of the same shape, see checkSameShape).
  [[nodiscard]] static const core::HierarchyNode& node(const std::vector<core::ObjectTree>& objects,
                                                       const LeafRef& leaf);

  // Throws std::invalid_argument unless `objects` has as many trees, with as many nodes and
  // the same leaves, as the trees the list was made from: node indices in the answers, and
  // the shapes a detector built from them, would otherwise be wrong without a sign.
  void checkSameShape(const std::vector<core::ObjectTree>& objects) const;

 private:
  std::vector<LeafRef> leaves_;
  std::vector<std::size_t> nodeCounts_;  // per object
};

// The pair of two leaves of different objects, the lower object first.
[[nodiscard]] LeafPairId orderedPair(const LeafRef& a, const LeafRef& b);

// Sorts and drops repeats (a library may report a pair more than once).
void sortUnique(std::vector<LeafPairId>& pairs);

// The end of a detect() timed from `start`: stops the clock first, so that collisionUs is the
// detector's own work and not this bookkeeping, then hands back `pairs` sorted, without repeats.
[[nodiscard]] Detection finishDetection(std::vector<LeafPairId> pairs,
                                        std::chrono::steady_clock::time_point start);

}  // namespace recode::verify
