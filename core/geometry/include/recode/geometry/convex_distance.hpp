#pragma once
// Distance between convex hulls of point sets, by the Gilbert-Johnson-Keerthi algorithm: an
// object-space check independent of any rendering. The built-in hand scene uses it to find
// when each finger first meets the ball, so that fingers stop at the ball by construction.

#include <span>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace recode::core {

// The Euclidean distance between the convex hulls of `a` and `b`; 0 when they intersect
// (touching included, to within about 1e-12 of the points' size). Throws
// std::invalid_argument when either set is empty.
[[nodiscard]] double convexHullDistance(std::span<const Eigen::Vector3d> a,
                                        std::span<const Eigen::Vector3d> b);

// A lower bound of that distance that does not depend on GJK having converged: the width of
// the empty slab between the two sets across GJK's closest direction (min over a of n.a minus
// max over b of n.b). It is 0 when GJK finds them intersecting, or when the slab is no wider
// than 1e-12 of the points' largest coordinate (a thousand times the rounding of its ends), so
// any positive answer proves the hulls apart. Where GJK stops early (face-to-face pairs), its
// direction can be slightly off and the bound a few per cent low, never high. Throws
// std::invalid_argument when either set is empty.
[[nodiscard]] double convexHullGap(std::span<const Eigen::Vector3d> a,
                                   std::span<const Eigen::Vector3d> b);

// Whether conv(a) grown by the box [-margin, margin] (per axis) and conv(b) are proven apart:
// GJK's closest direction n between the two, and an empty slab across n checked against every
// point, min over a of n.a - margin.|n| - max over b of n.b, wider than the rounding of its
// ends (as convexHullGap). true proves that no point of conv(a) and point of conv(b) differ by
// a vector of the box; false proves nothing (they may meet, or GJK's direction fell short).
// A fast way to rule a pair out before drawing it (docs/algorithm.md, "the skip-apart mode").
// Throws std::invalid_argument when either set is empty or the margin is negative or not
// finite.
[[nodiscard]] bool hullsApartBeyond(std::span<const Eigen::Vector3d> a,
                                    std::span<const Eigen::Vector3d> b,
                                    const Eigen::Vector3d& margin);

// A point set in its own coordinates and the map to the world: its world points are
// posedPoint(pose.linear(), pose.translation(), p), as core::transformed makes a mesh's vertices.
struct PosedPoints {
  std::span<const Eigen::Vector3d> local;
  Eigen::Isometry3d pose;
};

// hullsApartBeyond of the two sets' world points, without making them: GJK reads a point only
// when it is a support (made exactly as the world point), and the slab's ends are taken in each
// set's own coordinates, n.(L p + t) as (L^T n).p + n.t, whose rounding differs from the world
// points' by about 1e-15 of their size, far inside the 1e-12 the slab must clear. So true proves
// the world points' hulls apart as above. The same errors as above.
[[nodiscard]] bool hullsApartBeyond(const PosedPoints& a, const PosedPoints& b,
                                    const Eigen::Vector3d& margin);

}  // namespace recode::core
