#pragma once
// A pose in Bullet's float build, for the Bullet peers (bullet_detector.cpp,
// bullet_gimpact_peer.cpp). Internal to verify/peers.
#include <btBulletCollisionCommon.h>

#include <Eigen/Geometry>

namespace recode::verify {

inline btTransform toBullet(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d r = pose.linear();
  const Eigen::Vector3d t = pose.translation();
  const auto f = [](double x) { return static_cast<btScalar>(x); };
  return btTransform(btMatrix3x3(f(r(0, 0)), f(r(0, 1)), f(r(0, 2)), f(r(1, 0)), f(r(1, 1)),
                                 f(r(1, 2)), f(r(2, 0)), f(r(2, 1)), f(r(2, 2))),
                     btVector3(f(t.x()), f(t.y()), f(t.z())));
}

}  // namespace recode::verify
