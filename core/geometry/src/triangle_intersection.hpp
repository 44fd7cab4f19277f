#pragma once
// Internal to the self-intersection search (not installed, not public API): whether two
// triangles of a mesh meet anywhere but where they are joined, decided exactly with the
// orientation predicates of exact_predicates.hpp (no tolerance). Triangles and segments are
// closed: touching at a single point counts as meeting.
//
// Every triangle given must be non-degenerate (three points not on one line) and have finite
// coordinates within the predicates' range; the closed-mesh check (closed_mesh.hpp) ensures
// both before it asks.

#include <Eigen/Core>

#include "recode/geometry/mesh.hpp"

namespace recode::core::detail {

// True when the closed segment [p, q] (p != q) and the closed triangle (a, b, c) have a point
// in common.
[[nodiscard]] bool segmentMeetsTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                                        const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                        const Eigen::Vector3d& c);

// How many vertex indices triangles t and u have in common (0 to 3).
[[nodiscard]] int sharedVertexCount(const Triangle& t, const Triangle& u);

// True when triangles t and u of the mesh meet anywhere but where the surface joins them:
// sharing no vertex index, anywhere; sharing one vertex index, anywhere but that vertex;
// sharing two (an edge), when they lie in one plane on the same side of that edge (the surface
// folds onto itself); sharing three, always (the same triangle twice).
[[nodiscard]] bool trianglesMeet(const TriangleMesh& mesh, const Triangle& t, const Triangle& u);

}  // namespace recode::core::detail
