// A torus (a closed mesh, not convex) and two pegs: one through the hole, apart; one through the
// tube, interfering; and a ball inside the tube, contained. The layered pair of the collision
// API (docs/api.md, "Closed meshes"): the verdict, the overlap volume, the containment.
#include <cstdio>
#include <string>
#include <utility>

#include "recode/api/collision.hpp"
#include "recode/geometry/generators.hpp"

namespace {

recode::CollisionObject at(recode::CollisionGeometryPtr shape, double x, double y, double z) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return recode::CollisionObject(std::move(shape), pose);
}

void report(const char* what, const recode::CollisionObject& a, const recode::CollisionObject& b) {
  recode::CollisionResult result;
  const bool hit = recode::collide(a, b, recode::CollisionRequest{}, result);
  const recode::core::LayeredPairResult& layered = result.layered->result;
  std::printf("%s: collide %s, overlap volume %.4f, containment %s, layers %d and %d\n", what,
              hit ? "yes" : "no", layered.overlapVolume,
              std::string(recode::core::toString(layered.containment)).c_str(), layered.layersA,
              layered.layersB);
}

}  // namespace

int main() {
  // The torus about z: tube centre circle of radius 2, tube radius 0.5; the hole is 1.5 across
  // from the axis. ClosedMesh validates it (core::validateClosedMesh) and throws
  // core::MeshError naming the rule when it is not a closed mesh.
  const auto torus = recode::CollisionGeometry::closed(
      recode::ClosedMesh::fromMesh(recode::core::makeTorus(2.0, 0.5, 96, 48), "torus"));
  const auto peg = [](double radius) {
    return recode::CollisionGeometry::single(recode::ConvexBlock::fromMesh(
        recode::core::makeCylinder(radius, 4.0, 64), "peg"));  // along z, from z = 0 to 4
  };
  const auto ball = recode::CollisionGeometry::single(
      recode::ConvexBlock::fromMesh(recode::core::makeSphere(0.3, 32, 16), "ball"));

  const recode::CollisionObject ring = at(torus, 0, 0, 0);
  report("peg through the hole", ring, at(peg(0.5), 0, 0, -2));
  report("peg through the tube", ring, at(peg(0.2), 2, 0, -2));
  report("ball inside the tube", at(ball, 0, 2, 0), ring);
  return 0;
}
