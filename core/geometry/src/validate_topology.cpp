// Stage 4 of checkConvexBlock: the triangles form one closed, manifold, consistently
// oriented surface of genus 0. The later, geometric stages (volume, convexity, winding)
// are only meaningful on such a surface.

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "validate_stages.hpp"

namespace recode::core::detail {
namespace {

// Union-find for connected components.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) {
      parent_[std::max(a, b)] = std::min(a, b);
    }
  }

 private:
  std::vector<std::size_t> parent_;
};

struct HalfEdge {
  std::uint64_t key;       // (min index << 32) | max index
  std::uint32_t triangle;  // the triangle using it
  bool forward;            // true if the triangle runs from the smaller to the larger index
};

std::string edgeName(std::uint64_t key) {
  return "edge (" + std::to_string(key >> 32) + ", " + std::to_string(key & 0xffffffffU) + ")";
}

// Every triangle's three edges, sorted by edge and then by triangle, so that the uses of
// one edge are adjacent and listed in triangle order in the messages.
std::vector<HalfEdge> sortedHalfEdges(const std::vector<Triangle>& triangles) {
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (int k = 0; k < 3; ++k) {
      const VertexIndex a = tri[static_cast<std::size_t>(k)];
      const VertexIndex b = tri[static_cast<std::size_t>((k + 1) % 3)];
      if (a == b) {
        continue;  // repeated index: reported in stage 3
      }
      const std::uint64_t lo = std::min(a, b);
      const std::uint64_t hi = std::max(a, b);
      halfEdges.push_back({(lo << 32) | hi, static_cast<std::uint32_t>(t), a < b});
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end(), [](const HalfEdge& l, const HalfEdge& r) {
    return l.key < r.key || (l.key == r.key && l.triangle < r.triangle);
  });
  return halfEdges;
}

// Records the problem, if any, with one edge's uses halfEdges[first, end): a closed
// surface uses each edge twice, once in each direction. Returns true if the limit is reached.
bool recordEdgeProblem(const std::vector<HalfEdge>& halfEdges, std::size_t first, std::size_t end,
                       Recorder& recorder) {
  const std::size_t uses = end - first;
  std::size_t forward = 0;
  for (std::size_t k = first; k < end; ++k) {
    forward += halfEdges[k].forward ? 1 : 0;
  }
  const std::uint64_t key = halfEdges[first].key;
  if (uses == 1) {
    return recorder.add(MeshProblemKind::OpenEdge, edgeName(key) +
                                                       " is used by only one triangle (triangle " +
                                                       std::to_string(halfEdges[first].triangle) +
                                                       "): the mesh is not closed");
  }
  if (uses > 2) {
    std::string list;
    for (std::size_t k = first; k < end && k < first + 4; ++k) {
      list += (k == first ? "" : ", ") + std::to_string(halfEdges[k].triangle);
    }
    if (uses > 4) {
      list += ", ...";
    }
    return recorder.add(MeshProblemKind::NonManifoldEdge,
                        edgeName(key) + " is used by " + std::to_string(uses) +
                            " triangles (triangles " + list + "); a closed surface uses it twice");
  }
  if (forward != 1) {
    return recorder.add(MeshProblemKind::InconsistentOrientation,
                        edgeName(key) + " is used twice in the same direction (triangles " +
                            std::to_string(halfEdges[first].triangle) + " and " +
                            std::to_string(halfEdges[first + 1].triangle) +
                            "): inconsistent orientation");
  }
  return false;
}

// Closed, manifold and consistently oriented: every edge used by exactly two triangles, in
// opposite directions. Returns the number of distinct edges (for the Euler characteristic),
// or nullopt if it found a problem.
std::optional<std::size_t> checkEdges(const std::vector<Triangle>& triangles, Recorder& recorder) {
  const std::size_t before = recorder.count();
  const std::vector<HalfEdge> halfEdges = sortedHalfEdges(triangles);
  std::size_t edgeCount = 0;
  for (std::size_t i = 0; i < halfEdges.size();) {
    std::size_t j = i;
    while (j < halfEdges.size() && halfEdges[j].key == halfEdges[i].key) {
      ++j;
    }
    ++edgeCount;
    if (recordEdgeProblem(halfEdges, i, j, recorder)) {
      return std::nullopt;
    }
    i = j;
  }
  if (recorder.count() > before) {
    return std::nullopt;
  }
  return edgeCount;
}

// The number of connected components among the vertices that triangles use.
std::size_t countComponents(const TriangleMesh& mesh) {
  DisjointSets sets(mesh.vertices.size());
  for (const Triangle& tri : mesh.triangles) {
    sets.unite(tri[0], tri[1]);
    sets.unite(tri[0], tri[2]);
  }
  // Count distinct roots among used vertices.
  std::vector<bool> isRoot(mesh.vertices.size(), false);
  std::size_t components = 0;
  for (const Triangle& tri : mesh.triangles) {
    for (const VertexIndex v : tri) {
      const std::size_t root = sets.find(v);
      if (!isRoot[root]) {
        isRoot[root] = true;
        ++components;
      }
    }
  }
  return components;
}

// One surface without handles: connected, and Euler characteristic V - E + F = 2 (each
// handle of a closed surface lowers it by 2). Returns true if it found a problem.
bool checkSingleSurface(const TriangleMesh& mesh, std::size_t usedVertexCount,
                        std::size_t edgeCount, Recorder& recorder) {
  const std::size_t components = countComponents(mesh);
  if (components > 1) {
    recorder.add(MeshProblemKind::NotSingleSurface,
                 "the mesh has " + std::to_string(components) +
                     " connected components; a convex block is one closed surface");
    return true;
  }
  const std::size_t faceCount = mesh.triangles.size();
  const long long euler = static_cast<long long>(usedVertexCount) -
                          static_cast<long long>(edgeCount) + static_cast<long long>(faceCount);
  if (euler != 2) {
    recorder.add(MeshProblemKind::NotSingleSurface,
                 "Euler characteristic V - E + F = " + std::to_string(usedVertexCount) + " - " +
                     std::to_string(edgeCount) + " + " + std::to_string(faceCount) + " = " +
                     std::to_string(euler) + ", expected 2 (a closed surface without handles)");
    return true;
  }
  return false;
}

}  // namespace

bool checkTopology(const TriangleMesh& mesh, std::size_t usedVertexCount, Recorder& recorder) {
  const std::optional<std::size_t> edgeCount = checkEdges(mesh.triangles, recorder);
  if (!edgeCount) {
    return true;
  }
  return checkSingleSurface(mesh, usedVertexCount, *edgeCount, recorder);
}

}  // namespace recode::core::detail
