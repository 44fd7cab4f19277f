#pragma once
// Checking that a TriangleMesh is a convex block: a closed, consistently and outwardly
// oriented, convex polyhedral surface that the RECODE algorithm can rasterize as one solid
// (each view ray through its interior meets exactly one front and one back face).
//
// The checks run in stages; a stage runs only if the stages it depends on found nothing:
//   1. there are triangles;
//   2. every coordinate is finite; every index is below vertexCount();
//   3. no triangle repeats an index or has (near) zero area; every vertex is used;
//   4. every edge is used by exactly two triangles, once in each direction; the surface is
//      connected and has Euler characteristic V - E + F = 2 (stage 4 needs stage 2 only);
//   5. the signed volume is > 0 (faces point outward);
//   6. convexity: no vertex lies more than tol = relativeTolerance * (bounding-box diagonal)
//      in front of the plane of any triangle;
//   7. the surface winds exactly once around its vertex centroid (total solid angle 4*pi),
//      which rules out a surface that covers a convex solid twice.
// Stage 3's area test uses the same tolerance: a triangle is degenerate when its height
// over its longest edge is at most tol.
//
// Cost: stages 1-5 and 7 take O(V + F log F). Stage 6 is an exact brute-force search for
// the vertex farthest in front of each triangle's plane, accelerated by a bounding-volume
// hierarchy over the vertices that skips groups of vertices lying wholly behind the plane:
// O(V log V) to build, then per triangle O(log V) plus the vertices near its plane for the
// usual tessellated solids, O(V) per triangle in the worst case (all vertices near one
// plane), so O(F * V) at worst. docs/geometry.md has measurements.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "recode/geometry/mesh.hpp"
#include "recode/geometry/mesh_error.hpp"

namespace recode::core {

enum class MeshProblemKind {
  NoTriangles,
  NonFiniteCoordinate,
  IndexOutOfRange,
  DegenerateTriangle,
  UnusedVertex,
  OpenEdge,                 // an edge used by one triangle only: the mesh is not closed
  NonManifoldEdge,          // an edge used by more than two triangles
  InconsistentOrientation,  // an edge used twice in the same direction
  NotSingleSurface,         // disconnected, or Euler characteristic != 2
  InwardOrientation,        // signed volume <= 0
  NotConvex,
  MultipleWinding,
  // The closed-mesh check's own (closed_mesh.hpp):
  CoordinateOutOfRange,  // beyond +-kMaxExactCoordinate, where the exact predicates overflow
  NonManifoldVertex,     // the triangles around a vertex form more than one fan
  SelfIntersection,      // two triangles meet other than at their shared edge or vertex
  NestedShell,           // a shell's orientation disagrees with the shells around it
};

// Short name of a problem kind, e.g. "not convex". Both checks report with these kinds and
// ValidationReport: checkConvexBlock here, checkClosedMesh in closed_mesh.hpp.
[[nodiscard]] std::string_view toString(MeshProblemKind kind);

struct MeshProblem {
  MeshProblemKind kind;
  std::string message;  // e.g. "edge (3, 7) is used by only one triangle (triangle 12) ..."
};

struct ValidationReport {
  std::vector<MeshProblem> problems;  // in the order found, at most maxProblems
  bool truncated = false;             // true if the search stopped on reaching maxProblems problems

  [[nodiscard]] bool ok() const { return problems.empty(); }
};

// Runs the checks and records up to maxProblems problems (maxProblems >= 1; it stops
// searching once that many are found). relativeTolerance must be finite and >= 0
// (std::invalid_argument otherwise).
[[nodiscard]] ValidationReport checkConvexBlock(const TriangleMesh& mesh,
                                                double relativeTolerance = 1e-9,
                                                std::size_t maxProblems = 16);

// Throws MeshError("<sourceName>: <first problem>") if the mesh is not a valid convex block.
void validateConvexBlock(const TriangleMesh& mesh, std::string_view sourceName,
                         double relativeTolerance = 1e-9);

}  // namespace recode::core
