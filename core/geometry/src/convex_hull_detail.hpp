#pragma once
// Internal to the convex hull (not installed): the two steps of convex_hull.cpp. The
// incremental step leaves a triangulated hull whose planar faces may still hold points that
// are not corners (a point inserted on the plane of an existing face, or on a line through an
// edge); the facet step merges coplanar triangles into faces and keeps only their corners.

#include <cstdint>
#include <span>
#include <vector>

#include "recode/geometry/mesh.hpp"

namespace recode::core::detail {

// Outward triangles of the hull, indices into `points`. The points span a volume and are
// finite (checked by the caller).
[[nodiscard]] std::vector<Triangle> quickHullTriangles(std::span<const Eigen::Vector3d> points);

// Merges coplanar neighbours into faces, keeps each face's corners (a point strictly between
// its neighbours on a face's boundary is dropped) and fan-triangulates every face over its
// corners. Returns triangles over the same indices; the indices they use are the extreme points.
[[nodiscard]] std::vector<Triangle> cornerTriangulation(std::span<const Eigen::Vector3d> points,
                                                        const std::vector<Triangle>& triangles);

// A directed edge as one key.
inline std::uint64_t edgeKey(VertexIndex from, VertexIndex to) {
  return (static_cast<std::uint64_t>(from) << 32) | to;
}

}  // namespace recode::core::detail
