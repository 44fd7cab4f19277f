#pragma once
// The broad phase over all objects of a scene: sort and sweep on world AABBs. The boxes are
// kept sorted by their lower end along one axis; each frame the previous order is re-sorted
// by insertion sort, which is linear when objects move little between frames (the usual
// case), and a sweep along the sorted list finds the pairs whose boxes overlap on all three
// axes. A scene of hundreds of objects thus never tests all pairs.

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "recode/geometry/mesh.hpp"

namespace recode::core {

struct BroadPhaseStats {
  long long swaps = 0;          // insertion-sort moves this update (0 when nothing reordered)
  long long intervalTests = 0;  // pairs met in the sweep (overlapping on the sweep axis)
};

class SweepAndPrune {
 public:
  // Overlapping pairs (i < j, indices into `boxes`) in increasing order: every pair of boxes
  // that overlap as closed boxes (touching counts), none other; empty boxes overlap nothing.
  // The first call (or a call with a different number of boxes) chooses the sweep axis, the
  // one along which the box centres spread most, and sorts from scratch; later calls start
  // from the previous order.
  [[nodiscard]] std::vector<std::pair<int, int>> update(std::span<const Aabb> boxes);

  [[nodiscard]] int axis() const { return axis_; }
  [[nodiscard]] const BroadPhaseStats& stats() const { return stats_; }

 private:
  std::vector<int> order_;
  int axis_ = 0;
  BroadPhaseStats stats_;
};

}  // namespace recode::core
