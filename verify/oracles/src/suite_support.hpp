#pragma once
// What the generated suites (the pair suite, the mode property suite) share: random numbers from
// one std::mt19937 drawn through our own mappings (the standard distributions' outputs are
// implementation-defined), so a suite is the same on every compiler and library; and poses.

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

namespace recode::verify {

class Random {
 public:
  explicit Random(std::uint32_t seed) : engine_(seed) {}
  // Uniform in [lo, hi), from 53 bits of the engine's output.
  double uniform(double lo, double hi) {
    const std::uint64_t bits = (std::uint64_t{engine_()} << 21) ^ (engine_() >> 11);
    const double unit = static_cast<double>(bits & ((std::uint64_t{1} << 53) - 1)) * 0x1p-53;
    return lo + (hi - lo) * unit;
  }
  int index(int n) { return static_cast<int>(engine_() % static_cast<std::uint32_t>(n)); }
  // A unit vector, uniform on the sphere.
  Eigen::Vector3d direction() {
    const double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * M_PI);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
  // A rotation, uniform over SO(3) (a normalised random quaternion by Shoemake's method).
  Eigen::Matrix3d rotation() {
    const double u1 = uniform(0.0, 1.0), u2 = uniform(0.0, 2.0 * M_PI),
                 u3 = uniform(0.0, 2.0 * M_PI);
    const double s1 = std::sqrt(1.0 - u1), s2 = std::sqrt(u1);
    const Eigen::Quaterniond q(s1 * std::sin(u2), s1 * std::cos(u2), s2 * std::sin(u3),
                               s2 * std::cos(u3));
    return q.normalized().toRotationMatrix();
  }
  // One of the 24 rotations that map axes onto axes: exact in floating point, so touching
  // configurations built from them touch exactly.
  Eigen::Matrix3d quarterTurns() {
    static constexpr std::array<std::array<int, 3>, 6> kPerms = {
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    const std::array<int, 3>& perm = kPerms[static_cast<std::size_t>(index(6))];
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    m(perm[0], 0) = index(2) == 0 ? 1.0 : -1.0;
    m(perm[1], 1) = index(2) == 0 ? 1.0 : -1.0;
    m.col(2) = m.col(0).cross(m.col(1));  // keeps det = +1
    return m;
  }

 private:
  std::mt19937 engine_;
};

// The rigid motion x -> rotation x + translation.
inline Eigen::Isometry3d pose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = rotation;
  t.translation() = translation;
  return t;
}

}  // namespace recode::verify
