#pragma once
// Checking that a TriangleMesh is a closed mesh: the boundary of a solid of any shape and genus,
// possibly in several pieces, oriented outward, that never cuts, touches or overlaps itself.
// Such a surface splits space into inside and outside, and a view ray through it passes from
// one to the other at each triangle it crosses, which is what computing the solid by layers of
// depth relies on. Unlike the convex-block check (validate.hpp) it has no tolerance: every
// geometric decision is exact on the given doubles (exact_predicates.hpp).
//
// The checks run in stages; a stage runs only if the stages it depends on found nothing:
//   1. there are triangles;
//   2. every coordinate is finite and within +-kMaxExactCoordinate (1e100); every index is
//      below vertexCount();
//   3. no triangle repeats an index or has its three points on one line (exactly);
//   4. every edge is used by exactly two triangles, once in each direction (closed, manifold,
//      consistently oriented), and the triangles around each vertex form a single fan (the
//      surface does not pinch at a vertex); stages 3 and 4 both need stage 2 only;
//   5. no two triangles meet anywhere but at the edge or vertex they share by index
//      (self_intersection.hpp);
//   6. orientation, shell by shell (a shell is a connected piece of the surface): each shell
//      that lies inside no other piece of solid has positive signed volume (faces outward); a
//      shell inside the solid is a cavity's wall and faces inward; the winding number of the
//      whole surface is 0 or 1 at every point off it (docs/geometry.md explains the rule).
// Vertices no triangle uses are allowed and ignored: they are not part of the surface.
//
// Cost: stages 1-4 and 6 take O(V + F log F) (stage 6 casts one ray per shell through the
// triangle hierarchy); stage 5 is the self-intersection search, O(F log F) for evenly sized
// triangles. docs/geometry.md has measurements.

#include <cstddef>
#include <string_view>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/mesh_error.hpp"
#include "recode/geometry/validate.hpp"

namespace recode::core {

// Runs the checks and records up to maxProblems problems (maxProblems >= 1, else
// std::invalid_argument; the search stops once that many are found).
[[nodiscard]] ValidationReport checkClosedMesh(const TriangleMesh& mesh,
                                               std::size_t maxProblems = 16);

// Throws MeshError("<sourceName>: <first problem>") if the mesh is not a valid closed mesh.
void validateClosedMesh(const TriangleMesh& mesh, std::string_view sourceName);

}  // namespace recode::core
