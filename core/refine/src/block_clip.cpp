#include "recode/refine/block_clip.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "recode/geometry/hash_order.hpp"

namespace recode::core {

namespace {

std::uint64_t edgeKey(VertexIndex from, VertexIndex to) {
  return (std::uint64_t{from} << 32) | std::uint64_t{to};
}

// Builds the clipped mesh: kept vertices and cut points get new indices on first use.
class Clipper {
 public:
  Clipper(const TriangleMesh& block, int axis, double bound, bool keepBelow)
      : block_(block), axis_(axis), bound_(bound) {
    // Signed distance past the plane: positive is cut away.
    dist_.reserve(block.vertices.size());
    for (const Eigen::Vector3d& v : block.vertices)
      dist_.push_back(keepBelow ? v[axis] - bound : bound - v[axis]);
    kept_.assign(block.vertices.size(), ~VertexIndex{0});
  }

  [[nodiscard]] bool keeps(VertexIndex v) const { return dist_[v] <= 0.0; }

  VertexIndex keptVertex(VertexIndex v) {
    VertexIndex& k = kept_[v];
    if (k == ~VertexIndex{0}) {
      k = static_cast<VertexIndex>(out_.vertices.size());
      out_.vertices.push_back(block_.vertices[v]);
    }
    return k;
  }

  // The point where edge (p, q) crosses the plane, computed from the edge's lower index so
  // both triangles beside it get the same point, then put exactly on the plane.
  VertexIndex cutPoint(VertexIndex p, VertexIndex q) {
    const VertexIndex lo = std::min(p, q), hi = std::max(p, q);
    const std::uint64_t key = edgeKey(lo, hi);
    const auto found = cuts_.find(key);
    if (found != cuts_.end())
      return found->second;
    const double t = dist_[lo] / (dist_[lo] - dist_[hi]);
    Eigen::Vector3d x = block_.vertices[lo] + t * (block_.vertices[hi] - block_.vertices[lo]);
    x[axis_] = bound_;
    const auto index = static_cast<VertexIndex>(out_.vertices.size());
    out_.vertices.push_back(x);
    cuts_.emplace(key, index);
    return index;
  }

  void clipTriangle(const Triangle& tri) {
    std::vector<VertexIndex> poly;
    for (int k = 0; k < 3; ++k) {
      const VertexIndex p = tri[static_cast<std::size_t>(k)];
      const VertexIndex q = tri[static_cast<std::size_t>((k + 1) % 3)];
      if (keeps(p))
        poly.push_back(keptVertex(p));
      // A crossing strictly through the plane; an end on the plane is a kept vertex already.
      if ((dist_[p] < 0.0 && dist_[q] > 0.0) || (dist_[p] > 0.0 && dist_[q] < 0.0))
        poly.push_back(cutPoint(p, q));
    }
    for (std::size_t k = 1; k + 1 < poly.size(); ++k)
      out_.triangles.push_back({poly[0], poly[k], poly[k + 1]});
  }

  // Closes the hole on the plane: the directed edges without a twin bound it; the cap runs
  // them backwards.
  void cap() {
    std::unordered_set<std::uint64_t> edges;
    for (const Triangle& t : out_.triangles)
      for (int k = 0; k < 3; ++k)
        edges.insert(
            edgeKey(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]));
    std::unordered_map<VertexIndex, VertexIndex> next;  // cap edge b -> a for border edge a -> b
    // The order libstdc++'s map lists `next` in: each loop starts at its first key, as the
    // native build always has, whatever the standard library (hash_order.hpp); the cap's centre
    // is summed in loop order.
    LibstdcxxHashOrder order;
    for (const Triangle& t : out_.triangles)
      for (int k = 0; k < 3; ++k) {
        const VertexIndex a = t[static_cast<std::size_t>(k)];
        const VertexIndex b = t[static_cast<std::size_t>((k + 1) % 3)];
        if (a != b && !edges.contains(edgeKey(b, a))) {
          if (next.emplace(b, a).second)
            order.insert(b);
          else
            next[b] = a;
        }
      }
    while (!next.empty()) {
      std::vector<VertexIndex> loop;
      VertexIndex v = order.first();
      while (true) {
        const auto it = next.find(v);
        if (it == next.end())
          break;
        loop.push_back(v);
        v = it->second;
        next.erase(it);
        order.erase(loop.back());
      }
      if (loop.size() < 3)
        continue;
      // Fanned from the loop's centroid, not from a vertex: cut points often lie on a line
      // through a corner (a cut across a face's diagonal), and a fan from that corner would
      // make triangles of zero area.
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (const VertexIndex corner : loop)
        centre += out_.vertices[corner];
      centre /= static_cast<double>(loop.size());
      centre[axis_] = bound_;
      const auto c = static_cast<VertexIndex>(out_.vertices.size());
      out_.vertices.push_back(centre);
      for (std::size_t k = 0; k < loop.size(); ++k)
        out_.triangles.push_back({c, loop[k], loop[(k + 1) % loop.size()]});
    }
  }

  TriangleMesh take() { return std::move(out_); }

 private:
  const TriangleMesh& block_;
  int axis_;
  double bound_;
  std::vector<double> dist_;
  std::vector<VertexIndex> kept_;
  std::unordered_map<std::uint64_t, VertexIndex> cuts_;
  TriangleMesh out_;
};

}  // namespace

TriangleMesh clippedByPlane(const TriangleMesh& block, int axis, double bound, bool keepBelow) {
  Clipper clipper(block, axis, bound, keepBelow);
  bool anyKept = false, anyCut = false;
  for (VertexIndex v = 0; v < block.vertices.size(); ++v) {
    const bool k = clipper.keeps(v);
    anyKept = anyKept || k;
    anyCut = anyCut || !k;
  }
  if (!anyCut)
    return block;
  if (!anyKept)
    return {};
  for (const Triangle& t : block.triangles)
    clipper.clipTriangle(t);
  clipper.cap();
  TriangleMesh out = clipper.take();
  if (out.triangles.size() < 4)  // an edge on the plane: no solid left (a face on it: flat)
    return {};
  return out;
}

TriangleMesh clippedToBox(const TriangleMesh& block, const Aabb& box) {
  if (box.isEmpty())
    return {};
  TriangleMesh m = block;
  for (int axis = 0; axis < 3 && !m.triangles.empty(); ++axis) {
    m = clippedByPlane(m, axis, box.min[axis], false);
    if (!m.triangles.empty())
      m = clippedByPlane(m, axis, box.max[axis], true);
  }
  return m;
}

}  // namespace recode::core
