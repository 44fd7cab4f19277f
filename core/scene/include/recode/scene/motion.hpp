#pragma once
// Motion of scene nodes over frames (`recode run`): frame k's pose of every node is a pure
// function of k, so every algorithm that replays a scene sees the same motion. The formulas
// (docs/scenes.md, "motion", "keyframes", "joint"):
//
//   rest:      R0 = rotationFromDegrees(rotation_deg), p0 = position
//   motion:    R(k) = Rot(angular_velocity_deg * k) * R0, p(k) = p0 + velocity * k, each
//              coordinate reflected into bounce_within when given; Rot(w) turns by |w| degrees
//              about w / |w| (a constant angular velocity about a fixed axis of the parent)
//   keyframes: before the first / after the last keyframe its pose; between two, p by linear
//              interpolation and R by spherical linear interpolation (shortest arc)
//   joint:     J(k) = rotation about the joint axis by clamp(angle_deg + rate_deg * k, min, max)
//   pose(k):   x_parent = R(k) * J(k) * x_local + p(k)
//
// Placement holds a node's rest pose and its motion; Placement::poseAt applies these. The
// simulation's object trees keep a Placement per node, not the scene file's objects.

#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "recode/geometry/mesh.hpp"

namespace recode::core {

// Per-frame motion; frame k's pose is a pure function of k (used by `recode run`, see
// motion.hpp for the formulas).
struct Motion {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();            // world units per frame
  Eigen::Vector3d angularVelocityDeg = Eigen::Vector3d::Zero();  // degrees per frame, X Y Z
  // "bounce_within": the node's origin reflects off the walls of this box (its parent's
  // coordinates) instead of leaving it. Absent: straight-line motion.
  std::optional<Aabb> bounceWithin;
};

// A pose at a given frame ("keyframes"); between two keyframes the position is interpolated
// linearly and the rotation by spherical linear interpolation.
struct Keyframe {
  int frame = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotationDeg = Eigen::Vector3d::Zero();
};

// A hinge: the node turns about `axis` (a unit vector in the node's own coordinates, through
// its origin) by angle(k) = clamp(angleDeg + rateDeg * k, minDeg, maxDeg) degrees.
struct Joint {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double angleDeg = 0.0;
  double rateDeg = 0.0;
  std::optional<double> minDeg;  // absent: no lower limit
  std::optional<double> maxDeg;  // absent: no upper limit
};

// Where a node is and how it moves: the rest pose relative to its parent and at most one of
// motion or keyframes, plus an optional joint.
struct Placement {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotationDeg = Eigen::Vector3d::Zero();  // applied X, then Y, then Z
  std::optional<Motion> motion;
  std::vector<Keyframe> keyframes;  // empty: none; never together with motion
  std::optional<Joint> joint;

  // The rest transform local -> parent (world for a root): x' = R p + position with
  // R = Rz * Ry * Rx. Motion, keyframes and joint are not applied (see poseAt).
  [[nodiscard]] Eigen::Isometry3d pose() const;
  // The transform local -> parent at frame k, with motion, keyframes and joint applied (a pure
  // function of k).
  [[nodiscard]] Eigen::Isometry3d poseAt(int frame) const;
  // True if poseAt(k) depends on k.
  [[nodiscard]] bool moves() const;
};

// Rotation matrix for rotation_deg: about X by rx, then Y by ry, then Z by rz (fixed axes),
// i.e. Rz * Ry * Rx. Angles that are whole multiples of 90 degrees give exact 0 / +-1
// entries, so axis-aligned scenes stay exactly axis-aligned.
[[nodiscard]] Eigen::Matrix3d rotationFromDegrees(const Eigen::Vector3d& degrees);

// Rotation by `degrees` about the unit vector `axis`. When the axis is a coordinate axis the
// entries for whole multiples of 90 degrees are exact (as rotationFromDegrees).
[[nodiscard]] Eigen::Matrix3d rotationAboutAxisDegrees(const Eigen::Vector3d& axis, double degrees);

// Rot(w): |w| degrees about w / |w|; the identity for w = 0.
[[nodiscard]] Eigen::Matrix3d rotationFromVectorDegrees(const Eigen::Vector3d& w);

// x reflected back and forth between lo and hi (lo <= hi), as a point moving at constant
// speed bounces between two walls: the identity on [lo, hi], periodic with period 2(hi - lo).
[[nodiscard]] double reflectInto(double x, double lo, double hi);

// The joint's angle at frame k, degrees.
[[nodiscard]] double jointAngleDegrees(const Joint& joint, int frame);

// The keyframed pose at frame k (keyframes sorted by strictly increasing frame, non-empty).
[[nodiscard]] Eigen::Isometry3d keyframePose(std::span<const Keyframe> keyframes, int frame);

}  // namespace recode::core
