#pragma once
// The shapes of the collision API (docs/api.md): a ConvexBlock is one validated convex block,
// a ClosedMesh one validated closed mesh of any shape (a torus, a bowl, a hollow part), and a
// CollisionGeometry an object's shape: one or more blocks fixed together, or one closed mesh.
// All are immutable once made and shared through std::shared_ptr, so many CollisionObjects
// (FCL's split of geometry and pose) can use one shape at different poses.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "recode/geometry/mesh.hpp"
#include "recode/sim/hierarchy.hpp"

namespace recode {

class ConvexBlock;
// Blocks are shared, immutable once made.
using ConvexBlockPtr = std::shared_ptr<const ConvexBlock>;

// A closed convex block in its own coordinates. Every way of making one validates it with
// core::validateConvexBlock and throws its core::MeshError ("<name>: <problem>", the messages of
// docs/geometry.md), so a block that exists is one the pair algorithm can draw.
class ConvexBlock {
 public:
  // `name` starts the error message and names the block in results.
  [[nodiscard]] static ConvexBlockPtr fromMesh(core::TriangleMesh mesh, std::string name);
  // Vertices and counter-clockwise (seen from outside) triangles.
  [[nodiscard]] static ConvexBlockPtr fromArrays(std::span<const Eigen::Vector3d> vertices,
                                                 std::span<const core::Triangle> triangles,
                                                 std::string name);
  // An OBJ, OFF, STL or PLY file (core::readMesh); its errors are MeshErrors too, named by the
  // path. A file that reads but is not a valid convex block says so and points to fromFileHull.
  [[nodiscard]] static ConvexBlockPtr fromFile(const std::filesystem::path& path);
  // The convex hull of the points (core::convexHullBlock: exact, extreme points only, corners
  // closer than the validation tolerance merged). Bullet's btConvexHullShape and FCL's Convex
  // from qhull take a point set the same way. Fewer than 4 points, or points all on one point,
  // line or plane, throw core::MeshError("<name>: convex hull: ...") naming the rule.
  [[nodiscard]] static ConvexBlockPtr fromHull(std::span<const Eigen::Vector3d> points,
                                               std::string name);
  // The convex hull of all the vertices of an OBJ, OFF, STL or PLY file (its faces are read and
  // checked for syntax, not used): for collision meshes that are convex in shape but not a clean
  // closed surface (an edge used by three triangles, stray faces, holes). Named by the path.
  [[nodiscard]] static ConvexBlockPtr fromFileHull(const std::filesystem::path& path);

  // The validated mesh, in the block's own coordinates.
  [[nodiscard]] const core::TriangleMesh& mesh() const { return mesh_; }
  // The name given when it was made (the path for a file), which starts its error messages.
  [[nodiscard]] const std::string& name() const { return name_; }

 private:
  ConvexBlock(core::TriangleMesh mesh, std::string name)
      : mesh_(std::move(mesh)), name_(std::move(name)) {}
  core::TriangleMesh mesh_;
  std::string name_;
};

class ClosedMesh;
// Closed meshes are shared, immutable once made.
using ClosedMeshPtr = std::shared_ptr<const ClosedMesh>;

// A closed mesh in its own coordinates: the outward-oriented boundary of a solid of any shape
// and genus, possibly in several shells (a cavity's wall faces inward), that never cuts or
// touches itself. Every way of making one validates it with core::validateClosedMesh and throws
// its core::MeshError ("<name>: <problem>", naming the rule broken: docs/geometry.md). A pair
// with a closed mesh on either side is decided by the layered pair (core::collideLayered,
// docs/algorithm.md section 13), which also measures the overlap volume and containment.
class ClosedMesh {
 public:
  // `name` starts the error message and names the mesh in results.
  [[nodiscard]] static ClosedMeshPtr fromMesh(core::TriangleMesh mesh, std::string name);
  // Vertices and counter-clockwise (seen from outside the solid) triangles.
  [[nodiscard]] static ClosedMeshPtr fromArrays(std::span<const Eigen::Vector3d> vertices,
                                                std::span<const core::Triangle> triangles,
                                                std::string name);
  // An OBJ, OFF, STL or PLY file (core::readMesh), named by the path.
  [[nodiscard]] static ClosedMeshPtr fromFile(const std::filesystem::path& path);

