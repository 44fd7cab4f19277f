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
// SceneObject::poseAt and SceneObject::moves (scene.hpp) are defined with these.

#include <span>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "recode/core/scene.hpp"

namespace recode::core {

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
