#pragma once
// A block as collidePair draws it: its world mesh, with what can be worked out once and then
// shared by all the pair tests the block takes part in (its box, whether every vertex and index
// is drawable, and optionally a triangle hierarchy). With a hierarchy, a device that draws only
// what meets its scissor (CpuDevice) is handed only the triangles near the MOR, and only their
// vertices are mapped to the window; the command stream and every result are those of the
// block without one (docs/architecture.md, "The device seam").

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include <Eigen/Geometry>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/triangle_bvh.hpp"

namespace recode::core {

// A block's mesh in its own coordinates, flat, as a device that runs the vertex stage keeps it
// (raster::PosedMesh): made once for as long as the mesh lives, under a key of its own.
struct ObjectSpaceMesh {
  explicit ObjectSpaceMesh(const TriangleMesh& local);
  std::vector<double> xyz;             // x, y, z of each vertex
  std::vector<std::uint32_t> indices;  // three a triangle, in the mesh's order
  std::uint64_t key;                   // raster::newTriangleSourceKey()
};

// Makes (or finds) a block's object-space mesh when a device first asks for it, so that a run
// on a device that never does (the CPU device) does not copy its meshes
// (ObjectTree::objectSpaceMesh is one: made once, then shared).
using ObjectSpaceSource = std::function<std::shared_ptr<const ObjectSpaceMesh>()>;

class PairBlock {
 public:
  // The world mesh alone: drawn whole, its vertices all mapped to the window, as before.
  // `world` must outlive the block.
  explicit PairBlock(const TriangleMesh& world);

  // The world mesh with a hierarchy over the triangles of `local`, the mesh `world` was made
  // from by `localToWorld` (core::transformed: the same triangles, the same vertices mapped).
  // With a hierarchy of another mesh the culled draws could leave out triangles that matter;
  // the triangle counts are checked (std::invalid_argument), the rest is the caller's promise.
  // With `local`, the same mesh in its own coordinates (the one `world` was made from), a device
  // may keep the block and take, per draw, the pose and the view instead of window vertices
  // (BlockWindowSource offers it as raster::PosedMesh). Kept only for a drawable block whose pose
  // does not mirror (a mirroring pose swaps the world triangles' winding); its vertex and
  // triangle counts are checked (std::invalid_argument).
  PairBlock(const TriangleMesh& world, std::shared_ptr<const TriangleBvh> hierarchy,
            const Eigen::Isometry3d& localToWorld,
            std::shared_ptr<const ObjectSpaceMesh> local = nullptr);

  // A block whose hierarchy and object-space mesh are made here from `world` itself (identity
  // pose).
  [[nodiscard]] static PairBlock withHierarchy(const TriangleMesh& world);

  // The block of `local` moved by `localToWorld`, its world mesh made only when something asks
  // for it (mesh(): transformInto `storage`, so transformed()'s vertices, once even when threads
  // ask together), so that a device drawing the posed mesh never waits for it. `worldBox` must
  // be the box of those vertices bit for bit (ObjectTree's leaf box at this pose, or
  // posedVertexBox) and `localExtent` drawableExtent(local). Drawable when local is and no
  // coordinate can overflow (else the world mesh is made now and checked). `local` and
  // `storage` must outlive the block; the hierarchy is as the constructor's, and `objectSpace`
  // gives the constructor's `local` when asked (its counts are the caller's promise).
  [[nodiscard]] static PairBlock posedLazily(const TriangleMesh& local, TriangleMesh& storage,
                                             std::shared_ptr<const TriangleBvh> hierarchy,
                                             const Eigen::Isometry3d& localToWorld,
                                             const Aabb& worldBox, double localExtent,
                                             ObjectSpaceSource objectSpace);

  // The world mesh (made now when the block was made posedLazily and nobody asked yet).
  [[nodiscard]] const TriangleMesh& mesh() const;
  [[nodiscard]] const Aabb& box() const { return box_; }  // boundingBox(mesh()), bit for bit
  // Every vertex finite and every index in range: the only meshes whose culled draws are
  // offered, so that a mesh the device refuses is refused exactly as before.
  [[nodiscard]] bool drawable() const { return drawable_; }
  [[nodiscard]] const TriangleBvh* hierarchy() const { return hierarchy_.get(); }
  [[nodiscard]] const Eigen::Isometry3d& localToWorld() const { return localToWorld_; }
  // The mesh in its own coordinates (made now when its source has not made it yet), or null.
  [[nodiscard]] std::shared_ptr<const ObjectSpaceMesh> objectSpaceMesh() const {
    return local_ ? local_() : nullptr;
  }

 private:
  PairBlock() = default;
  // Sets the hierarchy, the pose and the object-space mesh's source of a drawable block after
  // checking the hierarchy's count against `triangles`.
  void attach(std::size_t triangles, std::shared_ptr<const TriangleBvh> hierarchy,
              const Eigen::Isometry3d& localToWorld, ObjectSpaceSource local);

  // A posedLazily block's world mesh, made on first use.
  struct LazyWorld {
    const TriangleMesh* local = nullptr;
    TriangleMesh* storage = nullptr;
    Eigen::Isometry3d pose;
    std::once_flag made;
  };

  const TriangleMesh* mesh_ = nullptr;  // null while lazy_ has not made it
  std::shared_ptr<LazyWorld> lazy_;
  Aabb box_;
  bool drawable_ = false;
  std::shared_ptr<const TriangleBvh> hierarchy_;
  Eigen::Isometry3d localToWorld_ = Eigen::Isometry3d::Identity();
  ObjectSpaceSource local_;  // empty: none
};

}  // namespace recode::core
