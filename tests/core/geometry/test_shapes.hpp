#pragma once
// Closed test shapes beyond the generators (a torus) and the operations the closed-mesh tests
// build their cases with: placing a copy, turning it inside out, putting meshes side by side.

#include <cmath>
#include <numbers>
#include <utility>

#include <Eigen/Core>

#include "recode/geometry/mesh.hpp"

namespace recode::core::test {

// A torus about the z axis (radii 2 and 0.5) made of an n x m grid of quads, each split into
// two triangles: closed, consistently oriented, connected, Euler characteristic 0; its faces
// point outward (positive volume).
inline TriangleMesh makeTorus(int n, int m) {
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i) {
    const double u = 2.0 * std::numbers::pi * i / n;
    for (int j = 0; j < m; ++j) {
      const double v = 2.0 * std::numbers::pi * j / m;
      const double rho = 2.0 + 0.5 * std::cos(v);
      mesh.vertices.emplace_back(rho * std::cos(u), rho * std::sin(u), 0.5 * std::sin(v));
    }
  }
  auto id = [&](int i, int j) { return static_cast<VertexIndex>((i % n) * m + (j % m)); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return mesh;
}

// The mesh moved by `offset` and scaled by `scale` about the origin (scale first).
inline TriangleMesh placed(TriangleMesh mesh, const Eigen::Vector3d& offset, double scale = 1.0) {
  for (Eigen::Vector3d& p : mesh.vertices) {
    p = scale * p + offset;
  }
  return mesh;
}

// The mesh with every triangle's winding reversed (inside out).
inline TriangleMesh reversed(TriangleMesh mesh) {
  for (Triangle& t : mesh.triangles) {
    std::swap(t[1], t[2]);
  }
  return mesh;
}

// `b` appended to `a`, its vertices after a's (no vertex shared).
inline TriangleMesh joined(TriangleMesh a, const TriangleMesh& b) {
  const auto offset = static_cast<VertexIndex>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const Triangle& t : b.triangles) {
    a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  return a;
}

}  // namespace recode::core::test
