#pragma once
// A convex block cut down to an axis-aligned box: the adaptive mode draws only the part of
// each block inside the small region where a contact could be, so that the region's frame has
// fine pixels and a short depth range (fine depth steps).

#include "recode/geometry/mesh.hpp"

namespace recode::core {

// The part of a closed, outward-oriented convex block on the side x[axis] <= bound
// (keepBelow) or x[axis] >= bound (otherwise), closed again by a cap on the plane. Cut points
// are computed once per edge, so the two triangles beside an edge share them and the result is
// watertight; each lies exactly on the plane. Empty when nothing of the block is on that side.
[[nodiscard]] TriangleMesh clippedByPlane(const TriangleMesh& block, int axis, double bound,
                                          bool keepBelow);

// The block clipped by the six planes of `box` (closed). Empty when they do not meet or the
// box is empty.
[[nodiscard]] TriangleMesh clippedToBox(const TriangleMesh& block, const Aabb& box);

}  // namespace recode::core
