// An object: a shared shape and its own posed copy of the shape's tree.
#include "recode/api/collision.hpp"

#include <stdexcept>
#include <utility>

namespace recode {

namespace {
const CollisionGeometry& required(const CollisionGeometryPtr& geometry) {
  if (!geometry)
    throw std::invalid_argument("a collision object needs a geometry");
  return *geometry;
}
}  // namespace

CollisionObject::CollisionObject(CollisionGeometryPtr geometry, const Eigen::Isometry3d& transform)
    : geometry_(std::move(geometry)), tree_(required(geometry_).tree()), transform_(transform) {
  setTransform(transform);
}

void CollisionObject::setTransform(const Eigen::Isometry3d& transform) {
  transform_ = transform;
  // Frame 0: the shape's placements are all rest poses (identity), so the pose is the user's.
  tree_.setFrame(0, transform_);
  tree_.updateBounds();
}

core::TriangleMesh CollisionObject::worldBlock(std::size_t block) const {
  return tree_.worldMesh(tree_.leaves().at(block));
}

}  // namespace recode
