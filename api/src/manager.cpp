// The manager: objects by id, the broad phase over their world boxes, every candidate's block
// pairs decided as one batch.
#include "recode/api/manager.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

#include "block_pairs.hpp"

namespace recode {

CollisionManager::CollisionManager(core::DeviceFactory factory) : devices_(std::move(factory)) {}

ObjectId CollisionManager::add(std::shared_ptr<CollisionObject> object) {
  if (!object)
    throw std::invalid_argument("cannot add a null collision object");
  entries_.push_back({next_, std::move(object)});
  return next_++;
}

CollisionManager::Entry& CollisionManager::entry(ObjectId id) {
  const auto it = std::lower_bound(entries_.begin(), entries_.end(), id,
                                   [](const Entry& e, ObjectId key) { return e.id < key; });
  if (it == entries_.end() || it->id != id)
    throw std::out_of_range("no collision object with id " + std::to_string(id));
  return *it;
}

void CollisionManager::remove(ObjectId id) {
  Entry& e = entry(id);
  // The broad phase sees a different number of boxes and sorts again from scratch.
  entries_.erase(entries_.begin() + (&e - entries_.data()));
}

void CollisionManager::update(ObjectId id, const Eigen::Isometry3d& transform) {
  entry(id).object->setTransform(transform);
}

CollisionObject& CollisionManager::object(ObjectId id) {
  return *entry(id).object;
}

void CollisionManager::collide(
    const CollisionRequest& request,
    const std::function<void(ObjectId, ObjectId, const CollisionResult&)>& onContact) {
  using Clock = std::chrono::steady_clock;
  stats_ = {};
  std::vector<core::Aabb> boxes;
  boxes.reserve(entries_.size());
  for (const Entry& e : entries_)
    boxes.push_back(e.object->worldBox());
  // Every candidate pair's block pairs are planned first and decided as one batch (one
  // submission round on a deferring GPU device), then each pair's result is merged and reported
  // in the broad phase's order: the same results as collide() on each pair in turn.
  const Clock::time_point start = Clock::now();
  const std::vector<std::pair<int, int>> candidates = broadPhase_.update(boxes);
  std::vector<CollisionResult> results(candidates.size());
  detail::BlockPairPlan plan;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    ++stats_.candidatePairs;
    plan.add(*entries_[static_cast<std::size_t>(candidates[k].first)].object,
             *entries_[static_cast<std::size_t>(candidates[k].second)].object, request, results[k]);
  }
  double setupUs = 0.0;
  std::vector<detail::BlockPairAnswer> answers =
      plan.decide(request.mode, devices_, request.threads, &setupUs);
  // Each pair's share of the call's time, by its block pairs (each pair at least one share).
  const double callUs =
      std::chrono::duration<double, std::micro>(Clock::now() - start).count() - setupUs;
  const double shares = static_cast<double>(plan.blockPairs() + candidates.size());
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    CollisionResult& result = results[k];
    plan.merge(k, answers, result);
    const double share = static_cast<double>(result.blockPairsDrawn + 1) / shares;
    result.collisionUs = callUs * share;
    result.deviceSetupUs = setupUs * share;
    if (result.collide) {
      ++stats_.pairsInContact;
      onContact(entries_[static_cast<std::size_t>(candidates[k].first)].id,
                entries_[static_cast<std::size_t>(candidates[k].second)].id, result);
    }
  }
}

std::vector<ObjectContact> CollisionManager::collide(const CollisionRequest& request) {
  std::vector<ObjectContact> contacts;
  collide(request, [&](ObjectId a, ObjectId b, const CollisionResult& r) {
    contacts.push_back({a, b, r});
  });
  // The broad phase gives pairs by index, and indices follow ids.
  std::sort(contacts.begin(), contacts.end(), [](const ObjectContact& x, const ObjectContact& y) {
    return std::pair(x.a, x.b) < std::pair(y.a, y.b);
  });
  return contacts;
}

}  // namespace recode
