// Node motion over frames: each formula of motion.hpp checked against values worked out by
// hand (straight lines, bouncing, constant angular velocity, keyframe interpolation, limited
// joints), and poses are a pure function of the frame (any order gives the same pose).

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "recode/scene/motion.hpp"

using namespace recode::core;

namespace {

bool near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tolerance = 1e-12) {
  return (a - b).cwiseAbs().maxCoeff() <= tolerance;
}

Eigen::Vector3d apply(const Eigen::Isometry3d& t, const Eigen::Vector3d& p) {
  return t.linear() * p + t.translation();
}

}  // namespace

TEST_CASE("motion: velocity and bouncing between walls", "[motion]") {
  Placement node;
  node.position = {1.0, 2.0, 3.0};
  Motion m;
  m.velocity = {0.5, -0.25, 0.0};
  node.motion = m;
  CHECK(node.poseAt(0).translation() == Eigen::Vector3d(1.0, 2.0, 3.0));
  CHECK(node.poseAt(4).translation() == Eigen::Vector3d(3.0, 1.0, 3.0));
  CHECK(node.poseAt(-2).translation() == Eigen::Vector3d(0.0, 2.5, 3.0));

  // Between x = 0 and x = 2, starting at 1 and moving +0.5 per frame: 1, 1.5, 2, 1.5, 1,
  // 0.5, 0, 0.5, 1 ... (period 8 frames).
  m.bounceWithin = Aabb{Eigen::Vector3d(0, -10, -10), Eigen::Vector3d(2, 10, 10)};
  node.motion = m;
  const double expected[] = {1.0, 1.5, 2.0, 1.5, 1.0, 0.5, 0.0, 0.5, 1.0, 1.5};
  for (int k = 0; k < 10; ++k)
    CHECK(node.poseAt(k).translation().x() == Approx(expected[k]).margin(1e-12));
  CHECK(node.poseAt(800 + 3).translation().x() == Approx(1.5).margin(1e-9));
  CHECK(reflectInto(-0.5, 0.0, 2.0) == Approx(0.5));
  CHECK(reflectInto(5.0, 1.0, 1.0) == 1.0);  // a flat box pins the coordinate
  CHECK(node.moves());
}

TEST_CASE("motion: angular velocity turns about a fixed axis at a constant rate", "[motion]") {
  Placement node;
  node.rotationDeg = {90.0, 0.0, 0.0};  // rest: +y -> +z
  Motion m;
  m.angularVelocityDeg = {0.0, 0.0, 30.0};
  node.motion = m;
  // Frame 3: the rest rotation, then 90 degrees about z: +y -> +z -> +z; +x -> +y.
  const Eigen::Isometry3d p3 = node.poseAt(3);
  CHECK(p3.linear() * Eigen::Vector3d::UnitX() == Eigen::Vector3d::UnitY());  // exact
  CHECK(p3.linear() * Eigen::Vector3d::UnitY() == Eigen::Vector3d::UnitZ());
  // A tilted axis: w = (1, 1, 0) * 10 deg per frame is |w| = 14.14 deg per frame about
  // (1, 1, 0) / sqrt 2; the axis itself stays put and a perpendicular vector turns by
  // 14.14 * k degrees.
  m.angularVelocityDeg = {10.0, 10.0, 0.0};
  node.motion = m;
  node.rotationDeg = Eigen::Vector3d::Zero();
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 1, 0).normalized();
  for (int k : {1, 5, 17}) {
    const Eigen::Matrix3d r = node.poseAt(k).linear();
    CHECK(near(r * axis, axis));
    const double angle = std::acos(std::clamp((r * Eigen::Vector3d::UnitZ()).z(), -1.0, 1.0));
    const double turned = std::fmod(std::sqrt(200.0) * k, 360.0);
    CHECK(angle * 180.0 / std::numbers::pi ==
          Approx(turned > 180.0 ? 360.0 - turned : turned).margin(1e-9));
  }
}

