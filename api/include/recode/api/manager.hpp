#pragma once
// Many objects at once (FCL's broad-phase manager, docs/api.md): objects are added and removed
// by id, moved through their own setTransform (the manager holds shared pointers and reads the
// current poses), and collide() finds every pair in contact: the sort-and-sweep broad phase of
// `recode run` (core::SweepAndPrune) on the objects' world boxes, then what recode::collide does
// for each candidate pair, all drawn on the manager's DevicePool: every candidate's block pairs
// are decided as one batch (core::collidePairs; one submission round on a GPU device that defers
// its commands), with the results of recode::collide on each pair in turn, timing aside.

#include <functional>
#include <memory>
#include <vector>

#include "recode/api/collision.hpp"
#include "recode/sim/broad_phase.hpp"

namespace recode {

// A CollisionManager's name for an object it holds (never reused within a manager).
using ObjectId = int;

// One object pair in contact; a < b.
struct ObjectContact {
  ObjectId a = 0;          // the smaller id
  ObjectId b = 0;          // the larger id
  CollisionResult result;  // recode::collide's result for the two objects
};

// What the last CollisionManager::collide() did.
struct ManagerStats {
  long long candidatePairs = 0;  // pairs whose world boxes overlap (the broad phase's output)
  long long pairsInContact = 0;  // of those, the pairs whose pixels interfere
};

// Objects by id, and every pair of them in contact (sort and sweep, then recode::collide).
class CollisionManager {
 public:
  // `factory` makes the devices pairs are drawn on; empty: raster::CpuDevice.
  explicit CollisionManager(core::DeviceFactory factory = {});

  // Ids are never reused. Throws std::invalid_argument for a null object.
  ObjectId add(std::shared_ptr<CollisionObject> object);
  // Throws std::out_of_range for an id not in the manager.
  void remove(ObjectId id);
  // Moves an object (the same as object(id).setTransform(transform)).
  void update(ObjectId id, const Eigen::Isometry3d& transform);
  // The object of this id. Throws std::out_of_range for an id not in the manager.
  [[nodiscard]] CollisionObject& object(ObjectId id);
  // The number of objects held.
  [[nodiscard]] std::size_t size() const { return entries_.size(); }

  // Every pair in contact at the objects' current poses, ordered by (a, b).
  [[nodiscard]] std::vector<ObjectContact> collide(const CollisionRequest& request);
  // The same, handing each pair in contact to `onContact` once all are decided, in the broad
  // phase's order. Each result's collisionUs and deviceSetupUs are its share of the call's, by
  // block pairs drawn.
  void collide(const CollisionRequest& request,
               const std::function<void(ObjectId, ObjectId, const CollisionResult&)>& onContact);

  // What the last collide() did.
  [[nodiscard]] const ManagerStats& stats() const { return stats_; }
  // The devices pairs are drawn on (one per frame size).
  [[nodiscard]] const DevicePool& devices() const { return devices_; }

 private:
  struct Entry {
    ObjectId id;
    std::shared_ptr<CollisionObject> object;
  };
  Entry& entry(ObjectId id);

  std::vector<Entry> entries_;  // by increasing id
  ObjectId next_ = 0;
  core::SweepAndPrune broadPhase_;
  DevicePool devices_;
  ManagerStats stats_;
};

}  // namespace recode
