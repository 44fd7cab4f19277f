// checkClosedMesh's order of stages (closed_mesh.hpp lists them), its own exact stages 2 and 3
// (coordinate range, collinear triangles) and 5 (self-intersection, reported pair by pair), and
// the advice added to the messages of the stages it shares with checkConvexBlock, so that each
// says what to do.

#include "recode/geometry/closed_mesh.hpp"

#include <stdexcept>
#include <string>

#include "format.hpp"
#include "recode/geometry/exact_predicates.hpp"
#include "recode/geometry/self_intersection.hpp"
#include "triangle_intersection.hpp"
#include "validate_stages.hpp"

namespace recode::core {
namespace {

using detail::Recorder;
using detail::triangleName;

// Stage 2, after the shared checks: coordinates the exact predicates can take.
bool checkCoordinateRange(const TriangleMesh& mesh, Recorder& recorder) {
  const std::size_t before = recorder.count();
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (mesh.vertices[i].cwiseAbs().maxCoeff() > kMaxExactCoordinate &&
        recorder.add(MeshProblemKind::CoordinateOutOfRange,
                     "vertex " + std::to_string(i) + " " + detail::formatPoint(mesh.vertices[i]) +
                         " has a coordinate beyond +-1e100, where the exact intersection tests "
                         "would overflow; scale the mesh down")) {
      return true;
    }
  }
  return recorder.count() > before;
}

// Stage 3: no triangle without area, decided exactly (a repeated index, or three points on one
// line): it has no plane, so neither a side nor an intersection test. Returns true if the
// problem limit is reached.
bool checkCollinearTriangles(const TriangleMesh& mesh, Recorder& recorder) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    std::string problem;
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
      const VertexIndex repeated = tri[0] == tri[1] || tri[0] == tri[2] ? tri[0] : tri[1];
      problem = " repeats vertex index " + std::to_string(repeated);
    } else if (collinear(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]])) {
      problem = " has zero area: its three points lie on one line";
    } else {
      continue;
    }
    if (recorder.add(MeshProblemKind::DegenerateTriangle,
                     triangleName(t, tri) + problem +
                         "; remove it (merge it into its neighbours) or move a vertex off the "
                         "line")) {
      return true;
    }
  }
  return false;
}

// Stage 5: the first pairs of triangles that meet, in order, up to the problem limit.
void checkSelfIntersection(const TriangleMesh& mesh, Recorder& recorder, std::size_t maxProblems) {
  for (const TrianglePair& pair : selfIntersections(mesh, maxProblems - recorder.count())) {
    const Triangle& t = mesh.triangles[pair.first];
    const Triangle& u = mesh.triangles[pair.second];
    std::string how;
    switch (detail::sharedVertexCount(t, u)) {
      case 0:
        how = " intersect";
        break;
      case 1:
        how = " meet beyond the vertex they share";
        break;
      case 2:
        how =
            " lie in one plane on the same side of the edge they share: the surface folds onto "
            "itself";
        break;
      default:
        how = " have the same three vertices: the surface doubles back on itself";
    }
    if (recorder.add(MeshProblemKind::SelfIntersection,
                     triangleName(pair.first, t) + " and " + triangleName(pair.second, u) + how +
                         "; a closed mesh must not cut, touch or overlap itself: separate or "
                         "remesh the parts that meet")) {
      return;
    }
  }
}

// What to do about a problem found by a stage shared with checkConvexBlock, whose messages say
// only what is wrong; nullptr for kinds whose messages already say it.
const char* adviceFor(MeshProblemKind kind) {
  switch (kind) {
    case MeshProblemKind::NoTriangles:
      return "a closed mesh needs the triangles of at least one closed surface";
    case MeshProblemKind::NonFiniteCoordinate:
      return "fix or remove that vertex";
    case MeshProblemKind::IndexOutOfRange:
      return "every index must name one of the vertices (counted from 0)";
    case MeshProblemKind::OpenEdge:
      return "fill the hole so that every edge has a triangle on each side";
    case MeshProblemKind::NonManifoldEdge:
      return "separate the surfaces that meet there so that each edge joins two triangles";
    case MeshProblemKind::InconsistentOrientation:
      return "reverse the winding of one of the two (swap two of its indices) so that all "
             "triangles of a piece face the same way";
    default:
      return nullptr;
  }
}

// Appends the advice to the messages recorded since `from`.
void addAdvice(ValidationReport& report, std::size_t from) {
  for (std::size_t k = from; k < report.problems.size(); ++k) {
    if (const char* advice = adviceFor(report.problems[k].kind)) {
      report.problems[k].message += std::string("; ") + advice;
    }
  }
}

// Stages 1 to 4 (closed_mesh.hpp); true if they found nothing. Stages 3 and 4 both run once
// stage 2 is clean, so that a file with several faults shows them together.
bool topologyIsClean(const TriangleMesh& mesh, Recorder& recorder) {
  if (detail::checkHasTriangles(mesh, recorder) ||
      detail::checkCoordinatesAndIndices(mesh, recorder) || checkCoordinateRange(mesh, recorder) ||
      checkCollinearTriangles(mesh, recorder)) {
    return false;
  }
  if (!detail::checkEdges(mesh.triangles, recorder) || detail::checkVertexFans(mesh, recorder)) {
    return false;
  }
  return recorder.count() == 0;
}

}  // namespace

ValidationReport checkClosedMesh(const TriangleMesh& mesh, std::size_t maxProblems) {
  if (maxProblems == 0) {
    throw std::invalid_argument("checkClosedMesh: maxProblems must be at least 1, got 0");
  }
  ValidationReport report;
  Recorder recorder(report, maxProblems);
  const bool clean = topologyIsClean(mesh, recorder);
  addAdvice(report, 0);
  if (!clean) {
    return report;
  }
  checkSelfIntersection(mesh, recorder, maxProblems);
  if (!report.ok()) {
    return report;
  }
  detail::checkShellNesting(mesh, recorder);
  return report;
}

void validateClosedMesh(const TriangleMesh& mesh, std::string_view sourceName) {
  const ValidationReport report = checkClosedMesh(mesh, 1);
  if (!report.ok()) {
    throw MeshError(std::string(sourceName) + ": " + report.problems.front().message);
  }
}

}  // namespace recode::core
