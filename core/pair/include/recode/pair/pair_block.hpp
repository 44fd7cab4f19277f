#pragma once
// A block as collidePair draws it: its world mesh, with what can be worked out once and then
// shared by all the pair tests the block takes part in (its box, whether every vertex and index
// is drawable, and optionally a triangle hierarchy). With a hierarchy, a device that draws only
// what meets its scissor (CpuDevice) is handed only the triangles near the MOR, and only their
// vertices are mapped to the window; the command stream and every result are those of the
// block without one (docs/architecture.md, "The device seam").

#include <memory>

#include <Eigen/Geometry>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/triangle_bvh.hpp"

namespace recode::core {

class PairBlock {
 public:
  // The world mesh alone: drawn whole, its vertices all mapped to the window, as before.
  // `world` must outlive the block.
  explicit PairBlock(const TriangleMesh& world);

  // The world mesh with a hierarchy over the triangles of `local`, the mesh `world` was made
  // from by `localToWorld` (core::transformed: the same triangles, the same vertices mapped).
  // With a hierarchy of another mesh the culled draws could leave out triangles that matter;
  // the triangle counts are checked (std::invalid_argument), the rest is the caller's promise.
  PairBlock(const TriangleMesh& world, std::shared_ptr<const TriangleBvh> hierarchy,
            const Eigen::Isometry3d& localToWorld);

  // A block whose hierarchy is built here over `world` itself (identity pose).
  [[nodiscard]] static PairBlock withHierarchy(const TriangleMesh& world);

  [[nodiscard]] const TriangleMesh& mesh() const { return *mesh_; }
  [[nodiscard]] const Aabb& box() const { return box_; }  // boundingBox(mesh()), bit for bit
  // Every vertex finite and every index in range: the only meshes whose culled draws are
  // offered, so that a mesh the device refuses is refused exactly as before.
  [[nodiscard]] bool drawable() const { return drawable_; }
  [[nodiscard]] const TriangleBvh* hierarchy() const { return hierarchy_.get(); }
  [[nodiscard]] const Eigen::Isometry3d& localToWorld() const { return localToWorld_; }

 private:
  const TriangleMesh* mesh_;
  Aabb box_;
  bool drawable_ = false;
  std::shared_ptr<const TriangleBvh> hierarchy_;
  Eigen::Isometry3d localToWorld_ = Eigen::Isometry3d::Identity();
};

}  // namespace recode::core