TEST_CASE("motion: keyframes interpolate position linearly and rotation by slerp", "[motion]") {
  Placement node;
  node.keyframes = {
      {10, {0, 0, 0}, {0, 0, 0}}, {20, {10, 0, -5}, {0, 0, 90}}, {30, {10, 10, -5}, {0, 0, 90}}};
  CHECK(node.poseAt(0).translation() == Eigen::Vector3d(0, 0, 0));  // before: the first
  CHECK(node.poseAt(10).translation() == Eigen::Vector3d(0, 0, 0));
  CHECK(near(node.poseAt(14).translation(), {4, 0, -2}));
  // Halfway between 0 and 90 degrees about z: 45 degrees (slerp turns at a constant rate).
  const Eigen::Matrix3d half = node.poseAt(15).linear();
  CHECK(near(half * Eigen::Vector3d::UnitX(), Eigen::Vector3d(1, 1, 0).normalized()));
  const Eigen::Matrix3d fifth = node.poseAt(12).linear();
  const double a = 18.0 * std::numbers::pi / 180.0;
  CHECK(near(fifth * Eigen::Vector3d::UnitX(), {std::cos(a), std::sin(a), 0}));
  // At a keyframe the pose is exact (quarter turns stay exact), and after the last it stays.
  CHECK(node.poseAt(20).linear() * Eigen::Vector3d::UnitX() == Eigen::Vector3d::UnitY());
  CHECK(near(node.poseAt(25).translation(), {10, 5, -5}));
  CHECK(node.poseAt(1000).translation() == Eigen::Vector3d(10, 10, -5));
  CHECK(node.moves());
  Placement still;
  still.keyframes = {{0, {1, 1, 1}, {0, 0, 0}}, {5, {1, 1, 1}, {0, 0, 0}}};
  CHECK_FALSE(still.moves());
}

TEST_CASE("motion: a joint turns about its axis, within its limits", "[motion]") {
  Placement finger;
  finger.position = {1.0, 0.0, 0.0};
  Joint j;
  j.axis = Eigen::Vector3d::UnitY();
  j.angleDeg = 10.0;
  j.rateDeg = 20.0;
  j.minDeg = 0.0;
  j.maxDeg = 90.0;
  finger.joint = j;
  CHECK(jointAngleDegrees(j, 0) == 10.0);
  CHECK(jointAngleDegrees(j, 2) == 50.0);
  CHECK(jointAngleDegrees(j, 4) == 90.0);  // 90, limited
  CHECK(jointAngleDegrees(j, 100) == 90.0);
  CHECK(jointAngleDegrees(j, -3) == 0.0);
  // About +y by 90 degrees the local +z goes to +x; the hinge is at the node's origin.
  const Eigen::Isometry3d p = finger.poseAt(4);
  CHECK(apply(p, Eigen::Vector3d(0, 0, 1)) == Eigen::Vector3d(2, 0, 0));
  CHECK(apply(p, Eigen::Vector3d(0, 0, 0)) == Eigen::Vector3d(1, 0, 0));
  // After the rest rotation: pose = R(rest) * J; the joint axis is in the node's own frame.
  finger.rotationDeg = {0.0, 0.0, 90.0};  // local y -> world -x
  const Eigen::Vector3d tip = apply(finger.poseAt(4), Eigen::Vector3d(0, 0, 1));
  CHECK(near(tip, Eigen::Vector3d(1, 1, 0)));  // local z -> local x -> world +y
  CHECK(finger.moves());
  j.minDeg = j.maxDeg = 10.0;
  finger.joint = j;
  CHECK_FALSE(finger.moves());
}

TEST_CASE("motion: poses are a pure function of the frame", "[motion]") {
  Placement node;
  node.position = {0.3, -0.2, 0.1};
  node.rotationDeg = {12, 34, 56};
  Motion m;
  m.velocity = {0.1, 0.2, -0.3};
  m.angularVelocityDeg = {3, -7, 11};
  m.bounceWithin = Aabb{Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1)};
  node.motion = m;
  Joint j;
  j.axis = Eigen::Vector3d(1, 2, 3).normalized();
  j.rateDeg = 4.5;
  j.maxDeg = 100;
  node.joint = j;
  const Eigen::Isometry3d first = node.poseAt(37);
  for (int k = 0; k < 60; k += 7)
    (void)node.poseAt(k);
  CHECK(node.poseAt(37).matrix() == first.matrix());
  const Placement copy = node;
  CHECK(copy.poseAt(37).matrix() == first.matrix());
}
