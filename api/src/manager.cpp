// The manager: objects by id, the broad phase over their world boxes, collide() per candidate.
#include "recode/api/manager.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

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
  stats_ = {};
  std::vector<core::Aabb> boxes;
  boxes.reserve(entries_.size());
  for (const Entry& e : entries_)
    boxes.push_back(e.object->worldBox());
  CollisionResult result;
  for (const auto& [i, j] : broadPhase_.update(boxes)) {
    ++stats_.candidatePairs;
    const Entry& a = entries_[static_cast<std::size_t>(i)];
    const Entry& b = entries_[static_cast<std::size_t>(j)];
    if (recode::collide(*a.object, *b.object, request, result, devices_)) {
      ++stats_.pairsInContact;
      onContact(a.id, b.id, result);
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
