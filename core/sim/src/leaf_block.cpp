#include "recode/sim/leaf_block.hpp"

#include <cstring>

namespace recode::core {

namespace {

const HierarchyNode& leafNode(const ObjectTree& tree, int leaf) {
  return tree.nodes().at(static_cast<std::size_t>(leaf));
}

}  // namespace

LeafBlock::LeafBlock(const ObjectTree& tree, int leaf)
    : mesh(tree.worldMesh(leaf)),
      pose(leafNode(tree, leaf).world),
      block(mesh, tree.triangleHierarchy(leaf), pose) {}

void LeafBlock::moveTo(const ObjectTree& tree, int leaf) {
  const HierarchyNode& node = leafNode(tree, leaf);
  // Bit for bit: a -0 where there was a +0 could change the sign of a zero coordinate.
  if (std::memcmp(node.world.matrix().data(), pose.matrix().data(), sizeof(double) * 16) == 0)
    return;
  transformInto(node.localMesh, node.world, mesh);
  // The pose last: if anything above threw, the next call makes the mesh again.
  block = PairBlock(mesh, tree.triangleHierarchy(leaf), node.world);
  pose = node.world;
}

}  // namespace recode::core
