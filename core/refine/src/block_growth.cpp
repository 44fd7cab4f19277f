#include "recode/refine/block_growth.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace recode::core {

namespace {

std::uint64_t edgeKey(VertexIndex from, VertexIndex to) {
  return (std::uint64_t{from} << 32) | std::uint64_t{to};
}

// Keeps only the vertices some triangle uses, in first-use order.
TriangleMesh compacted(const TriangleMesh& mesh) {
  TriangleMesh out;
  std::vector<VertexIndex> remap(mesh.vertices.size(), ~VertexIndex{0});
  out.triangles.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    Triangle n{};
    for (int k = 0; k < 3; ++k) {
      VertexIndex& r = remap[t[static_cast<std::size_t>(k)]];
      if (r == ~VertexIndex{0}) {
        r = static_cast<VertexIndex>(out.vertices.size());
        out.vertices.push_back(mesh.vertices[t[static_cast<std::size_t>(k)]]);
      }
      n[static_cast<std::size_t>(k)] = r;
    }
    out.triangles.push_back(n);
  }
  return out;
}

}  // namespace

TriangleMesh sweptAlongAxis(const TriangleMesh& block, int axis, double h) {
  if (!(h > 0.0))
    return block;
  const auto n = static_cast<VertexIndex>(block.vertices.size());
  TriangleMesh out;
  out.vertices.reserve(2 * block.vertices.size());
  // Vertex v - h e (index v) and v + h e (index n + v).
  for (const Eigen::Vector3d& v : block.vertices) {
    Eigen::Vector3d p = v;
    p[axis] -= h;
    out.vertices.push_back(p);
  }
  for (const Eigen::Vector3d& v : block.vertices) {
    Eigen::Vector3d p = v;
    p[axis] += h;
    out.vertices.push_back(p);
  }
  // A face moves up when its outward normal points up the axis; a face parallel to the axis
  // moves down, and the quads of its upper edges stretch it over the whole sweep.
  std::vector<char> up(block.triangles.size());
  std::unordered_map<std::uint64_t, std::size_t> owner;
  owner.reserve(3 * block.triangles.size());
  for (std::size_t t = 0; t < block.triangles.size(); ++t) {
    const Triangle& tri = block.triangles[t];
    const Eigen::Vector3d& a = block.vertices[tri[0]];
    const Eigen::Vector3d normal = (block.vertices[tri[1]] - a).cross(block.vertices[tri[2]] - a);
    up[t] = normal[axis] > 0.0 ? 1 : 0;
    for (int k = 0; k < 3; ++k)
      owner[edgeKey(tri[static_cast<std::size_t>(k)], tri[static_cast<std::size_t>((k + 1) % 3)])] =
          t;
  }
  out.triangles.reserve(block.triangles.size() + 16);
  for (std::size_t t = 0; t < block.triangles.size(); ++t) {
    const Triangle& tri = block.triangles[t];
    const VertexIndex shift = up[t] ? n : 0;
    out.triangles.push_back({tri[0] + shift, tri[1] + shift, tri[2] + shift});
    if (!up[t])
      continue;
    for (int k = 0; k < 3; ++k) {
      const VertexIndex i = tri[static_cast<std::size_t>(k)];
      const VertexIndex j = tri[static_cast<std::size_t>((k + 1) % 3)];
      const auto twin = owner.find(edgeKey(j, i));
      if (twin == owner.end() || up[twin->second])
        continue;
      // Edge i -> j of an upper face beside a lower face: the quad j+, i+, i-, j- lies outside
      // the upper face across that edge, wound like it (outward).
      out.triangles.push_back({j + n, i + n, i});
      out.triangles.push_back({j + n, i, j});
    }
  }
  return compacted(out);
}

TriangleMesh grownByBox(const TriangleMesh& block, const Eigen::Vector3d& half) {
  TriangleMesh m = sweptAlongAxis(block, 0, half.x());
  m = sweptAlongAxis(m, 1, half.y());
  return sweptAlongAxis(m, 2, half.z());
}

}  // namespace recode::core
