// Stage 4 of checkConvexBlock: the triangles form one closed, manifold, consistently
// oriented surface of genus 0. The later, geometric stages (volume, convexity, winding)
// are only meaningful on such a surface. checkClosedMesh uses the edge check and adds the
// vertex fans: closed and manifold, of any genus and in any number of pieces.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "validate_stages.hpp"

namespace recode::core::detail {
namespace {

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

// A triangle's corner: corner 3t + k is vertex triangles[t][k].
struct DirectedEdge {
  VertexIndex from;
  VertexIndex to;
  std::uint32_t corner;  // the corner at `from` of the triangle running from -> to

  [[nodiscard]] bool before(VertexIndex f, VertexIndex t) const {
    return from < f || (from == f && to < t);
  }
};

}  // namespace

// Around vertex v, triangle t = (v, next, prev) and the triangle that runs next -> v (the
// other side of edge (v, next)) are neighbours in v's fan. After checkEdges each directed edge
// is used once, so the neighbours join v's corners into cycles: one for a manifold vertex,
// several where separate fans only share the vertex (two cones tip to tip).
bool checkVertexFans(const TriangleMesh& mesh, Recorder& recorder) {
  const std::size_t cornerCount = 3 * mesh.triangles.size();
  std::vector<DirectedEdge> edges;
  edges.reserve(cornerCount);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (std::size_t k = 0; k < 3; ++k) {
      edges.push_back({tri[k], tri[(k + 1) % 3], static_cast<std::uint32_t>(3 * t + k)});
    }
  }
  std::sort(edges.begin(), edges.end(),
            [](const DirectedEdge& l, const DirectedEdge& r) { return l.before(r.from, r.to); });
  DisjointSets fans(cornerCount);
  for (const DirectedEdge& e : edges) {
    const auto back = std::lower_bound(
        edges.begin(), edges.end(), e,
        [](const DirectedEdge& l, const DirectedEdge& r) { return l.before(r.to, r.from); });
    if (back != edges.end() && back->from == e.to && back->to == e.from) {
      // back runs to -> from and has its corner at `to`; its corner at `from` is the next one.
      const std::uint32_t t = back->corner / 3;
      fans.unite(e.corner, 3 * t + (back->corner % 3 + 1) % 3);
    }
  }
  // A fan's root is its corner of lowest index; a vertex with a second root is pinched.
  std::vector<std::uint32_t> firstFan(mesh.vertices.size(),
                                      std::numeric_limits<std::uint32_t>::max());
  std::vector<std::uint32_t> fanCount(mesh.vertices.size(), 0);
  std::vector<std::uint32_t> secondFan(mesh.vertices.size(),
                                       std::numeric_limits<std::uint32_t>::max());
  for (std::size_t c = 0; c < cornerCount; ++c) {
    if (fans.find(c) != c) {
      continue;
    }
    const VertexIndex v = mesh.triangles[c / 3][c % 3];
    if (++fanCount[v] == 1) {
      firstFan[v] = static_cast<std::uint32_t>(c / 3);
    } else if (fanCount[v] == 2) {
      secondFan[v] = static_cast<std::uint32_t>(c / 3);
    }
  }
  const std::size_t before = recorder.count();
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (fanCount[v] > 1 &&
        recorder.add(MeshProblemKind::NonManifoldVertex,
                     "vertex " + std::to_string(v) + " is shared by " +
                         std::to_string(fanCount[v]) + " separate fans of triangles (triangles " +
                         std::to_string(firstFan[v]) + " and " + std::to_string(secondFan[v]) +
                         " are in different fans): the surface pinches there; give each fan a "
                         "vertex of its own and move them apart, or join the pieces")) {
      return true;
    }
  }
  return recorder.count() > before;
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

bool checkTopology(const TriangleMesh& mesh, std::size_t usedVertexCount, Recorder& recorder) {
  const std::optional<std::size_t> edgeCount = checkEdges(mesh.triangles, recorder);
  if (!edgeCount) {
    return true;
  }
  return checkSingleSurface(mesh, usedVertexCount, *edgeCount, recorder);
}

}  // namespace recode::core::detail
