#pragma once
// A bounding-volume hierarchy over a mesh's triangles, in the mesh's own coordinates: built
// once, then immutable (safe to share between threads). It answers "which triangles can meet
// this region", with the region given as a test on axis-aligned boxes, so the caller decides
// how a box maps into its space (a pose, a view).

#include <cstdint>
#include <span>
#include <vector>

#include "recode/geometry/mesh.hpp"

namespace recode::core {

class TriangleBvh {
 public:
  // Throws std::out_of_range if a triangle index is not below mesh.vertexCount().
  explicit TriangleBvh(const TriangleMesh& mesh);

  [[nodiscard]] std::size_t triangleCount() const { return order_.size(); }
  [[nodiscard]] std::size_t nodeCount() const { return nodes_.size(); }

  // Appends to `out`, in increasing order, every triangle whose box (that of its three
  // vertices) is inside a node box for which meets(box) held, down to the leaf. `meets` must be
  // conservative: true for any box containing a point of interest (it may say true more often).
  template <class BoxTest>
  void collect(const BoxTest& meets, std::vector<std::uint32_t>& out) const;

  // Calls take(t) for the same triangles as collect, leaf by leaf, in no useful order: for a
  // caller that filters the triangles further and sorts only what is left.
  template <class BoxTest, class Take>
  void visit(const BoxTest& meets, const Take& take) const;

 private:
  struct Node {
    Aabb box;
    std::uint32_t first = 0;  // leaf: range in order_; inner: index of the second child
    std::uint32_t count = 0;  // triangles of a leaf, 0 for an inner node (first child follows)
  };
  void sortAppended(std::vector<std::uint32_t>& out, std::size_t from) const;

  std::vector<Node> nodes_;           // depth first: an inner node's first child is next
  std::vector<std::uint32_t> order_;  // triangle ids, grouped by leaf
};

// Sorts distinct ids below idCount into increasing order, in place: with a bit per id when
// they are dense enough that one pass over the bits beats a comparison sort (a query's
// triangles usually are), else with std::sort. `bits` is scratch, kept by the caller so that
// repeated sorts allocate nothing.
void sortDistinctIds(std::span<std::uint32_t> ids, std::size_t idCount,
                     std::vector<std::uint64_t>& bits);

template <class BoxTest, class Take>
void TriangleBvh::visit(const BoxTest& meets, const Take& take) const {
  if (nodes_.empty())
    return;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (!meets(n.box))
      continue;
    if (n.count > 0) {
      for (std::uint32_t k = n.first; k < n.first + n.count; ++k)
        take(order_[k]);
      continue;
    }
    const auto self = static_cast<std::uint32_t>(&n - nodes_.data());
    stack[top++] = n.first;
    stack[top++] = self + 1;
  }
}

template <class BoxTest>
void TriangleBvh::collect(const BoxTest& meets, std::vector<std::uint32_t>& out) const {
  const std::size_t from = out.size();
  visit(meets, [&out](std::uint32_t t) { out.push_back(t); });
  sortAppended(out, from);
}

}  // namespace recode::core
