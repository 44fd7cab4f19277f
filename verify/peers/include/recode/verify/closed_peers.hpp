#pragma once
// The bench's peers on a pair of closed meshes (`recode bench closed`, docs/benchmarks.md,
// "Closed meshes against the peers"), each used the way its users would for a yes/no query:
//   fcl-obbrss      FCL 0.7: each mesh an OBBRSS bounding volume hierarchy of its triangles,
//                   fcl::collide with the default request (the first contact ends the search)
//   fcl-obbrss-all  the same with every contact asked for (as the scene experiments' fcl-obbrss
//                   and RAPID's "all contacts" mode): every pair of triangles that meet, the
//                   peer's nearest answer to a contact region
//   bullet-gimpact  Bullet 3.24: each mesh a btGImpactMeshShape (Bullet's shape for concave
//                   triangle meshes, margin 0), the pair tested with btGImpactCollisionAlgorithm
//                   through btCollisionWorld::contactPairTest
// Both test surfaces against surfaces: a mesh wholly inside the other is apart for them. Each
// is built once from the two meshes in their own coordinates; a query places them. Built only
// with RECODE_WITH_PEERS (peersBuilt()); the factories throw std::runtime_error otherwise. No
// FCL or Bullet type appears here.

#include <memory>
#include <string>

#include <Eigen/Geometry>

#include "recode/geometry/mesh.hpp"

namespace recode::verify {

class ClosedPairPeer {
 public:
  virtual ~ClosedPairPeer() = default;
  ClosedPairPeer() = default;
  ClosedPairPeer(const ClosedPairPeer&) = delete;
  ClosedPairPeer& operator=(const ClosedPairPeer&) = delete;

  // The column name in the bench's CSV and plots.
  [[nodiscard]] virtual std::string name() const = 0;

  // Whether the peer reports the two meshes, placed by poseA and poseB, as colliding.
  [[nodiscard]] virtual bool collide(const Eigen::Isometry3d& poseA,
                                     const Eigen::Isometry3d& poseB) = 0;
};

// allContacts: fcl-obbrss-all instead of fcl-obbrss.
[[nodiscard]] std::unique_ptr<ClosedPairPeer> makeFclObbrssClosedPeer(const core::TriangleMesh& a,
                                                                      const core::TriangleMesh& b,
                                                                      bool allContacts);
[[nodiscard]] std::unique_ptr<ClosedPairPeer> makeBulletGImpactClosedPeer(
    const core::TriangleMesh& a, const core::TriangleMesh& b);

}  // namespace recode::verify
