#pragma once
// Internal to checkConvexBlock and checkClosedMesh (not installed, not public API): what their
// stages share. The convex-block stages are split by job over validate.cpp (stages 1-3 and 5,
// and the order they run in), validate_topology.cpp (stage 4) and validate_convexity.cpp
// (stages 6 and 7); the closed-mesh check (closed_mesh.cpp) reuses stages 1 and 2 and the edge
// check of stage 4, and adds the vertex fans (validate_topology.cpp) and the shells
// (shell_nesting.cpp). validate.hpp and closed_mesh.hpp list the stages, docs/geometry.md
// their messages.

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/validate.hpp"

namespace recode::core::detail {

// Collects problems up to a limit.
class Recorder {
 public:
  Recorder(ValidationReport& report, std::size_t limit) : report_(report), limit_(limit) {}

  // Records a problem; returns true if the limit is now reached (the caller stops).
  bool add(MeshProblemKind kind, std::string message) {
    report_.problems.push_back({kind, std::move(message)});
    if (report_.problems.size() >= limit_) {
      report_.truncated = true;
      return true;
    }
    return false;
  }
  [[nodiscard]] bool full() const { return report_.problems.size() >= limit_; }
  [[nodiscard]] std::size_t count() const { return report_.problems.size(); }

 private:
  ValidationReport& report_;
  std::size_t limit_;
};

// Union-find, for connected components.
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
  // Joins the sets of a and b; the smaller root index becomes the root.
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

// "triangle 5 (vertices 1, 2, 3)", as the messages name a triangle.
inline std::string triangleName(std::size_t t, const Triangle& tri) {
  return "triangle " + std::to_string(t) + " (vertices " + std::to_string(tri[0]) + ", " +
         std::to_string(tri[1]) + ", " + std::to_string(tri[2]) + ")";
}

// The mesh's vertices relative to its bounding-box centre, which gives better conditioned
// planes than the file's coordinates, with the lengths the geometric stages measure against.
struct CentredPoints {
  std::vector<Eigen::Vector3d> points;  // vertices[i] - centre, same order
  double diagonal = 0.0;                // of the bounding box
  double tolerance = 0.0;               // relativeTolerance * diagonal
};

// Stage 1 (validate.cpp): there are triangles. Returns true if it found a problem.
bool checkHasTriangles(const TriangleMesh& mesh, Recorder& recorder);

// Stage 2 (validate.cpp): finite coordinates, indices in range. Returns true if it found a
// problem.
bool checkCoordinatesAndIndices(const TriangleMesh& mesh, Recorder& recorder);

// Stage 4's edge check (validate_topology.cpp): every edge used by exactly two triangles, in
// opposite directions. Returns the number of distinct edges, or nullopt if it found a problem.
std::optional<std::size_t> checkEdges(const std::vector<Triangle>& triangles, Recorder& recorder);

// Closed meshes, after checkEdges found nothing (validate_topology.cpp): the triangles around
// each vertex form one fan. Returns true if it found a problem.
bool checkVertexFans(const TriangleMesh& mesh, Recorder& recorder);

// Closed meshes, stage 6 (shell_nesting.cpp): each shell faces outward where it bounds the
// solid from outside and inward where it bounds a cavity. Needs stages 1-5.
void checkShellNesting(const TriangleMesh& mesh, Recorder& recorder);

// Stage 4 (validate_topology.cpp): closed, manifold, consistently oriented, one surface
// without handles. Needs stage 2 only. Returns true if it found a problem.
bool checkTopology(const TriangleMesh& mesh, std::size_t usedVertexCount, Recorder& recorder);

// Stage 6 (validate_convexity.cpp): no vertex more than the tolerance in front of any
// triangle's plane. Needs stages 1-5. Returns true if it found a problem.
bool checkConvexity(const TriangleMesh& mesh, const CentredPoints& centred, Recorder& recorder);

// Stage 7 (validate_convexity.cpp): the surface winds once around its interior. Needs
// stages 1-6.
void checkSingleWinding(const TriangleMesh& mesh, const CentredPoints& centred, Recorder& recorder);

}  // namespace recode::core::detail
