// The fcl-obbrss peer (peer_detectors.hpp): each block a triangle mesh in an OBBRSS bounding
// volume hierarchy, tested triangle against triangle with contacts on and no limit on their
// number, as RAPID's "all contacts" mode did. A triangle-mesh test only sees surfaces that
// cross or touch: a block wholly inside another is not reported (the bench counts it as FCL's
// miss, docs/benchmarks.md).
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

#include "fcl_scene_detector.hpp"
#include "recode/verify/peer_detectors.hpp"

namespace recode::verify {

std::shared_ptr<fcl::CollisionGeometryd> makeObbrssMesh(const core::TriangleMesh& mesh) {
  using ObbrssMesh = fcl::BVHModel<fcl::OBBRSSd>;
  const std::vector<fcl::Vector3d> vertices(mesh.vertices.begin(), mesh.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const core::Triangle& t : mesh.triangles)
    triangles.emplace_back(t[0], t[1], t[2]);
  auto model = std::make_shared<ObbrssMesh>();
  model->beginModel(static_cast<int>(triangles.size()), static_cast<int>(vertices.size()));
  model->addSubModel(vertices, triangles);
  model->endModel();
  return model;
}

fcl::CollisionRequestd allContactsRequest() {
  fcl::CollisionRequestd request;
  request.enable_contact = true;
  request.num_max_contacts = std::numeric_limits<std::size_t>::max();
  return request;
}

std::unique_ptr<SceneDetector> makeFclObbrssDetector(const std::vector<core::ObjectTree>& objects) {
  return std::make_unique<FclSceneDetector>("fcl-obbrss", objects, makeObbrssMesh,
                                            allContactsRequest());
}

}  // namespace recode::verify
