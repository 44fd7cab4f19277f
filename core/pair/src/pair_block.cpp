#include "recode/pair/pair_block.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "recode/raster/triangle_source.hpp"

namespace recode::core {

namespace {

bool allDrawable(const TriangleMesh& mesh) {
  return std::isfinite(drawableExtent(mesh));
}

}  // namespace

ObjectSpaceMesh::ObjectSpaceMesh(const TriangleMesh& local) : key(raster::newTriangleSourceKey()) {
  xyz.reserve(3 * local.vertices.size());
  for (const Eigen::Vector3d& v : local.vertices)
    xyz.insert(xyz.end(), {v.x(), v.y(), v.z()});
  indices.reserve(3 * local.triangles.size());
  for (const Triangle& t : local.triangles)
    indices.insert(indices.end(), t.begin(), t.end());
}

PairBlock::PairBlock(const TriangleMesh& world)
    : mesh_(&world), box_(boundingBox(world)), drawable_(allDrawable(world)) {}

PairBlock::PairBlock(const TriangleMesh& world, std::shared_ptr<const TriangleBvh> hierarchy,
                     const Eigen::Isometry3d& localToWorld,
                     std::shared_ptr<const ObjectSpaceMesh> local)
    : PairBlock(world) {
  if (local && (local->xyz.size() != 3 * world.vertices.size() ||
                local->indices.size() != 3 * world.triangles.size()))
    throw std::invalid_argument(
        "PairBlock: the object-space mesh has " + std::to_string(local->xyz.size() / 3) +
        " vertices and " + std::to_string(local->indices.size() / 3) +
        " triangles but the mesh has " + std::to_string(world.vertices.size()) + " and " +
        std::to_string(world.triangles.size()));
  ObjectSpaceSource source;
  if (local)
    source = [local] { return local; };
  attach(world.triangles.size(), std::move(hierarchy), localToWorld, std::move(source));
}

void PairBlock::attach(std::size_t triangles, std::shared_ptr<const TriangleBvh> hierarchy,
                       const Eigen::Isometry3d& localToWorld, ObjectSpaceSource local) {
  if (hierarchy && hierarchy->triangleCount() != triangles)
    throw std::invalid_argument("PairBlock: the hierarchy has " +
                                std::to_string(hierarchy->triangleCount()) +
                                " triangles but the mesh has " + std::to_string(triangles));
  if (drawable_) {
    hierarchy_ = std::move(hierarchy);
    localToWorld_ = localToWorld;
    // transformed() swaps the winding under a mirroring pose; the object-space indices would not.
    if (!(localToWorld.linear().determinant() < 0.0))
      local_ = std::move(local);
  }
}

PairBlock PairBlock::posedLazily(const TriangleMesh& local, TriangleMesh& storage,
                                 std::shared_ptr<const TriangleBvh> hierarchy,
                                 const Eigen::Isometry3d& localToWorld, const Aabb& worldBox,
                                 double localExtent, ObjectSpaceSource objectSpace) {
  PairBlock block;
  block.lazy_ = std::make_shared<LazyWorld>();
  block.lazy_->local = &local;
  block.lazy_->storage = &storage;
  block.lazy_->pose = localToWorld;
  block.box_ = worldBox;
  // Every world coordinate is a sum of three products and the translation: below this bound in
  // magnitude, so finite, when the local vertices are (drawableExtent also checks the indices,
  // which the world mesh shares). A pose near overflow makes the mesh and looks.
  const double bound = 3.0 * localToWorld.linear().cwiseAbs().maxCoeff() * localExtent +
                       localToWorld.translation().cwiseAbs().maxCoeff();
  if (std::isfinite(localExtent) && bound < 1e300)
    block.drawable_ = true;
  else
    block.drawable_ = allDrawable(block.mesh());
  block.attach(local.triangles.size(), std::move(hierarchy), localToWorld, std::move(objectSpace));
  return block;
}

const TriangleMesh& PairBlock::mesh() const {
  if (mesh_ != nullptr)
    return *mesh_;
  LazyWorld& lazy = *lazy_;
  std::call_once(lazy.made, [&lazy] { transformInto(*lazy.local, lazy.pose, *lazy.storage); });
  return *lazy.storage;
}

PairBlock PairBlock::withHierarchy(const TriangleMesh& world) {
  PairBlock block(world);
  if (block.drawable_) {
    block.hierarchy_ = std::make_shared<const TriangleBvh>(world);
    block.local_ = [local = std::make_shared<const ObjectSpaceMesh>(world)] { return local; };
  }
  return block;
}

}  // namespace recode::core
