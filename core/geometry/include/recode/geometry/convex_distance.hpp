#pragma once
// Distance between convex hulls of point sets, by the Gilbert-Johnson-Keerthi algorithm: an
// object-space check independent of any rendering. The built-in hand scene uses it to find
// when each finger first meets the ball, so that fingers stop at the ball by construction.

#include <span>

#include <Eigen/Core>

namespace recode::core {

// The Euclidean distance between the convex hulls of `a` and `b`; 0 when they intersect
// (touching included, to within about 1e-12 of the points' size). Throws
// std::invalid_argument when either set is empty.
[[nodiscard]] double convexHullDistance(std::span<const Eigen::Vector3d> a,
                                        std::span<const Eigen::Vector3d> b);

}  // namespace recode::core
