#pragma once
// Ruling a pair out before it is drawn (the skip-apart mode, docs/algorithm.md section 11): every
// fragment the device makes of a block drawn in a frame lies within a small box of the block's
// convex hull (the snapping across the view, the rounding and quantisation of depth along it),
// so blocks whose hulls are apart by more than both boxes together cannot share a depth at any
// pixel centre, and collidePair in that frame would report no interfering pixel.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"
#include "recode/pair/pair.hpp"
#include "recode/pair/pair_block.hpp"
#include "recode/pair/view.hpp"

namespace recode::core {

// Half-sides, in world units along the world axes x, y, z, of a box around a block's convex
// hull that holds every fragment (pixel centre, quantised depth) the device can make of the
// block drawn through `view`; `box` is the block's world box. Across the view: the snapping to
// 1/256 pixel (at most 1/512) doubled. Along it: the float rounding of a vertex's depth and the
// quantisation (half a 24-bit step each), plus a bound of the double rounding of the depth
// plane, which grows with the square of the block's extent in pixels (a sliver triangle's
// slopes are as steep as 2^8 times that extent), each doubled.
[[nodiscard]] Eigen::Vector3d fragmentSlack(const OrthoView& view, const Aabb& box);

// Whether collidePair(a, b) in `frame` is proven to find no interfering pixel: both blocks
// drawable, the frame and the pair's depth range a view accepts, every vertex inside its
// coordinate range (else false, so that the reference's refusal is seen as before), and their
// vertex hulls apart by more than the sum of their fragment slacks (hullsApartBeyond). false
// proves nothing. Never throws for such a refusal.
[[nodiscard]] bool provenApart(const PairBlock& a, const PairBlock& b, const FrameSpec& frame);

// A block as the skip-apart test can read it before its world mesh is made: the mesh in its own
// coordinates, the pose that maps it to the world (its world mesh is transformed(local, pose)),
// that world mesh's box, bit for bit (ObjectTree::updateAabbs makes it so), and
// drawableExtent(local), made once per mesh rather than per pair.
struct PosedBlock {
  const TriangleMesh& local;
  const Eigen::Isometry3d& pose;
  const Aabb& worldBox;
  double localExtent;
};

// provenApart of the world blocks these make, with the same answer's meaning: the posed
// hullsApartBeyond proves their world vertices' hulls apart. A block is drawable here when its
// own mesh is (a finite localExtent) and its pose cannot overflow a world coordinate
// (|L|_inf localExtent + |t|_inf below 1e300), so that every world vertex is finite.
[[nodiscard]] bool provenApart(const PosedBlock& a, const PosedBlock& b, const FrameSpec& frame);

// What the skip-apart mode reports for a pair provenApart: no interference and no contact, as the
// reference would report, but nothing drawn or read (boxesOverlap false, the MOR empty, no case
// map), and the pair's depth range, as collidePair sets it.
[[nodiscard]] PairResult skippedResult(const PairBlock& a, const PairBlock& b,
                                       const FrameSpec& frame);
// The same from the two world boxes.
[[nodiscard]] PairResult skippedResult(const Aabb& a, const Aabb& b, const FrameSpec& frame);

}  // namespace recode::core
