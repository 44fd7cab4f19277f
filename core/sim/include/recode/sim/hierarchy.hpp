#pragma once
// An object as a tree of nodes with rigid transforms (docs/scenes.md, docs/cli.md "recode run"):
// leaves are convex blocks, every node carries a world AABB (recomputed per frame, when the
// object comes near another: Simulation) and an OBB. Pairs of objects descend their trees while
// both kinds of box overlap; the leaf pairs that remain go to the pair algorithm.
//
// Boxes nest: a node's AABB is the union of its children's, and a node's OBB contains its
// children's OBBs (it is fitted to their corners, not to the vertices). So a leaf pair whose
// own boxes overlap has overlapping boxes at every pair of ancestors, and the descent reports
// exactly the leaf pairs whose boxes overlap, whatever order it splits nodes in.
//
// OBBs are fitted once, in the node's own coordinates (fitObb), and moved rigidly with the
// node, for every node whose subtree is rigid. A node whose subtree moves inside it (a joint,
// a motion or keyframes below it, as in a hand) cannot keep a fixed box; its "OBB" is
// instead recomputed per frame as the world-axis box of its children's OBB corners.

#include <cstddef>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/obb.hpp"
#include "recode/geometry/triangle_bvh.hpp"
#include "recode/pair/pair_block.hpp"
#include "recode/scene/motion.hpp"
#include "recode/scene/scene.hpp"

namespace recode::core {

struct HierarchyNode {
  std::string path;  // names from the root joined by '/': "left hand/index/distal"
  int parent = -1;   // index in ObjectTree::nodes(), -1 for the root
  std::vector<int> children;
  Placement placement;       // rest pose and motion relative to the parent
  TriangleMesh localMesh;    // leaves: the block in the node's own coordinates; empty otherwise
  double localExtent = 0.0;  // leaves: drawableExtent(localMesh), made once
  bool rigid = true;         // nothing below this node moves relative to it
  Obb localObb;              // in the node's coordinates (rigid nodes)

  // At the current frame:
  Eigen::Isometry3d world = Eigen::Isometry3d::Identity();  // local -> world
  Aabb worldAabb;
  Obb worldObb;

  [[nodiscard]] bool isLeaf() const { return children.empty(); }
};

class ObjectTree {
 public:
  // Flattens the object (depth first, the root is node 0). Throws std::invalid_argument for a
  // leaf without triangles.
  explicit ObjectTree(const SceneObject& root);

  [[nodiscard]] const std::string& name() const { return nodes_.front().path; }
  [[nodiscard]] const std::vector<HierarchyNode>& nodes() const { return nodes_; }
  [[nodiscard]] const HierarchyNode& root() const { return nodes_.front(); }
  [[nodiscard]] const std::vector<int>& leaves() const { return leaves_; }
  [[nodiscard]] std::size_t triangleCount() const { return triangles_; }

  // Every node's world transform at frame k (the animation step).
  void setFrame(int frame);
  // The same with the whole object moved by `base` (world <- the root's parent coordinates):
  // how the collision API (recode/api) places an object at the pose its user sets.
  void setFrame(int frame, const Eigen::Isometry3d& base);
  // Every node's world AABB and OBB for the current transforms (leaves recompute their
  // AABB from their vertices only when their transform changed): updateObbs, then updateAabbs.
  void updateBounds();
  // Every node's world OBB alone: no vertex is touched.
  void updateObbs();
  // Every node's world AABB alone.
  void updateAabbs();
  // After updateObbs: an axis-aligned box that holds every vertex of the object, from the
  // root's OBB (its AABB grown by a relative margin for rounding), so that it contains the
  // root's AABB as updateAabbs makes it. Cheaper than that AABB, and larger.
  [[nodiscard]] Aabb boxAroundObb() const;
  // Whether updateAabbs would make a leaf's box from its vertices (its transform changed since,
  // or it has none yet).
  [[nodiscard]] bool leafBoxStale(int node) const;
  // Sets a leaf's world AABB as updateAabbs would make it at its current transform: `box` must
  // be posedVertexBox's, bit for bit (a device's reduction, made again on the host where the
  // order of the comparisons matters). updateAabbs then keeps it and makes the nodes above.
  void setLeafBox(int node, const Aabb& box);
  // A leaf's world AABB when updateAabbs made it at the leaf's current transform (then it is the
  // box of worldMesh(node)'s vertices bit for bit), else null.
  [[nodiscard]] const Aabb* currentLeafBox(int node) const;
  // Both steps.
  void pose(int frame) {
    setFrame(frame);
    updateBounds();
  }

  // A leaf's block in world coordinates at the current frame.
  [[nodiscard]] TriangleMesh worldMesh(int node) const;

  // A leaf's triangle hierarchy in its own coordinates (the triangles of worldMesh(node) are
  // its triangles): built on first use, once even when threads ask at the same time, then
  // shared and never changed.
  [[nodiscard]] std::shared_ptr<const TriangleBvh> triangleHierarchy(int node) const;
  // A leaf's mesh in its own coordinates, flat, for devices that keep it (PairBlock): made on
  // first use, as the hierarchy, and shared while the tree or a block holds it.
  [[nodiscard]] std::shared_ptr<const ObjectSpaceMesh> objectSpaceMesh(int node) const;

 private:
  int add(const SceneObject& object, int parent, const std::string& parentPath);
  void fitLocalBoxes();

  std::vector<HierarchyNode> nodes_;
  std::vector<int> leaves_;
  std::vector<Eigen::Isometry3d> boundsAt_;  // per node: the transform its AABB was made at
  std::vector<bool> boundsValid_;
  std::size_t triangles_ = 0;
  struct LazyHierarchy {
    std::once_flag built;
    std::shared_ptr<const TriangleBvh> hierarchy;
    std::once_flag flattened;
    std::shared_ptr<const ObjectSpaceMesh> objectSpace;
  };
  std::vector<std::shared_ptr<LazyHierarchy>> hierarchies_;  // per node
};

// Whether two nodes' boxes overlap: their world AABBs and their world OBBs.
[[nodiscard]] bool nodeBoxesOverlap(const HierarchyNode& a, const HierarchyNode& b);

struct LeafPair {
  int leafA = 0;  // node index in the first tree
  int leafB = 0;  // node index in the second tree
  friend bool operator==(const LeafPair&, const LeafPair&) = default;
};

// Descends two trees from their roots while node boxes overlap; appends the leaf pairs whose
// boxes overlap to `out`, sorted by (leafA, leafB). Returns the number of node pairs whose
// boxes were tested (the roots' pair included). It stops once it has appended `maxLeafPairs`
// pairs (then unsorted): two trees of many blocks can overlap in billions of leaf pairs, and the
// caller refuses more than its limit anyway.
long long descendPair(const ObjectTree& a, const ObjectTree& b, std::vector<LeafPair>& out,
                      std::size_t maxLeafPairs = std::numeric_limits<std::size_t>::max());

}  // namespace recode::core
