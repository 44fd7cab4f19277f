#pragma once
// Finding where a triangle mesh cuts, touches or overlaps itself, exactly: two triangles
// intersect when they have a point in common other than along the edge or at the vertex they
// share by index. The tests use the exact orientation predicates (exact_predicates.hpp), with
// no tolerance, so a vertex lying exactly on another triangle counts, and one an ulp away does
// not; a bounding-volume hierarchy over the triangles (triangle_bvh.hpp) limits them to
// triangles whose boxes meet. Nothing outside the geometry library is used.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "recode/geometry/mesh.hpp"

namespace recode::core {

// Two triangles of a mesh, by index, first < second.
struct TrianglePair {
  std::uint32_t first = 0;
  std::uint32_t second = 0;

  friend bool operator==(const TrianglePair&, const TrianglePair&) = default;
};

// The pairs of triangles that intersect (as above), in increasing order of (first, second), at
// most maxPairs of them (the search stops there: the first maxPairs pairs in that order).
// Shared vertices are recognised by index: two triangles whose vertices coincide in position
// under different indices intersect there.
//
// The mesh must have finite coordinates within +-kMaxExactCoordinate (1e100,
// exact_predicates.hpp), indices below
// vertexCount() and no degenerate triangle (a repeated index or three points on one line);
// std::invalid_argument names the first vertex or triangle that breaks this. The closed-mesh
// check (closed_mesh.hpp) ensures all of it before it searches.
//
// Cost: O(F log F) to build the hierarchy, then for each triangle the hierarchy's nodes and
// triangles whose boxes meet its box; a mesh of evenly sized triangles gives O(F log F)
// overall. docs/geometry.md has measurements.
[[nodiscard]] std::vector<TrianglePair> selfIntersections(
    const TriangleMesh& mesh, std::size_t maxPairs = std::numeric_limits<std::size_t>::max());

}  // namespace recode::core
