// Making blocks and closed meshes (validated once, when made) and object shapes (an ObjectTree
// built from a scene object whose leaves are the blocks, already placed in object coordinates).
#include "recode/api/geometry.hpp"

#include <stdexcept>
#include <utility>

#include "recode/geometry/closed_mesh.hpp"
#include "recode/geometry/convex_hull.hpp"
#include "recode/geometry/mesh_io.hpp"
#include "recode/geometry/validate.hpp"
#include "recode/scene/scene.hpp"

namespace recode {

namespace {

// A mesh of the given vertices and triangles, for the fromArrays of blocks and closed meshes.
core::TriangleMesh meshOf(std::span<const Eigen::Vector3d> vertices,
                          std::span<const core::Triangle> triangles) {
  core::TriangleMesh mesh;
  mesh.vertices.assign(vertices.begin(), vertices.end());
  mesh.triangles.assign(triangles.begin(), triangles.end());
  return mesh;
}

}  // namespace

ConvexBlockPtr ConvexBlock::fromMesh(core::TriangleMesh mesh, std::string name) {
  core::validateConvexBlock(mesh, name);
  return ConvexBlockPtr(new ConvexBlock(std::move(mesh), std::move(name)));
}

ConvexBlockPtr ConvexBlock::fromArrays(std::span<const Eigen::Vector3d> vertices,
                                       std::span<const core::Triangle> triangles,
                                       std::string name) {
  return fromMesh(meshOf(vertices, triangles), std::move(name));
}

ConvexBlockPtr ConvexBlock::fromFile(const std::filesystem::path& path) {
  // Named by the path, as a scene's mesh file is (core/scene/src/scene_shapes.cpp).
  core::TriangleMesh mesh = core::readMesh(path);
  try {
    return fromMesh(std::move(mesh), path.string());
  } catch (const core::MeshError& e) {
    throw core::MeshError(std::string(e.what()) +
                          " (to use the convex hull of its vertices instead, use "
                          "ConvexBlock::fromFileHull)");
  }
}

ConvexBlockPtr ConvexBlock::fromHull(std::span<const Eigen::Vector3d> points, std::string name) {
  // convexHullBlock has validated it; fromMesh validates again, which costs little next to the
  // hull and keeps one way in.
  core::TriangleMesh hull = core::convexHullBlock(points, name);  // before name is moved
  return fromMesh(std::move(hull), std::move(name));
}

ConvexBlockPtr ConvexBlock::fromFileHull(const std::filesystem::path& path) {
  return fromHull(core::readMesh(path).vertices, path.string());
}

ClosedMeshPtr ClosedMesh::fromMesh(core::TriangleMesh mesh, std::string name) {
  core::validateClosedMesh(mesh, name);
  return ClosedMeshPtr(new ClosedMesh(std::move(mesh), std::move(name)));
}

ClosedMeshPtr ClosedMesh::fromArrays(std::span<const Eigen::Vector3d> vertices,
                                     std::span<const core::Triangle> triangles, std::string name) {
  return fromMesh(meshOf(vertices, triangles), std::move(name));
}

ClosedMeshPtr ClosedMesh::fromFile(const std::filesystem::path& path) {
  return fromMesh(core::readMesh(path), path.string());
}

namespace {

// The leaf of one part: its block moved into object coordinates, so the tree's placements
// stay the identity and the object's pose alone places it (no rounding through Euler angles).
core::SceneObject leafOf(const BlockPart& part) {
  if (!part.block)
    throw std::invalid_argument("a collision geometry's block is null");
  core::SceneObject leaf;
  leaf.name = part.block->name();
  leaf.localMesh = part.pose.matrix() == Eigen::Matrix4d::Identity()
                       ? part.block->mesh()
                       : core::transformed(part.block->mesh(), part.pose);
  return leaf;
}

}  // namespace

CollisionGeometryPtr CollisionGeometry::single(ConvexBlockPtr block) {
  std::vector<BlockPart> parts{{std::move(block), Eigen::Isometry3d::Identity()}};
  core::ObjectTree tree(leafOf(parts.front()));
  return CollisionGeometryPtr(new CollisionGeometry(std::move(parts), nullptr, std::move(tree)));
}

CollisionGeometryPtr CollisionGeometry::closed(ClosedMeshPtr mesh) {
  if (!mesh)
    throw std::invalid_argument("a collision geometry's closed mesh is null");
  core::SceneObject leaf;
  leaf.name = mesh->name();
  leaf.localMesh = mesh->mesh();
  leaf.closed = true;
  core::ObjectTree tree(leaf);
  return CollisionGeometryPtr(new CollisionGeometry({}, std::move(mesh), std::move(tree)));
}

CollisionGeometryPtr CollisionGeometry::compound(std::vector<BlockPart> parts, std::string name) {
  if (parts.empty())
    throw std::invalid_argument("a collision geometry needs at least one block");
  core::SceneObject root;
  root.name = std::move(name);
  for (const BlockPart& part : parts)
    root.children.push_back(leafOf(part));
  core::ObjectTree tree(root);
  return CollisionGeometryPtr(new CollisionGeometry(std::move(parts), nullptr, std::move(tree)));
}

CollisionGeometryPtr CollisionGeometry::fromObjGroups(const std::filesystem::path& path,
                                                      bool hull) {
  std::vector<BlockPart> parts;
  for (core::MeshGroup& group : core::readObjGroups(path)) {
    std::string name = path.string() + ": group '" + group.name + "'";
    parts.push_back({hull ? ConvexBlock::fromHull(group.mesh.vertices, std::move(name))
                          : ConvexBlock::fromMesh(std::move(group.mesh), std::move(name)),
                     Eigen::Isometry3d::Identity()});
  }
  return compound(std::move(parts), path.string());
}

CollisionGeometry::CollisionGeometry(std::vector<BlockPart> parts, ClosedMeshPtr closed,
                                     core::ObjectTree tree)
    : parts_(std::move(parts)), closed_(std::move(closed)), tree_(std::move(tree)) {
  // ObjectTree numbers its leaves depth first, in the order the parts were given.
  blockOfNode_.assign(tree_.nodes().size(), -1);
  for (std::size_t i = 0; i < tree_.leaves().size(); ++i)
    blockOfNode_[static_cast<std::size_t>(tree_.leaves()[i])] = static_cast<int>(i);
  // Each block's triangle hierarchy is built now, with the geometry, rather than inside the
  // first collide() that draws the block; the objects made from this geometry share them.
  for (const int leaf : tree_.leaves())
    (void)tree_.triangleHierarchy(leaf);
}

const BlockPart& CollisionGeometry::part(std::size_t i) const {
  if (closed_)
    throw std::logic_error("the geometry '" + name() +
                           "' is a closed mesh, not convex blocks: read closedMesh()");
  return parts_.at(i);
}

int CollisionGeometry::blockOfNode(int node) const {
  return blockOfNode_.at(static_cast<std::size_t>(node));
}

}  // namespace recode
