#pragma once
// A leaf of an object tree made ready for the pair algorithm at the tree's current pose: its
// world mesh, with the triangle hierarchy of its own mesh and its pose, so that a pair test
// draws only the triangles near its MOR. The results are those of the bare world mesh, bit for
// bit. Used by core::Simulation and by recode::collide.

#include "recode/pair/pair_block.hpp"
#include "recode/sim/hierarchy.hpp"

namespace recode::core {

struct LeafBlock {
  LeafBlock(const ObjectTree& tree, int leaf)
      : mesh(tree.worldMesh(leaf)),
        block(mesh, tree.triangleHierarchy(leaf),
              tree.nodes()[static_cast<std::size_t>(leaf)].world) {}
  // block refers to mesh, so a LeafBlock stays where it was made.
  LeafBlock(const LeafBlock&) = delete;
  LeafBlock& operator=(const LeafBlock&) = delete;

  TriangleMesh mesh;
  PairBlock block;
};

}  // namespace recode::core
