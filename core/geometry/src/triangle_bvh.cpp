#include "recode/geometry/triangle_bvh.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace recode::core {

namespace {

constexpr std::uint32_t kLeafTriangles = 4;

struct Builder {
  const std::vector<Aabb>& boxes;
  const std::vector<Eigen::Vector3d>& centres;
  std::vector<std::uint32_t>& order;

  // Builds the node over order[first, first + count) at the end of `nodes`, depth first.
  template <class Node>
  void build(std::vector<Node>& nodes, std::uint32_t first, std::uint32_t count, int depth) {
    const std::size_t self = nodes.size();
    nodes.push_back({});
    Aabb box, around;
    for (std::uint32_t k = first; k < first + count; ++k) {
      box.extend(boxes[order[k]]);
      around.extend(centres[order[k]]);
    }
    nodes[self].box = box;
    // Depth is bounded (the traversal's stack is 64 deep): median splits halve the count, so
    // 40 levels hold far more triangles than an index can name.
    if (count <= kLeafTriangles || depth >= 40) {
      nodes[self].first = first;
      nodes[self].count = count;
      return;
    }
    int axis = 0;
    around.extent().maxCoeff(&axis);
    const std::uint32_t half = count / 2;
    std::nth_element(order.begin() + first, order.begin() + first + half,
                     order.begin() + first + count, [&](std::uint32_t a, std::uint32_t b) {
                       const double ca = centres[a][axis], cb = centres[b][axis];
                       return ca < cb || (ca == cb && a < b);
                     });
    build(nodes, first, half, depth + 1);
    nodes[self].first = static_cast<std::uint32_t>(nodes.size());
    build(nodes, first + half, count - half, depth + 1);
  }
};

}  // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  std::vector<Aabb> boxes(n);
  std::vector<Eigen::Vector3d> centres(n);
  for (std::size_t t = 0; t < n; ++t) {
    for (VertexIndex i : mesh.triangles[t]) {
      if (i >= mesh.vertices.size())
        throw std::out_of_range("TriangleBvh: triangle " + std::to_string(t) +
                                " has vertex index " + std::to_string(i) + " out of range (" +
                                std::to_string(mesh.vertices.size()) + " vertices)");
      boxes[t].extend(mesh.vertices[i]);
    }
    centres[t] = boxes[t].center();
  }
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), std::uint32_t{0});
  if (n == 0)
    return;
  nodes_.reserve(2 * (n / kLeafTriangles + 1));
  Builder{boxes, centres, order_}.build(nodes_, 0, static_cast<std::uint32_t>(n), 0);
}

void TriangleBvh::sortAppended(std::vector<std::uint32_t>& out, std::size_t from) const {
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(from), out.end());
}

}  // namespace recode::core
