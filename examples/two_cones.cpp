// Two cones, tip into tip (the built-in pair of `recode pair`): one collide() call, then the
// verdict and the contact region. The smallest use of the collision API (docs/api.md).
#include <cstdio>
#include <numbers>

#include "recode/api/collision.hpp"
#include "recode/geometry/generators.hpp"

int main() {
  // A cone of radius 1 and height 2 along z, its apex at z = 2.
  const recode::CollisionGeometryPtr cone = recode::CollisionGeometry::single(
      recode::ConvexBlock::fromMesh(recode::core::makeCone(1.0, 2.0, 32), "cone"));

  recode::CollisionObject lower(cone);
  recode::CollisionObject upper(cone);
  // Upside down, apex at z = 1.75: the tips overlap by 0.25.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(Eigen::Vector3d(0.0, 0.0, 3.75));
  pose.rotate(Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()));
  upper.setTransform(pose);

  recode::CollisionRequest request;
  request.pixelSize = 0.01;  // world units: a tenth of the smallest feature we care about
  recode::CollisionResult result;
  const bool hit = recode::collide(lower, upper, request, result);

  std::printf("collide: %s\n", hit ? "yes" : "no");
  std::printf("interfering pixels: %lld\n", result.interferingPixels);
  const recode::core::Aabb& box = result.contact.box;
  std::printf("contact box: [%.2f %.2f %.2f] .. [%.2f %.2f %.2f]\n", box.min.x(), box.min.y(),
              box.min.z(), box.max.x(), box.max.y(), box.max.z());
  std::printf("greatest depth: %.3f, area: %.4f\n", result.contact.maxDepth, result.contact.area);
  return hit ? 0 : 1;
}
