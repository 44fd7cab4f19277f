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

// A lower bound of that distance that does not depend on GJK having converged: the width of
// the empty slab between the two sets across GJK's closest direction (min over a of n.a minus
// max over b of n.b), 0 when GJK finds them intersecting or the slab is empty. Each end is
// rounded once per point, so a gap above about 1e-15 of the points' size is a true one: the
// hulls are apart. Where GJK stops early (face-to-face pairs), its direction can be slightly
// off and the bound a few per cent low, never high. Throws std::invalid_argument when either
// set is empty.
[[nodiscard]] double convexHullGap(std::span<const Eigen::Vector3d> a,
                                   std::span<const Eigen::Vector3d> b);

}  // namespace recode::core
