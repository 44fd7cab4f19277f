#pragma once
// Closed meshes that are not convex, for the layered pair's suites (besides core::makeTorus): a
// hollow shell (a sphere with a spherical cavity) and the operations that build it.

#include <Eigen/Geometry>

#include "recode/geometry/generators.hpp"
#include "recode/geometry/mesh.hpp"
#include "recode/pair/frame.hpp"

namespace recode::test {

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

// A square frame of `width` pixels around both meshes along `axis` (the default window).
inline core::FrameSpec frameAround(core::ViewAxis axis, const core::TriangleMesh& a,
                                   const core::TriangleMesh& b, int width) {
  core::Aabb bounds = core::boundingBox(a);
  bounds.extend(core::boundingBox(b));
  core::FrameSpec f;
  f.axis = axis;
  f.width = f.height = width;
  f.window = core::defaultWindow(axis, bounds, std::array<int, 2>{width, width});
  return f;
}

}  // namespace recode::test
