#pragma once
// A leaf of an object tree made ready for the pair algorithm at the tree's current pose: its
// world box, with the triangle hierarchy of its own mesh, its pose and its object-space mesh,
// so that a pair test draws only the triangles near its MOR, or a device draws the posed mesh
// it keeps. The world mesh is made only when something asks for it (PairBlock::posedLazily).
// The results are those of the bare world mesh, bit for bit. Used by core::Simulation (which keeps
// a leaf's block from frame to frame while the leaf is drawn) and by recode::collide.

#include <Eigen/Geometry>

#include "recode/pair/pair_block.hpp"
#include "recode/sim/hierarchy.hpp"

namespace recode::core {

struct LeafBlock {
  LeafBlock(const ObjectTree& tree, int leaf);
  // block refers to mesh, so a LeafBlock stays where it was made.
  LeafBlock(const LeafBlock&) = delete;
  LeafBlock& operator=(const LeafBlock&) = delete;

  // Brings the block to the leaf's current pose in `tree` (the tree and leaf it was made
  // from): nothing when the pose is, bit for bit, the one the block was made at; else the block
  // is made again at the new pose, its world mesh to be rewritten in place when asked for
  // (transformInto: worldMesh's vertices, bit for bit, and no allocation).
  void moveTo(const ObjectTree& tree, int leaf);

  TriangleMesh worldStorage;  // the world mesh's storage: read it through block.mesh()
  Eigen::Isometry3d pose;     // the leaf's world pose that the block was made at
  PairBlock block;
};

}  // namespace recode::core
