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

// The hull as a convex block, one the pair algorithm can draw: convexHull, then, while a
// triangle's height over its longest edge is within the validation tolerance (1e-9 times the
// hull's bounding-box diagonal), the corner opposite that edge is dropped (it lies within the
// tolerance of the hull of the other points) and the hull made again; then
// validateConvexBlock. Points that span no volume at that tolerance (nearly in one plane)
// throw MeshError("<sourceName>: the convex hull of its N points is not a valid convex block
// (<problem>); its points are too close to one plane, line or point for the validation
// tolerance"); the degenerate sets of convexHull throw its errors.
[[nodiscard]] TriangleMesh convexHullBlock(std::span<const Eigen::Vector3d> points,
                                           std::string_view sourceName);

}  // namespace recode::core
