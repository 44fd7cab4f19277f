// A manager over frames: three boxes on the x axis, the outer two closing in on the middle
// one, and a spinning cone off to the side that touches nothing. Each frame moves the objects
// (setTransform) and asks the manager for every pair in contact.
#include <cstdio>
#include <memory>
#include <vector>

#include "recode/api/manager.hpp"
#include "recode/geometry/generators.hpp"

namespace {

Eigen::Isometry3d at(double x, double y, double z) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, y, z));
}

}  // namespace

int main() {
  namespace core = recode::core;
  const auto box = recode::CollisionGeometry::single(
      recode::ConvexBlock::fromMesh(core::makeBox(0.5, 0.5, 0.5), "box"));
  const auto cone = recode::CollisionGeometry::single(
      recode::ConvexBlock::fromMesh(core::makeCone(0.5, 1.0, 24), "cone"));

  recode::CollisionManager manager;
  auto left = std::make_shared<recode::CollisionObject>(box, at(-3.0, 0.0, 0.0));
  auto right = std::make_shared<recode::CollisionObject>(box, at(3.0, 0.0, 0.0));
  auto spinner = std::make_shared<recode::CollisionObject>(cone, at(0.0, 3.0, 0.0));
  const recode::ObjectId idLeft = manager.add(left);
  const recode::ObjectId idMiddle =
      manager.add(std::make_shared<recode::CollisionObject>(box, at(0.0, 0.0, 0.0)));
  const recode::ObjectId idRight = manager.add(right);
  manager.add(spinner);
  std::printf("objects: left %d, middle %d, right %d, cone 3\n", idLeft, idMiddle, idRight);

  recode::CollisionRequest request;
  request.pixelSize = 0.02;
  for (int frame = 0; frame < 9; ++frame) {
    // The outer boxes close in by 0.3 a frame: they reach the middle one at frame 7.
    const double x = 3.0 - 0.3 * frame;
    left->setTransform(at(-x, 0.0, 0.0));
    right->setTransform(at(x, 0.0, 0.0));
    Eigen::Isometry3d turned = at(0.0, 3.0, 0.0);
    turned.rotate(Eigen::AngleAxisd(0.2 * frame, Eigen::Vector3d::UnitX()));
    spinner->setTransform(turned);

    const std::vector<recode::ObjectContact> contacts = manager.collide(request);
    std::printf("frame %d: %zu pairs in contact", frame, contacts.size());
    for (const recode::ObjectContact& c : contacts)
      std::printf(" (%d,%d: %lld pixels)", c.a, c.b, c.result.interferingPixels);
    std::printf("\n");
  }
  return 0;
}
