// The bullet peer (peer_detectors.hpp): Bullet's collision world as its users set it up --
// default collision configuration, dispatcher, dynamic AABB tree broad phase -- with one
// btConvexHullShape per block. Bullet is used in its float build, the one Debian and most
// users have.
//
// Two settings differ from Bullet's defaults, both so that Bullet answers the bench's
// question (do the closed blocks meet?) rather than a physics engine's:
// - the collision margin is 0: the default 0.04 rounds every corner, so cone tips 1e-4 apart
//   were reported touching;
// - a pair collides when a contact point of its manifold has distance <= 0: manifolds also
//   keep points of pairs that are close but apart (up to the contact breaking threshold), and
//   two tips meeting exactly come out at distance -0.
// Blocks of one object are filtered out in the broad phase, so no narrow phase runs on them.
#include <btBulletCollisionCommon.h>

#include <chrono>
#include <memory>
#include <utility>
#include <vector>

#include "bullet_pose.hpp"
#include "recode/verify/peer_detectors.hpp"
#include "scene_leaves.hpp"

namespace recode::verify {

namespace {

// Each collision object's user index is its leaf's index in SceneLeaves, user index 2 its
// object's index.
int objectOf(const btBroadphaseProxy* proxy) {
  return static_cast<const btCollisionObject*>(proxy->m_clientObject)->getUserIndex2();
}

class SameObjectFilter final : public btOverlapFilterCallback {
 public:
  bool needBroadphaseCollision(btBroadphaseProxy* a, btBroadphaseProxy* b) const override {
    // Bullet's own group and mask test, which a filter callback replaces.
    const bool groups = (a->m_collisionFilterGroup & b->m_collisionFilterMask) != 0 &&
                        (b->m_collisionFilterGroup & a->m_collisionFilterMask) != 0;
    return groups && objectOf(a) != objectOf(b);
  }
};

std::unique_ptr<btConvexHullShape> makeHull(const core::TriangleMesh& mesh) {
  auto hull = std::make_unique<btConvexHullShape>();
  for (const Eigen::Vector3d& p : mesh.vertices)
    hull->addPoint(btVector3(static_cast<btScalar>(p.x()), static_cast<btScalar>(p.y()),
                             static_cast<btScalar>(p.z())),
                   false);
  // Before the local box is computed: the cached box includes the margin.
  hull->setMargin(0);
  hull->recalcLocalAabb();
  return hull;
}

class BulletDetector final : public SceneDetector {
 public:
  explicit BulletDetector(const std::vector<core::ObjectTree>& objects) : leaves_(objects) {
    world_.getPairCache()->setOverlapFilterCallback(&filter_);
    for (int i = 0; i < leaves_.size(); ++i) {
      const core::HierarchyNode& node = SceneLeaves::node(objects, leaves_[i]);
      shapes_.push_back(makeHull(node.localMesh));
      auto body = std::make_unique<btCollisionObject>();
      body->setCollisionShape(shapes_.back().get());
      // Moved by the caller every frame: kinematic, never put to sleep.
      body->setCollisionFlags(btCollisionObject::CF_KINEMATIC_OBJECT);
      body->setActivationState(DISABLE_DEACTIVATION);
      body->setWorldTransform(toBullet(node.world));
      body->setUserIndex(i);
      body->setUserIndex2(leaves_[i].object);
      world_.addCollisionObject(body.get());
      bodies_.push_back(std::move(body));
    }
  }

  ~BulletDetector() override {
    for (const auto& body : bodies_)
      world_.removeCollisionObject(body.get());
  }

  [[nodiscard]] std::string name() const override { return "bullet"; }

  [[nodiscard]] Detection detect(const std::vector<core::ObjectTree>& objects,
                                 int /*frame*/) override {
    leaves_.checkSameShape(objects);
    std::vector<LeafPairId> pairs;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < leaves_.size(); ++i)
      bodies_[static_cast<std::size_t>(i)]->setWorldTransform(
          toBullet(SceneLeaves::node(objects, leaves_[i]).world));
    world_.performDiscreteCollisionDetection();
    const int manifolds = dispatcher_.getNumManifolds();
    for (int m = 0; m < manifolds; ++m) {
      const btPersistentManifold* manifold = dispatcher_.getManifoldByIndexInternal(m);
      bool touching = false;
      for (int c = 0; c < manifold->getNumContacts() && !touching; ++c)
        touching = manifold->getContactPoint(c).getDistance() <= 0;
      if (touching)
        pairs.push_back(orderedPair(leaves_[manifold->getBody0()->getUserIndex()],
                                    leaves_[manifold->getBody1()->getUserIndex()]));
    }
    return finishDetection(std::move(pairs), start);
  }

 private:
  SceneLeaves leaves_;
  // Bullet's objects refer to each other by pointer: each is declared before those that use
  // it, so it is made before and destroyed after them.
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  SameObjectFilter filter_;
  std::vector<std::unique_ptr<btConvexHullShape>> shapes_;  // per leaf, as leaves_
  std::vector<std::unique_ptr<btCollisionObject>> bodies_;
  btCollisionWorld world_{&dispatcher_, &broadphase_, &configuration_};
};

}  // namespace

std::unique_ptr<SceneDetector> makeBulletDetector(const std::vector<core::ObjectTree>& objects) {
  return std::make_unique<BulletDetector>(objects);
}

}  // namespace recode::verify
