// bullet-gimpact on a pair of closed meshes (closed_peers.hpp): each mesh a btGImpactMeshShape,
// Bullet's shape for a concave triangle mesh that moves, in a btCollisionWorld whose dispatcher
// has btGImpactCollisionAlgorithm registered, as Bullet's documentation sets it up; the pair is
// tested by the world's discrete collision detection (contactPairTest asks the dispatcher for
// a closest-points algorithm, which GImpact does not register: it would answer nothing). As for the
// convex bullet peer (bullet_detector.cpp), the margin is 0 and a pair collides when some contact
// point has distance <= 0. Bullet's float build: the coordinates are rounded to float. Surfaces
// only: a mesh wholly inside the other is apart.
#include <btBulletCollisionCommon.h>

#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>

#include <memory>
#include <string>
#include <vector>

#include "bullet_pose.hpp"
#include "recode/verify/closed_peers.hpp"

namespace recode::verify {

namespace {

// A mesh as GImpact holds it: Bullet keeps pointers into the index and vertex arrays, so they
// live as long as the shape.
class GImpactMesh {
 public:
  explicit GImpactMesh(const core::TriangleMesh& mesh) {
    for (const core::Triangle& t : mesh.triangles)
      for (int corner = 0; corner < 3; ++corner)
        indices_.push_back(t[static_cast<std::size_t>(corner)]);
    for (const Eigen::Vector3d& p : mesh.vertices)
      for (int axis = 0; axis < 3; ++axis)
        vertices_.push_back(static_cast<btScalar>(p[axis]));
    array_ = std::make_unique<btTriangleIndexVertexArray>(
        static_cast<int>(mesh.triangles.size()), indices_.data(), 3 * static_cast<int>(sizeof(int)),
        static_cast<int>(mesh.vertices.size()), vertices_.data(),
        3 * static_cast<int>(sizeof(btScalar)));
    shape_ = std::make_unique<btGImpactMeshShape>(array_.get());
    shape_->setMargin(0);
    shape_->updateBound();
    object_.setCollisionShape(shape_.get());
  }
  GImpactMesh(const GImpactMesh&) = delete;
  GImpactMesh& operator=(const GImpactMesh&) = delete;

  btCollisionObject& object() { return object_; }

 private:
  std::vector<int> indices_;
  std::vector<btScalar> vertices_;
  std::unique_ptr<btTriangleIndexVertexArray> array_;
  std::unique_ptr<btGImpactMeshShape> shape_;
  btCollisionObject object_;
};

class BulletGImpactClosedPeer final : public ClosedPairPeer {
 public:
  BulletGImpactClosedPeer(const core::TriangleMesh& a, const core::TriangleMesh& b)
      : dispatcher_(&configuration_),
        world_(&dispatcher_, &broadphase_, &configuration_),
        a_(a),
        b_(b) {
    btGImpactCollisionAlgorithm::registerAlgorithm(&dispatcher_);
    world_.addCollisionObject(&a_.object());
    world_.addCollisionObject(&b_.object());
  }
  ~BulletGImpactClosedPeer() override {
    world_.removeCollisionObject(&a_.object());
    world_.removeCollisionObject(&b_.object());
  }

  [[nodiscard]] std::string name() const override { return "bullet-gimpact"; }

  [[nodiscard]] bool collide(const Eigen::Isometry3d& poseA,
                             const Eigen::Isometry3d& poseB) override {
    a_.object().setWorldTransform(toBullet(poseA));
    b_.object().setWorldTransform(toBullet(poseB));
    world_.performDiscreteCollisionDetection();
    for (int m = 0; m < dispatcher_.getNumManifolds(); ++m) {
      const btPersistentManifold* manifold = dispatcher_.getManifoldByIndexInternal(m);
      for (int p = 0; p < manifold->getNumContacts(); ++p)
        if (manifold->getContactPoint(p).getDistance() <= 0)
          return true;
    }
    return false;
  }

 private:
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btCollisionWorld world_;
  GImpactMesh a_;
  GImpactMesh b_;
};

}  // namespace

std::unique_ptr<ClosedPairPeer> makeBulletGImpactClosedPeer(const core::TriangleMesh& a,
                                                            const core::TriangleMesh& b) {
  return std::make_unique<BulletGImpactClosedPeer>(a, b);
}

}  // namespace recode::verify
