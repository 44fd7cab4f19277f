// checkConvexBlock's order of stages, and the stages that look at single vertices and
// triangles (1-3) or the whole volume (5); stages 1 and 2 serve checkClosedMesh too. Stage 4 is in
// validate_topology.cpp, stages 6 and 7 in validate_convexity.cpp; validate.hpp lists what each
// stage checks.

#include "recode/geometry/validate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "format.hpp"
#include "validate_stages.hpp"

namespace recode::core {
namespace {

using detail::CentredPoints;
using detail::formatDouble;
using detail::formatPoint;
using detail::Recorder;
using detail::triangleName;

// The vertices relative to the bounding-box centre, and the tolerance (needs stage 2).
CentredPoints centrePoints(const TriangleMesh& mesh, double relativeTolerance) {
  const Aabb box = boundingBox(mesh);
  const Eigen::Vector3d centre = box.center();
  CentredPoints centred;
  centred.diagonal = box.diagonal();
  centred.tolerance = relativeTolerance * centred.diagonal;
  centred.points.resize(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    centred.points[i] = mesh.vertices[i] - centre;
  }
  return centred;
}

// Stage 3, triangles: no triangle repeats an index or has (near) zero area, since such a
// triangle has no normal for the orientation and convexity stages. The area test compares
// the height over the longest edge, a length, with the tolerance. Returns true if the
// problem limit is reached (other problems do not stop stage 4).
bool checkTriangleShapes(const TriangleMesh& mesh, const CentredPoints& centred,
                         Recorder& recorder) {
  const std::vector<Eigen::Vector3d>& points = centred.points;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
      const VertexIndex repeated = tri[0] == tri[1] || tri[0] == tri[2] ? tri[0] : tri[1];
      if (recorder.add(
              MeshProblemKind::DegenerateTriangle,
              triangleName(t, tri) + " repeats vertex index " + std::to_string(repeated))) {
        return true;
      }
      continue;
    }
    const Eigen::Vector3d& a = points[tri[0]];
    const Eigen::Vector3d& b = points[tri[1]];
    const Eigen::Vector3d& c = points[tri[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const double height = longest > 0.0 ? (b - a).cross(c - a).norm() / longest : 0.0;
    if (!(height > centred.tolerance)) {
      if (recorder.add(MeshProblemKind::DegenerateTriangle,
                       triangleName(t, tri) + " has zero area: its height over its longest " +
                           "edge is " + formatDouble(height) + " (tolerance " +
                           formatDouble(centred.tolerance) + ")")) {
        return true;
      }
    }
  }
  return false;
}

// Which vertices some triangle uses (needs stage 2).
std::vector<bool> usedVertices(const TriangleMesh& mesh) {
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const Triangle& tri : mesh.triangles) {
    for (const VertexIndex v : tri) {
      used[v] = true;
    }
  }
  return used;
}

// Stage 3, vertices: every vertex is used, since a stray vertex would still count in the
// convexity and winding stages (which run over all vertices) and the Euler characteristic
// counts used vertices only. Returns true if the problem limit is reached.
bool checkUnusedVertices(const TriangleMesh& mesh, const std::vector<bool>& used,
                         Recorder& recorder) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!used[i] &&
        recorder.add(MeshProblemKind::UnusedVertex, "vertex " + std::to_string(i) + " " +
                                                        formatPoint(mesh.vertices[i]) +
                                                        " is not used by any triangle")) {
      return true;
    }
  }
  return false;
}

// Stage 5: the faces point outward, which the rasterizer's front/back test relies on; on a
// closed, consistently oriented surface the sign of the volume tells. Returns true if it
// found a problem.
bool checkOutwardOrientation(const TriangleMesh& mesh, Recorder& recorder) {
  const double volume = signedVolume(mesh);
  if (!(volume > 0.0)) {
    recorder.add(MeshProblemKind::InwardOrientation,
                 "signed volume is " + formatDouble(volume) +
                     " (must be > 0): the faces point inward" +
                     (volume == 0.0 ? " or the mesh is flat" : ""));
    return true;
  }
  return false;
}

}  // namespace

