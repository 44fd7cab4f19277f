// Poses of scene nodes at frame k: motion (velocity, angular velocity, bouncing), keyframes
// (linear position, slerp rotation) and joints (limited hinge angles).
#include "recode/scene/motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace recode::core {

namespace {

// The index (0, 1, 2) of the only non-zero component of v, or -1.
int singleAxis(const Eigen::Vector3d& v) {
  int found = -1;
  for (int i = 0; i < 3; ++i) {
    if (v[i] == 0.0)
      continue;
    if (found >= 0)
      return -1;
    found = i;
  }
  return found;
}

// sin and cos of an angle in degrees; exact (0, +-1) for whole multiples of 90 degrees.
std::pair<double, double> sinCosDegrees(double degrees) {
  const double reduced = std::fmod(degrees, 360.0);  // exact; in (-360, 360), sign of degrees
  if (std::fmod(reduced, 90.0) == 0.0) {
    const int quarter = (static_cast<int>(reduced / 90.0) % 4 + 4) % 4;
    static constexpr std::pair<double, double> kQuarterTurns[4] = {
        {0.0, 1.0}, {1.0, 0.0}, {0.0, -1.0}, {-1.0, 0.0}};
    return kQuarterTurns[quarter];
  }
  const double radians = reduced * (std::numbers::pi / 180.0);
  return {std::sin(radians), std::cos(radians)};
}

}  // namespace

Eigen::Matrix3d rotationFromDegrees(const Eigen::Vector3d& degrees) {
  const auto [sx, cx] = sinCosDegrees(degrees.x());
  const auto [sy, cy] = sinCosDegrees(degrees.y());
  const auto [sz, cz] = sinCosDegrees(degrees.z());
  Eigen::Matrix3d rx;
  rx << 1, 0, 0, 0, cx, -sx, 0, sx, cx;
  Eigen::Matrix3d ry;
  ry << cy, 0, sy, 0, 1, 0, -sy, 0, cy;
  Eigen::Matrix3d rz;
  rz << cz, -sz, 0, sz, cz, 0, 0, 0, 1;
  return rz * ry * rx;
}

Eigen::Isometry3d Placement::pose() const {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.linear() = rotationFromDegrees(rotationDeg);
  transform.translation() = position;
  return transform;
}

Eigen::Matrix3d rotationAboutAxisDegrees(const Eigen::Vector3d& axis, double degrees) {
  const int i = singleAxis(axis);
  if (i >= 0) {
    // A coordinate axis (either direction): rotationFromDegrees has the exact quarter turns.
    Eigen::Vector3d angles = Eigen::Vector3d::Zero();
    angles[i] = axis[i] > 0.0 ? degrees : -degrees;
    return rotationFromDegrees(angles);
  }
  const double radians = std::fmod(degrees, 360.0) * (std::numbers::pi / 180.0);
  return Eigen::AngleAxisd(radians, axis.normalized()).toRotationMatrix();
}

Eigen::Matrix3d rotationFromVectorDegrees(const Eigen::Vector3d& w) {
  const double degrees = w.norm();
  if (degrees == 0.0)
    return Eigen::Matrix3d::Identity();
  return rotationAboutAxisDegrees(w / degrees, degrees);
}

double reflectInto(double x, double lo, double hi) {
  const double length = hi - lo;
  if (!(length > 0.0))
    return lo;
  double u = std::fmod(x - lo, 2.0 * length);
  if (u < 0.0)
    u += 2.0 * length;
  if (u > length)
    u = 2.0 * length - u;
  return lo + u;
}

double jointAngleDegrees(const Joint& joint, int frame) {
  double angle = joint.angleDeg + joint.rateDeg * static_cast<double>(frame);
  if (joint.minDeg)
    angle = std::max(angle, *joint.minDeg);
  if (joint.maxDeg)
    angle = std::min(angle, *joint.maxDeg);
  return angle;
}

Eigen::Isometry3d keyframePose(std::span<const Keyframe> keyframes, int frame) {
  if (keyframes.empty())
    throw std::invalid_argument("keyframePose: no keyframes");
  const auto exact = [](const Keyframe& key) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = rotationFromDegrees(key.rotationDeg);
    t.translation() = key.position;
    return t;
  };
  if (frame <= keyframes.front().frame)
    return exact(keyframes.front());
  if (frame >= keyframes.back().frame)
    return exact(keyframes.back());
  // The first keyframe after `frame`; the one before it is at or before `frame`.
  const auto next = std::upper_bound(keyframes.begin(), keyframes.end(), frame,
                                     [](int f, const Keyframe& key) { return f < key.frame; });
  const Keyframe& k1 = *next;
  const Keyframe& k0 = *(next - 1);
  if (k0.frame == frame)
    return exact(k0);
  const double t = static_cast<double>(frame - k0.frame) / static_cast<double>(k1.frame - k0.frame);
  const Eigen::Quaterniond q0(rotationFromDegrees(k0.rotationDeg));
  const Eigen::Quaterniond q1(rotationFromDegrees(k1.rotationDeg));
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = q0.slerp(t, q1).normalized().toRotationMatrix();
  pose.translation() = (1.0 - t) * k0.position + t * k1.position;
  return pose;
}

Eigen::Isometry3d Placement::poseAt(int frame) const {
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
  if (!keyframes.empty()) {
    base = keyframePose(keyframes, frame);
  } else if (motion) {
    const double k = static_cast<double>(frame);
    base.linear() = rotationFromVectorDegrees(motion->angularVelocityDeg * k) *
                    rotationFromDegrees(rotationDeg);
    Eigen::Vector3d p = position + motion->velocity * k;
    if (motion->bounceWithin) {
      for (int i = 0; i < 3; ++i)
        p[i] = reflectInto(p[i], motion->bounceWithin->min[i], motion->bounceWithin->max[i]);
    }
    base.translation() = p;
  } else {
    base = pose();
  }
  if (joint)
    base.linear() =
        base.linear() * rotationAboutAxisDegrees(joint->axis, jointAngleDegrees(*joint, frame));
  return base;
}

bool Placement::moves() const {
  if (motion && (!motion->velocity.isZero(0.0) || !motion->angularVelocityDeg.isZero(0.0)))
    return true;
  for (std::size_t i = 1; i < keyframes.size(); ++i) {
    if (keyframes[i].position != keyframes[0].position ||
        keyframes[i].rotationDeg != keyframes[0].rotationDeg)
      return true;
  }
  if (joint && joint->rateDeg != 0.0 &&
      !(joint->minDeg && joint->maxDeg && *joint->minDeg == *joint->maxDeg))
    return true;
  return false;
}

}  // namespace recode::core
