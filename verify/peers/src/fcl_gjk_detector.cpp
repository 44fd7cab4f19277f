// The fcl-gjk peer (peer_detectors.hpp): each block an fcl::Convex, decided by FCL's default
// solver, libccd's GJK, with the default request (a yes/no answer, no contacts). The GST_INDEP
// solver is deliberately not used: on this FCL (0.7.0) it returned negative depths and contact
// points outside both bodies (docs/benchmarks.md).
#include <memory>
#include <vector>

#include "fcl_scene_detector.hpp"
#include "recode/verify/peer_detectors.hpp"

namespace recode::verify {

namespace {

std::shared_ptr<fcl::CollisionGeometryd> makeConvex(const core::TriangleMesh& mesh) {
  auto vertices =
      std::make_shared<std::vector<fcl::Vector3d>>(mesh.vertices.begin(), mesh.vertices.end());
  // FCL's face list: for each face its vertex count, then its vertex indices.
  auto faces = std::make_shared<std::vector<int>>();
  faces->reserve(4 * mesh.triangles.size());
  for (const core::Triangle& t : mesh.triangles) {
    faces->push_back(3);
    for (const core::VertexIndex v : t)
      faces->push_back(static_cast<int>(v));
  }
  return std::make_shared<fcl::Convexd>(std::move(vertices),
                                        static_cast<int>(mesh.triangles.size()), std::move(faces));
}

}  // namespace

std::unique_ptr<SceneDetector> makeFclGjkDetector(const std::vector<core::ObjectTree>& objects) {
  return std::make_unique<FclSceneDetector>("fcl-gjk", objects, makeConvex,
                                            fcl::CollisionRequestd());
}

}  // namespace recode::verify
