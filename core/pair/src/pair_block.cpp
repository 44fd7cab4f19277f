#include "recode/pair/pair_block.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace recode::core {

namespace {

bool allDrawable(const TriangleMesh& mesh) {
  return std::isfinite(drawableExtent(mesh));
}

}  // namespace

PairBlock::PairBlock(const TriangleMesh& world)
    : mesh_(&world), box_(boundingBox(world)), drawable_(allDrawable(world)) {}

PairBlock::PairBlock(const TriangleMesh& world, std::shared_ptr<const TriangleBvh> hierarchy,
                     const Eigen::Isometry3d& localToWorld)
    : PairBlock(world) {
  if (hierarchy && hierarchy->triangleCount() != world.triangles.size())
    throw std::invalid_argument(
        "PairBlock: the hierarchy has " + std::to_string(hierarchy->triangleCount()) +
        " triangles but the mesh has " + std::to_string(world.triangles.size()));
  if (drawable_) {
    hierarchy_ = std::move(hierarchy);
    localToWorld_ = localToWorld;
  }
}

PairBlock PairBlock::withHierarchy(const TriangleMesh& world) {
  PairBlock block(world);
  if (block.drawable_)
    block.hierarchy_ = std::make_shared<const TriangleBvh>(world);
  return block;
}

}  // namespace recode::core
