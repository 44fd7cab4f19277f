#include "recode/geometry/triangle_bvh.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace recode::core {

namespace {

constexpr std::uint32_t kLeafTriangles = 4;

// A triangle as the builder sorts it: its box centre next to its index, so that the median
// splits move and compare contiguous records rather than chase indices.
struct Item {
  Eigen::Vector3d centre;
  std::uint32_t triangle = 0;
};

struct Builder {
  const std::vector<Aabb>& boxes;  // per triangle
  std::vector<Item>& items;

  // Builds the node over items[first, first + count) at the end of `nodes`, depth first. A
  // leaf's box is its triangles' boxes, an inner node's its two children's: the same union.
  template <class Node>
  void build(std::vector<Node>& nodes, std::uint32_t first, std::uint32_t count, int depth) {
    const std::size_t self = nodes.size();
    nodes.push_back({});
    // Depth is bounded (the traversal's stack is 64 deep): median splits halve the count, so
    // 40 levels hold far more triangles than an index can name.
    if (count <= kLeafTriangles || depth >= 40) {
      Aabb box;
      for (std::uint32_t k = first; k < first + count; ++k)
        box.extend(boxes[items[k].triangle]);
      nodes[self].box = box;
      nodes[self].first = first;
      nodes[self].count = count;
      return;
    }
    Aabb around;
    for (std::uint32_t k = first; k < first + count; ++k)
      around.extend(items[k].centre);
    int axis = 0;
    around.extent().maxCoeff(&axis);
    const std::uint32_t half = count / 2;
    std::nth_element(items.begin() + first, items.begin() + first + half,
                     items.begin() + first + count, [axis](const Item& a, const Item& b) {
                       const double ca = a.centre[axis], cb = b.centre[axis];
                       return ca < cb || (ca == cb && a.triangle < b.triangle);
                     });
    build(nodes, first, half, depth + 1);
    const auto second = static_cast<std::uint32_t>(nodes.size());
    build(nodes, first + half, count - half, depth + 1);
    Aabb box = nodes[self + 1].box;
    box.extend(nodes[second].box);
    nodes[self].box = box;
    nodes[self].first = second;
  }
};

}  // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  std::vector<Aabb> boxes(n);
  std::vector<Item> items(n);
  for (std::size_t t = 0; t < n; ++t) {
    for (VertexIndex i : mesh.triangles[t]) {
      if (i >= mesh.vertices.size())
        throw std::out_of_range("TriangleBvh: triangle " + std::to_string(t) +
                                " has vertex index " + std::to_string(i) + " out of range (" +
                                std::to_string(mesh.vertices.size()) + " vertices)");
      boxes[t].extend(mesh.vertices[i]);
    }
    items[t] = {boxes[t].center(), static_cast<std::uint32_t>(t)};
  }
  order_.resize(n);
  if (n == 0)
    return;
  nodes_.reserve(2 * (n / kLeafTriangles + 1));
  Builder{boxes, items}.build(nodes_, 0, static_cast<std::uint32_t>(n), 0);
  for (std::size_t k = 0; k < n; ++k)
    order_[k] = items[k].triangle;
}

void TriangleBvh::sortAppended(std::vector<std::uint32_t>& out, std::size_t from) const {
  std::vector<std::uint64_t> bits;
  sortDistinctIds(std::span(out).subspan(from), order_.size(), bits);
}

void sortDistinctIds(std::span<std::uint32_t> ids, std::size_t idCount,
                     std::vector<std::uint64_t>& bits) {
  const std::size_t words = (idCount + 63) / 64;
  // A word costs about what one id costs the sort: log2 of the count in comparisons, which is
  // over 16 only past 65,536 ids.
  if (ids.size() * 16 < words) {
    std::sort(ids.begin(), ids.end());
    return;
  }
  bits.assign(words, 0);
  for (const std::uint32_t id : ids)
    bits[id / 64] |= std::uint64_t{1} << (id % 64);
  std::size_t k = 0;
  for (std::size_t w = 0; w < words; ++w)
    for (std::uint64_t b = bits[w]; b != 0; b &= b - 1)
      ids[k++] = static_cast<std::uint32_t>(64 * w + static_cast<std::size_t>(std::countr_zero(b)));
}

}  // namespace recode::core
