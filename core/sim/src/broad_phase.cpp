// Sort and sweep with an incremental (insertion) sort across frames.
#include "recode/sim/broad_phase.hpp"

#include <algorithm>
#include <numeric>

namespace recode::core {

std::vector<std::pair<int, int>> SweepAndPrune::update(std::span<const Aabb> boxes) {
  stats_ = {};
  const int n = static_cast<int>(boxes.size());
  if (static_cast<int>(order_.size()) != n) {
    // New set of objects: pick the axis of greatest spread of the box centres.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero(), square = Eigen::Vector3d::Zero();
    int counted = 0;
    for (const Aabb& b : boxes) {
      if (b.isEmpty())
        continue;
      const Eigen::Vector3d c = b.center();
      mean += c;
      square += c.cwiseProduct(c);
      ++counted;
    }
    axis_ = 0;
    if (counted > 0) {
      mean /= counted;
      const Eigen::Vector3d variance = square / counted - mean.cwiseProduct(mean);
      variance.maxCoeff(&axis_);
    }
    order_.resize(static_cast<std::size_t>(n));
    std::iota(order_.begin(), order_.end(), 0);
  }
  // Empty boxes (min +inf) sort last and overlap nothing.
  const auto key = [&](int i) { return boxes[static_cast<std::size_t>(i)].min[axis_]; };
  for (std::size_t i = 1; i < order_.size(); ++i) {
    const int moving = order_[i];
    const double k = key(moving);
    std::size_t j = i;
    while (j > 0 && key(order_[j - 1]) > k) {
      order_[j] = order_[j - 1];
      --j;
      ++stats_.swaps;
    }
    order_[j] = moving;
  }
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t i = 0; i < order_.size(); ++i) {
    const Aabb& a = boxes[static_cast<std::size_t>(order_[i])];
    if (a.isEmpty())
      continue;
    for (std::size_t j = i + 1; j < order_.size(); ++j) {
      const Aabb& b = boxes[static_cast<std::size_t>(order_[j])];
      if (b.min[axis_] > a.max[axis_])
        break;  // b and every box after it start beyond a
      if (b.isEmpty())
        continue;
      ++stats_.intervalTests;
      bool overlap = true;
      for (int d = 0; d < 3; ++d)
        overlap = overlap && a.min[d] <= b.max[d] && b.min[d] <= a.max[d];
      if (overlap)
        pairs.emplace_back(std::min(order_[i], order_[j]), std::max(order_[i], order_[j]));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace recode::core
