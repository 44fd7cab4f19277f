// The facet step of the convex hull: coplanar neighbouring triangles (decided exactly) are one
// face of the polytope, a convex polygon; its boundary is walked and a boundary point strictly
// between its two neighbours (exactly collinear with them) is not a corner. A point inside a
// face does not lie on its boundary at all. The points left are the extreme points, and each
// face is fan-triangulated over its corners, which gives no zero-area triangle.

#include <cstddef>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "convex_hull_detail.hpp"
#include "recode/geometry/exact_predicates.hpp"
#include "recode/geometry/hash_order.hpp"

namespace recode::core::detail {
namespace {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace

std::vector<Triangle> cornerTriangulation(std::span<const Eigen::Vector3d> points,
                                          const std::vector<Triangle>& triangles) {
  const auto p = [&](VertexIndex i) -> const Eigen::Vector3d& { return points[i]; };
  std::unordered_map<std::uint64_t, std::size_t> edgeTriangle;
  edgeTriangle.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::size_t i = 0; i < 3; ++i)
      edgeTriangle[edgeKey(triangles[t][i], triangles[t][(i + 1) % 3])] = t;
  }
  const auto across = [&](std::size_t t, std::size_t i) {
    return edgeTriangle.at(edgeKey(triangles[t][(i + 1) % 3], triangles[t][i]));
  };

  UnionFind faces(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& a = triangles[t];
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t s = across(t, i);
      // The neighbour's vertex off the shared edge.
      VertexIndex off = triangles[s][0];
      for (const VertexIndex v : triangles[s]) {
        if (v != a[i] && v != a[(i + 1) % 3])
          off = v;
      }
      if (orient3d(p(a[0]), p(a[1]), p(a[2]), p(off)) == 0)
        faces.unite(t, s);
    }
  }

  // A face of one triangle (the usual case on curved surfaces) is kept as it is: its three
  // vertices are not collinear, so all are corners.
  std::vector<std::size_t> faceSize(triangles.size(), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    ++faceSize[faces.find(t)];
  std::vector<Triangle> result;
  result.reserve(triangles.size());
  // Each larger face's boundary as "next vertex after u" (a convex polygon passes each vertex
  // once), and the order libstdc++'s map of it lists the vertices in: the loop starts at its
  // first (hash_order.hpp), as the native build always has, whatever the standard library.
  struct FaceBoundary {
    std::unordered_map<VertexIndex, VertexIndex> next;
    LibstdcxxHashOrder order;
  };
  std::unordered_map<std::size_t, FaceBoundary> boundary;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const std::size_t face = faces.find(t);
    if (faceSize[face] == 1) {
      result.push_back(triangles[t]);
      continue;
    }
    for (std::size_t i = 0; i < 3; ++i) {
      if (faces.find(across(t, i)) != face) {
        FaceBoundary& b = boundary[face];
        const VertexIndex from = triangles[t][i], to = triangles[t][(i + 1) % 3];
        if (b.next.emplace(from, to).second)
          b.order.insert(from);
        else
          b.next[from] = to;
      }
    }
  }

  std::vector<VertexIndex> loop;
  std::vector<VertexIndex> corners;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (faces.find(t) != t || faceSize[t] == 1)
      continue;
    const FaceBoundary& face = boundary.at(t);
    const auto& next = face.next;
    loop.clear();
    const VertexIndex first = face.order.first();
    VertexIndex v = first;
    do {
      loop.push_back(v);
      v = next.at(v);
      if (loop.size() > next.size())
        throw std::logic_error("convex hull: a face's boundary is not one loop");
    } while (v != first);
    corners.clear();
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const VertexIndex prev = loop[(k + loop.size() - 1) % loop.size()];
      const VertexIndex after = loop[(k + 1) % loop.size()];
      if (!collinear(p(prev), p(loop[k]), p(after)))
        corners.push_back(loop[k]);
    }
    if (corners.size() < 3)
      throw std::logic_error("convex hull: a face has fewer than 3 corners");
    for (std::size_t k = 1; k + 1 < corners.size(); ++k)
      result.push_back({corners[0], corners[k], corners[k + 1]});
  }
  return result;
}

}  // namespace recode::core::detail
