#pragma once
// A leaf of an object tree made ready for the pair algorithm at the tree's current pose: its
// world mesh, with the triangle hierarchy of its own mesh and its pose, so that a pair test
// draws only the triangles near its MOR. The results are those of the bare world mesh, bit for
// bit. Used by core::Simulation (which keeps a leaf's block from frame to frame while the leaf
// is drawn) and by recode::collide.

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
  // from): nothing when the pose is, bit for bit, the one the mesh was made at; else the world
  // mesh is rewritten in place (transformInto: worldMesh's vertices, bit for bit, and no
  // allocation) and the block made again over it.
  void moveTo(const ObjectTree& tree, int leaf);

  TriangleMesh mesh;
  Eigen::Isometry3d pose;  // the leaf's world pose that `mesh` was made at
  PairBlock block;
};

}  // namespace recode::core
