#include "recode/sim/leaf_block.hpp"

#include <cstring>

#include "posed_vertex_box.hpp"

namespace recode::core {

namespace {

const HierarchyNode& leafNode(const ObjectTree& tree, int leaf) {
  return tree.nodes().at(static_cast<std::size_t>(leaf));
}

// The leaf's block at its current pose, its world mesh to be made in `storage` when asked for.
PairBlock posedBlock(const ObjectTree& tree, int leaf, TriangleMesh& storage) {
  const HierarchyNode& node = leafNode(tree, leaf);
  const Aabb* current = tree.currentLeafBox(leaf);
  const Aabb box = current != nullptr
                       ? *current
                       : detail::posedVertexBox(node.localMesh.vertices, node.world.linear(),
                                                node.world.translation());
  return PairBlock::posedLazily(node.localMesh, storage, tree.triangleHierarchy(leaf), node.world,
                                box, node.localExtent,
                                [&tree, leaf] { return tree.objectSpaceMesh(leaf); });
}

}  // namespace

LeafBlock::LeafBlock(const ObjectTree& tree, int leaf)
    : pose(leafNode(tree, leaf).world), block(posedBlock(tree, leaf, worldStorage)) {}

void LeafBlock::moveTo(const ObjectTree& tree, int leaf) {
  const HierarchyNode& node = leafNode(tree, leaf);
  // Bit for bit: a -0 where there was a +0 could change the sign of a zero coordinate.
  if (std::memcmp(node.world.matrix().data(), pose.matrix().data(), sizeof(double) * 16) == 0)
    return;
  // The pose last: if anything above threw, the next call makes the block again.
  block = posedBlock(tree, leaf, worldStorage);
  pose = node.world;
}

}  // namespace recode::core
