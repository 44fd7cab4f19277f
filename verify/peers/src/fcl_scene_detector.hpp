#pragma once
// What the two FCL peers share (peer_detectors.hpp): one fcl::CollisionObject per leaf in a
// dynamic AABB tree broad phase, posed from the leaves' world transforms each frame, and
// fcl::collide on every candidate pair of leaves of different objects. They differ only in the
// geometry made for a leaf and in the request. Internal to verify/peers; FCL types stay here
// and in the .cpp files of the two peers.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <fcl/fcl.h>

#include "recode/verify/scene_detector.hpp"
#include "scene_leaves.hpp"

namespace recode::verify {

// A mesh as an OBBRSS bounding volume hierarchy of its triangles (fcl-obbrss, on blocks and on
// closed meshes).
[[nodiscard]] std::shared_ptr<fcl::CollisionGeometryd> makeObbrssMesh(
    const core::TriangleMesh& mesh);

// A request for every contact, without a limit on their number (fcl-obbrss on blocks, and
// fcl-obbrss-all on closed meshes).
[[nodiscard]] fcl::CollisionRequestd allContactsRequest();

class FclSceneDetector final : public SceneDetector {
 public:
  // The geometry of one block, in the leaf's own coordinates (HierarchyNode::localMesh).
  using GeometryMaker =
      std::function<std::shared_ptr<fcl::CollisionGeometryd>(const core::TriangleMesh&)>;

  FclSceneDetector(std::string name, const std::vector<core::ObjectTree>& objects,
                   const GeometryMaker& makeGeometry, fcl::CollisionRequestd request);

  [[nodiscard]] std::string name() const override { return name_; }
  [[nodiscard]] Detection detect(const std::vector<core::ObjectTree>& objects, int frame) override;

 private:
  std::string name_;
  SceneLeaves leaves_;
  fcl::CollisionRequestd request_;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> shapes_;  // per leaf, as leaves_
  fcl::DynamicAABBTreeCollisionManagerd manager_;
};

}  // namespace recode::verify
