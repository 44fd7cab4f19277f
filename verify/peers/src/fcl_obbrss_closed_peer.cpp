// fcl-obbrss and fcl-obbrss-all on a pair of closed meshes (closed_peers.hpp): the two OBBRSS
// hierarchies built once, fcl::collide with the default request, which stops at the first pair
// of triangles that meet (the yes/no query), or with every contact asked for. Surfaces only: a mesh
// wholly inside the other is apart (the bench counts it as a miss).
#include <memory>
#include <string>

#include "fcl_scene_detector.hpp"
#include "recode/verify/closed_peers.hpp"

namespace recode::verify {

namespace {

class FclObbrssClosedPeer final : public ClosedPairPeer {
 public:
  FclObbrssClosedPeer(const core::TriangleMesh& a, const core::TriangleMesh& b, bool allContacts)
      : a_(makeObbrssMesh(a)),
        b_(makeObbrssMesh(b)),
        request_(allContacts ? allContactsRequest() : fcl::CollisionRequestd{}),
        name_(allContacts ? "fcl-obbrss-all" : "fcl-obbrss") {}

  [[nodiscard]] std::string name() const override { return name_; }

  [[nodiscard]] bool collide(const Eigen::Isometry3d& poseA,
                             const Eigen::Isometry3d& poseB) override {
    a_.setTransform(poseA);
    b_.setTransform(poseB);
    a_.computeAABB();
    b_.computeAABB();
    fcl::CollisionResultd result;
    fcl::collide(&a_, &b_, request_, result);
    return result.isCollision();
  }

 private:
  fcl::CollisionObjectd a_;
  fcl::CollisionObjectd b_;
  fcl::CollisionRequestd request_;
  std::string name_;
};

}  // namespace

std::unique_ptr<ClosedPairPeer> makeFclObbrssClosedPeer(const core::TriangleMesh& a,
                                                        const core::TriangleMesh& b,
                                                        bool allContacts) {
  return std::make_unique<FclObbrssClosedPeer>(a, b, allContacts);
}

}  // namespace recode::verify