namespace detail {

// Stage 1 (of both checks): there is something to check; every later stage assumes at least one
// triangle. Returns true if it found a problem.
bool checkHasTriangles(const TriangleMesh& mesh, Recorder& recorder) {
  if (mesh.triangles.empty()) {
    recorder.add(MeshProblemKind::NoTriangles, "the mesh has no triangles");
    return true;
  }
  return false;
}

// Stage 2 (of both checks): every coordinate is finite and every index names a vertex, so that the
// later stages can do arithmetic on the points that the triangles index. Returns true if it found
// a problem.
bool checkCoordinatesAndIndices(const TriangleMesh& mesh, Recorder& recorder) {
  const std::size_t before = recorder.count();
  const std::size_t vertexCount = mesh.vertices.size();
  for (std::size_t i = 0; i < vertexCount; ++i) {
    if (!mesh.vertices[i].allFinite()) {
      if (recorder.add(MeshProblemKind::NonFiniteCoordinate, "vertex " + std::to_string(i) +
                                                                 " has a non-finite coordinate " +
                                                                 formatPoint(mesh.vertices[i]))) {
        return true;
      }
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (const VertexIndex v : mesh.triangles[t]) {
      if (v >= vertexCount) {
        if (recorder.add(MeshProblemKind::IndexOutOfRange,
                         "triangle " + std::to_string(t) + " has vertex index " +
                             std::to_string(v) + " out of range (" + std::to_string(vertexCount) +
                             " vertices)")) {
          return true;
        }
        break;  // one message per triangle
      }
    }
  }
  return recorder.count() > before;
}

}  // namespace detail

std::string_view toString(MeshProblemKind kind) {
  switch (kind) {
    case MeshProblemKind::NoTriangles:
      return "no triangles";
    case MeshProblemKind::NonFiniteCoordinate:
      return "non-finite coordinate";
    case MeshProblemKind::IndexOutOfRange:
      return "index out of range";
    case MeshProblemKind::DegenerateTriangle:
      return "degenerate triangle";
    case MeshProblemKind::UnusedVertex:
      return "unused vertex";
    case MeshProblemKind::OpenEdge:
      return "open edge";
    case MeshProblemKind::NonManifoldEdge:
      return "non-manifold edge";
    case MeshProblemKind::InconsistentOrientation:
      return "inconsistent orientation";
    case MeshProblemKind::NotSingleSurface:
      return "not a single surface";
    case MeshProblemKind::InwardOrientation:
      return "inward orientation";
    case MeshProblemKind::NotConvex:
      return "not convex";
    case MeshProblemKind::MultipleWinding:
      return "multiple winding";
    case MeshProblemKind::CoordinateOutOfRange:
      return "coordinate out of range";
    case MeshProblemKind::NonManifoldVertex:
      return "non-manifold vertex";
    case MeshProblemKind::SelfIntersection:
      return "self-intersection";
    case MeshProblemKind::NestedShell:
      return "nested shell";
  }
  return "unknown problem";
}

// Each stage runs only when the stages it relies on found nothing (validate.hpp), and the
// search stops as soon as the problem limit is reached.
ValidationReport checkConvexBlock(const TriangleMesh& mesh, double relativeTolerance,
                                  std::size_t maxProblems) {
  if (!std::isfinite(relativeTolerance) || relativeTolerance < 0.0) {
    throw std::invalid_argument(
        "checkConvexBlock: relativeTolerance must be finite and >= 0, got " +
        formatDouble(relativeTolerance));
  }
  if (maxProblems == 0) {
    throw std::invalid_argument("checkConvexBlock: maxProblems must be at least 1, got 0");
  }
  ValidationReport report;
  Recorder recorder(report, maxProblems);
  if (detail::checkHasTriangles(mesh, recorder) ||
      detail::checkCoordinatesAndIndices(mesh, recorder)) {
    return report;
  }
  const CentredPoints centred = centrePoints(mesh, relativeTolerance);
  const std::vector<bool> used = usedVertices(mesh);
  if (checkTriangleShapes(mesh, centred, recorder) || checkUnusedVertices(mesh, used, recorder)) {
    return report;
  }
  const auto usedVertexCount = static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
  if (detail::checkTopology(mesh, usedVertexCount, recorder) || !report.ok()) {
    return report;
  }
  if (checkOutwardOrientation(mesh, recorder) || detail::checkConvexity(mesh, centred, recorder)) {
    return report;
  }
  detail::checkSingleWinding(mesh, centred, recorder);
  return report;
}

void validateConvexBlock(const TriangleMesh& mesh, std::string_view sourceName,
                         double relativeTolerance) {
  const ValidationReport report = checkConvexBlock(mesh, relativeTolerance, 1);
  if (!report.ok()) {
    throw MeshError(std::string(sourceName) + ": " + report.problems.front().message);
  }
}

}  // namespace recode::core
