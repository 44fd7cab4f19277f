#pragma once
// Closed meshes that are not convex, for the layered pair's suites: a torus, a hollow shell
// (a sphere with a spherical cavity), and the operations that build them.

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh.hpp"

namespace recode::test {

// A torus about the z axis through the origin: tube centre radius R, tube radius r, `segments`
// around the z axis and `rings` around the tube; outward, counter-clockwise seen from outside.
inline core::TriangleMesh makeTorus(double R, double r, int segments, int rings) {
  core::TriangleMesh m;
  for (int i = 0; i < segments; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / segments;
    for (int j = 0; j < rings; ++j) {
      const double theta = 2.0 * std::numbers::pi * j / rings;
      const double w = R + r * std::cos(theta);
      m.vertices.emplace_back(w * std::cos(phi), w * std::sin(phi), r * std::sin(theta));
    }
  }
  const auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>(((i % segments) * rings) + (j % rings));
  };
  for (int i = 0; i < segments; ++i)
    for (int j = 0; j < rings; ++j) {
      // Around the z axis (i) then around the tube (j): the cross product of the two directions
      // points out of the tube.
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// The same surface facing the other way (every triangle's winding reversed).
inline core::TriangleMesh reversed(core::TriangleMesh m) {
  for (core::Triangle& t : m.triangles)
    std::swap(t[1], t[2]);
  return m;
}

// Both meshes as one (b's indices shifted past a's vertices).
inline core::TriangleMesh merged(core::TriangleMesh a, const core::TriangleMesh& b) {
  const auto offset = static_cast<std::uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (core::Triangle t : b.triangles) {
    for (auto& i : t)
      i += offset;
    a.triangles.push_back(t);
  }
  return a;
}

// A ball of radius `outer` with a spherical cavity of radius `inner`, both about the origin.
inline core::TriangleMesh makeHollowBall(double outer, double inner, int segments, int rings) {
  return merged(core::makeSphere(outer, segments, rings),
                reversed(core::makeSphere(inner, segments, rings)));
}

inline core::TriangleMesh shifted(const core::TriangleMesh& m, const Eigen::Vector3d& offset) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = offset;
  return core::transformed(m, t);
}

}  // namespace recode::test