  // The validated mesh, in its own coordinates.
  [[nodiscard]] const core::TriangleMesh& mesh() const { return mesh_; }
  // The name given when it was made (the path for a file).
  [[nodiscard]] const std::string& name() const { return name_; }

 private:
  ClosedMesh(core::TriangleMesh mesh, std::string name)
      : mesh_(std::move(mesh)), name_(std::move(name)) {}
  core::TriangleMesh mesh_;
  std::string name_;
};

// A block placed in its object's coordinates.
struct BlockPart {
  ConvexBlockPtr block;                                    // the block, shared
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // block -> object coordinates
};

class CollisionGeometry;
// Shapes are shared by the objects that use them, immutable once made.
using CollisionGeometryPtr = std::shared_ptr<const CollisionGeometry>;

// An object's shape: its blocks, or one closed mesh, held as a core::ObjectTree (the tree
// `recode run` uses: AABBs and OBBs per node, descended pair by pair to the block pairs worth
// drawing). Block i of the geometry is parts[i]; results name blocks by that index (a closed
// mesh is block 0 of its geometry).
class CollisionGeometry {
 public:
  // One block: the tree is that leaf alone. Throws std::invalid_argument for a null block.
  [[nodiscard]] static CollisionGeometryPtr single(ConvexBlockPtr block);
  // Several blocks under one root (one level: the blocks' poses are fixed in the object).
  // Throws std::invalid_argument for no parts or a null block.
  [[nodiscard]] static CollisionGeometryPtr compound(std::vector<BlockPart> parts,
                                                     std::string name = "compound");
  // One block per object or group of an OBJ file (core::readObjGroups), as convex
  // decompositions (V-HACD, CoACD) write them: `o convex_0`, `o convex_1`, ... Block i is the
  // i-th group in file order, named "<path>: group '<name>'", each validated (or, with hull,
  // the convex hull of the group's vertices); a bad group throws core::MeshError with that name.
  [[nodiscard]] static CollisionGeometryPtr fromObjGroups(const std::filesystem::path& path,
                                                          bool hull = false);

  // A closed mesh as an object's whole shape (one leaf). It cannot be part of a compound: the
  // layered pair takes one solid on each side.
  [[nodiscard]] static CollisionGeometryPtr closed(ClosedMeshPtr mesh);

  // The number of blocks (1 for a closed mesh).
  [[nodiscard]] std::size_t blockCount() const { return closed_ ? 1 : parts_.size(); }
  // Block i and its pose in the object. Throws std::out_of_range for i >= blockCount() and
  // std::logic_error for a closed mesh's geometry, which has no convex blocks (closedMesh()).
  [[nodiscard]] const BlockPart& part(std::size_t i) const;
  // The closed mesh of a geometry made by closed(); null for a geometry of convex blocks.
  [[nodiscard]] const ClosedMeshPtr& closedMesh() const { return closed_; }
  // Whether the shape is a closed mesh (its pairs are decided by the layered pair).
  [[nodiscard]] bool isClosed() const { return closed_ != nullptr; }
  // The shape's name: the compound's, or the block's or closed mesh's for one alone.
  [[nodiscard]] const std::string& name() const { return tree_.name(); }
  // The tree at the identity pose; each CollisionObject poses a copy of it.
  [[nodiscard]] const core::ObjectTree& tree() const { return tree_; }
  // Block index of a leaf node of tree() (-1 for a node that is not a leaf).
  [[nodiscard]] int blockOfNode(int node) const;

 private:
  CollisionGeometry(std::vector<BlockPart> parts, ClosedMeshPtr closed, core::ObjectTree tree);
  std::vector<BlockPart> parts_;  // empty for a closed mesh
  ClosedMeshPtr closed_;
  core::ObjectTree tree_;
  std::vector<int> blockOfNode_;
};

}  // namespace recode
