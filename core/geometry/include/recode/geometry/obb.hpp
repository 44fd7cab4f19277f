#pragma once
// Oriented bounding boxes for the object hierarchies (docs/cli.md "recode run", steps 2-4):
// fitted once to a node's geometry in the node's own coordinates, then moved rigidly with the
// node, and tested against each other with the separating-axis theorem. Boxes are closed:
// boxes that only touch overlap, as blocks that only touch interfere in the pair algorithm.

#include <array>
#include <span>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "recode/geometry/mesh.hpp"

namespace recode::core {

struct Obb {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  // Columns are the box's axes: orthonormal and right-handed (a rotation matrix).
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d halfExtents = Eigen::Vector3d::Zero();  // >= 0 along each axis

  // center + sum of +-halfExtents[i] * axes.col(i); corner k takes the + sign for axis i
  // when bit i of k is set.
  [[nodiscard]] std::array<Eigen::Vector3d, 8> corners() const;
  // The box moved by a rigid transform (the transform's linear part must be a rotation).
  [[nodiscard]] Obb transformed(const Eigen::Isometry3d& transform) const;
  [[nodiscard]] double volume() const { return 8.0 * halfExtents.prod(); }
  // The axis-aligned box of the eight corners.
  [[nodiscard]] Aabb aabb() const;
};

// The box with the given axes (columns, orthonormal) that just contains the points: their
// extreme projections on each axis. Throws std::invalid_argument for no points.
[[nodiscard]] Obb fitObbWithAxes(std::span<const Eigen::Vector3d> points,
                                 const Eigen::Matrix3d& axes);

// A tight box for the points, fitted once per node. Candidates, smallest volume wins (the
// first on a tie): the coordinate axes of the frame the points are given in (exact for
// boxes and for shapes built along their own axes, such as the generators' cones and
// cylinders), and the principal axes of the points' covariance (good for elongated shapes
// placed at an angle). Throws std::invalid_argument for no points.
[[nodiscard]] Obb fitObb(std::span<const Eigen::Vector3d> points);

// The same box grown by `margin` (>= 0) on every side.
[[nodiscard]] Obb grown(const Obb& box, double margin);

// Separating-axis test of two closed boxes over the 15 candidate axes (3 face normals of
// each box, 9 edge-direction cross products). True when no axis separates them, i.e. when the
// boxes share a point; touching boxes overlap. The test errs only toward "overlap": the
// cosines between the two boxes' axes are enlarged by kObbParallelSlack so that nearly
// parallel edges, whose cross product is a tiny ill-defined axis, cannot separate boxes that
// meet.
[[nodiscard]] bool obbsOverlap(const Obb& a, const Obb& b);
inline constexpr double kObbParallelSlack = 1e-9;

// Closed interval overlap on all three axes (touching boxes overlap); false if either is
// empty.
[[nodiscard]] bool aabbsOverlap(const Aabb& a, const Aabb& b);

}  // namespace recode::core
