// fcl-obbrss on a pair of closed meshes (closed_peers.hpp): the two OBBRSS hierarchies built
// once, fcl::collide with the default request, which stops at the first pair of triangles that
// meet: the yes/no query a user of FCL makes. Surfaces only: a mesh wholly inside the other is
// apart (the bench counts it as a miss).
#include <memory>
#include <string>

#include "fcl_scene_detector.hpp"
#include "recode/verify/closed_peers.hpp"

namespace recode::verify {

namespace {

class FclObbrssClosedPeer final : public ClosedPairPeer {
 public:
  FclObbrssClosedPeer(const core::TriangleMesh& a, const core::TriangleMesh& b)
      : a_(makeObbrssMesh(a)), b_(makeObbrssMesh(b)) {}

  [[nodiscard]] std::string name() const override { return "fcl-obbrss"; }

  [[nodiscard]] bool collide(const Eigen::Isometry3d& poseA,
                             const Eigen::Isometry3d& poseB) override {
    a_.setTransform(poseA);
    b_.setTransform(poseB);
    a_.computeAABB();
    b_.computeAABB();
    fcl::CollisionResultd result;
    fcl::collide(&a_, &b_, fcl::CollisionRequestd{}, result);
    return result.isCollision();
  }

 private:
  fcl::CollisionObjectd a_;
  fcl::CollisionObjectd b_;
};

}  // namespace

std::unique_ptr<ClosedPairPeer> makeFclObbrssClosedPeer(const core::TriangleMesh& a,
                                                        const core::TriangleMesh& b) {
  return std::make_unique<FclObbrssClosedPeer>(a, b);
}

}  // namespace recode::verify
