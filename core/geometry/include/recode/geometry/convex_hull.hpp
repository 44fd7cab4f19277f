#pragma once
// The convex hull of a point set as a convex block (docs/geometry.md section 5): how a block is
// made from a collision mesh that is not itself a clean closed convex surface (a mesh with an
// edge used by three triangles, a point cloud, one piece of a convex decomposition).
//
// The hull is computed with exact orientation predicates (exact_predicates.hpp), so its
// combinatorics are those of the exact hull of the given doubles: its vertices are exactly the
// extreme points (a point on a face or an edge of the hull that is not a corner is dropped,
// duplicates count once), every planar face is triangulated by a fan over its corners, and the
// triangles are counter-clockwise seen from outside.

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/mesh_error.hpp"

namespace recode::core {

struct ConvexHull {
  TriangleMesh mesh;                    // the hull: extreme points only, outward triangles
  std::vector<std::size_t> inputIndex;  // mesh.vertices[k] is points[inputIndex[k]]
};

// The exact convex hull of `points`. Throws MeshError("<sourceName>: <problem>") when the
// points span no volume: fewer than 4 points, all at one place, all on one line, all in one
// plane (the message names the rule and the counts), or a coordinate that is not finite.
// Coordinates must lie within +-1e100, far beyond any scene's range (std::invalid_argument
// otherwise: the exact arithmetic would overflow).
[[nodiscard]] ConvexHull convexHull(std::span<const Eigen::Vector3d> points,
                                    std::string_view sourceName);

// The hull as a convex block: convexHull, then validateConvexBlock with the default tolerance,
// so the result is one the pair algorithm can draw. A hull that is exact but too thin for the
// tolerance (points nearly in one plane, corners closer than the tolerance) throws
// MeshError("<sourceName>: the convex hull of its N points is not a valid convex block: ...").
[[nodiscard]] TriangleMesh convexHullBlock(std::span<const Eigen::Vector3d> points,
                                           std::string_view sourceName);

}  // namespace recode::core
