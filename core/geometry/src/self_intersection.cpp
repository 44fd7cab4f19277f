// The self-intersection search: each triangle against the later triangles whose boxes meet its
// own, found through the triangle hierarchy, each pair decided exactly
// (triangle_intersection.hpp).

#include "recode/geometry/self_intersection.hpp"

#include <stdexcept>
#include <string>

#include "format.hpp"
#include "recode/geometry/exact_predicates.hpp"
#include "recode/geometry/triangle_bvh.hpp"
#include "triangle_intersection.hpp"

namespace recode::core {
namespace {

bool boxesMeet(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

// The preconditions of the exact tests (self_intersection.hpp), each broken one named.
void requireExactInput(const TriangleMesh& mesh) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3d& p = mesh.vertices[i];
    if (!p.allFinite() || p.cwiseAbs().maxCoeff() > kMaxExactCoordinate) {
      throw std::invalid_argument("selfIntersections: vertex " + std::to_string(i) + " " +
                                  detail::formatPoint(p) + " is not finite or lies beyond +-1e100");
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (const VertexIndex v : tri) {
      if (v >= mesh.vertices.size()) {
        throw std::invalid_argument("selfIntersections: triangle " + std::to_string(t) +
                                    " has vertex index " + std::to_string(v) + " out of range");
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] ||
        collinear(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]])) {
      throw std::invalid_argument("selfIntersections: triangle " + std::to_string(t) +
                                  " is degenerate (its points lie on one line)");
    }
  }
}

}  // namespace

std::vector<TrianglePair> selfIntersections(const TriangleMesh& mesh, std::size_t maxPairs) {
  requireExactInput(mesh);
  std::vector<TrianglePair> pairs;
  if (maxPairs == 0) {
    return pairs;
  }
  const std::size_t n = mesh.triangles.size();
  std::vector<Aabb> boxes(n);
  for (std::size_t t = 0; t < n; ++t) {
    for (const VertexIndex v : mesh.triangles[t]) {
      boxes[t].extend(mesh.vertices[v]);
    }
  }
  const TriangleBvh bvh(mesh);
  std::vector<std::uint32_t> candidates;
  std::vector<std::uint64_t> sortBits;
  for (std::size_t t = 0; t < n; ++t) {
    const Aabb& box = boxes[t];
    candidates.clear();
    bvh.visit([&box](const Aabb& node) { return boxesMeet(node, box); },
              [&](std::uint32_t u) {
                if (u > t && boxesMeet(boxes[u], box)) {
                  candidates.push_back(u);
                }
              });
    // In increasing order, so that the pairs come out in order and the first maxPairs of
    // them are the same whatever the hierarchy's shape.
    sortDistinctIds(candidates, n, sortBits);
    for (const std::uint32_t u : candidates) {
      if (detail::trianglesMeet(mesh, mesh.triangles[t], mesh.triangles[u])) {
        pairs.push_back({static_cast<std::uint32_t>(t), u});
        if (pairs.size() >= maxPairs) {
          return pairs;
        }
      }
    }
  }
  return pairs;
}

}  // namespace recode::core
