#pragma once
// A convex block grown by an axis-aligned box: the Minkowski sum A + [-h0,h0] x [-h1,h1] x
// [-h2,h2] in world axes x, y, z, built without a hull by sweeping the block along one axis at
// a time (docs/algorithm.md, "Beyond the paper"). The conservative mode draws blocks grown this
// way; the adaptive mode uses it to decide whether a finer grid could change a verdict.

#include <Eigen/Core>

#include "recode/geometry/mesh.hpp"

namespace recode::core {

// The sweep of a closed, outward-oriented convex block along world axis `axis` (0 x, 1 y, 2 z)
// by [-h, h]: faces whose outward normal has a positive component along the axis move by +h,
// the others by -h, and every edge between the two kinds becomes a quad joining its two
// copies. The result is closed, outward-oriented and convex (the Minkowski sum of the block and
// the segment); vertices no triangle uses are dropped. h <= 0 returns the block unchanged.
[[nodiscard]] TriangleMesh sweptAlongAxis(const TriangleMesh& block, int axis, double h);

// The block grown by the box of half-sides `half` (world x, y, z): three sweeps.
[[nodiscard]] TriangleMesh grownByBox(const TriangleMesh& block, const Eigen::Vector3d& half);

}  // namespace recode::core
