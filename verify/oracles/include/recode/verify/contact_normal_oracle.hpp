#pragma once
// Oracles for the contact normal (docs/accuracy.md, "Contact normal"): exact candidate-direction
// searches over polytopes, no sampling. Both need only doubles; the exact intersection solid
// they are meant for comes from intersectionHull (cgal_oracle.hpp).

#include "recode/geometry/mesh.hpp"

#include <Eigen/Core>

namespace recode::verify {

struct OracleDirection {
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // unit; zero when there is none
  double extent = 0.0;                                  // world units
};

// The direction of least width of a closed convex polytope (its sign: largest component
// positive) and that width. The least width of a convex polytope is reached at a face normal or
// at the cross product of two of its edges, so every such direction is tried. Zero direction
// for a mesh without triangles.
[[nodiscard]] OracleDirection thinnestDirectionOf(const core::TriangleMesh& solid);

// The penetration normal of two convex blocks that overlap: the unit n (from A towards B)
// minimising max over A of x.n - min over B of x.n, the shortest translation of B that
// separates them, and that length (the penetration depth). For convex polytopes it is reached at
// a face normal of A or B or at the cross product of an edge of A and an edge of B, all tried.
[[nodiscard]] OracleDirection penetrationNormal(const core::TriangleMesh& a,
                                                const core::TriangleMesh& b);

// Angle between two directions in degrees, 0..180.
[[nodiscard]] double angleDegrees(const Eigen::Vector3d& u, const Eigen::Vector3d& v);

}  // namespace recode::verify
