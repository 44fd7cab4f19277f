#pragma once
// A convex block grown by an axis-aligned box: a closed convex block that contains the Minkowski
// sum A + [-h0,h0] x [-h1,h1] x [-h2,h2] (world axes x, y, z) exactly, and exceeds it by at most
// one unit in the last place of each coordinate (docs/algorithm.md section 9). The conservative
// mode draws blocks grown this way; the adaptive mode uses it to decide whether a finer grid
// could change a verdict.

#include <Eigen/Core>

#include "recode/geometry/mesh.hpp"

namespace recode::core {

// The exact convex hull (core::convexHull, exact predicates, nothing dropped) of every vertex of
// `block` moved to every corner of the box of half-sides `half`, each sum rounded away from the
// vertex, so that the hull holds the exact sum: its support in every direction is at least the
// exact Minkowski sum's. Holds for any block however it is turned, flattened or thinned: no face
// normal's sign is ever taken. A half-side <= 0 adds no corners along that axis. Throws
// MeshError when the points span no volume (a flat block grown along its plane only).
[[nodiscard]] TriangleMesh grownByBox(const TriangleMesh& block, const Eigen::Vector3d& half);

}  // namespace recode::core
