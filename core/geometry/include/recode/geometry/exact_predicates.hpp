#pragma once
// Exact orientation predicates on double coordinates: the sign they return is the sign of the
// exact determinant of the given doubles, as if computed with unbounded precision. A fast
// double evaluation with a forward error bound decides most calls; the rest are evaluated
// exactly in floating-point expansion arithmetic (sums of non-overlapping doubles, built from
// the error-free two-sum and two-product; docs/geometry.md section 5).
//
// Inputs must be finite and small enough that products of three coordinate differences do not
// overflow (|coordinate| well below 1e100); the convex hull's callers hold coordinates to
// 1e9. Differences must also not be so small that such products fall below the normal doubles
// (nonzero differences under about 1e-100): the error-free products then lose digits and the
// sign returned can be 0 or wrong, e.g. orient2d of (2^-600, 0), (0, 2^-600), (0, 0) is 0.

#include <Eigen/Core>

namespace recode::core {

// The largest coordinate magnitude that the predicates' callers accept (the convex hull, the
// self-intersection search): products of three differences of such coordinates stay far from
// overflow.
inline constexpr double kMaxExactCoordinate = 1e100;

// +1 when d lies below the plane through a, b, c (a, b, c counter-clockwise seen from above,
// i.e. from the side their normal (b - a) x (c - a) points to), -1 when above, 0 when the four
// points are coplanar. It is the sign of det[a - d; b - d; c - d].
[[nodiscard]] int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                           const Eigen::Vector3d& c, const Eigen::Vector3d& d);

// The sign of the 2-D orientation of (a, b, c) projected on the coordinate plane of axes i
// and j (0 = x, 1 = y, 2 = z): +1 counter-clockwise, -1 clockwise, 0 collinear.
[[nodiscard]] int orient2d(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                           const Eigen::Vector3d& c, int i, int j);

// True when the three points lie on one line (including when two or all coincide), decided
// exactly: all three coordinate-plane projections are collinear.
[[nodiscard]] bool collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3d& c);

}  // namespace recode::core
